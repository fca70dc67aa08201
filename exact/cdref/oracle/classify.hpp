// cdref/oracle/classify.hpp - the fast exact classification oracle for the eight campaign
// queries at double inputs. Each classify() returns exactly what the book's algorithm
// (include/cdref/book) returns when instantiated at CGAL::Gmpq on the same doubles, in three
// stages:
//
//   1. filter     each decisive polynomial evaluated in double, its sign accepted when the
//                 value exceeds an error bound derived below (no rounding-mode switch);
//   2. expansion  for the sphere queries first the robust tier's certified double words
//                 (double_word below), then the exact sign by floating-point expansions (Shewchuk 1997: Two-Sum,
//                 Two-Product with std::fma, Scale-Expansion, Fast-Expansion-Sum, a final
//                 Grow-Expansion pass), in fixed-size stack buffers, on inputs scaled by a
//                 power of two into a range where nothing overflows or underflows (each
//                 predicate is first tried by the filter there; only the undecided ones are
//                 expanded);
//   3. rational   the book at CGAL::Gmpq.
//
// ---- The polynomials ---------------------------------------------------------------------
// At an exact type every difference s = source - centre is exact, so the book's decisions are
// signs of polynomials in the inputs:
//   sphere-sphere   S^2 - |D|^2 >= 0, D = cA - cB, S = rhoA + rhoB.
//   ray/segment cast on a sphere (Algorithm 3.1, book::hit), s = source - c, r = t - s
//                   (= target - source for a segment, the direction for a ray), t = target - c:
//                   |r|^2 = 0 (a segment of length 0: exact comparison of the inputs) -> |s|^2 <= rho^2;
//                   sigma = (s.r)^2 - |r|^2 (|s|^2 - rho^2) >= 0, and by Lagrange's identity
//                   (s.r)^2 - |r|^2 |s|^2 = -|s x r|^2, sigma = |r|^2 rho^2 - |s x r|^2, the form
//                   used here (its rounding error is smaller; at exact types both are equal);
//                   lambda_2 >= 0 <=> s.r <= 0 or |s|^2 <= rho^2;
//                   lambda_1 <= 1 <=> s.r + |r|^2 = t.r >= 0 or |t|^2 <= rho^2.
//   segment-sphere  (Algorithm 3.2, book::intersect) delta = -s.r: delta <= 0 <=> s.r >= 0 ->
//                   |s|^2 <= rho^2; delta >= |r|^2 <=> t.r <= 0 -> |t|^2 <= rho^2; otherwise
//                   |s|^2|r|^2 - delta^2 <= rho^2 |r|^2 <=> sigma >= 0. Both algorithms decide
//                   whether the closed segment meets the closed ball, so at exact types they
//                   agree on every input (the test checks it on every family); the oracle keeps
//                   both branch structures and both names.
//   box-box         per axis |a - b| <= ea + eb <=> sign(ea + eb - |a - b|) >= 0.
//   ray/segment cast on a box (Algorithm 3.3): outcodes are signs of p - c + h and p - c - h.
//                   The book keeps the largest entering parameter (starting at 0) and the
//                   smallest exiting one (starting at 1 for a segment) and hits iff
//                   enter <= exit. Every entering parameter lies in [0, 1] (the source is
//                   outside that plane, the target is not) and every exiting one in [0, 1]
//                   ([0, inf) for a ray), so the decision is: for every entering plane p and
//                   exiting plane q, lambda_p <= lambda_q, i.e. with lambda = n / d, d > 0
//                   (sign of d known from the outcodes),  n_p d_q - n_q d_p <= 0.
//                   n = -(s - c) -+ h (3 inputs), d = |target - source| or |direction|.
//                   Ties between planes change which plane the book keeps, never the decision.
//   sphere-box      v_i = clamp(c_i, -h_i, h_i) - c_i, |v|^2 <= rho^2 with c = centre - box
//                   centre. |v_i| = max(0, |c_i| - h_i) whichever branch the book takes.
// Every one of these signs is invariant under scaling all inputs by the same power of two
// (each polynomial is homogeneous, and the box cast compares fractions), which stage 2 uses.
//
// ---- Stage 1: error bounds ---------------------------------------------------------------
// Model: u = 2^-53; fl(a op b) = (a op b)(1 + delta), |delta| <= u, for + - * while nothing
// overflows or underflows; theta_k: a product of k factors (1 + delta) equals 1 + theta_k with
// |theta_k| <= gamma_k = k u / (1 - k u) (Higham, Lemmas 3.1, 3.3). A leaf s~ = fl(p - c) is
// s (1 + delta): one factor. Expanding the computed expression into monomials of the exact
// leaves, each monomial carries at most K factors, K counted along the evaluation tree
// (K(leaf) <= 1, K(a +- b) = max(K(a), K(b)) + 1, K(a * b) = K(a) + K(b) + 1), so
//     |P~ - P| <= gamma_K P+,   P+ = the sum of the absolute values of the monomials.
// P+ is bounded by quantities computed anyway (sums of squares); the exact leaves are bounded
// by the computed ones (|s| <= |s~| / (1 - u)), the computed sums of squares by their terms
// (1 +- gamma_3), and the bound's own evaluation loses at most a factor (1 - u)^3. All these
// inflations together stay below (1 + 40u), so the constant is taken as the next integer
// multiple of u above K u: gamma_K (1 + 40u) < (K + 1) u (1 - 3u). The remaining margin,
// at least u P+ / 2, absorbs underflow: an underflowing product is off by at most 2^-1075,
// multiplied by cofactors bounded by the other magnitudes; the range checks (sums of squares
// in [2^-960, 2^1000], or [2^-480, 2^480] for the quartic sigma) keep that below 2^-500 times
// the margin, keep the bound itself a normal number, and exclude overflow (every intermediate
// is below the checked sum). A NaN or infinity fails the range checks. Outside them: stage 2.
//
// ---- Stage 2: expansions -------------------------------------------------------------------
// Two-Sum and Two-Product (x = fl(ab), y = fma(a, b, -x)) are error-free as long as nothing
// overflows and no product's exact value has bits below 2^-1074. After scaling by a power of
// two so that the largest input magnitude is below 2^100, and requiring every nonzero input
// to be at least 2^-180 (otherwise stage 3), every input is a multiple of 2^-232, every
// component of a degree-k quantity a multiple of 2^(-232 k) >= 2^-928 (k <= 4), and every
// magnitude below 2^420. So every sum and product is exact: the expansions represent the
// polynomials exactly whatever the overlap of their components. The sign is read after a
// Grow-Expansion pass (Shewchuk's Theorem 10: adding doubles one by one to a nonoverlapping
// expansion keeps it nonoverlapping, in any tie-breaking), whose largest component then
// dominates the sum of the others (skipped when a cheap rigorous test shows that the last
// component already does). Scale-Expansion and Fast-Expansion-Sum keep the lengths
// short (under round-to-even their outputs are nonoverlapping too); their correctness as sums
// does not depend on it.
#pragma once

#include <cdref/cdref.hpp>
#include <cdref/exact/rationals.hpp>
#include <cdref/filter/box_cast_filter.hpp>
#include <cdref/filter/sphere_filter.hpp>
#include <cdref/oracle/rational.hpp>
#include <cdref/oracle/stage.hpp>
#include <cdref/bounded/word_bounds.hpp>
#include <cdref/robust/ray_sphere.hpp>
#include <cdref/robust/segment_sphere.hpp>
#include <cdref/robust/sphere_box.hpp>
#include <cdref/robust/sphere_sphere.hpp>
#include <cmath>

namespace cdref::oracle {

namespace staged {

// (unknown, u, in_range and fsign: filter/box_cast_filter.hpp; le0, ge0, SphereFilter,
// hit_sphere_logic and segment_sphere_logic: filter/sphere_filter.hpp)

// ---- stage 2: expansions ----
template <int N>
struct Exp {
  int n = 0;
  double c[N];  // exact sum of c[0..n), no zeros, roughly increasing magnitude
};

inline void two_sum(double a, double b, double& x, double& y) {
  const double s = a + b, bv = s - a, av = s - bv;
  y = (a - av) + (b - bv);
  x = s;
}
inline void two_prod(double a, double b, double& x, double& y) {
  x = a * b;
  y = std::fma(a, b, -x);
}

// e = a (one component).
template <int N>
void set1(Exp<N>& e, double a) {
  e.n = 0;
  if (a != 0) e.c[e.n++] = a;
}
// e = a + b exactly (Two-Sum: |y| <= ulp(x) / 2, so (y, x) is nonoverlapping).
template <int N>
void set2(Exp<N>& e, double a, double b) {
  static_assert(N >= 2);
  double x, y;
  two_sum(a, b, x, y);
  e.n = 0;
  if (y != 0) e.c[e.n++] = y;
  if (x != 0) e.c[e.n++] = x;
}
template <int N>
void negate(Exp<N>& e) {
  for (int i = 0; i < e.n; ++i) e.c[i] = -e.c[i];
}
// h = e + f (or e - f): Fast-Expansion-Sum's merge by magnitude, then a Two-Sum chain with
// zero elimination. Exact whatever the inputs (every step is a Two-Sum); h.n <= e.n + f.n.
// h must not alias e or f; its capacity must cover e.n + f.n.
template <int A, int B, int N>
void add(const Exp<A>& e, const Exp<B>& f, Exp<N>& h, bool subtract = false) {
  const int m = e.n, n = f.n;
  int i = 0, j = 0, k = 0;
  auto take = [&]() -> double {
    if (j < n) {
      const double fv = subtract ? -f.c[j] : f.c[j];
      if (i < m && std::fabs(e.c[i]) < std::fabs(fv)) return e.c[i++];
      ++j;
      return fv;
    }
    return e.c[i++];
  };
  if (m + n == 0) {
    h.n = 0;
    return;
  }
  double q = take();
  for (int left = m + n - 1; left > 0; --left) {
    double hh;
    two_sum(q, take(), q, hh);
    if (hh != 0) h.c[k++] = hh;
  }
  if (q != 0) h.c[k++] = q;
  h.n = k;
}
// h = e * b: Scale-Expansion with zero elimination; h.n <= 2 e.n. Exact.
template <int A, int N>
void scale(const Exp<A>& e, double b, Exp<N>& h) {
  static_assert(N >= 2 * A);
  int k = 0;
  if (e.n == 0 || b == 0) {
    h.n = 0;
    return;
  }
  double q, hh;
  two_prod(e.c[0], b, q, hh);
  if (hh != 0) h.c[k++] = hh;
  for (int i = 1; i < e.n; ++i) {
    double p1, p0, sum;
    two_prod(e.c[i], b, p1, p0);
    two_sum(q, p0, sum, hh);
    if (hh != 0) h.c[k++] = hh;
    two_sum(p1, sum, q, hh);
    if (hh != 0) h.c[k++] = hh;
  }
  if (q != 0) h.c[k++] = q;
  h.n = k;
}
// h = a * b: the sum of the scalings of a by each component of b; h.n <= 2 a.n b.n.
template <int A, int B, int N>
void mul(const Exp<A>& a, const Exp<B>& b, Exp<N>& h) {
  static_assert(N >= 2 * A * B);
  if (b.n == 1) return scale(a, b.c[0], h);
  Exp<2 * A> t;
  Exp<N> buf[2];
  int cur = 0;
  buf[0].n = 0;
  for (int j = 0; j < b.n; ++j) {  // after step j the length is <= 2 A (j + 1) <= N
    scale(a, b.c[j], t);
    add(buf[cur], t, buf[1 - cur]);
    cur ^= 1;
  }
  h.n = buf[cur].n;
  for (int i = 0; i < h.n; ++i) h.c[i] = buf[cur].c[i];
}
// Shewchuk's Compress, in place: a top-down then a bottom-up Two-Sum pass that merges
// components sharing bits, so that a product of compressed expansions has few terms. Exact
// whatever the input (Two-Sum everywhere); the length never grows.
template <int N>
void compress(Exp<N>& e) {
  if (e.n < 2) return;
  double g[N];
  int bottom = e.n - 1;
  double q = e.c[bottom];
  for (int i = e.n - 2; i >= 0; --i) {
    double hi, lo;
    two_sum(q, e.c[i], hi, lo);
    if (lo != 0) {
      g[bottom--] = hi;
      q = lo;
    } else {
      q = hi;
    }
  }
  g[bottom] = q;
  int top = 0;
  for (int i = bottom + 1; i < e.n; ++i) {
    double hi, lo;
    two_sum(g[i], q, hi, lo);
    if (lo != 0) e.c[top++] = lo;
    q = hi;
  }
  if (q != 0) e.c[top++] = q;
  e.n = top;
}
// The sign of the exact value: Grow-Expansion of the components one by one into g (always
// nonoverlapping, increasing magnitude, by Theorem 10), then the sign of its largest one.
template <int N>
int sign(const Exp<N>& e) {
  if (e.n == 0) return 0;
  {  // Usually the last component already dominates: the others sum (computed with k = n - 1
     // roundings of nonnegative terms, so at most a factor 1 / (1 - gamma_k) below the exact
     // sum; components are multiples of 2^-928, so no underflow) to less than it.
    double rest = 0, top = std::fabs(e.c[e.n - 1]);
    for (int i = 0; i < e.n - 1; ++i) rest += std::fabs(e.c[i]);
    if (top > rest * (1 + (e.n + 2) * 0x1p-52)) return e.c[e.n - 1] > 0 ? 1 : -1;
  }
  double g[N];
  int n = 0;
  for (int i = 0; i < e.n; ++i) {
    double q = e.c[i];
    int k = 0;
    for (int j = 0; j < n; ++j) {
      double hh;
      two_sum(q, g[j], q, hh);
      if (hh != 0) g[k++] = hh;
    }
    if (q != 0) g[k++] = q;
    n = k;
  }
  return n == 0 ? 0 : (g[n - 1] > 0 ? 1 : -1);
}
// sign(a + b + c) for doubles a, b, c.
inline int sign3(double a, double b, double c) {
  Exp<2> x;
  Exp<1> z;
  Exp<3> s;
  set2(x, a, b);
  set1(z, c);
  add(x, z, s);
  return sign(s);
}

// Scales x[0..n) by one power of two so that the largest magnitude is in [1, 2) when it is
// outside [2^-100, 2^100) (exact: results below 2^-180 are refused, the others are normal);
// false when a nonzero value is below 2^-180 afterwards (stage 3 then).
inline bool normalize(double* x, int n) {
  double m = 0;
  // (the inputs are checked finite before any stage past the filter: std::max, inline, where
  // std::fmax's NaN rule made it a library call per value)
  for (int i = 0; i < n; ++i) m = std::max(m, std::fabs(x[i]));
  if (m == 0) return true;
  // Judged on the inputs before scaling: a value the scaling would flush to zero (or make
  // subnormal) is refused too, not only one that stays nonzero and tiny.
  // Without a scaling (the common case) the test needs no ldexp: std::ldexp is a library call,
  // and twelve of them were most of box-box's second stage (near-touching cases within 2^-52:
  // 220 -> 40 ns a case, standalone, 2026-11-28).
  if (m < 0x1p100 && m >= 0x1p-100) {
    for (int i = 0; i < n; ++i)
      if (x[i] != 0 && std::fabs(x[i]) < 0x1p-180) return false;
    return true;
  }
  const int e = std::ilogb(m);
  for (int i = 0; i < n; ++i)
    if (x[i] != 0 && std::fabs(std::ldexp(x[i], -e)) < 0x1p-180) return false;
  for (int i = 0; i < n; ++i) x[i] = std::ldexp(x[i], -e);
  return true;
}
inline int pack(const Vec3<double>& v, const Vec3<double>& w, double* x) {
  for (int i = 0; i < 3; ++i) x[i] = v[i], x[3 + i] = w[i];
  return 6;
}
inline int pack(const Vec3<double>& v, double r, double* x) {
  for (int i = 0; i < 3; ++i) x[i] = v[i];
  x[3] = r;
  return 4;
}
inline int pack(const Sphere<double>& s, double* x) { return pack(s.center, s.radius, x); }
inline int pack(const Box<double>& b, double* x) { return pack(b.center, b.extent, x); }
inline int pack(const Segment<double>& s, double* x) { return pack(s.source, s.target, x); }
inline int pack(const Ray<double>& r, double* x) { return pack(r.source, r.direction, x); }
inline Vec3<double> v3(const double* x) { return Vec3<double>(x[0], x[1], x[2]); }
inline void unpack(Sphere<double>& s, const double* x) { s = {v3(x), x[3]}; }
inline void unpack(Box<double>& b, const double* x) { b = {v3(x), v3(x + 3)}; }
inline void unpack(Segment<double>& s, const double* x) { s = {v3(x), v3(x + 3)}; }
inline void unpack(Ray<double>& r, const double* x) { r = {v3(x), v3(x + 3)}; }
// a2, b2: a and b scaled together for stage 2; false if out of its range.
template <class A, class B>
bool scaled(const A& a, const B& b, A& a2, B& b2) {
  double x[12];
  const int na = pack(a, x);
  const int nb = pack(b, x + na);
  if (!normalize(x, na + nb)) return false;
  unpack(a2, x);
  unpack(b2, x + na);
  return true;
}

// ======================= sphere-sphere =======================
// Filter: P = S~^2 - sum D~_i^2 with D~_i = fl(cA_i - cB_i), S~ = fl(rhoA + rhoB).
// K: D_x^2 has 2 (leaves) + 1 (square) + 2 (sums) + 1 (final) = 6 factors, S^2 has 4: K = 6,
// P+ = |D|^2 + S^2 <= (xx + yy)(1 + 8u) from the computed terms, so bound 7u fl(xx + yy).
inline int filter(const Sphere<double>& a, const Sphere<double>& b) {
  const double dx = a.center[0] - b.center[0], dy = a.center[1] - b.center[1], dz = a.center[2] - b.center[2];
  const double s = a.radius + b.radius;
  const double xx = dx * dx + dy * dy + dz * dz, yy = s * s, m = xx + yy;
  if (!in_range(m)) return unknown;
  return positive_or_unknown(yy - xx, (7 * u) * m);  // ge0(fsign(..))
}
inline int expansion(const Sphere<double>& a0, const Sphere<double>& b0) {
  Sphere<double> a, b;
  if (!scaled(a0, b0, a, b)) return unknown;
  Exp<2> s, d;
  Exp<8> sq;
  Exp<32> acc[2];
  set2(s, a.radius, b.radius);
  mul(s, s, sq);
  int cur = 0;
  acc[0].n = sq.n;
  for (int k = 0; k < sq.n; ++k) acc[0].c[k] = sq.c[k];
  for (int i = 0; i < 3; ++i) {
    set2(d, a.center[i], -b.center[i]);
    mul(d, d, sq);
    add(acc[cur], sq, acc[1 - cur], true);
    cur ^= 1;
  }
  return int(sign(acc[cur]) >= 0);
}

// ======================= ray / segment on a sphere =======================
// The filter (SphereFilter) and the two algorithms' logic over signs: filter/sphere_filter.hpp.

// Exact signs of the same polynomials (inputs already scaled into stage 2's range).
struct SphereExact {
  Exp<2> s[3], r[3], t[3];
  double rho;
  bool rzero;
  SphereExact(const Vec3<double>& src, const Vec3<double>& rt, const Sphere<double>& sp, bool segment) {
    for (int i = 0; i < 3; ++i) {
      set2(s[i], src[i], -sp.center[i]);
      if (segment) {
        set2(r[i], rt[i], -src[i]);
        set2(t[i], rt[i], -sp.center[i]);
      } else {
        set1(r[i], rt[i]);
        t[i].n = 0;
      }
    }
    rzero = segment && rt[0] == src[0] && rt[1] == src[1] && rt[2] == src[2];
    rho = sp.radius;
  }
  // a.b, or a.a - rho^2 when square.
  static int dot_sign(const Exp<2>* a, const Exp<2>* b, bool minus_rho2, double rho) {
    Exp<8> p;
    Exp<26> acc[2];
    int cur = 0;
    acc[0].n = 0;
    if (minus_rho2) {  // acc = -rho^2 = -(x + y)
      double x, y;
      two_prod(rho, rho, x, y);
      if (y != 0) acc[0].c[acc[0].n++] = -y;
      if (x != 0) acc[0].c[acc[0].n++] = -x;
    }
    for (int i = 0; i < 3; ++i) {
      mul(a[i], b[i], p);
      add(acc[cur], p, acc[1 - cur]);
      cur ^= 1;
    }
    return sign(acc[cur]);
  }
  int ss_rho2() const { return dot_sign(s, s, true, rho); }
  int tt_rho2() const { return dot_sign(t, t, true, rho); }
  int sr() const { return dot_sign(s, r, false, 0); }
  int tr() const { return dot_sign(t, r, false, 0); }
  int sigma() const {
    // |s x r|^2
    Exp<1536> cc[2];
    int cur = 0;
    cc[0].n = 0;
    for (int k = 0; k < 3; ++k) {
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      Exp<8> p, q;
      Exp<16> ck;
      Exp<512> sq;
      mul(s[i], r[j], p);
      mul(s[j], r[i], q);
      add(p, q, ck, true);
      compress(ck);
      mul(ck, ck, sq);
      add(cc[cur], sq, cc[1 - cur]);
      cur ^= 1;
    }
    // |r|^2 rho^2
    Exp<8> p;
    Exp<24> rr[2];
    int rc = 0;
    rr[0].n = 0;
    for (int i = 0; i < 3; ++i) {
      mul(r[i], r[i], p);
      add(rr[rc], p, rr[1 - rc]);
      rc ^= 1;
    }
    Exp<2> rho2;
    double x, y;
    two_prod(rho, rho, x, y);
    set2(rho2, x, y);
    Exp<96> rrr;
    compress(rr[rc]);
    mul(rr[rc], rho2, rrr);
    Exp<1632> sig;
    add(rrr, cc[cur], sig, true);
    return sign(sig);
  }
};

// Stage 2 runs on the scaled inputs: each predicate is first tried by the filter (valid there
// too), and computed exactly only when the filter cannot decide it.
struct SphereStaged {
  SphereFilter f;
  SphereExact x;
  bool rzero;
  SphereStaged(const Vec3<double>& src, const Vec3<double>& rt, const Sphere<double>& sp, bool segment)
      : f(src, rt, sp, segment), x(src, rt, sp, segment), rzero(x.rzero) {}
  int ss_rho2() const { const int s = f.ss_rho2(); return s != unknown ? s : x.ss_rho2(); }
  int tt_rho2() const { const int s = f.tt_rho2(); return s != unknown ? s : x.tt_rho2(); }
  int sr() const { const int s = f.sr(); return s != unknown ? s : x.sr(); }
  int tr() const { const int s = f.tr(); return s != unknown ? s : x.tr(); }
  int sigma() const { const int s = f.sigma(); return s != unknown ? s : x.sigma(); }
};

// ---- the sign of a signed sum of squares on double words ----
// sum_k sg_k v_k^2 (sg_k = +1 or -1), each v_k known within eps_k of a double word X_k + L_k
// (|L_k| <= u |X_k|, from two_sum): the second stage of the sphere casts and Algorithm 3.2
// (sigma, below) and of sphere-box (Q, below). A square: |v^2 - (X + L)^2| <= eps (2 (|X| +
// |L|) + eps); (X + L)^2 = Z.hi + Z.lo + 2 X L + L^2 with Z = two_prod(X, X) (exact, or within
// eta where X^2 < 2^-968), fl(2 X L) within 2u^2 X^2 + eta, L^2 <= u^2 X^2 left out: its error
// is at most eps (2 (|X| + |L|) + eps) + 3u^2 X^2 + 3 eta. The N values sg_k Z.hi are summed
// exactly (a chain of two_sum, its N - 1 errors kept), the 3N - 1 small terms (each Z.lo, each
// 2 X L, the chain's errors) in double, within gamma_{3N-2} <= 16u (1 + 16u) (N <= 6) of the
// sum of their magnitudes; then V = fl(H + that sum) is within u |V| of H + it. The sign of V
// is the sum's when |V| (1 - u) exceeds the sum of every bound above, computed with a factor
// 1 + 64u for the rounding of the bounds themselves (a few dozen nonnegative terms, each
// rounded a few times). Returns +1, -1 or `unknown` (every |X_k| at most 2^500, so that no
// square overflows and two_prod's split is exact; otherwise, and on a non-finite bound,
// unknown). Mul: the exact products' policy (robust/eft.hpp).
template <class Mul, int N>
int signed_squares(const double (&X)[N], const double (&L)[N], const double (&eps)[N], const double (&sg)[N]) {
  using std::fabs;
  using P2 = robust::Pair<double>;
  constexpr double u = 0x1p-53, eta = 0x1p-1074;
  static_assert(N <= 6, "the small terms' bound is written for at most 6 squares");
  double H = 0, small[3 * N], err = 0;
  int ns = 0;
  int ok = 1;  // (int, not bool: & without a branch, and no warning for & on booleans)
  for (int k = 0; k < N; ++k) {
    ok &= int(fabs(X[k]) <= 0x1p500);
    const P2 Z = Mul::prod(X[k], X[k]);
    small[ns++] = sg[k] * Z.lo;
    small[ns++] = sg[k] * ((2 * X[k]) * L[k]);
    err += eps[k] * (2 * (fabs(X[k]) + fabs(L[k])) + eps[k]) + 3 * u * u * (X[k] * X[k]) + 3 * eta;
    if (k == 0) {
      H = sg[k] * Z.hi;
    } else {
      const P2 t = robust::two_sum(H, sg[k] * Z.hi);
      H = t.hi;
      small[ns++] = t.lo;
    }
  }
  if (!ok) return unknown;
  // (summed in two interleaved halves: two shorter chains of dependent additions)
  double lows[2] = {0, 0}, mags[2] = {0, 0};
  for (int k = 0; k < ns; ++k) {
    lows[k & 1] += small[k];
    mags[k & 1] += fabs(small[k]);
  }
  const double V = H + (lows[0] + lows[1]);
  const double E = (err + 16 * u * (1 + 16 * u) * (mags[0] + mags[1])) * (1 + 64 * u);
  if (!std::isfinite(V) || !std::isfinite(E)) return unknown;
  if (fabs(V) * (1 - u) > E) return V > 0 ? 1 : -1;
  return unknown;
}

// sigma = |r|^2 rho^2 - |s x r|^2 on double words: the sphere casts' and Algorithm 3.2's second
// stage, where the filter leaves sigma's sign open (within about u |s|^2 |r|^2 of 0, the line
// near tangency). Inputs: s = source - centre and r (target - source, or the direction) as exact
// pairs hi + lo (two_sum), and rho. sigma = sum_k (D_k^2 - C_k^2) with D_k = r_k rho and
// C_k = s_i r_j - s_j r_i ((i, j) = (k+1, k+2) mod 3), each taken as a double word X + L
// (|L| <= u |X|, from two_sum) within eps of its exact value:
//   C_k: P = s_i.hi r_j.hi and Q = s_j.hi r_i.hi exactly (two_prod); (x, y) = two_sum(P.hi,
//     -Q.hi); m = (s_i.hi r_j.lo + s_i.lo r_j.hi) - (s_j.hi r_i.lo + s_j.lo r_i.hi);
//     lo = ((y + P.lo) - Q.lo) + m; (X, L) = two_sum(x, lo). With M = |P.hi| + |Q.hi|
//     (|s.lo| <= u |s.hi|, |r.lo| <= u |r.hi|): |y|, |P.lo| + |Q.lo| <= u M (1 + u), |m| <=
//     2u M (1 + 4u), so lo's three roundings are at most 3u 4.1u M; m's four products and three
//     sums err by at most 8.1 u^2 M + 4 eta; the terms s.lo r.lo left out are at most u^2 M:
//     eps_C <= 21.4 u^2 M + 4 eta, taken as 32 u^2 M + 8 eta.
//   D_k: (a, b) = two_prod(r_k.hi, rho) exactly; lo = fl(b + fl(r_k.lo rho)); (X, L) =
//     two_sum(a, lo): eps_D <= u |r.lo rho| + eta + u |lo| <= 2.1 u^2 |a| + 2 eta, taken as
//     4 u^2 |a| + 4 eta.
// Then the sign of sum_k (D_k^2 - C_k^2) by signed_squares.
// Range: every nonzero s.hi, r.hi and rho in [2^-300, 2^200] (the inputs scaled() leaves are
// in [2^-180, 2^100], their differences above 2^-233), so each two_prod of two of them is exact
// and no square overflows; otherwise unknown.
// sigma_words below takes the fused products where the CPU has the instruction (the split
// products were half of this stage's time).
template <class Mul>
int sigma_words_with(const robust::Pair<double> (&s)[3], const robust::Pair<double> (&r)[3], double rho) {
  using std::fabs;
  using P2 = robust::Pair<double>;
  constexpr double u = 0x1p-53, eta = 0x1p-1074;
  const auto in_range = [](double x) { return int(x == 0 || (fabs(x) >= 0x1p-300 && fabs(x) <= 0x1p200)); };
  int ok = in_range(rho);
  for (int i = 0; i < 3; ++i) ok &= in_range(s[i].hi) & in_range(r[i].hi);
  if (!ok) return unknown;
  double X[6], L[6], eps[6], sg[6];
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const P2 Pk = Mul::prod(s[i].hi, r[j].hi), Qk = Mul::prod(s[j].hi, r[i].hi);
    const P2 xy = robust::two_sum(Pk.hi, -Qk.hi);
    const double m = (s[i].hi * r[j].lo + s[i].lo * r[j].hi) - (s[j].hi * r[i].lo + s[j].lo * r[i].hi);
    const P2 C = robust::two_sum(xy.hi, ((xy.lo + Pk.lo) - Qk.lo) + m);
    X[k] = C.hi, L[k] = C.lo, eps[k] = 32 * u * u * (fabs(Pk.hi) + fabs(Qk.hi)) + 8 * eta, sg[k] = -1;
    const P2 ab = Mul::prod(r[k].hi, rho);
    const P2 D = robust::two_sum(ab.hi, ab.lo + r[k].lo * rho);
    X[3 + k] = D.hi, L[3 + k] = D.lo, eps[3 + k] = 4 * u * u * fabs(ab.hi) + 4 * eta, sg[3 + k] = 1;
  }
  return signed_squares<Mul>(X, L, eps, sg);
}
inline int sigma_words(const robust::Pair<double> (&s)[3], const robust::Pair<double> (&r)[3], double rho) {
  return robust::with_products([&](auto mul) { return sigma_words_with<decltype(mul)>(s, r, rho); });
}

// The filter's signs, and sigma on double words where the filter leaves it open (the second
// stage's first try; the other signs open: unknown, for the robust tier's double words).
struct SphereWords {
  SphereFilter f;
  robust::Pair<double> s[3], r[3];
  double rho;
  bool rzero;
  SphereWords(const Vec3<double>& src, const Vec3<double>& rt, const Sphere<double>& sp, bool segment)
      : f(src, rt, sp, segment), rho(sp.radius), rzero(f.rzero) {
    for (int i = 0; i < 3; ++i) {
      s[i] = robust::two_sum(src[i], -sp.center[i]);
      r[i] = segment ? robust::two_sum(rt[i], -src[i]) : robust::Pair<double>{rt[i], 0.0};
    }
  }
  int ss_rho2() const { return f.ss_rho2(); }
  int tt_rho2() const { return f.tt_rho2(); }
  int sr() const { return f.sr(); }
  int tr() const { return f.tr(); }
  int sigma() const {
    const int g = f.sigma();
    return g != unknown ? g : sigma_words(s, r, rho);
  }
};

// (inlined where the classification is: a call here was a tenth of a campaign's case)
[[gnu::always_inline]] inline int filter(const Segment<double>& seg, const Sphere<double>& sp) {
  return sphere_cast_filter(seg.source, seg.target, sp, true);
}
[[gnu::always_inline]] inline int filter(const Ray<double>& ray, const Sphere<double>& sp) {
  return sphere_cast_filter(ray.source, ray.direction, sp, false);
}
struct alg32 {};  // tag: book::intersect(Segment, Sphere), Algorithm 3.2
// Algorithm 3.2's answer is Algorithm 3.1's hit (a segment meets the closed ball exactly when
// the cast hits: the tests run both stages' rational answers side by side), and the cast's
// filter decides it for less: its first sign, sigma, settles every line that misses, where
// Algorithm 3.2's region tests (s . r, then t . r) branch either way on uniform cases
[[gnu::always_inline]] inline int filter(const Segment<double>& seg, const Sphere<double>& sp, alg32) {
  return sphere_cast_filter(seg.source, seg.target, sp, true);
}
inline int expansion(const Segment<double>& seg0, const Sphere<double>& sp0) {
  Segment<double> seg;
  Sphere<double> sp;
  if (!scaled(seg0, sp0, seg, sp)) return unknown;
  return hit_sphere_logic(SphereStaged(seg.source, seg.target, sp, true), true);
}
inline int expansion(const Ray<double>& ray0, const Sphere<double>& sp0) {
  Ray<double> ray;
  Sphere<double> sp;
  if (!scaled(ray0, sp0, ray, sp)) return unknown;
  return hit_sphere_logic(SphereStaged(ray.source, ray.direction, sp, false), false);
}
inline int expansion(const Segment<double>& seg0, const Sphere<double>& sp0, alg32) {
  Segment<double> seg;
  Sphere<double> sp;
  if (!scaled(seg0, sp0, seg, sp)) return unknown;
  return segment_sphere_logic(SphereStaged(seg.source, seg.target, sp, true));
}

// ======================= box-box =======================
// Filter per axis: P = e~ - |d~|, e~ = fl(ea + eb), d~ = fl(a - b): K = 2, P+ = e + |d|, bound
// 3u fl(e~ + |d~|). Additions have no underflow error; m = 0 means e = d = 0 exactly.
inline int filter(const Box<double>& a, const Box<double>& b) {
  int res = 1;
  for (int i = 0; i < 3; ++i) {
    const double d = std::fabs(a.center[i] - b.center[i]), e = a.extent[i] + b.extent[i], m = e + d;
    if (m == 0) continue;
    if (!in_range(m)) {
      res = unknown;
      continue;
    }
    const int sg = fsign(e - d, (3 * u) * m);
    if (sg == unknown)
      res = unknown;
    else if (sg < 0)
      return 0;
  }
  return res;
}
inline int expansion(const Box<double>& a0, const Box<double>& b0) {
  Box<double> a, b;
  if (!scaled(a0, b0, a, b)) return unknown;
  // ea + eb - |a - b| >= 0 on every axis (the book's two tests, ea + eb -+ (a - b) >= 0, of
  // which the one with the sign of a - b is the binding one: the other adds two nonnegative
  // sums). a - b is the pair set2 makes, its sign that of its larger component (0 for none).
  for (int i = 0; i < 3; ++i) {
    Exp<2> e, d;
    Exp<4> p;
    set2(e, a.extent[i], b.extent[i]);
    set2(d, a.center[i], -b.center[i]);
    if (d.n > 0 && d.c[d.n - 1] < 0) negate(d);
    add(e, d, p, true);
    if (sign(p) < 0) return 0;
  }
  return 1;
}

// ======================= ray / segment on a box =======================
// Stage 1 (outcodes and the plane pairs in double): filter/box_cast_filter.hpp, which the robust
// tier runs first too. Stage 2 below: the same logic on exact signs.
struct BoxExact {
  const Vec3<double> &src, &rt;
  const Box<double>& box;
  bool bounded;
  BoxExact(const Vec3<double>& s, const Vec3<double>& t, const Box<double>& b, bool segment)
      : src(s), rt(t), box(b), bounded(segment) {}
  int src_lo(int i) const { return sign3(src[i], -box.center[i], box.extent[i]); }
  int src_hi(int i) const { return sign3(src[i], -box.center[i], -box.extent[i]); }
  int tgt_lo(int i) const { return sign3(rt[i], -box.center[i], box.extent[i]); }
  int tgt_hi(int i) const { return sign3(rt[i], -box.center[i], -box.extent[i]); }
  int dir_sign(int i) const {
    const double a = rt[i], b = bounded ? src[i] : 0.0;
    return a > b ? 1 : (a < b ? -1 : 0);
  }
  // n' and d' of plane p as expansions.
  void plane(int p, Exp<3>& n, Exp<2>& d) const {
    const int i = p / 2;
    Exp<2> x;
    Exp<1> h;
    set2(x, -src[i], box.center[i]);
    set1(h, p % 2 == 0 ? -box.extent[i] : box.extent[i]);
    add(x, h, n);
    if (bounded)
      set2(d, rt[i], -src[i]);
    else
      set1(d, rt[i]);
    if (dir_sign(i) < 0) negate(n), negate(d);
  }
  int compare(int p, int q) const {
    Exp<3> np, nq;
    Exp<2> dp, dq;
    plane(p, np, dp);
    plane(q, nq, dq);
    Exp<12> a, b;
    Exp<24> c;
    mul(np, dq, a);
    mul(nq, dp, b);
    add(a, b, c, true);
    return sign(c);
  }
};
// The filter's signs, the plane pairs on double words (bounded/word_bounds.hpp, AabbWords), then
// the expansions. (The pairs on words: 2^-52 from grazing, a cast the filter left took about 500
// ns a case, nine exact pairs at most, each a product of expansions.)
template <class Mul>
struct BoxStaged {
  BoxFilter f;
  word_bounds::AabbWords<Mul> w;
  BoxExact x;
  bool bounded;
  BoxStaged(const Vec3<double>& s, const Vec3<double>& t, const Box<double>& b, bool segment)
      : f(s, t, b, segment), w(s, t, b, segment), x(s, t, b, segment), bounded(segment) {}
  // (the filter's outcodes only within its range test, BoxFilter::ok)
  int src_lo(int i) const { const int s = f.ok ? f.src_lo(i) : unknown; return s != unknown ? s : x.src_lo(i); }
  int src_hi(int i) const { const int s = f.ok ? f.src_hi(i) : unknown; return s != unknown ? s : x.src_hi(i); }
  int tgt_lo(int i) const { const int s = f.ok ? f.tgt_lo(i) : unknown; return s != unknown ? s : x.tgt_lo(i); }
  int tgt_hi(int i) const { const int s = f.ok ? f.tgt_hi(i) : unknown; return s != unknown ? s : x.tgt_hi(i); }
  int dir_sign(int i) const { return x.dir_sign(i); }
  int compare(int p, int q) const {
    int s = f.compare(p, q);
    if (s == unknown) s = w.compare(p, q);
    return s != unknown ? s : x.compare(p, q);
  }
};

inline int expansion(const Segment<double>& seg0, const Box<double>& box0) {
  Segment<double> seg;
  Box<double> box;
  if (!scaled(seg0, box0, seg, box)) return unknown;
  return robust::with_products(
      [&](auto mul) { return hit_box_logic(BoxStaged<decltype(mul)>(seg.source, seg.target, box, true)); });
}
inline int expansion(const Ray<double>& ray0, const Box<double>& box0) {
  Ray<double> ray;
  Box<double> box;
  if (!scaled(ray0, box0, ray, box)) return unknown;
  return robust::with_products(
      [&](auto mul) { return hit_box_logic(BoxStaged<decltype(mul)>(ray.source, ray.direction, box, false)); });
}

// ======================= sphere-box =======================
// The filter: filter/sphere_filter.hpp.
inline int expansion(const Sphere<double>& sp0, const Box<double>& box0) {
  Sphere<double> sp;
  Box<double> box;
  if (!scaled(sp0, box0, sp, box)) return unknown;
  Exp<56> acc[2];
  int cur = 0;
  double x, y;
  two_prod(sp.radius, sp.radius, x, y);
  set2(acc[0], -x, -y);
  for (int i = 0; i < 3; ++i) {
    const double c = sp.center[i], b = box.center[i], h = box.extent[i];
    double hs;
    if (sign3(c, -b, h) < 0)
      hs = -h;  // c_i < -h_i: v_i = -h_i - c_i
    else if (sign3(c, -b, -h) > 0)
      hs = h;  // c_i > h_i: v_i = h_i - c_i
    else
      continue;  // v_i = 0
    Exp<2> cb;
    Exp<1> hh;
    Exp<3> v;
    Exp<18> sq;
    set2(cb, b, -c);
    set1(hh, hs);
    add(cb, hh, v);
    mul(v, v, sq);
    add(acc[cur], sq, acc[1 - cur]);
    cur ^= 1;
  }
  return int(sign(acc[cur]) <= 0);
}

// ======================= stage 3: the book at CGAL::Gmpq =======================
using rational_inputs::toq;
inline bool rational(const Sphere<double>& a, const Sphere<double>& b) { return book::intersect(toq(a), toq(b)); }
inline bool rational(const Segment<double>& s, const Sphere<double>& b) { return book::hit(toq(s), toq(b)); }
inline bool rational(const Ray<double>& s, const Sphere<double>& b) { return book::hit(toq(s), toq(b)); }
inline bool rational(const Segment<double>& s, const Sphere<double>& b, alg32) {
  return book::intersect(toq(s), toq(b));
}
inline bool rational(const Box<double>& a, const Box<double>& b) { return book::intersect(toq(a), toq(b)); }
inline bool rational(const Segment<double>& s, const Box<double>& b) { return book::hit(toq(s), toq(b)); }
inline bool rational(const Ray<double>& s, const Box<double>& b) { return book::hit(toq(s), toq(b)); }
inline bool rational(const Sphere<double>& a, const Box<double>& b) { return book::intersect(toq(a), toq(b)); }

// One stage alone on validated inputs: 0 or 1, or `unknown` when that stage cannot decide
// (the filter) or does not apply (expansion outside its range). For tests and benchmarks.
template <class A, class B, class... Tag>
int at_stage(Stage st, const A& a, const B& b, Tag... tag) {
  switch (st) {
    case Stage::filter:
      return filter(a, b, tag...);
    case Stage::expansion:
      return expansion(a, b, tag...);
    default:
      return int(rational(a, b, tag...));
  }
}
// Between the filter and the expansions, for the sphere queries: the robust tier's
// certified decision (float/cdref/robust: the inputs' differences as exact pairs, every
// decisive quantity in double words with a rigorous bound; its certificate is fuzzed against
// the exact answer). Where it is certain its answer is exact, and it decides every case but
// those within about u^2 of the boundary (2^-52 from tangency costs it 0.17 us where the
// expansions took 1.1 us); it reports as the expansion stage, the second.
inline int certain_or_unknown(robust::Decision d) { return d.certain ? int(d.value) : unknown; }
inline int double_word(const Sphere<double>& a, const Sphere<double>& b) { return certain_or_unknown(robust::decide(a, b)); }
// (the casts: the double words alone, robust::decide_words. run() reaches them with the inputs
// checked and the first stage past, which robust::decide would run again; the robust tier's
// own single-word filter after it, whose band near tangency is about u |s| wide where the
// double words' is u^2 wide, is skipped too)
// Before them, sigma on double words over the filter's other signs (SphereWords: a sixth of the
// robust tier's analysis, which computes the foot and its quotient), on the scaled inputs.
inline int sphere_words(const Segment<double>& seg0, const Sphere<double>& sp0, bool alg32) {
  Segment<double> seg;
  Sphere<double> sp;
  if (!scaled(seg0, sp0, seg, sp)) return unknown;
  const SphereWords w(seg.source, seg.target, sp, true);
  return alg32 ? segment_sphere_logic(w) : hit_sphere_logic(w, true);
}
inline int sphere_words(const Ray<double>& ray0, const Sphere<double>& sp0) {
  Ray<double> ray;
  Sphere<double> sp;
  if (!scaled(ray0, sp0, ray, sp)) return unknown;
  return hit_sphere_logic(SphereWords(ray.source, ray.direction, sp, false), false);
}
inline int double_word(const Segment<double>& s, const Sphere<double>& b) {
  if (const int r = sphere_words(s, b, false); r != unknown) return r;
  return certain_or_unknown(robust::decide_words(s, b));
}
inline int double_word(const Ray<double>& s, const Sphere<double>& b) {
  if (const int r = sphere_words(s, b); r != unknown) return r;
  return certain_or_unknown(robust::decide_words(s, b));
}
// Sphere-box: Q = |v|^2 - rho^2 on double words (v the centre's offset from the box, as in
// sphere_filter.hpp), where the filter leaves its sign open (within about u (|c| + h)^2 of 0,
// near touching). On the scaled inputs c_i - b_i = ch + cl exactly (two_sum); the clamp is
// exact (c_i < b_i - h_i iff ch < -h_i, or ch = -h_i and cl < 0: rounding is monotone;
// likewise above); a clamped v_i = +-h_i - ch - cl = a + b + e exactly ((p, e) = two_sum(+-h_i,
// -ch), (a, b) = two_sum(p, -cl)), taken as X + L = two_sum(a, fl(b + e)), within eps = u |fl(b
// + e)| + eta of v_i (one rounding to nearest, at most u times the rounded value, plus eta where
// it is subnormal). rho: X = rho, L = 0, eps = 0. Q's sign by signed_squares; Q <= 0 is an
// intersection (the closed ball and the closed box), and no axis clamped puts the centre in
// the box: 1. Range: every nonzero input in [2^-300, 2^200] (scaled() leaves them in [2^-180,
// 2^100]), so that |v_i| < 2^202 and each square is a normal number or within eta (as sigma's).
// Inputs already in that range are taken as they are, unscaled.
inline bool sphere_box_words_range(const Sphere<double>& sp, const Box<double>& box) {
  const auto in_range = [](double x) {  // (int flags: no branch per input)
    const double a = std::fabs(x);
    return int(a <= 0x1p200) & (int(a >= 0x1p-300) | int(a == 0));
  };
  int ok = in_range(sp.radius);
  for (int i = 0; i < 3; ++i) ok &= in_range(sp.center[i]) & in_range(box.center[i]) & in_range(box.extent[i]);
  return ok != 0;
}
template <class Mul>
int sphere_box_words_with(const Sphere<double>& sp, const Box<double>& box) {
  using std::fabs;
  using P2 = robust::Pair<double>;
  constexpr double u = 0x1p-53, eta = 0x1p-1074;
  double X[4] = {0, 0, 0, sp.radius}, L[4] = {0, 0, 0, 0}, eps[4] = {0, 0, 0, 0}, sg[4] = {1, 1, 1, -1};
  bool outside = false;
  for (int i = 0; i < 3; ++i) {
    const P2 c = robust::two_sum(sp.center[i], -box.center[i]);
    const double h = box.extent[i];
    double side;
    if (c.hi < -h || (c.hi == -h && c.lo < 0))
      side = -h;
    else if (c.hi > h || (c.hi == h && c.lo > 0))
      side = h;
    else
      continue;  // v_i = 0
    outside = true;
    const P2 p = robust::two_sum(side, -c.hi);
    const P2 q = robust::two_sum(p.hi, -c.lo);
    const double lo = q.lo + p.lo;
    const P2 v = robust::two_sum(q.hi, lo);
    X[i] = v.hi, L[i] = v.lo, eps[i] = u * fabs(lo) + eta;
  }
  if (!outside) return 1;
  const int q = signed_squares<Mul>(X, L, eps, sg);
  return q == unknown ? unknown : int(q < 0);
}
inline int sphere_box_words(const Sphere<double>& sp0, const Box<double>& box0) {
  Sphere<double> sp = sp0;
  Box<double> box = box0;
  if (!sphere_box_words_range(sp, box) && !(scaled(sp0, box0, sp, box) && sphere_box_words_range(sp, box)))
    return unknown;
  return robust::with_products([&](auto mul) { return sphere_box_words_with<decltype(mul)>(sp, box); });
}
// After the robust tier's own filter (robust/sphere_box.hpp: it decides to within about u^2 of
// the scale from touching, for less), before its decision (2^-52 from touching it took about
// 200 ns a case, its expansions over 19 exact products).
inline int double_word(const Sphere<double>& a, const Box<double>& b) {
  if (const int f = robust::detail::sphere_box_filter_own(a, b)) return int(f < 0);
  if (const int r = sphere_box_words(a, b); r != unknown) return r;
  return certain_or_unknown(robust::decide(a, b));
}
// Algorithm 3.2's answer is the segment cast's (a segment meets the closed ball exactly when
// Algorithm 3.1's cast hits), whose double words leave a band u^2 wide (decide_closest's, on
// the closest point, is u wide: it decided few cases 2^-52 from tangency)
inline int double_word(const Segment<double>& s, const Sphere<double>& b, alg32) {
  if (const int r = sphere_words(s, b, true); r != unknown) return r;
  return certain_or_unknown(robust::decide_words(s, b));
}

// All the stages in order (the filter's answer given where the caller has it: `unknown`).
template <class A, class B, class... Tag>
bool run(Stage* used, int filtered, const A& a, const B& b, Tag... tag) {
  int r = filtered;
  if (r != unknown) {
    if (used) *used = Stage::filter;
    return r != 0;
  }
  if constexpr (requires { double_word(a, b, tag...); }) {
    r = double_word(a, b, tag...);
    if (r != unknown) {
      if (used) *used = Stage::expansion;
      return r != 0;
    }
  }
  r = expansion(a, b, tag...);
  if (r != unknown) {
    if (used) *used = Stage::expansion;
    return r != 0;
  }
  if (used) *used = Stage::rational;
  return rational(a, b, tag...);
}

// ---- The input checks folded into the filter: sphere-sphere, the sphere casts, Algorithm
// 3.2, sphere-box, box-box, the box casts ----
// For these filters a valid input pays the filter alone: the checks (a branch per vector)
// cost as much as the filter's arithmetic on sphere-sphere and half of it on the casts. Sound
// because each of them decides only where its range tests passed, and those tests fail on
// every infinity or NaN among the inputs (an infinite or NaN operand makes the tested sum
// infinite or NaN):
//   sphere-sphere   m = |cA - cB|^2 + (rhoA + rhoB)^2 in range: every coordinate and radius;
//   the casts       every decided path of hit_sphere_logic passes sigma's range test (|s|^2,
//                   |r|^2 in [2^-480, 2^480], rho^2 <= 2^480: source, centre, target or
//                   direction, radius; a ray's zero direction fails |r|^2 >= 2^-480), or, for a
//                   segment whose target equals its source, ss_rho2's (source, centre, radius);
//   Algorithm 3.2   sr's test on |s|^2 + |r|^2 first (source, centre, target), then ss_rho2's,
//                   tt_rho2's or sigma's, each of which bounds rho^2 too;
//   sphere-box      m = sum (|c_i - b_i| + h_i)^2 + rho^2: both centres, the extents, the radius;
//   box-box         per axis m = |cA - cB| + eA + eB in range, or 0 (with eA, eB >= 0 both
//                   extents and the difference are then 0, and a difference of two infinities
//                   is NaN): both centres and both extents.
//   the box casts   hit_box_logic takes every outcode's sign before it decides anything, and
//                   outcode_sign refuses |L~| > 2^1000, NaN included: L~ = fl(p_i - c_i) -+ h_i
//                   at the source and (a segment) at the target cover both points, the centre
//                   and the extents; a ray's direction only enters through its signs and the
//                   pairs, so it is tested first (finite, not zero) with the extents' signs.
//                   The separating axes before them (axes_filter) decide only where
//                   sum |fl(p_i - c_i)| + h_i over both points and |r|_1 are finite: every
//                   input.
// What no range test sees, a negative radius or extent (its square or its sum with |c_i| can be
// in range), is tested before the filter (a NaN fails that test too). Every input the filter
// leaves undecided, and every bad one, takes the checks (cdref::invalid_input naming what is
// wrong, the same message as before) and then all the stages, out of line.
// (signs_valid(Box) and direction_valid: filter/box_cast_filter.hpp)
inline bool signs_valid(const Sphere<double>& s) { return s.radius >= 0; }
inline bool signs_valid(const Segment<double>&) { return true; }
inline bool signs_valid(const Ray<double>&) { return true; }  // a zero direction: sigma's range test
template <class A, class B>
bool unseen_valid(const A& a, const B& b) {
  return signs_valid(a) && signs_valid(b);
}
inline bool unseen_valid(const Ray<double>& r, const Box<double>& b) {  // the direction too
  return signs_valid(b) && direction_valid(r.direction);
}

// `filtered`: the filter's answer where it ran (then `unknown`), else run it after the checks.
template <class A, class B, class... Tag>
[[gnu::noinline]] bool checked_run(Stage* used, bool filtered, const A& a, const char* na, const B& b, const char* nb,
                                   Tag... tag) {
  check(a, na);
  check(b, nb);
  return run(used, filtered ? unknown : filter(a, b, tag...), a, b, tag...);
}
// The classification with the checks after the filter (for the pairs above only).
template <class A, class B, class... Tag>
bool filter_first(Stage* used, const A& a, const char* na, const B& b, const char* nb, Tag... tag) {
  const bool valid = unseen_valid(a, b);
  if (valid) {
    const int r = filter(a, b, tag...);
    if (r != unknown) [[likely]] {
      if (used) *used = Stage::filter;
      return r != 0;
    }
  }
  return checked_run(used, valid, a, na, b, nb, tag...);
}

}  // namespace staged

// ---- the oracle: validation as the book does it (after the filter where it is folded into
// the filter's range tests, above), then the stages ----
inline bool classify(const Sphere<double>& a, const Sphere<double>& b, Stage* used = nullptr) {
  return staged::filter_first(used, a, "sphere A", b, "sphere B");
}
inline bool classify(const Segment<double>& seg, const Sphere<double>& sp, Stage* used = nullptr) {
  return staged::filter_first(used, seg, "segment", sp, "sphere");
}
inline bool classify(const Ray<double>& ray, const Sphere<double>& sp, Stage* used = nullptr) {
  return staged::filter_first(used, ray, "ray", sp, "sphere");
}
inline bool classify_segment_sphere(const Segment<double>& seg, const Sphere<double>& sp, Stage* used = nullptr) {
  return staged::filter_first(used, seg, "segment", sp, "sphere", staged::alg32{});
}
inline bool classify(const Box<double>& a, const Box<double>& b, Stage* used = nullptr) {
  return staged::filter_first(used, a, "box A", b, "box B");
}
inline bool classify(const Segment<double>& seg, const Box<double>& box, Stage* used = nullptr) {
  return staged::filter_first(used, seg, "segment", box, "box");
}
inline bool classify(const Ray<double>& ray, const Box<double>& box, Stage* used = nullptr) {
  return staged::filter_first(used, ray, "ray", box, "box");
}
inline bool classify(const Sphere<double>& sp, const Box<double>& box, Stage* used = nullptr) {
  return staged::filter_first(used, sp, "sphere", box, "box");
}

}  // namespace cdref::oracle
