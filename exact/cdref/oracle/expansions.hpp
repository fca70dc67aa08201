// cdref/oracle/expansions.hpp - what the fast exact classification oracles of sphere-sphere, the
// sphere casts, segment-sphere, box-box, the box casts and sphere-box share: the model of their
// three stages, the expansions, the scaling into stage 2's range and the signed sum of squares
// on double words. Each query's stages are in its own file (sphere_sphere.hpp, sphere_casts.hpp,
// box_box.hpp, box_casts.hpp, sphere_box.hpp, each opening with its polynomials);
// stages.hpp runs them in order. Each classify() returns exactly what the book's algorithm
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
#include <cdref/filters/box_cast_filter.hpp>
#include <cdref/filters/sphere_filter.hpp>
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

// The filters, the first stage: unknown, u, in_range and fsign (filters/box_cast_filter.hpp); le0,
// ge0, SphereFilter, hit_sphere_logic and segment_sphere_logic (filters/sphere_filter.hpp).
using namespace cdref::filters::staged;

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
// unknown). Mul: the exact products' policy (bounded/eft.hpp).
template <class Mul, int N>
int signed_squares(const double (&X)[N], const double (&L)[N], const double (&eps)[N], const double (&sg)[N]) {
  using std::fabs;
  using P2 = eft::Pair<double>;
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
      const P2 t = eft::two_sum(H, sg[k] * Z.hi);
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

using rational_inputs::toq;
inline int certain_or_unknown(robust::Decision d) { return d.certain ? int(d.value) : unknown; }

}  // namespace staged

}  // namespace cdref::oracle
