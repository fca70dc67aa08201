/// \file
/// cdref/book/ray_sphere.hpp - Section 3.1.2, Algorithm 3.1: ray casts on a sphere.
///
/// In the sphere's local coordinates (centre at the origin), with r the direction:
///   sigma = (s.r)^2 - |r|^2 (|s|^2 - rho^2),
///   lambda_{1,2} = (-s.r -+ sqrt(sigma)) / |r|^2.
/// The line meets the sphere iff sigma >= 0; the segment s->t (lambda in [0,1]) iff
/// moreover lambda_1 <= 1 and lambda_2 >= 0; the infinite ray (lambda >= 0) iff
/// lambda_2 >= 0. Then lambda_enter = max(lambda_1, 0), lambda_exit = min(lambda_2, 1)
/// (just lambda_2 for the infinite ray), and x = s + lambda_enter r.
///
/// cast() follows the listing verbatim; it divides by |r|^2 for lambda_exit only when
/// lambda_exit is asked for, as the chapter suggests. The normal is x / rho, the unit
/// outward normal.
///
/// hit() decides the same thing with no square root and no division. Given sigma >= 0
/// and |r|^2 > 0 (derivation: move the root to one side and square where both sides are
/// nonnegative):
///   lambda_2 >= 0  <=>  s.r <= 0  or  |s|^2 <= rho^2   (s is in the sphere),
///   lambda_1 <= 1  <=>  s.r + |r|^2 >= 0  or  |t|^2 <= rho^2   (t is in the sphere).
/// The test sigma >= 0 is kept as the chapter writes it: that is where the float
/// version loses its digits at long range, since (s.r)^2 ~ |r|^2 |s|^2 there.
///
/// Boundary cases, as the chapter's closed intervals give them:
///   - source strictly inside (lambda_1 < 0 < lambda_2): hit, lambda_enter = 0,
///     enters = false, point = source, normal = 0;
///   - source on the sphere, pointing inward or tangent: lambda_1 = 0, enters = true,
///     point = source, normal = source / rho;
///   - source on the sphere, pointing outward: lambda_2 = 0, a touching hit with
///     lambda_enter = lambda_exit = 0 and enters = false;
///   - tangent line: lambda_1 = lambda_2, a touching hit when it lies in range;
///   - zero-length segment (s = t, where the listing would divide by 0): a point test,
///     hit iff |s| <= rho; then every lambda in [0,1] gives that point, so
///     lambda_enter = 0, lambda_exit = 1 (as Algorithm 3.3 gives for a box), enters = false;
///   - rho = 0: the sphere is a point; the normal is left at 0.
#pragma once

#include "common.hpp"

namespace cdref::book {

namespace detail {

/// s: source in local coordinates; r: direction (t - s for a segment); bounded: lambda <= 1.
template <class T>
bool hit_sphere_local(const Vec3<T>& s, const Vec3<T>& r, const T& rho, bool bounded) {
  const T rr = r.squaredNorm();
  const T ss = s.squaredNorm();
  const T rho2 = rho * rho;
  if (rr == T(0)) return ss <= rho2;
  const T sr = s.dot(r);
  const T sigma = sr * sr - rr * (ss - rho2);
  if (!(sigma >= T(0))) return false;
  const bool exit_ahead = sr <= T(0) || ss <= rho2;  // lambda_2 >= 0
  if (!bounded) return exit_ahead;
  const Vec3<T> t = s + r;
  return exit_ahead && (sr + rr >= T(0) || t.squaredNorm() <= rho2);  // lambda_1 <= 1
}

/// The chapter's formulation of sigma and of the entry point x = s + lambda_1 r. The cast below
/// takes it as a parameter: the every-output oracle runs the same cast with the perpendicular
/// foot's formulation (exact/cdref/oracle/sphere_cast_foot.hpp), equal to this one at exact types.
struct ChapterForm {
  template <class T>
  static T sigma(const Vec3<T>& s, const Vec3<T>& /*r*/, const T& rr, const T& sr, const T& rho2) {
    return sr * sr - rr * (s.squaredNorm() - rho2);
  }
  template <class S, class T>
  static Vec3<S> entry(const Vec3<T>& s, const Vec3<T>& r, const T& /*rr*/, const S& /*root_sigma*/,
                       const S& lambda1) {
    return affine(s, lambda1, r);
  }
};

template <class T, class Form = ChapterForm>
Cast<sqrt_t<T>> cast_sphere_local(const Vec3<T>& s, const Vec3<T>& r, const Sphere<T>& sp, bool bounded,
                                  unsigned w) {
  using S = sqrt_t<T>;
  Cast<S> res;
  const T& rho = sp.radius;
  const T rr = r.squaredNorm();
  const T rho2 = rho * rho;
  if (rr == T(0)) {  // a zero-length segment: a point
    res.hit = s.squaredNorm() <= rho2;
    if (res.hit && (w & want_lambda_exit)) res.lambda_exit = S(1);
    if (res.hit && (w & want_point)) res.point = lift<S>(Vec3<T>(s + sp.center));
    return res;
  }
  const T sr = s.dot(r);
  const T sigma = Form::sigma(s, r, rr, sr, rho2);
  if (!(sigma >= T(0))) return res;
  const S root_sigma = root(sigma);
  const S lambda1 = (S(-sr) - root_sigma) / S(rr);
  const S num2 = S(-sr) + root_sigma;  // lambda_2 * |r|^2
  if (bounded && !(lambda1 <= S(1))) return res;
  if (!(num2 >= S(0))) return res;
  res.hit = true;
  res.enters = lambda1 >= S(0);
  res.lambda_enter = res.enters ? lambda1 : S(0);
  if (w & want_lambda_exit) {
    const S lambda2 = num2 / S(rr);
    res.lambda_exit = bounded ? min_of(lambda2, S(1)) : lambda2;
  }
  if (w & (want_point | want_normal)) {
    // entering at 0 (the source inside): x = s + 0 r = s
    const Vec3<S> x = res.enters ? Form::entry(s, r, rr, root_sigma, lambda1) : lift<S>(s);
    if (w & want_point) res.point = Vec3<S>(x + lift<S>(sp.center));
    if ((w & want_normal) && res.enters && rho != T(0)) res.normal = x / S(rho);
  }
  return res;
}

}  // namespace detail

namespace unchecked {
/// Algorithm 3.1 for the segment s->t: does it meet the sphere? No root, no division.
template <class T>
bool hit(const Segment<T>& seg, const Sphere<T>& sp) {
  const Vec3<T> s = seg.source - sp.center;
  const Vec3<T> t = seg.target - sp.center;
  return detail::hit_sphere_local(s, Vec3<T>(t - s), sp.radius, true);
}
/// Algorithm 3.1 for the infinite ray: does it meet the sphere? No root, no division.
template <class T>
bool hit(const Ray<T>& ray, const Sphere<T>& sp) {
  return detail::hit_sphere_local(Vec3<T>(ray.source - sp.center), ray.direction, sp.radius, false);
}
}  // namespace unchecked

/// Whether the segment meets the closed sphere: the cast's classification alone. Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
bool hit(const Segment<T>& seg, const Sphere<T>& sp) {
  check(seg, "segment");
  check(sp, "sphere");
  return unchecked::hit(seg, sp);
}
/// Whether the ray meets the closed sphere: the cast's classification alone. Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
bool hit(const Ray<T>& ray, const Sphere<T>& sp) {
  check(ray, "ray");
  check(sp, "sphere");
  return unchecked::hit(ray, sp);
}

/// Algorithm 3.1 for the segment s->t, with the quantities asked for in w.
template <class T>
Cast<sqrt_t<T>> cast(const Segment<T>& seg, const Sphere<T>& sp, unsigned w = want_cast) {
  check(seg, "segment");
  check(sp, "sphere");
  const Vec3<T> s = seg.source - sp.center;
  const Vec3<T> t = seg.target - sp.center;
  return detail::cast_sphere_local(s, Vec3<T>(t - s), sp, true, w);
}

/// Algorithm 3.1 for the infinite ray s + lambda d, lambda >= 0.
template <class T>
Cast<sqrt_t<T>> cast(const Ray<T>& ray, const Sphere<T>& sp, unsigned w = want_cast) {
  check(ray, "ray");
  check(sp, "sphere");
  return detail::cast_sphere_local(Vec3<T>(ray.source - sp.center), ray.direction, sp, false, w);
}

}  // namespace cdref::book
