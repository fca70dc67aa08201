// cdref/oracle/enter_sphere.hpp - oracle::enter on a sphere (Algorithm 3.1): a segment's or a
// ray's lambda_enter correctly rounded to double (what every cast shares, and the exact path:
// enter.hpp).
//
// ---- A sphere, first: one Newton step from the stable root, certified a posteriori ---------
// s = source - centre and r (target - source, or the direction) as exact two_sum pairs, u =
// 2^-53, eta = 2^-1074 (the smallest subnormal; the code adds multiples of 2^-1022 instead,
// `under`: a larger bound, and a normal constant). P(z) = |s + z r|^2 - rho^2 = a z^2 + 2 b z
// + c (a = |r|^2, b = s.r, c = |s|^2 - rho^2). On a hit lambda_enter = 0 when c <= 0 (source in or on the sphere);
// otherwise b < 0 (b >= 0 and c > 0 puts both roots behind the source) and lambda_enter = z*,
// the smaller root, where P falls through 0.
//  1. c's sign from c^ = fl(|sh|^2) - rho^2 with |c^ - c| <= 8u (|sh|^2 + rho^2) (the
//     filter's bound, sphere_casts.hpp; exact s = sh + sl, |sl| <= u |sh|). Not decided: the
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
#pragma once

#include <cdref/oracle/sphere_casts.hpp>
#include <cdref/oracle/enter.hpp>
#include <cdref/robust/ray_sphere.hpp>

namespace cdref::oracle {

namespace enter_detail {

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
  const Pair<double> z = eft::two_sum(z0, delta);
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
  const Pair<double> X = eft::sqrt_pair(eft::mul_pair(Q.a, Q.D));
  const Pair<double> qs = eft::two_sum(-Q.b.hi, X.hi);
  const Pair<double> q = eft::fast_two_sum(qs.hi, qs.lo + (X.lo - Q.b.lo));
  const Pair<double> z = eft::div_pair(A.c, q);
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
  const Pair<double> zn = eft::fast_two_sum(z.hi, z.lo);
  const double bound = 2 * 1.35 * rel_z * fabs(zn.hi) + E;  // |z| <= 1.35 |zn.hi|; x 2: the bound's own rounding
  if (!std::isfinite(bound) || !(fabs(zn.hi) >= 0x1p-960)) return 2;
  out = Bounded2::within(zn.hi, zn.lo, bound);
  return 1;
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

// (the inputs checked by the classification: staged::filter_first, after its filter)
template <class Shot>
Entry sphere_enter(const Shot& x, const char* name, const Sphere<double>& sp, bool* exact_used) {
  return entry_of(staged::filter_first(nullptr, x, name, sp, "sphere"), x, sp, exact_used, [&] {
    if (const auto v = solid_double(x, sp)) return v;  // the Newton step
    return sphere_second(x, sp);
  });
}

}  // namespace enter_detail

// A segment or a ray against a sphere.
inline Entry enter(const Segment<double>& seg, const Sphere<double>& sp, bool* exact_used = nullptr) {
  return enter_detail::sphere_enter(seg, "segment", sp, exact_used);
}
inline Entry enter(const Ray<double>& ray, const Sphere<double>& sp, bool* exact_used = nullptr) {
  return enter_detail::sphere_enter(ray, "ray", sp, exact_used);
}

}  // namespace cdref::oracle
