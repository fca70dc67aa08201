// cdref/oracle/enter.hpp - the entry parameter of a cast, correctly rounded to double:
// oracle::enter(shot, solid) is round-to-nearest of the lambda_enter that the book's cast
// returns at an exact type (0 on a miss, and 0 when the source lies in the solid), for the
// casts on a sphere (Algorithm 3.1), on an axis-aligned box (Algorithm 3.3), on an oriented
// box (the solid's cast, solid/obb.hpp: the truth where the axes are not exactly orthonormal),
// on a triangle (Section 3.4, Moller-Trumbore) and on a union of triangles (a polygon's fan, a
// mesh's fan: enter_first, the smallest of the triangles' values). It is the one output a ray
// tracer takes from a cast, and `cdref report` prices it beside the oracle's classification and
// its every-output path.
//
// Each call: the input checks (for the sphere and box casts after the classification's
// filter, whose range tests refuse what they would: classify.hpp, staged::filter_first); the
// classification (oracle::classify: filter, double words, expansions, rationals; each query's
// own stages); on a hit a double path whose error is bounded rigorously, accepted when the
// exact value cannot lie on the other side of a rounding midpoint (Bounded2::try_rounded);
// otherwise the truth's formulation at oracle::Bounded2, then
// at CGAL::Gmpq.
//
// ---- A sphere, first: one Newton step from the stable root, certified a posteriori ---------
// s = source - centre and r (target - source, or the direction) as exact two_sum pairs, u =
// 2^-53, eta = 2^-1074 (the smallest subnormal; the code adds multiples of 2^-1022 instead,
// `under`: a larger bound, and a normal constant). P(z) = |s + z r|^2 - rho^2 = a z^2 + 2 b z
// + c (a = |r|^2, b = s.r, c = |s|^2 - rho^2). On a hit lambda_enter = 0 when c <= 0 (source in or on the sphere);
// otherwise b < 0 (b >= 0 and c > 0 puts both roots behind the source) and lambda_enter = z*,
// the smaller root, where P falls through 0.
//  1. c's sign from c^ = fl(|sh|^2) - rho^2 with |c^ - c| <= 8u (|sh|^2 + rho^2) (the
//     filter's bound, classify.hpp; exact s = sh + sl, |sl| <= u |sh|). Not decided: the
//     next path.
//  2. z0: the stable root in double, z0 = c / (sqrt(a D) - b) with a D = a rho^2 - |s x r|^2
//     (Lagrange's identity: |s x r| / |r| is the distance from the centre to the line, so the
//     cancellation is that of the perpendicular foot, with no division before the last), a few
//     ulps from z* away from tangency. No bound is needed on it: the step below is certified
//     whatever z0 is.
//  3. The residual at z0, P0 = P(z0) = |w|^2 - rho^2, w = s + z0 r: each w_i a double word,
//     sh_i + z0 rh_i by an exact product and an exact two_sum, the lows (the two_sum's, sl_i,
//     the product's, z0 rl_i) summed in double: |w_i^ - w_i| <= ew_i = 4u (sum of the lows'
//     magnitudes) + 8 eta. P0 from robust::detail::rho2_minus_norm2 (exact squares of the
//     high parts, the lows in double): off by 56 u^2 (rho^2 + |wh|^2) + 64 eta for the
//     double words w^, plus 2.01 sum |wh_i| ew_i for w^ against w; rounding the pair to one
//     double adds u |P0^|.
//  4. The step. g = -P'(z0) = -2 r.w in double from the high parts: the exact r.w differs
//     from fl(sum rh_i wh_i) by at most sum |rh_i| (|wl_i| + ew_i) (the lows) + u sum |rh_i|
//     |w_i| (r's lows) + gamma_3 sum |rh_i| |wh_i|, so |g^ - g| <= eg = 2 (5u G + sum |rh_i|
//     (|wl_i| + 2 ew_i)) + 16 eta, G = sum |rh_i| |wh_i| (1 + 4u). Required: g > 0 certainly
//     (g_lo = g^ - eg > 0), i.e. z0 lies before the roots' midpoint -b/a, so that the root of
//     P nearest z0 is z*. Then exactly, with e = z* - z0 and kappa = 4 a P0 / g^2,
//         a e^2 - g e + P0 = 0,   e = (P0 / g) 2 / (1 + sqrt(1 - kappa)),
//     (the root of smaller magnitude; g^2 - 4 a P0 = 4 a^2 h^2 >= 0, h the half chord), and
//     |2 / (1 + sqrt(1 - kappa)) - 1| <= 0.6 |kappa| for |kappa| <= 1/2 (required; it is
//     about (z* - z0) / h: tiny away from tangency). The step delta = fl(P0^ / g^):
//         |delta - P0 / g| <= (|P0^ - P0| + |P0^| eg / g^) / g_lo + u |delta|,
//     and z* = z0 + delta + E with |E| <= that + 0.6 |kappa| |P0| / g_lo. z0 + delta is a
//     double word by two_sum (exact); the bound is doubled to cover its own rounding (a few
//     dozen operations on nonnegative numbers, one reciprocal).
//  5. Bounded2::try_rounded: the exact z* rounds to the high part when [v - E, v + E] lies
//     strictly between the midpoints around it.
// Size of the bound: about u^2 (rho^2 + rho |s|) / (|r| sqrt D) from the residual plus
// u^2 z0 rho / sqrt(D) from g's cancellation. The rounding is left uncertain only where the
// exact value lies within that of a midpoint, and the step is refused near tangency (where z0
// itself is only u rho / sqrt(D) accurate, kappa or the step's second-order term grow) and at
// long range (|s| / rho ~ 10^12: the residual's u^2 rho |s| reaches a fraction of an ulp):
// measured (tests/test_oracle_classify.cpp, CDREF_TEST_REPORT=1), the Newton step answers
// every uniform and long-range hit of the campaigns' draws but about one in a thousand at 10^12
// radii, 70% of the near-tangent ones (2^-1 to 2^-52 of the radius) and 28% of those tangent
// at range.
// Range: every |sh_i|, |rh_i| and rho at most 2^300, |sh|^2 and |rh|^2 at least 2^-600, z0
// in [2^-600, 2^600]: no product overflows, two_prod_split's split cannot overflow, and every
// u^2-sized term of the bound stays a normal number (products below the normal range are
// covered by the eta terms). Outside: the next path.
//
// ---- A sphere, second: the robust tier's double words --------------------------------------
// z = c / q, q = |b| + sqrt(a D), from the robust cast's own double-word quantities
// (robust/ray_sphere.hpp, steps 0-4: s and r scaled by a power of two, a, b, c, the foot and
// D in double words), with that header's error bound (items A-C: rel_z = (rel_c + rel_q) /
// (1 - rel_q) + 8.1 u^2, here 10 u^2) evaluated with computed upper bounds of |s|^2, |r|^2,
// rho^2 and |l|^2 and lower bounds of a, c, D and q in place of the exact quantities, as its
// certificate (decide_cast) evaluates items A's terms; x 2.7 for |z| against its high part and
// the bound's own rounding. Its error does not grow with |s| / rho (c = |s|^2 - rho^2 is formed
// directly, and D's error reaches q only through sqrt(a D), small beside |b| at range), and near
// tangency it is u^2 rho / sqrt(D) relative: it answers every near-tangent draw down to 2^-52
// of the radius. Only inside robust::in_certified_range (where the double words are derived).
//
// ---- A box: the largest entering parameter, each quotient rounded ---------------------------
// In the book (book/ray_box.hpp) lambda_enter is the largest lambda_p = n_p / d_p over the
// planes p the source lies outside of (none: 0), n_p = (c_i -+ h_i) - source_i, d_p =
// target_i - source_i (a ray: direction_i); on a hit every such lambda_p lies in [0, 1] (or
// [0, inf)). Rounding to nearest is monotone, so round(max_p lambda_p) = max_p round(lambda_p).
// For each axis: (p, pe) = two_sum(c_i, -source_i), (m, me) = two_sum(p, -+h_i), so n = m + t
// exactly with t = me + pe, rounded once to t^ (|t - t^| <= u |t^|). The outcode bit is the
// sign of n: sign(m) where |m| > 2 |t^|, sign(t^) where m = 0 (then t = pe exactly), else
// undecided. d = dh + dl exactly (two_sum; a ray's dl = 0). The quotient: q1 = fl(m / dh); the
// residual R = n - q1 d = (m - P) - Pe + t - q1 dl with (P, Pe) = two_prod_split(q1, dh)
// exact and m - P exact (P is within 2u of m: Sterbenz), the small terms summed with three
// roundings: |R^ - R| <= 4u (|m - P| + |Pe| + |t^| + |q1 dl|)(1 + 8u). Then n / d = q1 + R / d
// exactly, and q2 = fl(R^ / dh) is off by |R^ - R| / |d| + 2.1 u |q2| (dl against d, q2's
// rounding); q1 + q2 as a double word by two_sum, the bound doubled, Bounded2::try_rounded.
// Range: |m|, |dh| and |q1| in [2^-900, 2^900] (no product below the normal range); outside,
// or any sign or rounding undecided: the exact path.
//
// ---- A triangle: the plane's parameter, corrected once, certified ---------------------------
// Where det = e1 . (d x e2) != 0 the book's lambda = e2 . q / det with q = (s - v0) x e1, that
// is lambda* = -(sv . n) / (d . n) with sv = s - v0, n = e1 x e2 (scalar triple products
// permuted), and the plane's signed offset g(l) = (sv + l d) . n is linear in l: for any l0,
//     lambda* = l0 - g(l0) / (d . n)   exactly.
// So l0 = -(sv . n) / (d . n) rounded needs no bound; the correction is where the accuracy is
// (plane_parameter, shared with the oriented box). e1, e2, sv and d are exact two_sum pairs;
// n_i = e1_j e2_k - e1_k e2_j as a double word (cross_term: the two products of high parts
// exact, the four cross terms and the lows summed in double, the lows' products dropped), off
// by en_i = 8u (the lows' and cross terms' magnitudes) + 2u^2 (|e1_j e2_k| + |e1_k e2_j|) +
// 16 eta; w = sv + l0 d as double words with ew_i as the sphere's (affine_words); each dot
// product with n (dot_words: the products of the high parts exact and summed by two_sum, the
// lows in double) is off by 12u (the lows' magnitudes) + 1.01 (sum |x_i| en_i + |n_i| ex_i +
// the dropped x.lo n.lo) + 64 eta. D = d . n must be certainly nonzero (|D| - eD > 0; else a
// shot parallel to the plane or in it: the exact path); g = w . n is rounded once more (2u of
// the two terms summed). Then delta = -g^ / D^ is off from -g / D by (eg + |g^| eD / |D^|) /
// D_lo + u |delta|; l0 + delta as a double word (two_sum), the bound doubled,
// Bounded2::try_rounded. The exact value's
// relative error is then of order u^2 |w| |n| / |d . n| / lambda*: away from grazing shots the
// rounding is decided on all but a few in 10^13 cases. Range: robust::in_certified_range, every
// difference at most 2^250, l0 at most 2^250 (no product overflows; underflow in the eta terms).
//
// ---- An oriented box: the solid's faces, each a plane as the triangle's ---------------------
// The truth is the solid's cast (solid/obb.hpp): with the face normals n_i = a_{i+1} x a_{i+2},
// turned by sign(delta), delta = a_i . n_i (the same determinant for every i), the box is
// [-H, H] in U_i = n_i . (p - c), H_i = |delta| h_i, and Algorithm 3.3 runs there: lambda_enter
// is the largest lambda over the faces the source lies outside of (U_i(s) < -H_i or > H_i), the
// parameter where U_i(s + lambda d) = -+H_i. Face by face (face_entry): n_i a cross product of
// exact doubles (cross_term, its cross terms 0), delta a dot_words of a_i and n_i whose sign
// must be certain, H_i = delta h_i a double word (scale_word, word_bounds.hpp). The outcode bits
// are the certain signs of U_i(s) + H_i and U_i(s) - H_i (add_words and sign_of: never an exact
// 0, so a source on a face is uncertain); undecided: the exact path. A face's plane is g(l) = n_i . (s - c + l d) -+ H_i,
// linear in l: plane_parameter with the offset -+H_i. Rounding is monotone, so the largest of
// the rounded parameters is the rounded largest. Range: robust::in_certified_range, every input
// at most 2^200 (H_i is of degree 4).
// First, though, the entering face alone (filter/obb_face.hpp: the classification's filter,
// kept, picks it from its certain signs, and that face's parameter alone on double words, about
// 18 exact products instead of some 60 for three faces). Where the filter cannot tell (two
// faces entered at nearly the same parameter, an outcode near 0) or the face's rounding is
// uncertain, every face as above.
//
// Measured (`cdref_bench`, ratios to that run's `bare`): docs/cost-report.* and the README.
#pragma once

#include <cdref/bounded/bounded2.hpp>
#include <cdref/oracle/classify.hpp>
#include <cdref/filter/obb_face.hpp>
#include <cdref/oracle/rational.hpp>
#include <cdref/oracle/ray_triangle.hpp>
#include <cdref/oracle/separating_axes.hpp>
#include <cdref/oracle/stage.hpp>
#include <cdref/bounded/word_bounds.hpp>
#include <cdref/robust/ray_sphere.hpp>
#include <cmath>
#include <limits>
#include <optional>

namespace cdref::oracle {

namespace enter_detail {

using robust::Pair;

using namespace word_bounds;

// w = x + l d for exact pairs x, d and a double l, as double words with their bounds.
template <class Mul = SplitProduct>
inline void affine_words(const Pair<double> (&x)[3], double l, const Pair<double> (&d)[3], Pair<double> (&w)[3],
                         double (&ew)[3]) {
  using std::fabs;
  for (int i = 0; i < 3; ++i) {
    const Pair<double> P = Mul::prod(l, d[i].hi);
    const Pair<double> T = robust::two_sum(x[i].hi, P.hi);
    const double zl = l * d[i].lo;
    w[i] = robust::two_sum(T.hi, ((T.lo + x[i].lo) + P.lo) + zl);
    ew[i] = 4 * uu * (((fabs(T.lo) + fabs(x[i].lo)) + fabs(P.lo)) + fabs(zl)) + 8 * eta;
  }
}

// The plane's parameter lambda* = l0 - g(l0) / D, g(l) = n . (x + l d) + off linear in l
// (off: a word, 0 for the triangle), D = n . d, l0 = -(N + off) / D in double with N = n . x
// (computed by the caller): the double word l0 + delta with its bound, rounded (nothing when
// the rounding is not certain).
template <class Mul = SplitProduct>
inline std::optional<double> plane_parameter(const Pair<double> (&x)[3], const Pair<double> (&d)[3], const Word (&n)[3],
                                             const Word& N, const Word& off) {
  using std::fabs;
  const double zero[3] = {0, 0, 0};
  const Word D = dot_words<Mul>(d, zero, n);
  const double D_lo = magnitude_lo(D);
  if (!(D_lo > 0)) return std::nullopt;  // nearly parallel, or in the plane: the exact path
  const double Dv = D.v.hi + D.v.lo;
  const double l0 = -((N.v.hi + off.v.hi) + (N.v.lo + off.v.lo)) / Dv;
  if (!std::isfinite(l0) || fabs(l0) > 0x1p250) return std::nullopt;
  Pair<double> w[3];
  double ew[3];
  affine_words<Mul>(x, l0, d, w, ew);
  const Word G = dot_words<Mul>(w, ew, n);
  // g = G + off: one two_sum of the highs, the rest in double
  const Pair<double> S = robust::two_sum(G.v.hi, off.v.hi);
  const double rest = S.lo + (G.v.lo + off.v.lo);
  const double g = S.hi + rest;
  const double eg = (G.e + off.e + 2 * uu * (fabs(rest) + fabs(g))) * (1 + 4 * uu);
  // delta = -g / D, off from -g_exact / D_exact by (eg + |g| eD / |D|) / D_lo + u |delta|
  const double delta = -g / Dv;
  const double err = 2 * ((eg + fabs(g) * D.e / fabs(Dv)) / D_lo + uu * fabs(delta)) + eta;
  const Pair<double> z = robust::two_sum(l0, delta);
  double v;
  if (!std::isfinite(err) || !Bounded2::within(z.hi, z.lo, err).try_rounded(v)) return std::nullopt;
  return v;
}

// The sphere's double path (header, steps 1-4). Returns 0 when lambda_enter is 0 (c < 0
// certainly), 1 with `out` set, or 2 when it cannot tell (the exact path then answers).
template <class Mul = SplitProduct>
inline int sphere_step(const Pair<double> (&s)[3], const Pair<double> (&r)[3], double rho, Bounded2& out) {
  using std::fabs;
  constexpr double u = uu, big = 0x1p300;
  double S = 0, A = 0, B = 0;
  for (int i = 0; i < 3; ++i) {
    if (!(fabs(s[i].hi) <= big && fabs(r[i].hi) <= big)) return 2;
    S += s[i].hi * s[i].hi;
    A += r[i].hi * r[i].hi;
    B += s[i].hi * r[i].hi;
  }
  if (!(rho <= big && S >= 0x1p-600 && A >= 0x1p-600)) return 2;
  // 1. the sign of c
  const double rho2 = rho * rho;
  const double c = S - rho2, ec = 8 * u * (S + rho2) + 8 * eta;
  if (c < -ec) return 0;
  if (!(c > ec)) return 2;
  // 2. the stable root, without a division before the last: a D = a rho^2 - |s x r|^2
  // (Lagrange's identity; |s x r| / |r| is the miss distance, its error u |s|)
  const double x0 = s[1].hi * r[2].hi - s[2].hi * r[1].hi, x1 = s[2].hi * r[0].hi - s[0].hi * r[2].hi,
               x2 = s[0].hi * r[1].hi - s[1].hi * r[0].hi;
  const double aD = A * rho2 - ((x0 * x0 + x1 * x1) + x2 * x2);
  const double z0 = c / (std::sqrt(std::max(aD, 0.0)) - B);
  if (!(z0 >= 0x1p-600 && z0 <= 0x1p600)) return 2;
  // 3. the residual at z0
  Pair<double> w[3];
  double ew[3], G = 0, W = 0, lows = 0;
  affine_words<Mul>(s, z0, r, w, ew);
  for (int i = 0; i < 3; ++i) {
    G += fabs(r[i].hi) * fabs(w[i].hi);
    W += fabs(w[i].hi) * ew[i];
    lows += fabs(r[i].hi) * (fabs(w[i].lo) + 2 * ew[i]);
  }
  const Pair<double> negP = robust::detail::rho2_minus_norm2<double, Mul>(rho, w);
  const double P0 = -(negP.hi + negP.lo);
  const double W2 = w[0].hi * w[0].hi + w[1].hi * w[1].hi + w[2].hi * w[2].hi;
  const double eP = 56 * u * u * (rho2 + W2) * (1 + 8 * u) + 2.01 * W + u * fabs(P0) + 64 * eta;
  // 4. the step
  const double g = -2 * (r[0].hi * w[0].hi + r[1].hi * w[1].hi + r[2].hi * w[2].hi);
  const double eg = 2 * (5 * u * G * (1 + 4 * u) + lows) + 16 * eta;
  const double g_lo = (g - eg) * (1 - 4 * u);
  if (!(g_lo > 0)) return 2;
  const double P_up = fabs(P0) + eP, inv = 1 / g_lo;  // (inv rounded: the factor 2 below covers it)
  const double kappa = 4 * A * (1 + 8 * u) * P_up * inv * inv;
  if (!(kappa <= 0.5)) return 2;
  const double delta = P0 / g;
  const double E = 2 * ((eP + fabs(P0) * eg * inv) * inv + u * fabs(delta) + 0.6 * kappa * P_up * inv) + eta;
  const Pair<double> z = robust::two_sum(z0, delta);
  out = Bounded2::within(z.hi, z.lo, E);
  return std::isfinite(E) ? 1 : 2;
}

// The second double path (header, "the robust tier's double words"): z = c / q from
// robust/ray_sphere.hpp's double words (the robust cast's own steps 0-4) and a bound on its
// error from that header's items A-C, evaluated with computed upper bounds (and lower bounds
// of the divisors) in place of the exact quantities. Same returns as sphere_step.
template <class Shot>
int sphere_words(const Shot& x, const Sphere<double>& sp, const Pair<double> (&s)[3], const Pair<double> (&r)[3],
                 Bounded2& out) {
  using std::fabs;
  constexpr double u = 0x1p-53, E = under, tiny = 0x1p-1022;
  if (!robust::in_certified_range(x, sp)) return 2;
  const auto A = robust::detail::analyse(s, r, sp.radius, std::is_same_v<Shot, Segment<double>>);
  const auto& L = A.L;
  auto ok = [](double v) { return v == 0 || (std::isfinite(v) && fabs(v) >= tiny); };
  if (A.zero || !ok(L.rho)) return 2;
  for (int i = 0; i < 3; ++i)
    if (!ok(L.s[i].hi) || !ok(L.s[i].lo) || !ok(L.r[i].hi) || !ok(L.r[i].lo)) return 2;
  // item A's terms, as robust::detail::decide_cast computes them
  const double S2 = (L.s[0].hi * L.s[0].hi + L.s[1].hi * L.s[1].hi + L.s[2].hi * L.s[2].hi) * (1 + 8 * u);
  const double rho2 = L.rho * L.rho * (1 + 2 * u);
  const double err_c = 55 * u * u * (S2 + rho2) + 32 * E;
  if (A.c.hi < -2 * err_c) return 0;
  const double c_lo = A.c.hi * (1 - 4 * u) - err_c;
  if (!(c_lo > 0)) return 2;
  const auto& Q = A.Q;
  const double R2 = Q.a.hi * (1 + 8 * u) + 64 * E;
  const double ns = std::sqrt(S2) * (1 + 2 * u), nr = std::sqrt(R2) * (1 + 2 * u);
  const double err_a = 52 * u * u * R2 + 32 * E;
  const double err_b = 51 * u * u * (ns * nr) + 32 * E;
  const double a_lo = Q.a.hi * (1 - 4 * u) - err_a;
  if (!(a_lo > 0) || !(Q.b.hi < -2 * err_b)) return 2;  // on a hit with c > 0, b < 0
  const double L2 = (Q.lh[0] * Q.lh[0] + Q.lh[1] * Q.lh[1] + Q.lh[2] * Q.lh[2]) * (1 + 8 * u);
  const double nl = std::sqrt(L2) * (1 + 2 * u);
  const double e = 33 * u * u * ns;
  const double delta = err_b / a_lo + fabs(Q.f.hi) * (1 + 4 * u) * (err_a / a_lo + 8 * u * u);
  const double err_D = 56 * u * u * (rho2 + L2) + 2 * (nl + e) * e + e * e + delta * delta * R2 + 64 * E;
  // step 4 of that header: q = |b| + X, X = sqrt(a D), z = c / q
  const Pair<double> X = robust::sqrt_pair(robust::mul_pair(Q.a, Q.D));
  const Pair<double> qs = robust::two_sum(-Q.b.hi, X.hi);
  const Pair<double> q = robust::fast_two_sum(qs.hi, qs.lo + (X.lo - Q.b.lo));
  const Pair<double> z = robust::div_pair(A.c, q);
  // item B: |X^ - X| (X exact on the right-hand sides: solved for it, 1 / (1 - k) <= 1 + 2k)
  const double rel_a = err_a / a_lo;
  const double sq = std::sqrt(R2 * err_D) * (1 + 4 * u);
  const double k = 0.51 * rel_a + 6.2 * u * u;
  const double Xh = fabs(X.hi) * (1 + 2 * u);
  double eX = (1.01 * sq + (Xh + sq) * k) * (1 + 2 * k);
  const double D_lo = Q.D.hi * (1 - 4 * u) - err_D;
  if (D_lo > 0) {
    const double theta = 1.01 * (rel_a + err_D / D_lo) + 4 * u * u;
    if (theta <= 0.4) {
      const double m = 0.57 * theta + 4.1 * u * u;
      eX = std::min(eX, Xh * m * (1 + 2 * m));
    }
  }
  // item C
  const double q_lo = q.hi * (1 - 4 * u) - (err_b + eX);
  if (!(q_lo > 0)) return 2;
  const double rel_q = (err_b + eX) / q_lo + 3.1 * u * u, rel_c = err_c / c_lo;
  if (!(rel_q <= 0.1 && rel_c <= 0.1)) return 2;
  const double rel_z = (rel_c + rel_q) / (1 - rel_q) + 10 * u * u;
  const Pair<double> zn = robust::fast_two_sum(z.hi, z.lo);
  const double bound = 2 * 1.35 * rel_z * fabs(zn.hi) + E;  // |z| <= 1.35 |zn.hi|; x 2: the bound's own rounding
  if (!std::isfinite(bound) || !(fabs(zn.hi) >= 0x1p-960)) return 2;
  out = Bounded2::within(zn.hi, zn.lo, bound);
  return 1;
}

// The exact path: the truth's formulation (the book's cast; for an oriented box the solid's,
// solid/obb.hpp: the book's frame transform assumes orthonormal axes) at Bounded2 (certain,
// or it throws), then at CGAL::Gmpq.
template <class Shot, class Solid>
auto truth_cast(const Shot& x, const Solid& y) {
  return book::cast(x, y, want_lambda_enter);
}
template <class Shot, class T>
auto truth_cast(const Shot& x, const OrientedBox<T>& y) {
  return solid::cast(x, y, want_lambda_enter);
}
template <class Shot, class Solid>
double exact_enter(const Shot& x, const Solid& y) {
  try {
    const auto c = truth_cast(exactly<Bounded2>(x), exactly<Bounded2>(y));
    return c.hit ? c.lambda_enter.rounded() : 0.0;
  } catch (const uncertain&) {
  }
  const auto c = truth_cast(rational_inputs::toq(x), rational_inputs::toq(y));
  return c.hit ? round_to<double>(c.lambda_enter) : 0.0;
}

// A double path's answer rounded: the value, or nothing when the path could not tell.
inline std::optional<double> rounded(int st, const Bounded2& z) {
  if (st == 0) return 0.0;
  double v;
  if (st == 1 && z.try_rounded(v)) return v;
  return std::nullopt;
}

// The two double paths on a hit (stage 1: the Newton step, 2: the double words).
// The Newton step alone, with the products of Mul.
template <class Mul, class Shot>
std::optional<double> sphere_first(const Shot& x, const Sphere<double>& sp) {
  Pair<double> s[3], r[3];
  shot_pairs(x, sp.center, s, r);
  Bounded2 z;
  return rounded(sphere_step<Mul>(s, r, sp.radius, z), z);
}
// The double words alone.
template <class Shot>
std::optional<double> sphere_second(const Shot& x, const Sphere<double>& sp) {
  Pair<double> s[3], r[3];
  shot_pairs(x, sp.center, s, r);
  Bounded2 z;
  return rounded(sphere_words(x, sp, s, r, z), z);
}
template <class Shot>
std::optional<double> sphere_double(const Shot& x, const Sphere<double>& sp, int stage) {
  return stage == 1 ? sphere_first<SplitProduct>(x, sp) : sphere_second(x, sp);
}

// (the triangle's and the oriented box's double paths: below)
template <class Mul = SplitProduct, class Shot>
std::optional<double> triangle_double(const Shot& x, const Triangle<double>& tri);
template <class Mul = SplitProduct, class Shot>
std::optional<double> obb_double(const Shot& x, const OrientedBox<double>& b, const std::optional<ObbFace>& face);

// The first double path of a solid, with the products of Mul (an oriented box's: with the
// entering face, where the filter picked it).
template <class Mul, class Shot, class Solid, class... Face>
std::optional<double> first_double(const Shot& x, const Solid& y, const Face&... face) {
  if constexpr (std::is_same_v<Solid, Sphere<double>>)
    return sphere_first<Mul>(x, y);
  else if constexpr (std::is_same_v<Solid, Triangle<double>>)
    return triangle_double<Mul>(x, y);
  else
    return obb_double<Mul>(x, y, face...);
}

// The double path with fused products where the CPU has them (robust::with_products: on x86-64
// a copy compiled for the FMA extension, every call inside it inlined, chosen at run time; a
// build with -mfma or on another architecture: the split copy, or std::fma as the compiler
// provides it). fused_double is that copy alone (the tests compare it with the split one).
using robust::cpu_fma;
// The copy's answer crosses the call as one double, NaN for "cannot tell" (a value is finite):
// returned as std::optional<double>, g++ stored its flag byte and reloaded the pair as one
// word, a store the load could not take forwarded, and that stall was 9% of a hit's time
// (perf annotate, the ray cast's uniform hits, 2026-11-30).
inline double value_or_nan(const std::optional<double>& v) { return v ? *v : std::numeric_limits<double>::quiet_NaN(); }
inline std::optional<double> nan_to_none(double v) {
  if (std::isnan(v)) return std::nullopt;
  return v;
}
template <class Shot, class Solid, class... Face>
std::optional<double> fused_double(const Shot& x, const Solid& y, const Face&... face) {
  return nan_to_none(
      robust::fused_call([&](auto mul) { return value_or_nan(first_double<decltype(mul)>(x, y, face...)); }));
}
template <class Shot, class Solid, class... Face>
std::optional<double> solid_double(const Shot& x, const Solid& y, const Face&... face) {
  return nan_to_none(
      robust::with_products([&](auto mul) { return value_or_nan(first_double<decltype(mul)>(x, y, face...)); }));
}

// The classification's answer, then on a hit the double path (a value, or nothing when it
// cannot tell), then the exact path.
template <class Shot, class Solid, class Path>
Entry entry_of(bool hit, const Shot& x, const Solid& y, bool* exact_used, Path double_path) {
  Entry out;
  if (exact_used) *exact_used = false;
  if (!hit) return out;
  out.hit = true;
  if (const std::optional<double> v = double_path()) {
    out.lambda_enter = *v;
    return out;
  }
  if (exact_used) *exact_used = true;
  out.lambda_enter = exact_enter(x, y);
  return out;
}

// (the inputs checked by the classification: staged::filter_first, after its filter)
template <class Shot>
Entry sphere_enter(const Shot& x, const char* name, const Sphere<double>& sp, bool* exact_used) {
  return entry_of(staged::filter_first(nullptr, x, name, sp, "sphere"), x, sp, exact_used, [&] {
    if (const auto v = solid_double(x, sp)) return v;  // the Newton step
    return sphere_second(x, sp);
  });
}

// The box's double path on a hit (header, "A box"): the value, or nothing when a sign or a
// rounding is uncertain.
template <class Shot>
std::optional<double> box_double(const Shot& x, const Box<double>& box) {
  using std::fabs;
  constexpr double u = 0x1p-53, lo_lim = 0x1p-900, hi_lim = 0x1p900;
  double best = 0.0;
  for (int i = 0; i < 3; ++i) {
    // n = (c_i - source_i) -+ h_i = m + t exactly, t = me + pe rounded once (|t - t^| <= u |t^|)
    const Pair<double> p = robust::two_sum(box.center[i], -x.source[i]);
    const Pair<double> lower = robust::two_sum(p.hi, -box.extent[i]), upper = robust::two_sum(p.hi, box.extent[i]);
    const double tl = lower.lo + p.lo, tu = upper.lo + p.lo;
    // the source's outcode bits: the signs of n (certain when m dominates, or m = 0: then t
    // is exact and its rounding keeps its sign)
    auto sign = [](const Pair<double>& mm, double tt) -> int {
      if (mm.hi == 0) return tt > 0 ? 1 : (tt < 0 ? -1 : 0);
      if (fabs(mm.hi) > 2 * fabs(tt)) return mm.hi > 0 ? 1 : -1;
      return 2;
    };
    const int sl = sign(lower, tl), su = sign(upper, tu);
    if (sl == 2 || su == 2) return std::nullopt;
    const bool below = sl > 0, above = su < 0;
    if (!below && !above) continue;
    const double m = below ? lower.hi : upper.hi, tn = below ? tl : tu;
    // d = dh + dl exactly (a ray: dl = 0)
    Pair<double> d;
    if constexpr (std::is_same_v<Shot, Segment<double>>)
      d = robust::two_sum(x.target[i], -x.source[i]);
    else
      d = {x.direction[i], 0.0};
    if (!(fabs(m) >= lo_lim && fabs(m) <= hi_lim && fabs(d.hi) >= lo_lim && fabs(d.hi) <= hi_lim))
      return std::nullopt;
    // q1 = m / dh; the residual R = n - q1 d: m - P exact (P = fl(q1 dh) is within 2u of m),
    // the small terms summed with three roundings
    const double q1 = m / d.hi;
    const Pair<double> P = robust::two_prod_split(q1, d.hi);
    const double r0 = m - P.hi, qd = q1 * d.lo;
    const double R = ((r0 - P.lo) + tn) - qd;
    const double eR = 4 * u * (((fabs(r0) + fabs(P.lo)) + fabs(tn)) + fabs(qd)) * (1 + 8 * u);
    // z = q1 + R_exact / d: q2 = R / dh off by eR / |d| + 2.1 u |q2| (dl, and q2's rounding)
    const double q2 = R / d.hi;
    const double E = 2 * (eR / (fabs(d.hi) * (1 - u)) + 2.1 * u * fabs(q2)) + under;
    const Pair<double> z = robust::two_sum(q1, q2);
    double v;
    if (!(fabs(q1) >= lo_lim && fabs(q1) <= hi_lim) || !Bounded2::within(z.hi, z.lo, E).try_rounded(v))
      return std::nullopt;
    best = std::max(best, v);
  }
  return best;
}

template <class Shot>
Entry box_enter(const Shot& x, const char* name, const Box<double>& box, bool* exact_used) {
  return entry_of(staged::filter_first(nullptr, x, name, box, "box"), x, box, exact_used,
                  [&] { return box_double(x, box); });
}

// The triangle's double path on a hit (header, "A triangle"): the value, or nothing.
template <class Mul, class Shot>
std::optional<double> triangle_double(const Shot& x, const Triangle<double>& tri) {
  if (!robust::in_certified_range(x, tri)) return std::nullopt;
  const Vec3<double>& v0 = tri.vertex[0];
  Pair<double> e1[3], e2[3], sv[3], d[3];
  shot_pairs(x, v0, sv, d);
  for (int i = 0; i < 3; ++i) {
    e1[i] = robust::two_sum(tri.vertex[1][i], -v0[i]);
    e2[i] = robust::two_sum(tri.vertex[2][i], -v0[i]);
  }
  if (!(std::max({largest(e1), largest(e2), largest(sv), largest(d)}) <= 0x1p250)) return std::nullopt;
  Word n[3];
  cross_words<Mul>(e1, e2, n);
  const double zero[3] = {0, 0, 0};
  return plane_parameter<Mul>(sv, d, n, dot_words<Mul>(sv, zero, n), Word{{0, 0}, 0});
}

// Face i's entry on double words (header, "An oriented box"): n_i = a_{i+1} x a_{i+2}, delta =
// a_i . n_i (the same determinant for every i) turned so that delta > 0, H_i = delta h_i, the
// source's coordinate U_i and its certain outcode, then the plane's parameter; 0 where the
// source lies between the face's two planes (no entry through them), nothing where a sign or
// the rounding is uncertain.
template <class Mul>
std::optional<double> face_entry(const Pair<double> (&sc)[3], const Pair<double> (&d)[3],
                                 const Pair<double> (&a)[3][3], double h, int i) {
  Word n[3];
  cross_words<Mul>(a[(i + 1) % 3], a[(i + 2) % 3], n);
  const double zero[3] = {0, 0, 0};
  Word delta = dot_words<Mul>(a[i], zero, n);
  if (!(magnitude_lo(delta) > 0)) return std::nullopt;
  if (delta.v.hi < 0) {
    delta = negated(delta);
    for (auto& c : n) c = negated(c);
  }
  const Word H = scale_word<Mul>(delta, h);
  const Word U = dot_words<Mul>(sc, zero, n);
  // U + H < 0: outside the lower plane; U - H > 0: outside the upper one (sign_of is never 0)
  const int lower = sign_of(add_words(U, H, 1)), upper = sign_of(add_words(U, H, -1));
  if (lower == staged::unknown || upper == staged::unknown) return std::nullopt;
  if (lower > 0 && upper < 0) return 0.0;
  return plane_parameter<Mul>(sc, d, n, U, lower < 0 ? H : negated(H));
}

// The entering face's parameter alone (filter/obb_face.hpp), rounded; nothing where D's sign or
// the rounding is uncertain.
template <class Mul>
std::optional<double> one_face_entry(const Pair<double> (&sc)[3], const Pair<double> (&d)[3],
                                     const OrientedBox<double>& b, const ObbFace& e) {
  const std::optional<FaceParameter> p = face_parameter<Mul>(sc, d, b, e);
  double v;
  if (!p || !Bounded2::within(p->z.hi, p->z.lo, p->err).try_rounded(v)) return std::nullopt;
  return v;
}

// The oriented box's double path on a hit (header, "An oriented box"): the value, or nothing.
template <class Mul, class Shot>
std::optional<double> obb_double(const Shot& x, const OrientedBox<double>& b, const std::optional<ObbFace>& face) {
  using std::fabs;
  if (face && face->plane < 0) return 0.0;  // the source in the box (the filter's certain outcodes)
  Pair<double> sc[3], d[3], a[3][3];
  shot_pairs(x, b.center, sc, d);
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 3; ++i) a[k][i] = {b.axis[k][i], 0.0};
  if (!in_face_range(sc, d, b)) return std::nullopt;
  // most hits: the entering face picked in double, its parameter alone
  if (face)
    if (const auto v = one_face_entry<Mul>(sc, d, b, *face)) return v;
  // the others: every face, the largest entry (rounding is monotone)
  if (!robust::in_certified_range(x, b)) return std::nullopt;
  double best = 0.0;
  for (int i = 0; i < 3; ++i) {
    const auto v = face_entry<Mul>(sc, d, a, b.extent[i], i);
    if (!v) return std::nullopt;
    best = std::max(best, *v);
  }
  return best;
}

template <class Shot>
Entry triangle_enter(const Shot& x, const Triangle<double>& tri, bool* exact_used) {
  return entry_of(classify_triangle_cast(x, tri, nullptr), x, tri, exact_used, [&] { return solid_double(x, tri); });
}

// The classification's first stage kept (its answer where it decides; sat::run's stages where
// it does not), then on a hit the entering face from its signs.
template <class Shot>
Entry obb_enter(const Shot& x, const OrientedBox<double>& b, int det, bool* exact_used) {
  staged::ObbFilter f = staged::obb_filter(x, b);
  const int r = staged::filter(f);
  const bool hit = r != staged::unknown ? r == 1 : sat::run(nullptr, x, b);
  return entry_of(hit, x, b, exact_used, [&] { return solid_double(x, b, crossed_face(f, det, false)); });
}

}  // namespace enter_detail

// oracle::enter (oracle::Entry: stage.hpp): `exact_used` (optional) says whether the exact path answered. Inputs are checked as the
// book checks them (cdref::invalid_input naming what is wrong).
inline Entry enter(const Segment<double>& seg, const Sphere<double>& sp, bool* exact_used = nullptr) {
  return enter_detail::sphere_enter(seg, "segment", sp, exact_used);
}
inline Entry enter(const Ray<double>& ray, const Sphere<double>& sp, bool* exact_used = nullptr) {
  return enter_detail::sphere_enter(ray, "ray", sp, exact_used);
}
inline Entry enter(const Segment<double>& seg, const Box<double>& box, bool* exact_used = nullptr) {
  return enter_detail::box_enter(seg, "segment", box, exact_used);
}
inline Entry enter(const Ray<double>& ray, const Box<double>& box, bool* exact_used = nullptr) {
  return enter_detail::box_enter(ray, "ray", box, exact_used);
}
inline Entry enter(const Segment<double>& seg, const Triangle<double>& tri, bool* exact_used = nullptr) {
  check(seg, "segment");
  check(tri, "triangle");
  return enter_detail::triangle_enter(seg, tri, exact_used);
}
inline Entry enter(const Ray<double>& ray, const Triangle<double>& tri, bool* exact_used = nullptr) {
  check(ray, "ray");
  check(tri, "triangle");
  return enter_detail::triangle_enter(ray, tri, exact_used);
}
// A shot against a union of triangles (a polygon's fan, a mesh's fan): the book's cast takes the
// smallest lambda_enter over the triangles hit, and rounding is monotone, so the smallest of the
// triangles' correctly rounded values is the union's (each triangle's classification and double
// path as above; exact_used when any triangle took the exact path). `enter_k(k, bool*)` is
// triangle k's Entry, k < count.
template <class EnterK>
Entry enter_first(int count, EnterK enter_k, bool* exact_used = nullptr) {
  Entry out;
  if (exact_used) *exact_used = false;
  for (int k = 0; k < count; ++k) {
    bool e = false;
    const Entry t = enter_k(k, &e);
    if (exact_used) *exact_used = *exact_used || e;
    if (!t.hit) continue;
    if (!out.hit || t.lambda_enter < out.lambda_enter) out.lambda_enter = t.lambda_enter;
    out.hit = true;
  }
  return out;
}
inline Entry enter(const Segment<double>& seg, const Polygon<double>& p, bool* exact_used = nullptr) {
  check(seg, "segment");
  check(p);
  return enter_first(
      p.triangles(), [&](int k, bool* e) { return enter_detail::triangle_enter(seg, p.triangle(k), e); }, exact_used);
}
inline Entry enter(const Ray<double>& ray, const Polygon<double>& p, bool* exact_used = nullptr) {
  check(ray, "ray");
  check(p);
  return enter_first(
      p.triangles(), [&](int k, bool* e) { return enter_detail::triangle_enter(ray, p.triangle(k), e); }, exact_used);
}
inline Entry enter(const Segment<double>& seg, const OrientedBox<double>& b, bool* exact_used = nullptr) {
  check(seg, "segment");
  const int det = checked_orientation(b, "oriented box");
  return enter_detail::obb_enter(seg, b, det, exact_used);
}
inline Entry enter(const Ray<double>& ray, const OrientedBox<double>& b, bool* exact_used = nullptr) {
  check(ray, "ray");
  const int det = checked_orientation(b, "oriented box");
  return enter_detail::obb_enter(ray, b, det, exact_used);
}

}  // namespace cdref::oracle
