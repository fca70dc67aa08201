// cdref/stable/ray_sphere.hpp - ray and segment casts on a sphere as careful float code
// writes them (Haines, Guenther and Akenine-Moeller, "Precision improvements for ray/sphere
// intersection", Ray Tracing Gems, 2019, ch. 7; the stable quadratic of Jolt's FindRoot):
// plain F arithmetic (float, double, long double), no extra precision, no certificate. Same
// signatures and results as cdref::book (hit, cast; a segment s->t or a ray s + lambda d).
//
// Formulation (f = source - centre, r the direction (t - s for a segment), a = r.r,
// b = f.r, c = f.f - rho^2; the roots lambda_1 <= lambda_2 of a l^2 + 2 b l + c = 0):
//  1. The foot of the perpendicular from the centre to the line: tc = -b / a and
//     l = f + tc r, the line's closest point relative to the centre. The discriminant is
//     b^2 - a c = a D with D = rho^2 - l.l. The book's sigma = (s.r)^2 - |r|^2 (|s|^2 - rho^2)
//     subtracts numbers of size |s|^2 |r|^2 to get one of size rho^2 |r|^2; l is of the size
//     of the miss distance and D is computed from it.
//  2. The line misses iff D < 0. Otherwise the ray (segment) decides as the book's hit()
//     does, without a root: the exit lies ahead (lambda_2 >= 0) iff b <= 0 or c <= 0, and
//     for a segment the entry is not past the end (lambda_1 <= 1) iff b + a >= 0 or
//     |f + r|^2 <= rho^2.
//  3. The roots, stable: q = -(b + sign(b) sqrt(a D)) adds two terms of one sign, and the
//     roots are c / q and q / a (q = 0 only when b = 0 and D = 0: the source is the point of
//     tangency, both roots 0).
//  4. lambda_enter = max(lambda_1, 0) (0 when the source is inside); for a segment
//     lambda_exit = min(lambda_2, 1). The entry point is source + lambda_enter r and the
//     normal (f + lambda_enter r) / rho, as the book computes them.
// A zero-length segment (a = 0) is the point test c <= 0 (lambda_enter 0, lambda_exit 1).
// Range: a, b, c and D are sums of squares and products, and a D a product of two: inputs past
// about 10^150 overflow them (the campaign's magnitude family at 10^150 and beyond gets
// non-finite outputs: 297 of 58,000 ray casts in the default campaign, the book 30) and
// inputs below about 10^-150 underflow. Careful float code lives within those bounds; the
// robust tier scales every query by a power of two first.
//
// Error bound of the classification (first order in u, the unit roundoff of F; f taken as
// computed, that is the source moved by at most u |f|, as every tier does). With
// gamma_n = n u: b^ = b + e_b, |e_b| <= 3u |f||r|; a^ relative 3u; tc^ = tc + e_t with
// |e_t| <= (3u |f||r| + 5u |b|) / a <= 8u |f| / |r| (|b| <= |f||r|); each l^_i =
// (f_i + tc^ r_i (1 + d1))(1 + d2), so |l^ - l| <= |e_t||r| + u |tc||r| + u |l| <= 9u |f| +
// u |l| (|tc||r| <= |f|); D^ = rho^2 - l^.l^ rounded four more times:
//     |D^ - D| <= 2 |l| (9u |f| + u |l|) + 4u (rho^2 + |l|^2),
// so near the boundary (|l| ~ rho) D's sign is right whenever |D| > u (18 |f| rho + 10 rho^2),
// i.e. unless the line passes within about u (9 |f| + 5 rho) of tangency. Against the exact
// inputs add the roundings of f = source - centre (u |f| to l) and, for a segment, of
// r = target - source (a turn of the direction by u: 3u |f|): 10u |f| + u |l| and 13u |f| +
// u |l| in place of 9u |f| + u |l|. The book's sigma is
// off by about 4u |f|^2 |r|^2, i.e. D by 4u |f|^2: its band is about 2u |f|^2 / rho wide.
// At |f| = 10^8 rho in double that is 10^-7 rho against the book's 2 rho (every shot near
// the sphere a coin toss); at 10^12 rho it is 10^-3 rho. The range conditions: the sign of b
// is right unless |b| <= 5u |f||r| (the line nearly perpendicular to f: the foot is within
// 5u |f| of the source; input roundings included), c's unless |c| <= 6u (|f|^2 + rho^2) (the
// source on the sphere to within about 3u |f|); for a segment likewise t = f + r against the
// sphere and the sign of b + a = t.r. tests/test_robust_spheres.cpp ("[stable]") checks that
// every misclassified generated case lies in one of these bands, measured exactly.
// Measured: `cdref campaign --impl stable-double` (and `cdref report`).
//
// Outputs: lambda_enter = c / q has relative error about u (3 + |e_D| / (2 D)) (c and q
// from sums of one sign, and sqrt(aD) with D's error above): a few ulps except near
// tangency, where the problem itself amplifies an ulp of input by rho / sqrt(D). The point
// source + lambda r carries lambda's relative error times |lambda r| plus one rounding: at
// range (|lambda r| ~ |f| >> rho) that is a few ulps of |f|, many ulps of the point's
// coordinates near the sphere; the robust tier removes it.
#pragma once

#include <cdref/book/common.hpp>
#include <cmath>

namespace cdref::stable {

namespace detail {

template <class F>
struct Foot {
  F a, b, c, D;
};
// a, b, c and D (step 1) for f (source relative to the centre), r and rho.
template <class F>
Foot<F> foot(const Vec3<F>& f, const Vec3<F>& r, const F& rho) {
  Foot<F> k;
  k.a = r.squaredNorm();
  k.b = f.dot(r);
  k.c = f.squaredNorm() - rho * rho;
  if (k.a == F(0)) {
    k.D = F(0);
    return k;
  }
  const F tc = -k.b / k.a;
  const Vec3<F> l = f + tc * r;
  k.D = rho * rho - l.squaredNorm();
  return k;
}

// Step 2: the classification from the foot.
template <class F>
bool hit_local(const Foot<F>& k, const Vec3<F>& f, const Vec3<F>& r, const F& rho, bool bounded) {
  if (k.a == F(0)) return k.c <= F(0);
  if (!(k.D >= F(0))) return false;
  const bool exit_ahead = k.b <= F(0) || k.c <= F(0);
  if (!bounded) return exit_ahead;
  return exit_ahead && (k.b + k.a >= F(0) || Vec3<F>(f + r).squaredNorm() <= rho * rho);
}

template <class F>
Cast<F> cast_local(const Vec3<F>& f, const Vec3<F>& r, const Sphere<F>& sp, bool bounded, unsigned w) {
  Cast<F> res;
  const F& rho = sp.radius;
  const Foot<F> k = foot(f, r, rho);
  res.hit = hit_local(k, f, r, rho, bounded);
  if (!res.hit) return res;
  if (k.a == F(0)) {  // a zero-length segment inside: a point
    if (w & want_lambda_exit) res.lambda_exit = F(1);
    if (w & want_point) res.point = Vec3<F>(f + sp.center);
    return res;
  }
  // step 3: q = -(b + sign(b) sqrt(a D)), roots c / q and q / a
  const F root = std::sqrt(k.a * k.D);
  const F q = k.b < F(0) ? F(root - k.b) : F(-(k.b + root));
  F l1 = F(0), l2 = F(0);
  if (q != F(0)) {
    const F x = k.c / q, y = q / k.a;
    l1 = x < y ? x : y;
    l2 = x < y ? y : x;
  }
  res.enters = l1 >= F(0);
  res.lambda_enter = res.enters ? l1 : F(0);
  if (bounded && res.lambda_enter > F(1)) res.lambda_enter = F(1);  // rounding past the end
  if (w & want_lambda_exit) {
    const F e = bounded && l2 > F(1) ? F(1) : l2;
    res.lambda_exit = e < res.lambda_enter ? res.lambda_enter : e;
  }
  if (w & (want_point | want_normal)) {
    const Vec3<F> x = f + res.lambda_enter * r;
    if (w & want_point) res.point = Vec3<F>(x + sp.center);
    if ((w & want_normal) && res.enters && rho != F(0)) res.normal = x / rho;
  }
  return res;
}

}  // namespace detail

// The classification without the input checks (see book/common.hpp).
namespace unchecked {
template <class F>
bool hit(const Segment<F>& seg, const Sphere<F>& sp) {
  const Vec3<F> f = seg.source - sp.center;
  const Vec3<F> r = seg.target - seg.source;
  return detail::hit_local(detail::foot(f, r, sp.radius), f, r, sp.radius, true);
}
template <class F>
bool hit(const Ray<F>& ray, const Sphere<F>& sp) {
  const Vec3<F> f = ray.source - sp.center;
  return detail::hit_local(detail::foot(f, ray.direction, sp.radius), f, ray.direction, sp.radius, false);
}
}  // namespace unchecked

template <class F>
bool hit(const Segment<F>& seg, const Sphere<F>& sp) {
  check(seg, "segment");
  check(sp, "sphere");
  return unchecked::hit(seg, sp);
}
template <class F>
bool hit(const Ray<F>& ray, const Sphere<F>& sp) {
  check(ray, "ray");
  check(sp, "sphere");
  return unchecked::hit(ray, sp);
}
template <class F>
Cast<F> cast(const Segment<F>& seg, const Sphere<F>& sp, unsigned w = want_cast) {
  check(seg, "segment");
  check(sp, "sphere");
  return detail::cast_local(Vec3<F>(seg.source - sp.center), Vec3<F>(seg.target - seg.source), sp, true, w);
}
template <class F>
Cast<F> cast(const Ray<F>& ray, const Sphere<F>& sp, unsigned w = want_cast) {
  check(ray, "ray");
  check(sp, "sphere");
  return detail::cast_local(Vec3<F>(ray.source - sp.center), ray.direction, sp, false, w);
}

}  // namespace cdref::stable
