// cdref/oracle/sphere_casts.hpp - the exact classification of a ray or a segment cast on a sphere
// (Algorithm 3.1) and of segment-sphere (Algorithm 3.2) at double inputs: the filter, sigma on
// double words, the robust tier's double words, the expansions and the rationals.
// The decision at an exact type (every difference exact, so a sign of a polynomial in the
// inputs; expansions.hpp: the model of the three stages):
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
//
// Its classify() is at the end of this file; <cdref/oracle/stages.hpp> runs the stages in order.
#pragma once

#include <cdref/oracle/expansions.hpp>
#include <cdref/oracle/stages.hpp>
#include <cdref/filters/sphere_filter.hpp>
#include <cdref/robust/ray_sphere.hpp>
#include <cdref/robust/segment_sphere.hpp>

namespace cdref::oracle {

namespace staged {

// ======================= ray / segment on a sphere =======================
// The filter (SphereFilter) and the two algorithms' logic over signs: filters/sphere_filter.hpp.

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
int sigma_words_with(const eft::Pair<double> (&s)[3], const eft::Pair<double> (&r)[3], double rho) {
  using std::fabs;
  using P2 = eft::Pair<double>;
  constexpr double u = 0x1p-53, eta = 0x1p-1074;
  const auto in_range = [](double x) { return int(x == 0 || (fabs(x) >= 0x1p-300 && fabs(x) <= 0x1p200)); };
  int ok = in_range(rho);
  for (int i = 0; i < 3; ++i) ok &= in_range(s[i].hi) & in_range(r[i].hi);
  if (!ok) return unknown;
  double X[6], L[6], eps[6], sg[6];
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const P2 Pk = Mul::prod(s[i].hi, r[j].hi), Qk = Mul::prod(s[j].hi, r[i].hi);
    const P2 xy = eft::two_sum(Pk.hi, -Qk.hi);
    const double m = (s[i].hi * r[j].lo + s[i].lo * r[j].hi) - (s[j].hi * r[i].lo + s[j].lo * r[i].hi);
    const P2 C = eft::two_sum(xy.hi, ((xy.lo + Pk.lo) - Qk.lo) + m);
    X[k] = C.hi, L[k] = C.lo, eps[k] = 32 * u * u * (fabs(Pk.hi) + fabs(Qk.hi)) + 8 * eta, sg[k] = -1;
    const P2 ab = Mul::prod(r[k].hi, rho);
    const P2 D = eft::two_sum(ab.hi, ab.lo + r[k].lo * rho);
    X[3 + k] = D.hi, L[3 + k] = D.lo, eps[3 + k] = 4 * u * u * fabs(ab.hi) + 4 * eta, sg[3 + k] = 1;
  }
  return signed_squares<Mul>(X, L, eps, sg);
}
inline int sigma_words(const eft::Pair<double> (&s)[3], const eft::Pair<double> (&r)[3], double rho) {
  return eft::with_products<true>([&](auto mul) { return sigma_words_with<decltype(mul)>(s, r, rho); });
}

// The filter's signs, and sigma on double words where the filter leaves it open (the second
// stage's first try; the other signs open: unknown, for the robust tier's double words).
struct SphereWords {
  SphereFilter f;
  eft::Pair<double> s[3], r[3];
  double rho;
  bool rzero;
  SphereWords(const Vec3<double>& src, const Vec3<double>& rt, const Sphere<double>& sp, bool segment)
      : f(src, rt, sp, segment), rho(sp.radius), rzero(f.rzero) {
    for (int i = 0; i < 3; ++i) {
      s[i] = eft::two_sum(src[i], -sp.center[i]);
      r[i] = segment ? eft::two_sum(rt[i], -src[i]) : eft::Pair<double>{rt[i], 0.0};
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
[[gnu::always_inline]] inline int filter(const Segment<double>& seg, const Sphere<double>& sp, plain = {}) {
  return sphere_cast_filter(seg.source, seg.target, sp, true);
}
[[gnu::always_inline]] inline int filter(const Ray<double>& ray, const Sphere<double>& sp, plain = {}) {
  return sphere_cast_filter(ray.source, ray.direction, sp, false);
}
// Algorithm 3.2's answer is Algorithm 3.1's hit (a segment meets the closed ball exactly when
// the cast hits: the tests run both stages' rational answers side by side), and the cast's
// filter decides it for less: its first sign, sigma, settles every line that misses, where
// Algorithm 3.2's region tests (s . r, then t . r) branch either way on uniform cases
[[gnu::always_inline]] inline int filter(const Segment<double>& seg, const Sphere<double>& sp, alg32) {
  return sphere_cast_filter(seg.source, seg.target, sp, true);
}
inline int expansion(const Segment<double>& seg0, const Sphere<double>& sp0, plain = {}) {
  Segment<double> seg;
  Sphere<double> sp;
  if (!scaled(seg0, sp0, seg, sp)) return unknown;
  return hit_sphere_logic(SphereStaged(seg.source, seg.target, sp, true), true);
}
inline int expansion(const Ray<double>& ray0, const Sphere<double>& sp0, plain = {}) {
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

inline bool rational(const Segment<double>& s, const Sphere<double>& b, plain = {}) { return book::hit(toq(s), toq(b)); }
inline bool rational(const Ray<double>& s, const Sphere<double>& b, plain = {}) { return book::hit(toq(s), toq(b)); }
inline bool rational(const Segment<double>& s, const Sphere<double>& b, alg32) {
  return book::intersect(toq(s), toq(b));
}

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
inline int double_word(const Segment<double>& s, const Sphere<double>& b, plain = {}) {
  if (const int r = sphere_words(s, b, false); r != unknown) return r;
  return certain_or_unknown(robust::decide_words(s, b));
}
inline int double_word(const Ray<double>& s, const Sphere<double>& b, plain = {}) {
  if (const int r = sphere_words(s, b); r != unknown) return r;
  return certain_or_unknown(robust::decide_words(s, b));
}
// Algorithm 3.2's answer is the segment cast's (a segment meets the closed ball exactly when
// Algorithm 3.1's cast hits), whose double words leave a band u^2 wide (decide_closest's, on
// the closest point, is u wide: it decided few cases 2^-52 from tangency)
inline int double_word(const Segment<double>& s, const Sphere<double>& b, alg32) {
  if (const int r = sphere_words(s, b, true); r != unknown) return r;
  return certain_or_unknown(robust::decide_words(s, b));
}

}  // namespace staged

// ---- the oracle: the filter (the input checks folded into it: stages.hpp), then the stages ----
inline bool classify(const Segment<double>& seg, const Sphere<double>& sp, Stage* used = nullptr) {
  return staged::filter_first(used, seg, "segment", sp, "sphere");
}
inline bool classify(const Ray<double>& ray, const Sphere<double>& sp, Stage* used = nullptr) {
  return staged::filter_first(used, ray, "ray", sp, "sphere");
}
inline bool classify_segment_sphere(const Segment<double>& seg, const Sphere<double>& sp, Stage* used = nullptr) {
  return staged::filter_first(used, seg, "segment", sp, "sphere", staged::alg32{});
}

}  // namespace cdref::oracle
