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
#pragma once

#include <algorithm>
#include <cdref/primitives.hpp>
#include <cdref/results.hpp>
#include <cmath>

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

}  // namespace cdref::robust
