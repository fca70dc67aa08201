// cdref/robust/ray_sphere.hpp - ray casts on a sphere that keep their accuracy where
// Algorithm 3.1 loses it, for F = float, double, long double. Same signatures and results
// as cdref::book (hit, cast for a segment and for an infinite ray). At F = float every entry
// point runs the double version on the same inputs (each float is a double) and rounds each
// value once (decision.hpp, widened): the derivation below is then that of double, and the
// float values are within an ulp of float of the truth (the pairs of floats it used before left
// thousands of ulps of point and normal at range).
//
// Formulation (s the source relative to the centre, r the direction, a = r.r, b = s.r,
// c = s.s - rho^2, lambda_{1,2} the roots of a l^2 + 2 b l + c = 0). u is the unit roundoff
// of F, eta its smallest subnormal; "double-word" is a pair hi + lo, |lo| <= ulp(hi)/2.
//  0. Exact differences. s_i = source_i - centre_i and, for a segment, r_i = target_i -
//     source_i (the book's t - s, exactly) are kept as two_sum pairs sh + sl, rh + rl: no
//     rounding of the inputs' differences at all. A ray's r is its direction (rl = 0).
//  1. Scale. Every pair and rho is multiplied by one power of two 2^-e, e the exponent of
//     the largest of |sh_i|, |rh_i|, rho: exact (barring underflow of components 2^(emin)
//     below the largest: eta per value), lambda is unchanged, and no square or product can
//     overflow (the 1e160 and 1e-160 cases). Below, quantities are in these units.
//  2. a, b, c as double-words: the exact products sh_i rh_i (one fused multiply-add each
//     where the CPU has it, else Dekker's two_prod_split: bounded/eft.hpp, with_products; the same
//     pair wherever the product does not underflow; the full ray cast on 2,000 uniform
//     cases 40.3 -> 34.2 ns against the split products, standalone loop, 2026-11-29)
//     summed by a two_sum chain, and the products' low parts, the chain's
//     errors and the cross terms sh_i rl_i + sl_i rh_i summed in F (sl_i rl_i <= u^2 |sh_i rh_i|
//     is dropped).
//  3. The discriminant from the perpendicular foot: b^2 - a c = a D, D = rho^2 - |l|^2,
//     l = s - f r, f = b/a (the book's sigma cancels (s.r)^2 against |r|^2 |s|^2; |l| is of
//     the size of the miss distance; Haines et al., "Precision improvements for ray/sphere
//     intersection", Ray Tracing Gems, 2019). f is the double-word quotient (div_pair),
//     each l_i = sh_i + sl_i - (fh + fl)(rh_i + rl_i) a double-word (the exact product
//     fh rh_i, an exact two_sum with sh_i, the rest summed in F), and D a double-word from
//     the exact squares of lh_i and rho.
//  4. The stable quadratic in double-words: X = sqrt(a D) (mul_pair, then sqrt_pair: one
//     Newton step), q = -(b + sign(b) X), a sum of two terms of one sign; the roots q / a
//     and c / q by div_pair, each with one final rounding. Neither subtracts nearly equal
//     numbers.
//  5. The entry point from the foot: x = l - h r, h = sqrt(D / a) (lambda_1 = -f - h), each
//     x_i a double-word (l's pairs, the exact product h.hi r_i, the rest in F); the point is
//     centre + x and the normal x / rho, each rounded once. s + lambda r with the rounded
//     lambda would carry lambda's half ulp times |lambda r| (of the size of |s|): at range
//     every digit of a point near the sphere. x's error is l's (33 u^2 |s|) plus h's
//     (relative 10 u^2 + err_D / (2D)): the point and normal are within an ulp of the
//     truth except near tangency, where an ulp of input moves the point by rho / sqrt(D)
//     times as much.
//  6. Where step 5 leaves a coordinate's rounding loose (at range, l's 33u^2 |s| against a
//     coordinate near a coordinate plane: the m_i test in cast_local), one Newton step on
//     g(lambda) = |s + lambda r|^2 - rho^2 first (newton_entry). lambda_0 = -(f + h) is a double
//     word; x_0 = s + lambda_0 r is formed from the exact products (foot_exactly: within u^2
//     |x_0| + 3.2e4 u^3 (|s| + |lambda_0 r|) of that point on the line); G = |x_0|^2 - rho^2
//     (rho2_minus_norm2) and g' = 2 r . x_0 in F; Delta = G / g', lambda_1 = lambda_0 - Delta.
//     Exactly, g(lambda_0) = delta (g' - a delta), delta = lambda_0 - lambda, so
//       lambda_1 - lambda = a delta^2 / g' + (G - G^) / g' + Delta (g'^ - g') / g' + Delta's rounding,
//     with delta bounded by item A's error of f, step 5's relative error of h (required <= 1/4)
//     and lambda_0's rounding. Each term is computed, and |s| is gone from the bound but for
//     u^3 and u^4 terms: at range a delta^2 / |g'| is about 1e4 u^4 |s|^2 / (rho cos theta), the
//     rest about 55u^2 rho / cos theta. y = x_0 - Delta r is formed from its six exact parts
//     (u^2 |y| + 3 gamma_12^3 of them). A coordinate of the point (y scaled back plus the
//     centre, one rounding) or of the normal (y / rho by div_pair, one rounding) is kept where
//     its bound is below u/4 of it (half an ulp, with a factor 2 for the bound's own
//     rounding): within an ulp of the truth. Elsewhere exact_entry runs, as before. At 10^12
//     radii, 2,075 of 20,000 ray casts took exact_entry (about 5 us each, 811 ns a cast on
//     average); in a standalone count none did, on 20,000 casts of each of 21 cells of the
//     uniform, long-range, near-tangent, tangent-at-range and magnitude families.
// The decision (hit or miss) is D >= 0 with the same range conditions as the book.
//
// Accuracy of lambda_enter (the header's bound; tests/test_robust_spheres.cpp evaluates
// it for every case and asserts it). lambda_enter > 0 only where b < 0 < c, and then
// lambda_enter = c / q with q = |b| + X, X = sqrt(a D) = |r| sqrt(D); write P = |b| / |r|
// (the distance from the source to the foot) and E = eta (underflow of the lows, of
// products below the normal range and of scaled components; scaled units throughout).
//  A. Error terms (each double-word accumulation: its hi chain and the two_prod lows exact,
//     the n terms of its F sum of total size L off by gamma_{n-1} L; the final two_sum exact):
//       c: |c^ - c| <= err_c = 55 u^2 (|s|^2 + rho^2) + 32 E (10 lows of total <= 6u(|s|^2+rho^2));
//       b: |b^ - b| <= err_b = 51 u^2 |s||r| + 32 E      (11 lows of total <= 5u |s||r|);
//       a: relative rel_a = 52 u^2 + 32 E / a;
//       f: delta = f^ - f = (b^ - b) / a^ + f (a - a^) / a^, so |delta| <= err_b / a^ +
//          |f| err_a / a^ + 8 u^2 |f| (div_pair: 8u^2); err_a / a is rel_a = 52 u^2 when a is
//          far above the underflow threshold, but as large as u where a's lows underflow (a
//          direction whose squares are near 2^emin: the E term);
//       l: the computed l^ = l' + e with l' = s - f^ r exactly and |e| <= 33 u^2 |s| (five
//          lows per component, of total <= u(2|s_i| + 4|f r_i|), |f||r| = P <= |s|).
//     The foot is where the error in f does not matter to first order: l . r = 0, so
//     |l'|^2 = |l - delta r|^2 = |l|^2 + delta^2 a exactly. Hence, for a hit (|l| <= rho),
//       |D^ - D| <= err_D = 111 u^2 rho^2 + 2 (rho + |delta||r|) |e| + |e|^2 + delta^2 a + 64 E,
//     with delta^2 a <= 2 err_b^2 / a + 7200 u^4 b^2 / a away from underflow (where a's lows
//     underflow, 2 (err_a / a)^2 b^2 / a: of the size of u^2 b^2 / a); the 111 u^2 rho^2 is D's own sum
//     (10 lows of total <= 6u (rho^2 + |l^|^2)) and the l^2 lows dropped. So err_D is about
//     u^2 (111 rho^2 + 66 rho |s|): at range it grows like rho |s|, not like |s|^2.
//  B. |X^ - X| <= eX, the smaller of
//       1.01 sqrt(a err_D) + (X + sqrt(a err_D)) (0.51 rel_a + 6.2 u^2)   (always: |sqrt x -
//          sqrt y| <= sqrt|x - y|; mul_pair 4u^2, sqrt_pair 4u^2), and
//       X (0.57 theta + 4.1 u^2), theta = 1.01 (rel_a + err_D / D) + 4u^2, when theta <= 0.4.
//     q^ = |b^| + X^ with 3.1 u^2 of its own: rel_q = (err_b + eX) / q + 3.1 u^2.
//  C. rel_z = (err_c / c + rel_q) / (1 - rel_q) + 8.1 u^2 for the double-word c^ / q^, then one
//     rounding: for rel_q, err_c / c <= 0.1,
//       ulps(lambda_enter) <= 1 + rel_z (1 + 1/u)
//     (ulps at the truth's binade: ulp(x) > u |x|; the rounding itself is half an ulp of
//     the result). Away from the degenerate places this is 1 + O(u) ulps: the result is the
//     correctly rounded value except within ~70 u^2 relative of a rounding midpoint.
// Where it degrades (the places where the problem itself is ill-conditioned):
//  - near tangency: the term err_D / (2 sqrt(D) (P + sqrt D)) of rel_q is about
//    (33 + 56 rho / P) (rho / sqrt D) u^2: more than an ulp's worth only when the half chord
//    sqrt(D) is below (33 + 56 rho / P) u rho, i.e. the line passes within about
//    (33 + 56 rho / P)^2 u^2 rho / 2 of tangency (depth rho - |l|);
//    at exact tangency the first form of eX still gives rel_q <= u sqrt(111 rho^2 +
//    66 rho |s|) / P, a few ulps from P ~ 10 rho on and fewer at range. An input perturbation
//    of one ulp moves lambda_enter by ~(rho / sqrt(D)) ulps there, so the bound is u times
//    the problem's own condition number;
//  - a source on the sphere: err_c / c = 55 u^2 (|s|^2 + rho^2) / c, an ulp's worth when
//    c < 55 u (|s|^2 + rho^2), i.e. the source within about 55 u rho of the surface (a
//    perturbation of the source by one ulp changes c by as much);
//  - grazing with b ~ 0: err_b / q = 51 u^2 |s||r| / q, an ulp's worth when q < 51 u |s||r|.
// Measured (cdref campaign, seed 1, 2000 cases per cell, uniform, long-range, near-tangent
// and tangent-at-range, segment and ray): lambda_enter is correctly rounded in every case
// at float and double (0 ulps; the test suite: at most 0.5 ulps), lambda_exit within 1 ulp.
//
// Certificates (decide(), decision.hpp). dot2_cert (used by sphere_sphere.hpp, sphere_box.hpp,
// segment_sphere.hpp): a decisive sign is taken from a value q^ with
// a computed bound E, |q^ - q| <= E, and is certain iff |q^| > E. For dot2 over N terms
// (bounded/eft.hpp) with S = sum |x_i y_i|: |q^ - q| <= u|q| + gamma_N^2 S, hence (solving for |q|)
// |q^ - q| <= (u|q^| + gamma_N^2 S)/(1 - u). dot2_cert() returns
//   E = 2u|q^| + 2 N^2 u^2 S^ + K eta,
// S^ the float sum of |x_i||y_i|, eta the smallest subnormal: the factor 2 covers 1/(1-u),
// gamma_N^2 <= 1.03 N^2 u^2 (N u <= 0.01), S <= S^/(1 - gamma_N) and the rounding of E
// itself (a handful of operations on nonnegative numbers). Underflow: a product below the
// normal range makes two_prod inexact by at most eta/2 (sums of floats never underflow
// inexactly), so dot2 gains at most N eta/2 and S^ loses at most N eta/2: K = 4N + extra,
// where `extra` counts the caller's own absolute errors in units of eta (for instance the
// low parts of expansions scaled into the subnormal range).
//
// decide(Segment or Ray, Sphere): the cast's classification (value == hit(): both run the
// same steps 0-4) and whether the book's exact answer is certainly the same. The book decides
// (Algorithm 3.1 at an exact type, a = |r|^2, b = s.r, c = |s|^2 - rho^2, sigma = b^2 - a c
// = a D; its own equivalences for the roots against 0 and 1, book/ray_sphere.hpp):
//   hit <=> D >= 0 and (b <= 0 or c <= 0) [lambda_2 >= 0] and, for a segment,
//           (a + b >= 0 or a + 2b + c <= 0) [lambda_1 <= 1, a + 2b + c = |t|^2 - rho^2];
//   r = 0: hit <=> c <= 0.
// Each decisive sign is read from the double-word value the cast computes, with the bound of
// item A on its error (scaled units; S2, R2, rho2, L2 computed upper bounds of |s|^2, |r|^2,
// rho^2 and |l^|^2 from the high parts, x (1 + 8u); ns, nr, nl their square roots, x (1 + 2u)):
//   c:  err_c = 55 u^2 (S2 + rho2) + 32 E                (0 when s = 0 and rho = 0: c = 0 exactly)
//   b:  err_b = 51 u^2 ns nr + 32 E
//   a:  err_a = 52 u^2 R2 + 32 E; a >= a_lo = a^(1 - 4u) - err_a, required > 0
//   D:  err_D = 56 u^2 (rho2 + L2) + 2 (nl + e) e + e^2 + delta^2 R2 + 64 E,
//       e = 33 u^2 ns (the foot's rounding), delta = err_b / a_lo + |f^| (err_a / a_lo + 8 u^2)
//       (the quotient's: a's own error enters f relatively, E / a included),
//       D^'s own sum being off by at most 55.5 u^2 (rho^2 + |l^|^2) (item A, for any |l|: its
//       lows total at most 6u (rho^2 + |l^|^2)) and |l'|^2 = |l|^2 + delta^2 a, |l'| <= |l^| + e;
//   a + b, a + 2b + c: an exact two_sum chain of the high parts (2b exact), the lows summed in
//       F: err_a + err_b + 6 u^2 (|a^| + |b^|) + u |v^| and err_a + 2 err_b + err_c +
//       14 u^2 (|a^| + 2|b^| + |c^|) + u |v^| (v^ the computed sum; its final rounding keeps
//       its sign, the u |v^| covers reading the bound against v^).
// A sign is known where the high part exceeds twice its bound (the factor 2 covers the
// rounding of the bound, (1 + u)^k for its few dozen operations, and hi against hi + lo: a
// normalized pair has the sign of its high part and |hi + lo| >= (1 - u)|hi|). The truth is
// known when the known signs decide the formula above; certain = known and equal to the
// cast's value. Near tangency the uncertain band is |D| <~ 2 u^2 (112 rho^2 + 66 rho |s|):
// u^2 wide, where a single-word evaluation of D would leave a band u wide.
// Measured (cdref campaign, seed 3, 1000 cases per cell, float, double, long double):
// uncertain only on degenerate draws (exact zeros: 13-15% of them at double and long double,
// 2-3% at float) and on at most 1 of the 13000 draws per query of the long-range and
// tangent-at-range families at float; certain
// but wrong never. (Those float figures are of the formulation at F = float, on pairs of
// floats; float now runs the double version: 0.05% and 0.09% uncertain for the ray and segment
// casts, `cdref campaign --impl robust-float --n 300 --seed 3`, 2026-11-24.)
// The filter first (cast_filter: hit() and decide() try it before the double words). At double
// the oracle's first stage runs before it (filters/sphere_filter.hpp: sigma = |r|^2 rho^2 -
// |s x r|^2 with its error bounded component by component, no division; its band near
// tangency is about u (5 rho + 9 |s|), within its own range tests), and this one only where
// that leaves the case open. The same
// formula on the stable tier's arithmetic in F, each quantity with a bound that covers the
// rounding of the inputs' differences (s_i = fl(source_i - centre_i) off by u |s_i|, for a
// segment r_i = fl(t_i - source_i) off by u |r_i|) and of its own evaluation:
//   b = fl(s.r):              8u P + 8 eta, P = sum |s_i r_i| (exact b off by (2u + gamma_3) P);
//   c = fl(fl(s.s) - rho^2):  8u (S + rho^2) + 8 eta, S = fl(s.s) ((3u + gamma_3) S + 2u rho^2);
//   a + b (segment):          10u (A + P) + 8 eta, A = fl(r.r);
//   |t|^2 - rho^2 (segment):  8u (T + rho^2) + 8 eta, from t_i = fl(target_i - centre_i);
//   D = rho^2 - |l^|^2, l^ = s - fl(b / a) r in F: the exact foot of the exact inputs is within
//       El = 26u |s| + 2u |l^| + 4 eta of l^, |s| and |l^| bounded above by sqrt(3) max_i |.|
//       (the projector on r's normal plane moves by
//       sin(angle) <= u with r, so the inputs' rounding moves the foot by 2u |s|; the quotient
//       and the subtraction by 8u |s| + u |l^| as in stable/ray_sphere.hpp; El doubles their
//       sum for the second-order terms), so D is off by (2 |l^| + El) El + 4u |l^|^2 + 2u rho^2
//       + 2u |D^| + 8 eta.
// decide() and hit() at double run it before the input checks (a valid input then pays the
// filter alone; the checks are a third of the cost): it decides only where its range test
// passed, which every infinity or NaN among the inputs fails (S from the source and the centre,
// A from the target or the direction, which fails for a ray's zero direction too, rho^2 from
// the radius), and a negative radius, which no range test sees, is tested first; everything
// else takes the checks (the same messages) and then the filter again, out of line.
// decide(), hit() and cast() all take its answer where it decides, so the three classify alike
// everywhere (the double words' own value is certified only within in_certified_range,
// decision.hpp). It answers where S and A lie in [2^emin / u, max / 64] and T, rho^2 below max / 64 (then
// the products below the normal range add the eta terms, and the quotient's underflow,
// 1.5 eta / |r| <= 2u^2 |s|, hides in El), and only where those signs decide the formula; then
// the answer is certain (the double words, u^2 accurate, give the same). Its band near tangency
// is |rho - |l|| <~ 26u |s|: at 10^12 radii about 3e-3 of the radius at double.
// Preconditions (otherwise uncertain): the scaling exact (every scaled hi and lo zero or
// normal, so E only covers products below the normal range); for r = 0 after scaling, the
// input r exactly 0. What stays uncertain: exact zeros of a decisive quantity (a source
// exactly on the sphere pointing outward, c = 0; a line exactly through a point sphere,
// D = 0), which no bound decides.
#pragma once

#include <algorithm>
#include <cdref/primitives.hpp>
#include <cdref/results.hpp>
#include <cmath>

#include <limits>

#include <cdref/filters/sphere_filter.hpp>

#include "decision.hpp"
#include <cdref/bounded/eft.hpp>
#include "rational.hpp"

namespace cdref::robust {

using namespace cdref::eft;  // the error-free transformations (bounded/eft.hpp)

namespace detail {

// x 2^-e for every value of one query: one multiplication by 2^-e when that power is a
// normal number (exact unless the product is subnormal), ldexp otherwise.
template <class F>
struct Pow2 {
  int e;
  F f;
  bool direct;
  explicit Pow2(int e_) : e(e_) {
    constexpr int emax = std::numeric_limits<F>::max_exponent;
    direct = e > -(emax - 2) && e < emax - 2;
    f = direct ? exp2_of<F>(-e) : F(0);
  }
  F operator()(F x) const { return direct ? x * f : std::ldexp(x, -e); }
};

// The double-word formulation (header, "Accuracy"): s = source - centre and r = target -
// source as exact pairs, scaled by 2^-scale.
template <class F>
struct LocalDW {
  Pair<F> s[3], r[3];
  F rho;
  int scale;
};

template <class F>
LocalDW<F> scaled_dw(const Pair<F> (&s)[3], const Pair<F> (&r)[3], F rho) {
  F m = rho;
  for (int i = 0; i < 3; ++i) m = std::max({m, std::fabs(s[i].hi), std::fabs(r[i].hi)});
  LocalDW<F> L{};
  L.scale = m > F(0) ? exponent_of(m) : 0;
  const Pow2<F> sc(L.scale);
  for (int i = 0; i < 3; ++i) {
    L.s[i] = {sc(s[i].hi), sc(s[i].lo)};
    L.r[i] = {sc(r[i].hi), sc(r[i].lo)};
  }
  L.rho = sc(rho);
  return L;
}

template <class F>
struct Roots {
  bool line_hits = false;
  F lambda1 = 0, lambda2 = 0;
};

// c = |s|^2 - rho^2 as a double-word: the exact squares of the high parts and rho^2 summed
// by a two_sum chain, their low parts, the chain's errors and 2 sh.sl summed in F.
template <class Mul = SplitProduct, class F>
Pair<F> c_dw(const LocalDW<F>& L) {
  const Pair<F> p0 = Mul::prod(L.s[0].hi, L.s[0].hi), p1 = Mul::prod(L.s[1].hi, L.s[1].hi),
                p2 = Mul::prod(L.s[2].hi, L.s[2].hi), pr = Mul::prod(L.rho, L.rho);
  const Pair<F> h1 = two_sum(p0.hi, p1.hi), h2 = two_sum(h1.hi, p2.hi), h3 = two_sum(h2.hi, F(-pr.hi));
  const F x = L.s[0].hi * L.s[0].lo + L.s[1].hi * L.s[1].lo + L.s[2].hi * L.s[2].lo;
  const F lo = F(F(p0.lo + p1.lo) + F(p2.lo - pr.lo)) + F(F(h1.lo + h2.lo) + h3.lo) + F(2) * x;
  return two_sum(h3.hi, lo);
}

// rho^2 - |l|^2 for double words l_i: the exact squares of rho and the high parts summed by a
// two_sum chain, their lows, the chain's errors and 2 lh.ll in F (item A: within 55.5 u^2
// (rho^2 + |l|^2), the l.l lows dropped).
template <class F, class Mul = SplitProduct>
Pair<F> rho2_minus_norm2(F rho, const Pair<F> (&l)[3]) {
  const Pair<F> pr = Mul::prod(rho, rho), q0 = Mul::prod(l[0].hi, l[0].hi), q1 = Mul::prod(l[1].hi, l[1].hi),
                q2 = Mul::prod(l[2].hi, l[2].hi);
  const Pair<F> dh1 = two_sum(pr.hi, F(-q0.hi)), dh2 = two_sum(dh1.hi, F(-q1.hi)), dh3 = two_sum(dh2.hi, F(-q2.hi));
  const F dx = l[0].hi * l[0].lo + l[1].hi * l[1].lo + l[2].hi * l[2].lo;
  const F dlo = F(F(pr.lo - q0.lo) - F(q1.lo + q2.lo)) + F(F(dh1.lo + dh2.lo) + dh3.lo) - F(2) * dx;
  return two_sum(dh3.hi, dlo);
}

// The double-word quantities of steps 2-3 (header): a = |r|^2, b = s.r, f = b/a, the foot
// l = s - f r (its high parts kept for the certificate) and D = rho^2 - |l|^2.
template <class F>
struct Quantities {
  Pair<F> a, b, f, D;
  Pair<F> l[3];
  F lh[3];
};

template <class Mul = SplitProduct, class F>
Quantities<F> quantities(const LocalDW<F>& L) {
  const auto& s = L.s;
  const auto& r = L.r;
  Quantities<F> Q;
  // a = |r|^2 (no cancellation)
  const Pair<F> a0 = Mul::prod(r[0].hi, r[0].hi), a1 = Mul::prod(r[1].hi, r[1].hi), a2 = Mul::prod(r[2].hi, r[2].hi);
  const Pair<F> ah1 = two_sum(a0.hi, a1.hi), ah2 = two_sum(ah1.hi, a2.hi);
  const F ax = r[0].hi * r[0].lo + r[1].hi * r[1].lo + r[2].hi * r[2].lo;
  Q.a = fast_two_sum(ah2.hi, F(F(F(a0.lo + a1.lo) + F(a2.lo + ah1.lo)) + F(ah2.lo + F(2) * ax)));
  // b = s.r
  const Pair<F> b0 = Mul::prod(s[0].hi, r[0].hi), b1 = Mul::prod(s[1].hi, r[1].hi), b2 = Mul::prod(s[2].hi, r[2].hi);
  const Pair<F> bh1 = two_sum(b0.hi, b1.hi), bh2 = two_sum(bh1.hi, b2.hi);
  const F bx = F(F(s[0].hi * r[0].lo + s[0].lo * r[0].hi) + F(s[1].hi * r[1].lo + s[1].lo * r[1].hi)) +
               F(s[2].hi * r[2].lo + s[2].lo * r[2].hi);
  Q.b = two_sum(bh2.hi, F(F(F(b0.lo + b1.lo) + F(b2.lo + bh1.lo)) + F(bh2.lo + bx)));
  // the foot of the perpendicular, l = s - f r, f = b / a, each l_i a double-word
  Q.f = div_pair<Mul>(Q.b, Q.a);
  Pair<F>(&l)[3] = Q.l;
  for (int i = 0; i < 3; ++i) {
    const Pair<F> P = Mul::prod(Q.f.hi, r[i].hi);
    const Pair<F> T = two_sum(s[i].hi, F(-P.hi));
    const F lo = F(F(T.lo + s[i].lo) - P.lo) - F(Q.f.hi * r[i].lo + Q.f.lo * r[i].hi);
    l[i] = two_sum(T.hi, lo);
    Q.lh[i] = l[i].hi;
  }
  Q.D = rho2_minus_norm2<F, Mul>(L.rho, l);
  return Q;
}

// The roots of a l^2 + 2 b l + c, a > 0, from the double-word quantities, each with one
// final rounding (step 4).
template <class Mul = SplitProduct, class F>
Roots<F> roots(const Quantities<F>& Q, const Pair<F>& c) {
  const Pair<F>& a = Q.a;
  const Pair<F>& b = Q.b;
  const Pair<F>& D = Q.D;
  Roots<F> out;
  if (!(D.hi >= F(0))) return out;
  out.line_hits = true;
  // q = -(b + sign(b) sqrt(a D)): a sum of two terms of one sign
  const Pair<F> X0 = sqrt_pair<Mul>(mul_pair<Mul>(a, D));
  const Pair<F> X = std::signbit(b.hi) ? Pair<F>{-X0.hi, -X0.lo} : X0;
  const Pair<F> qs = two_sum(b.hi, X.hi);
  const Pair<F> q0s = fast_two_sum(qs.hi, F(qs.lo + F(b.lo + X.lo)));
  const Pair<F> q{-q0s.hi, -q0s.lo};
  if (q.hi == F(0)) {  // b = 0 and D = 0: tangent at lambda = 0
    out.lambda1 = out.lambda2 = F(0);
    return out;
  }
  const Pair<F> x1p = div_pair<Mul>(q, a), x2p = div_pair<Mul>(c, q);
  const F x1 = x1p.hi + x1p.lo, x2 = x2p.hi + x2p.lo;
  out.lambda1 = std::min(x1, x2);
  out.lambda2 = std::max(x1, x2);
  return out;
}

// Everything the classification needs, kept for decide() (cast_local() runs the same steps
// and keeps only what its outputs need). hit is the cast's classification.
template <class F>
struct Analysis {
  LocalDW<F> L;
  bool zero = false;  // r = 0 exactly (a zero-length segment)
  Pair<F> c{};
  Quantities<F> Q{};
  Roots<F> R;
  bool hit = false;
};

// The cast's classification from its roots (a nonzero direction).
template <class F>
bool in_range(const Roots<F>& R, bool bounded) {
  return R.line_hits && (!bounded || R.lambda1 <= F(1)) && R.lambda2 >= F(0);
}

// s = source - centre (pairs), r = the direction (pairs; exact: target - source for a segment)
template <class Mul = SplitProduct, class F>
Analysis<F> analyse(const Pair<F> (&s)[3], const Pair<F> (&r)[3], F rho, bool bounded) {
  Analysis<F> A;
  A.L = scaled_dw(s, r, rho);
  A.zero = A.L.r[0].hi == F(0) && A.L.r[1].hi == F(0) && A.L.r[2].hi == F(0);
  A.c = c_dw<Mul>(A.L);
  if (A.zero) {  // a zero-length segment: a point test, as in the book
    A.hit = A.c.hi <= F(0);
    return A;
  }
  A.Q = quantities<Mul>(A.L);
  A.R = roots<Mul>(A.Q, A.c);
  A.hit = in_range(A.R, bounded);
  return A;
}

// Coordinate i of the entry point c + x and of the normal x / rho exactly, each rounded once
// (rational.hpp, surd_rounded), for a shot entering from outside: with s = source - c and r
// exact (the pairs), a = r.r, b = s.r, D = b^2 - a (s.s - rho^2), lambda_1 = (-b - sqrt D) / a
// and x_i = s_i + lambda_1 r_i = (s_i - b r_i / a) - sqrt(D) r_i / a.
template <class F>
void exact_entry(const Pair<F> (&s)[3], const Pair<F> (&r)[3], const Sphere<F>& sp, int i, F* point, F* normal) {
  RVec S, R;
  for (int k = 0; k < 3; ++k) set_pair(S[k], s[k].hi, s[k].lo), set_pair(R[k], r[k].hi, r[k].lo);
  Rational a, b, c, D, t, p0, k;
  dot_vec(a, R, R);
  dot_vec(b, S, R);
  dot_vec(c, S, S);
  set_rational(t, sp.radius);
  mpq_mul(t.q, t.q, t.q);
  mpq_sub(c.q, c.q, t.q);
  mpq_mul(D.q, b.q, b.q);
  mpq_mul(t.q, a.q, c.q);
  mpq_sub(D.q, D.q, t.q);
  if (mpq_sgn(D.q) < 0 || mpq_sgn(a.q) == 0) return;  // no entry (a classification not certain)
  mpq_div(k.q, R[i].q, a.q);   // r_i / a
  mpq_mul(p0.q, b.q, k.q);
  mpq_sub(p0.q, S[i].q, p0.q);  // s_i - b r_i / a
  if (normal) {
    Rational rho, p1, k1;
    set_rational(rho, sp.radius);
    mpq_div(p1.q, p0.q, rho.q);
    mpq_div(k1.q, k.q, rho.q);
    *normal = surd_rounded<F>(p1, D, k1);
  }
  if (point) {
    set_rational(t, sp.center[i]);
    mpq_add(p0.q, p0.q, t.q);
    *point = surd_rounded<F>(p0, D, k);
  }
}

// The sum S of the first N - 1 floats of p (p[N - 1] a free slot) as a double word: summed as
// if in triple precision (sum_k, K = 3), then the residual S - hi likewise, then one exact
// two_sum: within u^2 |S| + 3 gamma_{2N-2}^3 sum |p_i| of S.
template <class F, std::size_t N>
Pair<F> expansion_dw(const F (&p)[N]) {
  F a[N], q[N];
  for (std::size_t i = 0; i + 1 < N; ++i) a[i] = q[i] = p[i];
  a[N - 1] = F(0);
  const F hi = sum_k(a, 3);
  q[N - 1] = -hi;
  return two_sum(hi, sum_k(q, 3));
}

// s - f r for pairs s, r and a double-word f, as a double word from its ten exact parts
// (expansion_dw): within u^2 |s - f r| + 3.2e4 u^3 (|s| + |f r|) (3 gamma_20^3 of the parts,
// (1 + u) (|s| + |f r|)), plus 10 eta where a product underflows.
template <class Mul = SplitProduct, class F>
Pair<F> foot_exactly(const Pair<F>& s, const Pair<F>& f, const Pair<F>& r) {
  const Pair<F> a = Mul::prod(f.hi, r.hi), b = Mul::prod(f.hi, r.lo), c = Mul::prod(f.lo, r.hi), d = Mul::prod(f.lo, r.lo);
  return expansion_dw({s.hi, s.lo, F(-a.hi), F(-a.lo), F(-b.hi), F(-b.lo), F(-c.hi), F(-c.lo), F(-d.hi), F(-d.lo), F(0)});
}

// Item A's bounds (header) on a = |r|^2, b = s.r and f = b / a, from the high parts (scaled
// units): S2, R2 upper bounds of |s|^2 and |r|^2, ns and nr of |s| and |r|, err_a and err_b,
// a_lo a lower bound of a (not positive: no bound), delta = |f^ - f|'s.
template <class F>
struct FootBounds {
  F S2, R2, ns, nr, err_a, err_b, a_lo, delta;
};
template <class F>
FootBounds<F> foot_bounds(const LocalDW<F>& L, const Quantities<F>& Q) {
  const F u = std::numeric_limits<F>::epsilon() / F(2);
  constexpr F E = std::numeric_limits<F>::denorm_min();
  FootBounds<F> B;
  // (|s_i| <= (1 + u) |sh_i|)
  B.S2 = F(L.s[0].hi * L.s[0].hi + L.s[1].hi * L.s[1].hi + L.s[2].hi * L.s[2].hi) * F(1 + 8 * u);
  B.R2 = F(Q.a.hi * F(1 + 8 * u)) + F(64) * E;
  B.ns = std::sqrt(B.S2) * F(1 + 2 * u);
  B.nr = std::sqrt(B.R2) * F(1 + 2 * u);
  B.err_a = F(52) * u * u * B.R2 + F(32) * E;
  B.err_b = F(51) * u * u * F(B.ns * B.nr) + F(32) * E;
  B.a_lo = Q.a.hi * F(1 - 4 * u) - B.err_a;
  B.delta = B.a_lo > F(0) ? B.err_b / B.a_lo + F(std::fabs(Q.f.hi) * F(1 + 4 * u)) * F(B.err_a / B.a_lo + F(8) * u * u)
                          : std::numeric_limits<F>::infinity();
  return B;
}

// Step 6 (header): the entry point relative to the centre after one Newton step on lambda, each
// coordinate a double word with a bound on its distance from the exact entry point (scaled
// units); ok = false where a precondition fails (then exact_entry, as before).
template <class F>
struct NewtonEntry {
  bool ok = false;
  Pair<F> y[3];
  F err[3];
};
template <class Mul, class F>
NewtonEntry<F> newton_entry(const LocalDW<F>& L, const Quantities<F>& Q, const Pair<F>& h, F errD_over_uD) {
  using std::fabs;
  NewtonEntry<F> out;
  const F u = std::numeric_limits<F>::epsilon() / F(2);
  constexpr F E = std::numeric_limits<F>::denorm_min();
  if (!(L.rho >= exp2_of<F>(-400)) || !(h.hi > F(0)) || !std::isfinite(errD_over_uD)) return out;
  // the prior bound on lambda_0 - lambda (item A's delta for f, step 5's relative error for h,
  // lambda_0's own rounding to a double word)
  const FootBounds<F> B = foot_bounds(L, Q);
  // h's relative error (step 5), at most 1/4 here, so that the true h is below 4/3 of h^
  const F rel_h = F(u * errD_over_uD) / F(2) + F(40) * u * u;
  if (!(B.a_lo > F(0)) || !(rel_h <= F(0.25))) return out;
  const F fa = fabs(Q.f.hi) * F(1 + 4 * u), ha = h.hi * F(1.34);
  const F d_prior = B.delta + ha * rel_h + F(4) * u * u * F(fa + ha);
  // lambda_0 = -(f + h) as a double word; x_0 = s + lambda_0 r exactly on the line, formed
  // from the exact products (foot_exactly with -lambda_0): X_i within eps_i of it
  const Pair<F> t0 = two_sum(F(-Q.f.hi), F(-h.hi));
  const Pair<F> lam = fast_two_sum(t0.hi, F(F(t0.lo - Q.f.lo) - h.lo));
  const Pair<F> mlam{F(-lam.hi), F(-lam.lo)};
  const F la = fabs(lam.hi) * F(1 + 2 * u);
  Pair<F> X[3];
  F eps[3], xx = 0, cross = 0, gp = 0, rx = 0, reps = 0;
  for (int i = 0; i < 3; ++i) {
    X[i] = foot_exactly<Mul>(L.s[i], mlam, L.r[i]);
    const F si = fabs(L.s[i].hi) * F(1 + 2 * u), ri = fabs(L.r[i].hi) * F(1 + 2 * u), xi = fabs(X[i].hi) * F(1 + 2 * u);
    eps[i] = F(u * u * xi + F(F(3.2e4) * u * u * u) * F(si + la * ri)) + F(16) * E;
    xx += xi * xi;
    cross += F(F(2) * xi + eps[i]) * eps[i];
    gp += L.r[i].hi * X[i].hi;
    rx += ri * xi;
    reps += ri * eps[i];
  }
  // G = |x_0|^2 - rho^2 (rho2_minus_norm2: 55.5 u^2 (rho^2 + |X|^2), and X's errors); g' =
  // 2 r . x_0 in F (gamma_3 and the dropped lows, 6u of sum |r_i X_i|, and X's errors)
  const Pair<F> mG = rho2_minus_norm2<F, Mul>(L.rho, X);
  const F E_G = F(F(56) * u * u * F(F(L.rho * L.rho) * F(1 + 2 * u) + xx)) + cross + F(64) * E;
  gp *= F(2);
  const F E_gp = F(2) * F(F(F(6) * u) * rx + reps) + F(64) * E;
  const F gp_lo = fabs(gp) * F(1 - 4 * u) - E_gp;
  if (!(gp_lo > F(0)) || !(E_gp <= fabs(gp) / F(4))) return out;
  // Delta = G / g', lambda_1 = lambda_0 - Delta: |lambda_1 - lambda| <= (a delta^2 + E_G +
  // |Delta| E_gp) / |g'| + 2.01u |Delta| (the header's step 6)
  const F Dl = F(-mG.hi) / gp;
  const F Da = fabs(Dl) * F(1 + 4 * u);
  const F E_lam = F(F(F(Q.a.hi * F(1 + 8 * u)) * F(d_prior * d_prior) + E_G) + Da * E_gp) / gp_lo + F(F(2.01) * u) * Da;
  if (!std::isfinite(E_lam)) return out;
  for (int i = 0; i < 3; ++i) {
    // y_i = X_i - Delta r_i from its six exact parts (expansion_dw: u^2 |y_i| + 3 gamma_12^3
    // of the parts)
    const Pair<F> P = Mul::prod(Dl, L.r[i].hi), Pl = Mul::prod(Dl, L.r[i].lo);
    out.y[i] = expansion_dw({X[i].hi, X[i].lo, F(-P.hi), F(-P.lo), F(-Pl.hi), F(-Pl.lo), F(0)});
    const F ri = fabs(L.r[i].hi) * F(1 + 2 * u);
    const F parts = fabs(X[i].hi) * F(1 + 2 * u) + Da * ri;
    out.err[i] = F(F(eps[i] + ri * E_lam) + F(F(u * u) * F(fabs(out.y[i].hi) * F(1 + 2 * u)) + F(F(6e3) * u * u * u) * parts)) +
                 F(8) * E;
    if (!std::isfinite(out.err[i])) return out;
  }
  out.ok = true;
  return out;
}

// The same steps as analyse(), with nothing kept that the outputs do not need.
template <class Mul = SplitProduct, class F>
Cast<F> cast_local(const Pair<F> (&s)[3], const Pair<F> (&r)[3], const Sphere<F>& sp, bool bounded, unsigned w) {
  Cast<F> res;
  // the source itself, from its exact offset s to the centre
  const auto source_point = [&] {
    for (int i = 0; i < 3; ++i) res.point[i] = F(s[i].hi + sp.center[i]) + s[i].lo;
  };
  const LocalDW<F> L = scaled_dw(s, r, sp.radius);
  const bool zero = L.r[0].hi == F(0) && L.r[1].hi == F(0) && L.r[2].hi == F(0);
  const Pair<F> c = c_dw<Mul>(L);
  if (zero) {  // a zero-length segment: a point test, as in the book
    res.hit = c.hi <= F(0);
    if (res.hit && (w & want_lambda_exit)) res.lambda_exit = F(1);
    if (res.hit && (w & want_point)) source_point();
    return res;
  }
  const Quantities<F> Q = quantities<Mul>(L);
  const Roots<F> R = roots<Mul>(Q, c);
  res.hit = in_range(R, bounded);
  if (!res.hit) return res;
  res.enters = R.lambda1 >= F(0);
  res.lambda_enter = res.enters ? R.lambda1 : F(0);
  if (w & want_lambda_exit) res.lambda_exit = bounded ? std::min(R.lambda2, F(1)) : R.lambda2;
  if (!(w & (want_point | want_normal))) return res;
  if (!res.enters) {  // the source is inside: the entry point is the source itself
    if (w & want_point) source_point();
    return res;
  }
  // step 5: the entry point relative to the centre, x = l - h r with h = sqrt(D / a) (the
  // foot minus the half chord), each x_i a double-word, then one rounding for the point
  // (centre added) and for the normal (x / rho)
  const Pair<F> h = sqrt_pair<Mul>(div_pair<Mul>(Q.D, Q.a));
  Pair<F> x[3];
  for (int i = 0; i < 3; ++i) {
    const Pair<F> P = Mul::prod(h.hi, L.r[i].hi);
    const Pair<F> T = two_sum(Q.l[i].hi, F(-P.hi));
    x[i] = two_sum(T.hi, F(F(T.lo + Q.l[i].lo) - P.lo) - F(h.hi * L.r[i].lo + h.lo * L.r[i].hi));
  }
  if (w & want_point) {
    const Pow2<F> up(-L.scale);  // x 2^scale, as std::ldexp gives it
    for (int i = 0; i < 3; ++i) {
      const Pair<F> P = two_sum(up(x[i].hi), sp.center[i]);
      res.point[i] = P.hi + F(P.lo + up(x[i].lo));
    }
  }
  if ((w & want_normal) && L.rho != F(0))
    for (int i = 0; i < 3; ++i) res.normal[i] = F(x[i].hi + x[i].lo) / L.rho;
  // x_i carries l_i's error, at most u^2 (33 |s| + 10 |l_i|) (step 5), and h r_i's: h's relative
  // error is at most err_D / (2D) + 40u^2 (a's 52u^2 halved, the quotient's and the root's), with
  // err_D <= u^2 (64 (rho^2 + |l|^2) + 80 |l| |s|) (the decision's bound above; its u^4 terms
  // inside the slack). Where a coordinate of the point or of x (the normal) is below
  //   m_i = 2u (64 |s| + 16 |l_i| + 64 |h r_i|) + |h r_i| err_D / (u D)
  // (|s| <= 2 max |s_i|, |l| <= 2 max |l_i|), those errors could be more than u/2 of it, half an
  // ulp, and the coordinate takes step 6's Newton step, or is evaluated exactly (exact_entry)
  // where that cannot tell: at range a point near a coordinate plane (26 ulps at 10^12 radii
  // before), near tangency where D is small. Elsewhere
  // the error before the last rounding is below half an ulp, and the coordinate is within an ulp
  // of the truth: the correctly rounded value or its neighbour. (Until 2026-11-29 the threshold
  // was 32u (64 |s| + 16 (|l_i| + |h r_i|)), u/32 of the coordinate without the tangency term,
  // which sent far more coordinates at range to the rationals: see the README.)
  {
    const F u = std::numeric_limits<F>::epsilon() / F(2);
    F sn = 0, ln = 0;
    for (int i = 0; i < 3; ++i) {
      sn = std::max(sn, std::fabs(L.s[i].hi));
      ln = std::max(ln, std::fabs(Q.l[i].hi));
    }
    const F errD_u = F(F(64) * F(L.rho * L.rho + F(F(4) * ln) * ln)) + F(F(320) * ln) * sn;  // err_D / u^2
    const F t = Q.D.hi > F(0) ? F(u * errD_u) / Q.D.hi : std::numeric_limits<F>::infinity();
    NewtonEntry<F> ne;
    bool tried = false;
    for (int i = 0; i < 3; ++i) {
      const F hr = std::fabs(F(h.hi * L.r[i].hi));
      const F m = F(F(F(2) * u) * F(F(64) * sn + F(16) * std::fabs(Q.l[i].hi) + F(64) * hr)) + F(hr * t);
      bool pt = (w & want_point) && !(std::fabs(res.point[i]) >= Pow2<F>(-L.scale)(m));
      bool nm = (w & want_normal) && L.rho != F(0) && !(std::fabs(x[i].hi) >= m);
      if (!(pt || nm)) continue;
      // step 6: one Newton step (once a cast), each value kept where its bound is below a
      // quarter of u of it (half an ulp, with a factor 2 for the bound's own rounding)
      if (!tried) ne = newton_entry<Mul>(L, Q, h, t), tried = true;
      if (ne.ok) {
        const Pair<F>& y = ne.y[i];
        if (pt) {
          const Pow2<F> up(-L.scale);
          const Pair<F> P = two_sum(sp.center[i], up(y.hi));
          const F v = P.hi + F(P.lo + up(y.lo));
          const F e = up(ne.err[i]) + F(F(u * u) * F(F(std::fabs(P.hi) + std::fabs(up(y.hi))) * F(1 + 2 * u)));
          if (F(F(4) * e) <= F(u * std::fabs(v))) res.point[i] = v, pt = false;
        }
        if (nm) {
          const Pair<F> n = div_pair<Mul>(y, Pair<F>{L.rho, F(0)});
          const F v = n.hi + n.lo;
          const F e = F(ne.err[i] / L.rho) * F(1 + 4 * u) + F(F(9) * u * u) * std::fabs(v);
          if (F(F(4) * e) <= F(u * std::fabs(v))) res.normal[i] = v, nm = false;
        }
      }
      if (pt || nm) exact_entry(s, r, sp, i, pt ? &res.point[i] : nullptr, nm ? &res.normal[i] : nullptr);
    }
  }
  return res;
}

template <class F>
void diff_pairs(const Vec3<F>& x, const Vec3<F>& y, Pair<F> (&out)[3]) {
  for (int i = 0; i < 3; ++i) out[i] = two_sum(x[i], F(-y[i]));
}

// A value and a bound on its error (see the header: certificates).
template <class F>
struct Bounded {
  F value, err;
  // +1 or -1 when the exact value's sign is certain, 0 when it is not.
  int sign() const { return value > err ? 1 : (-value > err ? -1 : 0); }
};

template <class F>
constexpr F unit_roundoff() {
  return std::numeric_limits<F>::epsilon() / F(2);
}

template <class F, std::size_t N>
Bounded<F> dot2_cert(const F (&x)[N], const F (&y)[N], int extra = 0) {
  const F u = unit_roundoff<F>();
  const F q = dot2(x, y);
  F S = 0;
  for (std::size_t i = 0; i < N; ++i) S += std::fabs(x[i]) * std::fabs(y[i]);
  const F k = F(2 * N * N) * u * u;
  constexpr F eta = std::numeric_limits<F>::denorm_min();
  return {q, F(F(F(2) * u * std::fabs(q) + k * S) + F(4 * int(N) + extra) * eta)};
}

// Three-valued logic for the truth assembled from certified signs.
enum class Tri { no, yes, unknown };
inline Tri tri_or(Tri a, Tri b) {
  if (a == Tri::yes || b == Tri::yes) return Tri::yes;
  if (a == Tri::no && b == Tri::no) return Tri::no;
  return Tri::unknown;
}
inline Tri tri_and(Tri a, Tri b) {
  if (a == Tri::no || b == Tri::no) return Tri::no;
  if (a == Tri::yes && b == Tri::yes) return Tri::yes;
  return Tri::unknown;
}
// "q <= 0" and "q >= 0" from a bounded q.
template <class F>
Tri le0(const Bounded<F>& q) {
  const int sg = q.sign();
  return sg < 0 ? Tri::yes : (sg > 0 ? Tri::no : Tri::unknown);
}
template <class F>
Tri ge0(const Bounded<F>& q) {
  return le0(Bounded<F>{-q.value, q.err});
}

// The exponent that brings the largest of the inputs (m) below 2^(max_exponent - 3), so
// that sums of up to four of them cannot overflow: 0 unless m is within 2^4 of overflow.
template <class F>
int overflow_guard(F m) {
  if (!(m > F(0))) return 0;
  return std::max(0, exponent_of(m) - (std::numeric_limits<F>::max_exponent - 4));
}

// x 2^-e, flagging in `exact` a result that lost bits in the subnormal range.
template <class F>
F scale_down(F x, int e, bool& exact) {
  if (e == 0) return x;
  const F y = std::ldexp(x, -e);
  if (std::ldexp(y, e) != x) exact = false;
  return y;
}

// A sum of double-words with its sign bound: v = the F sum of the terms' high parts (an
// exact two_sum chain) and of their low parts and the chain's errors. err: the terms' own
// errors (summed by the caller), the F sum of the lows (n_lo terms of total at most
// 2u sum |hi|: gamma_{n_lo} of it) and the final rounding u |v|.
template <class F>
Bounded<F> sum_bounded(const Pair<F>& x, const Pair<F>& y, F err) {
  const F u = unit_roundoff<F>();
  const Pair<F> h = two_sum(x.hi, y.hi);
  const F v = h.hi + F(F(h.lo + x.lo) + y.lo);
  return {v, F(err + F(F(6) * u * u * F(std::fabs(x.hi) + std::fabs(y.hi)) + u * std::fabs(v)))};
}
template <class F>
Bounded<F> sum_bounded(const Pair<F>& x, const Pair<F>& y, const Pair<F>& z, F err) {
  const F u = unit_roundoff<F>();
  const Pair<F> h1 = two_sum(x.hi, y.hi), h2 = two_sum(h1.hi, z.hi);
  const F v = h2.hi + F(F(F(h1.lo + h2.lo) + F(x.lo + y.lo)) + z.lo);
  return {v, F(err + F(F(14) * u * u * F(F(std::fabs(x.hi) + std::fabs(y.hi)) + std::fabs(z.hi)) + u * std::fabs(v)))};
}

// The certificate of the header ("Certificates"), from the cast's own double-word
// quantities. s, r: the exact pairs cast() starts from.
template <class Mul, class F>
Decision decide_cast_with(const Pair<F> (&s)[3], const Pair<F> (&r)[3], const Sphere<F>& sp, bool bounded) {
  using std::fabs;
  Decision out;
  const Analysis<F> A = analyse<Mul>(s, r, sp.radius, bounded);
  out.value = A.hit;
  const F u = unit_roundoff<F>();
  constexpr F E = std::numeric_limits<F>::denorm_min();
  const F tiny = std::numeric_limits<F>::min();
  const LocalDW<F>& L = A.L;
  // the scaling must have been exact: every scaled value zero or normal (and finite)
  auto ok = [tiny](F x) { return x == F(0) || (std::isfinite(x) && fabs(x) >= tiny); };
  if (!ok(L.rho)) return out;
  bool r_zero = true;
  for (int i = 0; i < 3; ++i) {
    if (!ok(L.s[i].hi) || !ok(L.s[i].lo) || !ok(L.r[i].hi) || !ok(L.r[i].lo)) return out;
    r_zero = r_zero && r[i].hi == F(0);
  }
  // upper bounds of |s|^2, rho^2 (scaled; |s_i| <= (1 + u) |sh_i|)
  const F S2 = F(L.s[0].hi * L.s[0].hi + L.s[1].hi * L.s[1].hi + L.s[2].hi * L.s[2].hi) * F(1 + 8 * u);
  const F rho2 = F(L.rho * L.rho) * F(1 + 2 * u);
  const F g = F(2);  // safety factor: the rounding of the bounds themselves, hi against hi + lo
  // c = 0 exactly when s = 0 and rho = 0 (every term of its sum is 0)
  const bool c_exact = S2 == F(0) && L.rho == F(0);
  const Bounded<F> c{A.c.hi, c_exact ? F(0) : g * F(F(55) * u * u * F(S2 + rho2) + F(32) * E)};
  if (A.zero) {
    if (!r_zero) return out;  // r underflowed in the scaling, the exact r is not 0
    const Tri t = c_exact ? Tri::yes : le0(c);
    out.certain = t != Tri::unknown && (t == Tri::yes) == out.value;
    return out;
  }
  const Quantities<F>& Q = A.Q;
  const FootBounds<F> B = foot_bounds(L, Q);  // item A: a, b, f (S2 as above)
  const F R2 = B.R2, ns = B.ns, err_a = B.err_a, err_b = B.err_b, delta = B.delta;
  if (!(B.a_lo > F(0))) return out;
  // D: its own sum, the foot's rounding e and the quotient's error delta (header)
  const F L2 = F(Q.lh[0] * Q.lh[0] + Q.lh[1] * Q.lh[1] + Q.lh[2] * Q.lh[2]) * F(1 + 8 * u);
  const F nl = std::sqrt(L2) * F(1 + 2 * u);
  const F e = F(33) * u * u * ns;
  const F err_D = F(F(F(56) * u * u * F(rho2 + L2) + F(2) * F(nl + e) * e) + F(e * e + F(delta * delta) * R2)) + F(64) * E;
  const Bounded<F> D{Q.D.hi, g * err_D};
  const Bounded<F> b{Q.b.hi, g * err_b};
  Tri truth = ge0(D);
  truth = tri_and(truth, tri_or(le0(b), le0(c)));
  if (bounded) {
    const Pair<F> b2{F(2) * Q.b.hi, F(2) * Q.b.lo};
    const Bounded<F> AB = sum_bounded(Q.a, Q.b, F(err_a + err_b));
    const Bounded<F> ABC = sum_bounded(Q.a, b2, A.c, F(F(err_a + F(2) * err_b) + c.err / g));
    truth = tri_and(truth, tri_or(ge0(Bounded<F>{AB.value, g * AB.err}), le0(Bounded<F>{ABC.value, g * ABC.err})));
  }
  out.certain = truth != Tri::unknown && (truth == Tri::yes) == out.value;
  return out;
}

// With the products cast() takes (bounded/eft.hpp, with_products), so that both classify alike where
// a product underflows (fused and split products differ only there).
template <class F>
Decision decide_cast(const Pair<F> (&s)[3], const Pair<F> (&r)[3], const Sphere<F>& sp, bool bounded) {
  return with_products([&](auto mul) { return decide_cast_with<decltype(mul)>(s, r, sp, bounded); });
}

// The filter of the header: +1 (hit) or -1 (miss) where the formula is decided by the stable
// arithmetic's signs and their bounds, 0 where it is not. `to` is the target (bounded: a
// segment) or the direction (a ray).
template <class F>
int cast_filter_own(const Vec3<F>& from, const Vec3<F>& to, const Sphere<F>& sp, bool bounded) {
  using std::fabs;
  constexpr F u = unit_roundoff<F>();
  constexpr F eta = std::numeric_limits<F>::denorm_min();  // constexpr: no run-time conversion
  F s[3], r[3];
  F S(0), A(0), B(0), P(0), T(0);
  for (int i = 0; i < 3; ++i) {
    s[i] = from[i] - sp.center[i];
    r[i] = bounded ? F(to[i] - from[i]) : to[i];
    S += s[i] * s[i];
    A += r[i] * r[i];
    B += s[i] * r[i];
    P += fabs(s[i]) * fabs(r[i]);
    if (bounded) {
      const F t = to[i] - sp.center[i];
      T += t * t;
    }
  }
  const F rho2 = sp.radius * sp.radius;
  const F big = std::numeric_limits<F>::max() / F(64), small = std::numeric_limits<F>::min() / u;
  if (!(S <= big && A <= big && T <= big && rho2 <= big && S >= small && A >= small)) return 0;
  // Every quantity is computed and the signs combined without branches (the hit-or-miss
  // outcome follows the data, and mispredicted early exits cost more than the few operations
  // they saved). A condition "x >= 0" with bound e is certainly true where x > e and certainly
  // false where x < -e; the cast hits iff (b <= 0 or |s|^2 <= rho^2) [and, for a segment,
  // (a + b >= 0 or |t|^2 <= rho^2)] and D >= 0: yes = every conjunct certainly true, no = one
  // certainly false (Tri's and/or, the same answers as the three-valued logic before).
  const F eB = F(8) * u * P + F(8) * eta;
  const F Sr = S - rho2, eS = F(8) * u * (S + rho2) + F(8) * eta;
  int yes = int(B < -eB) | int(Sr < -eS);
  int no = int(B > eB) & int(Sr > eS);
  if (bounded) {
    const F AB = A + B, eAB = F(10) * u * (A + P) + F(8) * eta;
    const F Tr = T - rho2, eT = F(8) * u * (T + rho2) + F(8) * eta;
    yes &= int(AB > eAB) | int(Tr < -eT);
    no |= int(AB < -eAB) & int(Tr > eT);
  }
  const F k = B / A;
  F L2(0), lm(0), sm(0);
  for (int i = 0; i < 3; ++i) {
    const F l = s[i] - k * r[i];
    L2 += l * l;
    lm = std::max(lm, fabs(l));
    sm = std::max(sm, fabs(s[i]));
  }
  const F D = rho2 - L2;
  // |l^| and |s| enter the bound only through upper bounds: sqrt(3) times the largest
  // component (1.7321 > sqrt(3) after its rounding) instead of two square roots, a bound at
  // most sqrt(3) wider
  const F nl = F(1.7321) * lm;
  const F El = F(26) * u * (F(1.7321) * sm) + F(2) * u * nl + F(4) * eta;
  const F ED = (F(2) * nl + El) * El + F(4) * u * L2 + F(2) * u * rho2 + F(2) * u * fabs(D) + F(8) * eta;
  yes &= int(D > ED);
  no |= int(D < -ED);
  return yes - no;  // (never both: yes needs every conjunct certainly true)
}

// The filter every entry point takes (header): at double the oracle's first stage, then the
// one above where that leaves the case open; at other types the one above.
template <class F>
int cast_filter(const Vec3<F>& from, const Vec3<F>& to, const Sphere<F>& sp, bool bounded) {
  if constexpr (std::is_same_v<F, double>) {
    const int o = filters::staged::sphere_cast_filter(from, to, sp, bounded);
    if (o != filters::staged::unknown) [[likely]]
      return o ? 1 : -1;
  }
  return cast_filter_own(from, to, sp, bounded);
}

// The filter as hit() and decide() (and segment_sphere.hpp's decide_closest()) take it before
// their input checks (header): 0 where it does not decide or does not apply (at float, which
// runs at double after its checks; a negative or NaN radius, which no range test sees).
template <class F>
int unchecked_filter(const Vec3<F>& from, const Vec3<F>& to, const Sphere<F>& sp, bool bounded) {
  if constexpr (std::is_same_v<F, float>)
    return 0;
  else
    return sp.radius >= F(0) ? cast_filter(from, to, sp, bounded) : 0;
}

}  // namespace detail

// (at F = float every entry point runs at double on the same inputs: decision.hpp, widened)
template <class F>
Cast<F> cast(const Segment<F>& seg, const Sphere<F>& sp, unsigned w = want_cast) {
  check(seg, "segment");
  check(sp, "sphere");
  if constexpr (std::is_same_v<F, float>) return detail::rounded(cast(detail::widened(seg), detail::widened(sp), w));
  // the filter first, as decide() and hit() take it: a certain miss has no values to compute
  const int f = detail::cast_filter(seg.source, seg.target, sp, true);
  if (f < 0) return Cast<F>{};
  Pair<F> s[3], r[3];
  detail::diff_pairs(seg.source, sp.center, s);
  detail::diff_pairs(seg.target, seg.source, r);
  Cast<F> c = with_products([&](auto mul) { return detail::cast_local<decltype(mul)>(s, r, sp, true, w); });
  if (f > 0) c.hit = true;
  return c;
}

template <class F>
Cast<F> cast(const Ray<F>& ray, const Sphere<F>& sp, unsigned w = want_cast) {
  check(ray, "ray");
  check(sp, "sphere");
  if constexpr (std::is_same_v<F, float>) return detail::rounded(cast(detail::widened(ray), detail::widened(sp), w));
  const int f = detail::cast_filter(ray.source, ray.direction, sp, false);  // (as the segment's)
  if (f < 0) return Cast<F>{};
  Pair<F> s[3];
  detail::diff_pairs(ray.source, sp.center, s);
  const Pair<F> r[3] = {{ray.direction[0], F(0)}, {ray.direction[1], F(0)}, {ray.direction[2], F(0)}};
  Cast<F> c = with_products([&](auto mul) { return detail::cast_local<decltype(mul)>(s, r, sp, false, w); });
  if (f > 0) c.hit = true;
  return c;
}

// The decision alone: the same computation as cast() (the range tests need the roots),
// with none of the outputs assembled.
template <class F>
[[gnu::noinline]] bool hit_checked(const Segment<F>& seg, const Sphere<F>& sp) {
  check(seg, "segment");
  check(sp, "sphere");
  if constexpr (std::is_same_v<F, float>) return hit_checked(detail::widened(seg), detail::widened(sp));
  if (const int f = detail::cast_filter(seg.source, seg.target, sp, true)) return f > 0;
  return cast(seg, sp, 0).hit;
}
template <class F>
bool hit(const Segment<F>& seg, const Sphere<F>& sp) {
  if (const int f = detail::unchecked_filter(seg.source, seg.target, sp, true)) [[likely]]  // (checks after it)
    return f > 0;
  return hit_checked(seg, sp);
}

template <class F>
[[gnu::noinline]] bool hit_checked(const Ray<F>& ray, const Sphere<F>& sp) {
  check(ray, "ray");
  check(sp, "sphere");
  if constexpr (std::is_same_v<F, float>) return hit_checked(detail::widened(ray), detail::widened(sp));
  if (const int f = detail::cast_filter(ray.source, ray.direction, sp, false)) return f > 0;
  return cast(ray, sp, 0).hit;
}
template <class F>
bool hit(const Ray<F>& ray, const Sphere<F>& sp) {
  if (const int f = detail::unchecked_filter(ray.source, ray.direction, sp, false)) [[likely]]  // (checks after it)
    return f > 0;
  return hit_checked(ray, sp);
}

// decide_words: the double words alone, on inputs already checked and where the filters have
// already left the case open (the classification oracle's second stage: through decide() the
// filters ran there four times and the checks twice, a third of its 2^-52-from-tangency path).
template <class F>
Decision decide_words(const Segment<F>& seg, const Sphere<F>& sp) {
  Pair<F> s[3], r[3];
  detail::diff_pairs(seg.source, sp.center, s);
  detail::diff_pairs(seg.target, seg.source, r);
  return within_range(detail::decide_cast(s, r, sp, true), seg, sp);
}
template <class F>
Decision decide_words(const Ray<F>& ray, const Sphere<F>& sp) {
  Pair<F> s[3];
  detail::diff_pairs(ray.source, sp.center, s);
  const Pair<F> r[3] = {{ray.direction[0], F(0)}, {ray.direction[1], F(0)}, {ray.direction[2], F(0)}};
  return within_range(detail::decide_cast(s, r, sp, false), ray, sp);
}
// The cast's classification with its certificate (decision.hpp; bound in the header): the
// cast's own computation and a bound on each decisive sign.
template <class F>
[[gnu::noinline]] Decision decide_checked(const Segment<F>& seg, const Sphere<F>& sp) {
  check(seg, "segment");
  check(sp, "sphere");
  if constexpr (std::is_same_v<F, float>) return decide_checked(detail::widened(seg), detail::widened(sp));
  if (const int f = detail::cast_filter(seg.source, seg.target, sp, true)) return Decision{f > 0, true};
  return decide_words(seg, sp);
}
template <class F>
Decision decide(const Segment<F>& seg, const Sphere<F>& sp) {
  if (const int f = detail::unchecked_filter(seg.source, seg.target, sp, true)) [[likely]]  // (checks after it)
    return Decision{f > 0, true};
  return decide_checked(seg, sp);
}

template <class F>
[[gnu::noinline]] Decision decide_checked(const Ray<F>& ray, const Sphere<F>& sp) {
  check(ray, "ray");
  check(sp, "sphere");
  if constexpr (std::is_same_v<F, float>) return decide_checked(detail::widened(ray), detail::widened(sp));
  if (const int f = detail::cast_filter(ray.source, ray.direction, sp, false)) return Decision{f > 0, true};
  return decide_words(ray, sp);
}
template <class F>
Decision decide(const Ray<F>& ray, const Sphere<F>& sp) {
  if (const int f = detail::unchecked_filter(ray.source, ray.direction, sp, false)) [[likely]]  // (checks after it)
    return Decision{f > 0, true};
  return decide_checked(ray, sp);
}

}  // namespace cdref::robust
