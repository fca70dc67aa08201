// cdref/robust/sphere_sphere.hpp - sphere-sphere (Section 3.1.1) that keeps its accuracy
// where the book's |v|^2 <= (rhoA + rhoB)^2 loses it, for F = float, double, long double.
// Same signatures and results as cdref::book: intersect, proximity; and decide
// (decision.hpp). u is the unit roundoff, eta the smallest subnormal.
// At F = float every entry point runs the double version on the same inputs and rounds each
// value once (decision.hpp, widened).
//
// Formulation, with v = cA - cB and s = rhoA + rhoB (the book's definitions, exactly):
//  1. Exact differences. Each v_i = fl(cA_i - cB_i) + lo_i and s = fl(rhoA + rhoB) + s_lo
//     exactly (two_sum). The inputs are first scaled by 2^-e1, e1 > 0 only within 2^4 of
//     overflow (so that no sum overflows); then the pairs are scaled by one power of two
//     2^-e2 putting the largest |v_i|, s in [1,2): no square below overflows or underflows
//     except terms 2^(emin/2) below the largest, which count as absolute errors (eta).
//  2. Q = |v|^2 - s^2 = sum (v_i + lo_i)^2 - (s + s_lo)^2, expanded into 12 exact products,
//     by dot2: |Q^ - Q| <= u|Q| + gamma_12^2 S, S = sum of the products' moduli
//     <= (1+u)^2 (|v|^2 + s^2). intersect = Q^ <= 0.
//  3. |v| as a double word (norm_dw: the pairs scaled by their largest high, |v|^2 a double
//     word, one Newton step for the root): relative error <= 18u^2.
//  4. distance = Q / (|v| + s) when Q > 0, depth = -Q / (|v| + s) when Q < 0 (the book's
//     |v| - s and s - |v|, whose cancellation is gone), with Q within (1 + 1/16)u|Q|: step 2's
//     value where dot2_cert's bound shows its gamma^2 S term below u|Q|/16, else the 24 parts
//     of the 12 exact products summed as if in triple precision (sum_k, K = 3: (u + 3
//     gamma_23^2)|Q| + gamma_46^3 S, i.e. u|Q| until |Q| falls below ~10^5 u^2 S); |v| + s a
//     double word (norm_dw, 18u^2), the quotient by div_pair (8u^2) rounded once: within
//     half an ulp plus 1.07u of the truth, i.e. 2.1 ulps at worst and 1.6 but at a binade's
//     edge. (The previous Q / (fl|v| + s) in F: 4.5u + 145 u^2 S/|Q|, 44 ulps measured at 2^-52
//     from touching.)
//  5. Witnesses pA = cA - rhoA n, pB = cB + rhoB n, n = v/|v| from the pair v scaled by its
//     own largest component (so that a tiny v next to large radii keeps its direction):
//     each n_i a double word with relative error <= 27u^2 (unit_dw), and pA_i = cA_i - rhoA
//     n_i rounded once (along_dw): within half an ulp plus 31u^2 max(|pA_i|, rhoA |n_i|), i.e.
//     within one ulp unless the witness cancels to below 62u rhoA |n_i| (a witness near a
//     coordinate plane through a far centre; then 31u^2 rhoA |n_i| absolute). fma(-rhoA,
//     fl(n_i), cA_i) was off by 3.5u rhoA |n_i|: 144 ulps at p99 on the magnitude family.
//     Concentric (v = 0 exactly): n = e_x as in the book; pA_x = fl(cA_x - rhoA), 0.5 ulp.
//  6. Distances are scaled back by 2^(e1+e2), exactly unless the result leaves the range.
//  7. First, where the filter below decides (so the classification is certain) and the pairs
//     are exact and |v| is not below 2^-400 after scaling (its squares' low parts then stay
//     normal, but for components 2^-400 below the largest, whose absolute errors of order eta
//     are below 2^-270 of |v|^2): |v| as a double word alone (norm2_dw and sqrt_pair: 18u^2)
//     and g = |v| - s as t = two_sum(|v|.hi, -s), g = t.hi + (t.lo + (|v|.lo - s_lo)). Before
//     that last rounding g is within 18u^2 |v| + u^2 (|v| + s) (|v|.lo - s_lo, each part
//     below u of its high) + 3.01u^2 (|v| + s) (t.lo plus it) < 32u^2 (|v^| + s) of |v| - s.
//     Where |g| > 520u fl(|v^| + s) that is below u|g|/16, so g's sign is Q's (the filter's)
//     and g rounded once is within half an ulp plus u|g|/16 of the distance or the depth:
//     items 2-4 are skipped. The witnesses from the same |v|: 1/|v| by recip_pair (its 10u^2
//     and |v|'s 18u^2: 28u^2), n_i = v_i (1/|v|) by mul_pair (4u^2 more, 33u^2 with the
//     rounding), then along_dw as in item 5: within half an ulp plus 37u^2 max(|p_i|, rho
//     |n_i|), one ulp unless the witness cancels to below 74u rho |n_i| (one division where
//     three div_pairs took six). Where the CPU has fused
//     multiply-adds the exact products here are fma's (bounded/eft.hpp, with_products), else
//     Dekker's: the same pairs. On 2,000 uniform cases this first look took the full query
//     from 210 to 76 ns a case (standalone loop, 2026-11-29); near touching (the filter
//     undecided, or |g| within 520u of |v| + s) items 2-5 run as before.
//  8. Item 7 runs on the pairs of item 1 without either scaling (e1 = e2 = 0): where the
//     filter below decides, m = fl(|v^|^2 + s^2) <= max / 4, so no difference, square or sum
//     in item 7 overflows (nor Dekker's split, |v_i| <= 2^(emax/2)); the other purpose of the
//     scaling, squares clear of the subnormal range, is item 7's own test, now on |v|'s
//     largest component as it is (>= 2^-401 at double: every square and product of a high
//     and a low part is normal, and a component whose square underflows errs by eta against
//     |v|^2 >= 2^-802). Every bound of item 7 is relative, so it holds as it is. Only where
//     item 7 declines are the scaled pairs formed. 2,000 uniform cases (standalone loop,
//     2026-11-29, g++ 12.2 -O3): distance and depth 50.7 -> 26.1 ns, every output 78.5 ->
//     54 ns a case.
//
// decide() and intersect() first try a filter on the stable tier's arithmetic (Box2D's, in F):
// v_i = fl(cA_i - cB_i), s = fl(rhoA + rhoB), vv = fl(v.v), ss = fl(s s), q = fl(vv - ss). With
// round to nearest each difference is off by at most u of its rounded value, so the exact
// |v|^2 and s^2 differ from v.v and s^2 (of the rounded values) by at most (2u + u^2) of
// them, fl(v.v) from v.v by gamma_3 v.v and fl(s s) from s^2 by u s^2, plus eta/2 per product
// below the normal range: |Q - (vv - ss)| <= (5u + O(u^2)) vv + (3u + O(u^2)) ss + 2 eta, and
// q is (vv - ss) rounded once. Where m = fl(vv + ss) lies in [2^emin / u, max / 4] (no sum
// overflows; 2 eta = 4u 2^emin <= 4u^2 m) the sign of q is the sign of Q whenever
// |q| > fl(8u m), which covers (1 + u)(5.01u m + 4u^2 m) with the rounding of m and of the
// product. Then the answer is certain without the scaled pairs below (decide(), intersect()
// and proximity() all take it where it decides, so the three classify alike everywhere: the
// pairs' own value is certified only within in_certified_range, decision.hpp): every case but those
// within about 8u (|v|^2 + s^2) of touching, at every range where the squares stay finite. At
// double, decide() and intersect() run it before the input checks: its range test on m fails
// for every infinity or NaN among the centres and radii, and negative radii are tested first;
// the rest takes the checks (the same messages) and the filter again, out of line.
// decide() otherwise: the sign of Q from dot2_cert (ray_sphere.hpp) with the scaling's absolute term:
// certain iff |Q^| > 2u|Q^| + 288 u^2 S^ + K eta (K covers the subnormal low parts); if the
// first scaling lost bits (inputs 2^(emax+emin) apart) it is never certain. When all of v
// and s are zero Q = 0 exactly and intersect is certain. Exact touching (Q = 0 with S > 0)
// is always uncertain.
#pragma once

#include <algorithm>
#include <cdref/primitives.hpp>
#include <cdref/results.hpp>
#include <cmath>

#include "decision.hpp"
#include <cdref/bounded/eft.hpp>
#include "ray_sphere.hpp"

namespace cdref::robust {

using namespace cdref::eft;  // the error-free transformations (bounded/eft.hpp)

namespace detail {

template <class F>
struct SphereSphereLocal {
  F v[3], vl[3];  // v = cA - cB = v + vl, scaled by 2^-(e1 + e2)
  F s, sl;        // rhoA + rhoB = s + sl, scaled likewise
  int scale = 0;  // e1 + e2
  bool exact = true;
  bool zero_v = false, all_zero = false;
};

// (scaled = false: the pairs as they are, e1 = e2 = 0; item 8)
template <class F>
SphereSphereLocal<F> sphere_sphere_local(const Sphere<F>& a, const Sphere<F>& b, bool scaled = true) {
  SphereSphereLocal<F> L;
  int e1 = 0;
  if (scaled) {
    F m = std::max(a.radius, b.radius);
    for (int i = 0; i < 3; ++i) m = std::max({m, std::fabs(a.center[i]), std::fabs(b.center[i])});
    e1 = overflow_guard(m);
  }
  F vh[3], vlo[3];
  F top = 0, vtop = 0;
  for (int i = 0; i < 3; ++i) {
    const Pair<F> p = two_sum(scale_down(a.center[i], e1, L.exact), F(-scale_down(b.center[i], e1, L.exact)));
    vh[i] = p.hi;
    vlo[i] = p.lo;
    vtop = std::max(vtop, std::fabs(p.hi));
  }
  const Pair<F> sp = two_sum(scale_down(a.radius, e1, L.exact), scale_down(b.radius, e1, L.exact));
  top = std::max(vtop, sp.hi);
  L.zero_v = vtop == F(0);
  L.all_zero = top == F(0);
  const int e2 = scaled && top > F(0) ? exponent_of(top) : 0;
  const Pow2<F> down(e2);  // x 2^-e2, as ldexp gives it
  for (int i = 0; i < 3; ++i) {
    L.v[i] = down(vh[i]);
    L.vl[i] = down(vlo[i]);
  }
  L.s = down(sp.hi);
  L.sl = down(sp.lo);
  L.scale = e1 + e2;
  return L;
}

// Q = |v|^2 - s^2 with its bound.
template <class F>
Bounded<F> sphere_sphere_q(const SphereSphereLocal<F>& L) {
  const F* v = L.v;
  const F* l = L.vl;
  return dot2_cert({v[0], v[1], v[2], F(2 * l[0]), F(2 * l[1]), F(2 * l[2]), l[0], l[1], l[2], L.s, F(2 * L.sl), L.sl},
                   {v[0], v[1], v[2], v[0], v[1], v[2], l[0], l[1], l[2], F(-L.s), F(-L.s), F(-L.sl)},
                   64);  // 8 low parts scaled below the normal range: each |dQ| <= 8 eta
}

// Q as sphere_sphere_q, summed as if in triple precision (sum_k, K = 3, over the 24 parts of
// the 12 exact products): |Q^ - Q| <= (u + 3 gamma_23^2)|Q| + gamma_46^3 S (+ 24 eta for
// products below the normal range).
template <class F>
F sphere_sphere_q3(const SphereSphereLocal<F>& L) {
  const F* v = L.v;
  const F* l = L.vl;
  const F x[12] = {v[0], v[1], v[2], F(2 * l[0]), F(2 * l[1]), F(2 * l[2]), l[0], l[1], l[2], L.s, F(2 * L.sl), L.sl};
  const F y[12] = {v[0], v[1], v[2], v[0], v[1], v[2], l[0], l[1], l[2], F(-L.s), F(-L.s), F(-L.sl)};
  F p[24];
  for (int i = 0; i < 12; ++i) {
    const Pair<F> t = two_prod(x[i], y[i]);
    p[2 * i] = t.hi;
    p[2 * i + 1] = t.lo;
  }
  return sum_k(p, 3);
}

// |v| for v = hi + lo (exact pairs): dot2 of the 9 products, relative error <= 1.5u + O(u^2).
template <class F>
F norm_of_pairs(const F (&v)[3], const F (&l)[3]) {
  return std::sqrt(dot2({v[0], v[1], v[2], F(2 * l[0]), F(2 * l[1]), F(2 * l[2]), l[0], l[1], l[2]},
                        {v[0], v[1], v[2], v[0], v[1], v[2], l[0], l[1], l[2]}));
}

// |x|^2 for x = h + l (normalized pairs, |l_i| <= u|h_i|) as a double word: the exact squares
// of the highs (two_prod_split: the caller keeps |h_i| < 2^(emax/2)) summed by a two_sum
// chain; the squares' lows, the chain's errors and 2 h.l summed in F (five terms of total
// <= 5u|x|^2, so gamma_4 of it), l.l dropped (<= u^2|x|^2); 2 h.l itself off by gamma_3 2u|x|^2:
// relative error <= 28u^2 (+ eta for squares below the normal range).
template <class Mul = SplitProduct, class F>
Pair<F> norm2_dw(const F (&h)[3], const F (&l)[3]) {
  const Pair<F> p0 = Mul::prod(h[0], h[0]), p1 = Mul::prod(h[1], h[1]), p2 = Mul::prod(h[2], h[2]);
  const Pair<F> s1 = two_sum(p0.hi, p1.hi), s2 = two_sum(s1.hi, p2.hi);
  const F x = F(h[0] * l[0] + h[1] * l[1]) + h[2] * l[2];
  return fast_two_sum(s2.hi, F(F(F(p0.lo + p1.lo) + F(p2.lo + s1.lo)) + F(s2.lo + F(2) * x)));
}

// scale_to_top: x 2^-e for x = h + l, e the exponent of its largest high (returned).
// unit_dw: x/|x| for a nonzero x = h + l (normalized pairs), each component a double word, x
// scaled first by scale_to_top so that neither a tiny nor a huge x under- or
// overflows: |x| = sqrt_pair(norm2_dw) (14u^2 + 4u^2), n_i = div_pair(x_i, |x|) (+ 8u^2):
// relative error <= 27u^2 per component (a component whose square falls below the normal
// range after scaling is below 2^(emin/2) of the largest: its absolute error is of that size).
template <class F>
int scale_to_top(const F (&h)[3], const F (&l)[3], F (&hs)[3], F (&ls)[3]) {
  const F top = std::max({std::fabs(h[0]), std::fabs(h[1]), std::fabs(h[2])});
  // (a zero or non-finite top -- x underflowed, or overflowed upstream -- is not scaled:
  // ilogb would return INT_MIN or INT_MAX there)
  const int e = top > F(0) && std::isfinite(top) ? exponent_of(top) : 0;
  const Pow2<F> down(e);
  for (int i = 0; i < 3; ++i) {
    hs[i] = down(h[i]);
    ls[i] = down(l[i]);
  }
  return e;
}
template <class Mul = SplitProduct, class F>
void unit_dw(const F (&h)[3], const F (&l)[3], Pair<F> (&n)[3]) {
  F hs[3], ls[3];
  scale_to_top(h, l, hs, ls);
  const Pair<F> len = sqrt_pair<Mul>(norm2_dw<Mul>(hs, ls));
  for (int i = 0; i < 3; ++i) n[i] = len.hi > F(0) ? div_pair<Mul>(Pair<F>{hs[i], ls[i]}, len) : Pair<F>{F(0), F(0)};
}
template <class Mul = SplitProduct, class F>
void unit_dw(const Pair<F> (&x)[3], Pair<F> (&n)[3]) {
  const F h[3] = {x[0].hi, x[1].hi, x[2].hi}, l[3] = {x[0].lo, x[1].lo, x[2].lo};
  unit_dw<Mul>(h, l, n);
}

// |x| for a nonzero x = h + l (normalized pairs) as a double word, scaled as in unit_dw and
// back: relative error <= 18u^2 (14u^2 from norm2_dw, 4u^2 sqrt_pair).
template <class Mul = SplitProduct, class F>
Pair<F> norm_dw(const F (&h)[3], const F (&l)[3]) {
  F hs[3], ls[3];
  const Pow2<F> up(-scale_to_top(h, l, hs, ls));
  const Pair<F> len = sqrt_pair<Mul>(norm2_dw<Mul>(hs, ls));
  return {up(len.hi), up(len.lo)};
}

// c + k n for a double-word n, rounded once: k n.hi exactly (two_prod; k |n| <= k, no
// overflow), its sum with c exactly (two_sum), the three small terms in F. The error before
// the last rounding is at most u^2 |c + k n| + 3u^2 k |n|, so the result is within half an
// ulp plus (1 + 3 + d) u^2 max(|c + k n|, k |n|) of c + k n_true when n has relative error
// d u^2: with unit_dw's 27u^2, within one ulp unless c + k n cancels to below 62u k |n|.
template <class F>
F along_dw(F c, F k, const Pair<F>& n) {
  const Pair<F> p = two_prod(k, n.hi);
  const Pair<F> s = two_sum(c, p.hi);
  return s.hi + F(s.lo + F(p.lo + k * n.lo));
}

// c + x 2^e for a double-word x, rounded once (x 2^e exact unless it leaves the normal range).
template <class F>
F plus_dw(F c, const Pair<F>& x, int e) {
  const Pow2<F> up(-e);  // x 2^e, as std::ldexp gives it
  const Pair<F> s = two_sum(c, up(x.hi));
  return s.hi + F(s.lo + up(x.lo));
}

// The exact sign of x_0 + ... + x_{N-1} (Shewchuk's Grow-Expansion with zero elimination:
// two_sum is exact, the expansion is nonoverlapping and its largest component, the last,
// carries the sign; a zero term is skipped, as it leaves the expansion as it is).
template <class F, std::size_t N>
int exact_sign_of_sum(const F (&x)[N]) {
  F e[N + 1];
  int m = 0;
  for (std::size_t k = 0; k < N; ++k) {
    if (x[k] == F(0)) continue;
    F q = x[k];
    F h[N + 1];
    int j = 0;
    for (int i = 0; i < m; ++i) {
      const Pair<F> p = two_sum(q, e[i]);
      q = p.hi;
      if (p.lo != F(0)) h[j++] = p.lo;
    }
    if (q != F(0)) h[j++] = q;
    for (int i = 0; i < j; ++i) e[i] = h[i];
    m = j;
  }
  return m == 0 ? 0 : (e[m - 1] > F(0) ? 1 : -1);
}

// The filter of the header: +1 (Q > 0: apart) or -1 (Q < 0: overlapping) where the sign of
// Q is certain from the stable tier's arithmetic, 0 where it is not.
template <class F>
int sphere_sphere_filter(const Sphere<F>& a, const Sphere<F>& b) {
  const F v0 = a.center[0] - b.center[0], v1 = a.center[1] - b.center[1], v2 = a.center[2] - b.center[2];
  const F s = a.radius + b.radius;
  const F vv = v0 * v0 + v1 * v1 + v2 * v2, ss = s * s;
  const F q = vv - ss, m = vv + ss;
  constexpr F u = unit_roundoff<F>();
  if (!(m <= std::numeric_limits<F>::max() / F(4) && m >= std::numeric_limits<F>::min() / u)) return 0;
  const F e = F(8) * u * m;
  return int(q > e) - int(q < -e);
}

// The filter as intersect() and decide() take it before their input checks (header): 0 where
// it does not decide or does not apply (at float; a negative or NaN radius).
template <class F>
int unchecked_filter(const Sphere<F>& a, const Sphere<F>& b) {
  if constexpr (std::is_same_v<F, float>)
    return 0;
  else
    return a.radius >= F(0) && b.radius >= F(0) ? sphere_sphere_filter(a, b) : 0;
}

}  // namespace detail

template <class F>
[[gnu::noinline]] bool intersect_checked(const Sphere<F>& a, const Sphere<F>& b) {
  check(a, "sphere A");
  check(b, "sphere B");
  if constexpr (std::is_same_v<F, float>) return intersect_checked(detail::widened(a), detail::widened(b));  // (decision.hpp, widened)
  if (const int f = detail::sphere_sphere_filter(a, b)) return f < 0;
  const auto L = detail::sphere_sphere_local(a, b);
  return L.all_zero || detail::sphere_sphere_q(L).value <= F(0);
}
// (intersect() and decide(): the filter before the input checks at double, header)
template <class F>
bool intersect(const Sphere<F>& a, const Sphere<F>& b) {
  if (const int f = detail::unchecked_filter(a, b)) [[likely]]
    return f < 0;
  return intersect_checked(a, b);
}

template <class F>
[[gnu::noinline]] Decision decide_checked(const Sphere<F>& a, const Sphere<F>& b) {
  check(a, "sphere A");
  check(b, "sphere B");
  if constexpr (std::is_same_v<F, float>) return decide_checked(detail::widened(a), detail::widened(b));  // (decision.hpp, widened)
  if (const int f = detail::sphere_sphere_filter(a, b)) return Decision{f < 0, true};
  const auto L = detail::sphere_sphere_local(a, b);
  if (L.all_zero) return within_range(Decision{true, L.exact}, a, b);
  const detail::Bounded<F> q = detail::sphere_sphere_q(L);
  return within_range(Decision{q.value <= F(0), L.exact && q.sign() != 0}, a, b);
}
template <class F>
Decision decide(const Sphere<F>& a, const Sphere<F>& b) {
  if (const int f = detail::unchecked_filter(a, b)) [[likely]]
    return Decision{f < 0, true};
  return decide_checked(a, b);
}

namespace detail {

// Item 7's first look (header), shared with sphere_box.hpp. first_look_norm: |v| for v = h + l
// (pairs) as a double word (18u^2), or false where |v| lies below 2^-400 (scaled units).
// first_look_gap: g = |v| - s (s = sh + sl) summed once; where |g| > 520u (|v^| + s) and g's sign
// is the filter's (cls), the distance or the depth, scaled back by 2^scale, and true.
template <class Mul, class F>
bool first_look_norm(const F (&h)[3], const F (&l)[3], Pair<F>& len) {
  const F top = std::max({std::fabs(h[0]), std::fabs(h[1]), std::fabs(h[2])});
  if (!(top >= exp2_of<F>(std::numeric_limits<F>::min_exponent / 2 + 110))) return false;
  len = sqrt_pair<Mul>(norm2_dw<Mul>(h, l));
  return true;
}
template <class F>
bool first_look_gap(const Pair<F>& len, F sh, F sl, int cls, int scale, unsigned w, Proximity<F>& res) {
  const Pair<F> t = two_sum(len.hi, F(-sh));
  const F g = t.hi + F(t.lo + F(len.lo - sl));
  const F u = unit_roundoff<F>();
  if (!(std::fabs(g) > F(F(520) * u) * F(len.hi + sh) && (g > F(0)) == (cls > 0))) return false;
  const F dv = Pow2<F>(-scale)(std::fabs(g));
  if (w & want_distance) res.distance = g > F(0) ? dv : F(0);
  if (w & want_depth) res.depth = g < F(0) ? dv : F(0);
  return true;
}

// The first look for two spheres: which of the asked values it set (want_distance | want_depth
// together, and want_witnesses); the caller computes the rest as items 2-5 do.
template <class Mul, class F>
unsigned sphere_sphere_fast(const SphereSphereLocal<F>& L, const Sphere<F>& a, const Sphere<F>& b, int cls, unsigned w,
                            Proximity<F>& res) {
  Pair<F> len;
  if (cls == 0 || !L.exact || !first_look_norm<Mul>(L.v, L.vl, len)) return 0;
  unsigned done = 0;
  if ((w & (want_distance | want_depth)) && first_look_gap(len, L.s, L.sl, cls, L.scale, w, res))
    done |= want_distance | want_depth;
  if (w & want_witnesses) {
    const Pair<F> r = recip_pair<Mul>(len);  // 1 / |v| (1 + 28u^2)
    for (int i = 0; i < 3; ++i) {
      const Pair<F> n = mul_pair<Mul>(Pair<F>{L.v[i], L.vl[i]}, r);  // v_i / |v| (1 + 33u^2)
      res.on_a[i] = along_dw(a.center[i], F(-a.radius), n);
      res.on_b[i] = along_dw(b.center[i], b.radius, n);
    }
    done |= want_witnesses;
  }
  return done;
}

template <class F, class Mul = SplitProduct>
Proximity<F> proximity_dw(const Sphere<F>& a, const Sphere<F>& b, unsigned w) {
  Proximity<F> res;
  const int cls = detail::sphere_sphere_filter(a, b);
  if (cls != 0) res.intersect = cls < 0;
  const unsigned asked = w & (want_distance | want_depth | want_witnesses);
  unsigned done = 0;
  if (cls != 0) {
    // item 7 on the pairs as they are (item 8)
    if (asked) done = sphere_sphere_fast<Mul>(sphere_sphere_local(a, b, false), a, b, cls, w, res);
    if ((asked & ~done) == 0) return res;
  }
  const auto L = detail::sphere_sphere_local(a, b);
  w &= ~done;
  const detail::Bounded<F> qb = L.all_zero ? detail::Bounded<F>{F(0), F(0)} : detail::sphere_sphere_q(L);
  const F q = qb.value;
  res.intersect = q <= F(0);
  // the classification of decide() and intersect(): the filter's where it decides (the same
  // in the certified range; outside it, the filter's is the exact one)
  if (cls != 0) res.intersect = cls < 0;
  if (!(w & (want_distance | want_depth | want_witnesses))) return res;
  if ((w & (want_distance | want_depth)) && q != F(0)) {
    // Q within (1 + 1/16)u of itself: dot2's where its bound says so (E <= 2.125u|Q^|, i.e.
    // gamma^2 S below u|Q|/16), else summed as if in triple precision (item 4)
    const F aq = std::fabs(q);
    const F Q = qb.err <= F(2.125) * detail::unit_roundoff<F>() * aq ? q : detail::sphere_sphere_q3(L);
    // |v| + s as a double word (norm_dw: 18u^2), the quotient by div_pair, one rounding
    Pair<F> len{F(0), F(0)};
    if (!L.zero_v) len = detail::norm_dw<Mul>(L.v, L.vl);
    const Pair<F> t = two_sum(len.hi, L.s);
    const Pair<F> den = fast_two_sum(t.hi, F(t.lo + F(len.lo + L.sl)));
    if (den.hi > F(0) && (Q > F(0)) == (q > F(0))) {
      const Pair<F> d = div_pair<Mul>(Pair<F>{std::fabs(Q), F(0)}, den);
      const F dv = Pow2<F>(-L.scale)(F(d.hi + d.lo));
      if ((w & want_distance) && q > F(0)) res.distance = dv;
      if ((w & want_depth) && q < F(0)) res.depth = dv;
    }
  }
  if (w & want_witnesses) {
    Pair<F> n[3] = {{F(1), F(0)}, {F(0), F(0)}, {F(0), F(0)}};
    if (!L.zero_v) detail::unit_dw<Mul>(L.v, L.vl, n);
    for (int i = 0; i < 3; ++i) {
      res.on_a[i] = detail::along_dw(a.center[i], F(-a.radius), n[i]);
      res.on_b[i] = detail::along_dw(b.center[i], b.radius, n[i]);
    }
  }
  return res;
}
}  // namespace detail

template <class F>
Proximity<F> proximity(const Sphere<F>& a, const Sphere<F>& b, unsigned w = want_proximity) {
  check(a, "sphere A");
  check(b, "sphere B");
  if constexpr (std::is_same_v<F, float>)
    return detail::rounded(proximity(detail::widened(a), detail::widened(b), w));  // (decision.hpp, widened)
  else
    return with_products([&](auto mul) { return detail::proximity_dw<F, decltype(mul)>(a, b, w); });
}

}  // namespace cdref::robust
