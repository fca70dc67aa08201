// cdref/robust/ray_sphere.hpp - ray casts on a sphere that keep their accuracy where
// Algorithm 3.1 loses it, for F = float, double, long double. Same signatures and results
// as cdref::book (hit, cast for a segment and for an infinite ray).
//
// Formulation (s the source relative to the centre, r the direction, a = r.r, b = s.r,
// c = s.s - rho^2, lambda_{1,2} the roots of a l^2 + 2 b l + c = 0):
//  1. Scale. s, r and rho are multiplied by one power of two 2^-e, e the exponent of the
//     largest of them: exact (barring underflow of components 2^1000 times smaller than the
//     largest), lambda is unchanged, and no square or product can overflow or underflow
//     to zero any more (the 1e160 and 1e-160 cases).
//  2. The discriminant from the distance of the centre to the line. With l = s - (b/a) r,
//     the foot of the perpendicular, b^2 - a c = a (rho^2 - |l|^2): the book's sigma
//     cancels (s.r)^2 against |r|^2 |s|^2, both of size |s|^2 |r|^2, while |l| is of the
//     size of the miss distance, so rho^2 - |l|^2 has an absolute error of order
//     u (|l| |s| + rho^2) instead of u |s|^2 (Haines et al., "Precision improvements for
//     ray/sphere intersection", Ray Tracing Gems, 2019). rho^2 - |l|^2 is evaluated with
//     dot2 (eft.hpp), so the only error left is that of l itself, each component
//     l_i = fma(-b/a, r_i, s_i).
//  3. c = |s|^2 - rho^2 with dot2: exact to about an ulp even when the source is on the
//     sphere.
//  4. The stable quadratic: q = -(b + sign(b) sqrt(a D)), D = rho^2 - |l|^2; the roots are
//     q / a and c / q, neither computed by subtracting nearly equal numbers.
//  5. The entry point s + lambda r with one fma per coordinate, then the centre added back.
// The decision (hit or miss) is D >= 0 with the same range conditions as the book. Where
// the book's sigma is wrong by u |s|^2 |r|^2, this one is wrong by about u |l| |s| |r|^2:
// at long range, aimed at the sphere, that is |s| / rho times smaller.
//
// Certificates (decide(), decision.hpp). Every decisive sign is taken from a value q^ with
// a computed bound E, |q^ - q| <= E, and is certain iff |q^| > E. For dot2 over N terms
// (eft.hpp) with S = sum |x_i y_i|: |q^ - q| <= u|q| + gamma_N^2 S, hence (solving for |q|)
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
// decide(Segment or Ray, Sphere): the cast's classification (value == hit()) and whether
// the book's exact answer is certainly the same. The book decides (Algorithm 3.1 at an exact
// type, a = |r|^2, b = s.r, c = |s|^2 - rho^2, sigma = b^2 - a c = a D):
//   hit <=> D >= 0 and (b <= 0 or c <= 0) [lambda_2 >= 0] and, for a segment,
//           (a + b >= 0 or a + 2b + c <= 0) [lambda_1 <= 1];  a = 0: hit <=> c <= 0.
// Each of D, b, c, a + b, a + 2b + c is known from the formulation's computed value within a
// bound, in the scaled units (max |s_i|, |r_i|, rho in [1,2)), with ns, nr upper bounds of
// |s|, |r| (1-norms, inflated) and rmin = max |r_i| <= |r|:
//   - the inputs: s = fl(source - c) is off by at most u|s|, r = fl(fl(t - c) - s) by at most
//     u(|s| + |t| + |r|) <= 2u(|s| + |r|) (0 for a ray): dS, dR. Then |b - b*| <= dS nr +
//     ns dR + dS dR, |a - a*| <= 2 nr dR + dR^2, |c - c*| <= 2 ns dS + dS^2, and the distance
//     d of the centre to the line moves by at most E_in = dS + (ns + dS) dR / (rmin - dR)
//     (d(p, r*) <= |p - lambda r*| <= d(p, r) + |lambda| |dR| at the foot lambda of r, with
//     |lambda| <= |p| / |r|), so |d^2 - d*^2| <= E_in (2 nl + E_in), nl >= |l|;
//   - the arithmetic: a, b, c by dot2_cert; f = b/a is within df = 3.1 u ns/rmin of b/a
//     (b and a each within ~u ns nr and u a, one division), and the point s - f r of the line
//     lies a (f - b/a)^2 <= (nr df)^2 farther (squared) from the centre than the foot; the
//     fma rounding of l costs (2u + u^2)|l|^2; dot2_cert bounds D's last step.
// All these are added and doubled (covering the rounding of the bound). A sign is known
// where the value is farther from 0 than its bound; the truth is known when the known signs
// decide the formula above, and certain = known and equal to the computed value.
// (Scaling: s, r, rho are scaled exactly unless a component falls 2^(emin) below the
// largest; an absolute 16 eta per input covers that.)
#pragma once

#include <algorithm>
#include <cdref/primitives.hpp>
#include <cdref/results.hpp>
#include <cmath>

#include <limits>

#include "decision.hpp"
#include "eft.hpp"

namespace cdref::robust {

namespace detail {

template <class F>
struct Local {
  F s[3], r[3], rho;
  int scale;  // inputs were multiplied by 2^-scale
};

template <class F>
Local<F> scaled(const Vec3<F>& s, const Vec3<F>& r, F rho) {
  F m = rho;
  for (int i = 0; i < 3; ++i) m = std::max({m, std::fabs(s[i]), std::fabs(r[i])});
  Local<F> L{};
  L.scale = m > F(0) ? std::ilogb(m) : 0;
  for (int i = 0; i < 3; ++i) {
    L.s[i] = std::ldexp(s[i], -L.scale);
    L.r[i] = std::ldexp(r[i], -L.scale);
  }
  L.rho = std::ldexp(rho, -L.scale);
  return L;
}

template <class F>
struct Roots {
  bool line_hits = false;
  F lambda1 = 0, lambda2 = 0;
};

// The roots of a l^2 + 2 b l + c, a > 0, from the scaled inputs.
template <class F>
Roots<F> roots(const Local<F>& L) {
  const F a = dot2(L.r, L.r);
  const F b = dot2(L.s, L.r);
  const F c = dot2({L.s[0], L.s[1], L.s[2], L.rho}, {L.s[0], L.s[1], L.s[2], F(-L.rho)});
  const F f = b / a;
  const F l[3] = {std::fma(-f, L.r[0], L.s[0]), std::fma(-f, L.r[1], L.s[1]), std::fma(-f, L.r[2], L.s[2])};
  const F D = dot2({L.rho, l[0], l[1], l[2]}, {L.rho, F(-l[0]), F(-l[1]), F(-l[2])});  // rho^2 - |l|^2
  Roots<F> out;
  if (!(D >= F(0))) return out;
  out.line_hits = true;
  const F q = -(b + std::copysign(std::sqrt(a) * std::sqrt(D), b));
  if (q == F(0)) {  // b = 0 and D = 0: tangent at lambda = 0
    out.lambda1 = out.lambda2 = F(0);
    return out;
  }
  const F x1 = q / a, x2 = c / q;
  out.lambda1 = std::min(x1, x2);
  out.lambda2 = std::max(x1, x2);
  return out;
}

template <class F>
Cast<F> cast_local(const Vec3<F>& s, const Vec3<F>& r, const Sphere<F>& sp, bool bounded, unsigned w) {
  Cast<F> res;
  const Local<F> L = scaled(s, r, sp.radius);
  const bool zero = L.r[0] == F(0) && L.r[1] == F(0) && L.r[2] == F(0);
  if (zero) {  // a zero-length segment: a point test, as in the book
    const F c = dot2({L.s[0], L.s[1], L.s[2], L.rho}, {L.s[0], L.s[1], L.s[2], F(-L.rho)});
    res.hit = c <= F(0);
    if (res.hit && (w & want_lambda_exit)) res.lambda_exit = F(1);
    if (res.hit && (w & want_point)) res.point = Vec3<F>(s + sp.center);
    return res;
  }
  const Roots<F> R = roots(L);
  if (!R.line_hits || (bounded && !(R.lambda1 <= F(1))) || !(R.lambda2 >= F(0))) return res;
  res.hit = true;
  res.enters = R.lambda1 >= F(0);
  res.lambda_enter = res.enters ? R.lambda1 : F(0);
  if (w & want_lambda_exit) res.lambda_exit = bounded ? std::min(R.lambda2, F(1)) : R.lambda2;
  if (w & (want_point | want_normal)) {
    F x[3];
    for (int i = 0; i < 3; ++i) x[i] = std::fma(res.lambda_enter, L.r[i], L.s[i]);  // scaled, local
    if (w & want_point)
      for (int i = 0; i < 3; ++i) res.point[i] = std::ldexp(x[i], L.scale) + sp.center[i];
    if ((w & want_normal) && res.enters && L.rho != F(0))
      for (int i = 0; i < 3; ++i) res.normal[i] = x[i] / L.rho;
  }
  return res;
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
  const F eta = std::numeric_limits<F>::denorm_min();
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
  return std::max(0, std::ilogb(m) - (std::numeric_limits<F>::max_exponent - 4));
}

// x 2^-e, flagging in `exact` a result that lost bits in the subnormal range.
template <class F>
F scale_down(F x, int e, bool& exact) {
  if (e == 0) return x;
  const F y = std::ldexp(x, -e);
  if (std::ldexp(y, e) != x) exact = false;
  return y;
}

template <class F>
Decision decide_cast(const Vec3<F>& s, const Vec3<F>& r, const Sphere<F>& sp, bool bounded, bool zero_exact) {
  Decision out;
  out.value = cast_local(s, r, sp, bounded, 0).hit;
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(s[i]) || !std::isfinite(r[i])) return out;  // fl(source - c) overflowed
  const Local<F> L = scaled(s, r, sp.radius);
  const F u = unit_roundoff<F>();
  const F eta = std::numeric_limits<F>::denorm_min();
  const bool zero = L.r[0] == F(0) && L.r[1] == F(0) && L.r[2] == F(0);
  F ns = 0, nr = 0, rmin = 0;
  for (int i = 0; i < 3; ++i) {
    ns += std::fabs(L.s[i]);
    nr += std::fabs(L.r[i]);
    rmin = std::max(rmin, std::fabs(L.r[i]));
  }
  ns = ns * F(1 + 4 * u) + F(16) * eta;
  nr = nr * F(1 + 4 * u) + F(16) * eta;
  const F dS = F(1.01) * u * ns + F(16) * eta;
  const F dR = bounded ? F(2.02) * u * (ns + nr) + F(16) * eta : F(0);
  const Bounded<F> c0 = dot2_cert({L.s[0], L.s[1], L.s[2], L.rho}, {L.s[0], L.s[1], L.s[2], F(-L.rho)});
  const Bounded<F> c{c0.value, F(2) * (c0.err + F(2) * ns * dS + dS * dS)};
  if (zero) {
    if (!zero_exact) return out;  // r rounded to 0 but the exact r is not
    const Tri t = le0(c);
    out.certain = t != Tri::unknown && (t == Tri::yes) == out.value;
    return out;
  }
  if (!(rmin > F(2) * dR)) return out;  // the direction itself is not known well enough
  const Bounded<F> a0 = dot2_cert(L.r, L.r);
  const Bounded<F> b0 = dot2_cert(L.s, L.r);
  const Bounded<F> a{a0.value, F(2) * (a0.err + F(2) * nr * dR + dR * dR)};
  const Bounded<F> b{b0.value, F(2) * (b0.err + dS * nr + ns * dR + dS * dR)};
  // D exactly as roots() computes it
  const F f = b.value / a.value;
  const F l[3] = {std::fma(-f, L.r[0], L.s[0]), std::fma(-f, L.r[1], L.s[1]), std::fma(-f, L.r[2], L.s[2])};
  const Bounded<F> D0 = dot2_cert({L.rho, l[0], l[1], l[2]}, {L.rho, F(-l[0]), F(-l[1]), F(-l[2])});
  const F df = F(3.1) * u * ns / rmin;
  F nl = 0, ll = 0;
  for (int i = 0; i < 3; ++i) {
    nl += std::fabs(l[i]);
    ll += l[i] * l[i];
  }
  nl = nl * F(1 + 4 * u) + nr * df;
  const F e_in = dS + (ns + dS) * dR / (rmin - dR);
  const F e_D = D0.err + F(2.01) * u * ll + (nr * df) * (nr * df) + e_in * (F(2) * nl + e_in) + F(16) * eta;
  const Bounded<F> D{D0.value, F(2) * e_D};
  Tri truth = ge0(D);
  truth = tri_and(truth, tri_or(le0(b), le0(c)));
  if (bounded) {
    const F ab = a.value + b.value;
    const F abc = a.value + F(2) * b.value + c.value;
    const Bounded<F> AB{ab, F(2) * (a.err + b.err + u * std::fabs(ab))};
    const Bounded<F> ABC{abc, F(2) * (a.err + F(2) * b.err + c.err +
                                      F(2) * u * (a.value + F(2) * std::fabs(b.value) + std::fabs(c.value)))};
    truth = tri_and(truth, tri_or(ge0(AB), le0(ABC)));
  }
  out.certain = truth != Tri::unknown && (truth == Tri::yes) == out.value;
  return out;
}

}  // namespace detail

template <class F>
Cast<F> cast(const Segment<F>& seg, const Sphere<F>& sp, unsigned w = want_cast) {
  check(seg, "segment");
  check(sp, "sphere");
  const Vec3<F> s = seg.source - sp.center;
  const Vec3<F> t = seg.target - sp.center;
  return detail::cast_local(s, Vec3<F>(t - s), sp, true, w);
}

template <class F>
Cast<F> cast(const Ray<F>& ray, const Sphere<F>& sp, unsigned w = want_cast) {
  check(ray, "ray");
  check(sp, "sphere");
  return detail::cast_local(Vec3<F>(ray.source - sp.center), ray.direction, sp, false, w);
}

// The decision alone: the same computation as cast() (the range tests need the roots),
// with none of the outputs assembled.
template <class F>
bool hit(const Segment<F>& seg, const Sphere<F>& sp) {
  return cast(seg, sp, 0).hit;
}

template <class F>
bool hit(const Ray<F>& ray, const Sphere<F>& sp) {
  return cast(ray, sp, 0).hit;
}

// The cast's classification with its certificate (decision.hpp; bound in the header).
template <class F>
Decision decide(const Segment<F>& seg, const Sphere<F>& sp) {
  check(seg, "segment");
  check(sp, "sphere");
  const Vec3<F> s = seg.source - sp.center;
  const Vec3<F> t = seg.target - sp.center;
  return detail::decide_cast(s, Vec3<F>(t - s), sp, true, seg.source == seg.target);
}

template <class F>
Decision decide(const Ray<F>& ray, const Sphere<F>& sp) {
  check(ray, "ray");
  check(sp, "sphere");
  return detail::decide_cast(Vec3<F>(ray.source - sp.center), ray.direction, sp, false, false);
}

}  // namespace cdref::robust
