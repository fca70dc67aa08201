/// \file
/// cdref/book/segment_sphere.hpp - Section 3.1.3, Algorithm 3.2: segment-sphere.
///
/// In the sphere's local coordinates, with r = t - s and delta = -s.r, the point x of the
/// segment closest to the centre is s if delta <= 0, t if delta >= |r|^2, and otherwise
/// s + (delta / |r|^2) r. The segment meets the sphere iff |x|^2 <= rho^2.
///   distance max(|x| - rho, 0), depth max(rho - |x|, 0),
///   witness on the segment x, witness on the sphere rho x / |x|.
/// When x = 0 (the segment passes through the centre) the witness on the sphere is
/// rho y / |y| with y = r x e_i, e_i the axis on which r has its smallest absolute
/// coordinate, so y != 0 and y is orthogonal to r. For a zero-length segment at the
/// centre (r = 0 too) cdref takes y = e_x.
///
/// intersect() makes the same decision without the division: for 0 < delta < |r|^2,
///   |s + (delta/|r|^2) r|^2 = |s|^2 - delta^2 / |r|^2 <= rho^2
///   <=>  |s|^2 |r|^2 - delta^2 <= rho^2 |r|^2.
/// proximity() follows the listing verbatim and divides.
/// In proximity(), A is the segment and B the sphere; `closest` is x in world coordinates.
#pragma once

#include "common.hpp"

namespace cdref::book {

namespace detail {
/// The listing's x: the point of the segment s->t (r = t - s) closest to the origin.
template <class T>
Vec3<T> closest_to_origin(const Vec3<T>& s, const Vec3<T>& t, const Vec3<T>& r) {
  const T delta = -s.dot(r);
  if (delta <= T(0)) return s;
  const T rr = r.squaredNorm();
  if (delta >= rr) return t;
  const T lambda = delta / rr;
  return s + lambda * r;
}
/// proximity()'s classification alone (|x|^2 <= rho^2, with the division), on checked input.
template <class T>
bool closest_point_intersect(const Segment<T>& seg, const Sphere<T>& sp) {
  const Vec3<T> s = seg.source - sp.center;
  const Vec3<T> t = seg.target - sp.center;
  return closest_to_origin(s, t, Vec3<T>(t - s)).squaredNorm() <= sp.radius * sp.radius;
}
}  // namespace detail

namespace unchecked {
/// Algorithm 3.2's test on input already checked (see common.hpp).
template <class T>
bool intersect(const Segment<T>& seg, const Sphere<T>& sp) {
  const Vec3<T> s = seg.source - sp.center;
  const Vec3<T> t = seg.target - sp.center;
  const Vec3<T> r = t - s;
  const T rho2 = sp.radius * sp.radius;
  const T delta = -s.dot(r);
  if (delta <= T(0)) return s.squaredNorm() <= rho2;
  const T rr = r.squaredNorm();
  if (delta >= rr) return t.squaredNorm() <= rho2;
  return s.squaredNorm() * rr - delta * delta <= rho2 * rr;
}
}  // namespace unchecked

/// Whether the closed segment and sphere share a point (touching counts). Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
bool intersect(const Segment<T>& seg, const Sphere<T>& sp) {
  check(seg, "segment");
  check(sp, "sphere");
  return unchecked::intersect(seg, sp);
}

/// Distance, penetration depth and witness points of the segment and the sphere (a
/// cdref::Proximity; only what the mask `w` asks for is computed, the rest stays 0). Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
Proximity<sqrt_t<T>> proximity(const Segment<T>& seg, const Sphere<T>& sp, unsigned w = want_proximity) {
  using S = sqrt_t<T>;
  check(seg, "segment");
  check(sp, "sphere");
  Proximity<S> res;
  const Vec3<T> s = seg.source - sp.center;
  const Vec3<T> t = seg.target - sp.center;
  const Vec3<T> r = t - s;
  const Vec3<T> x = detail::closest_to_origin(s, t, r);
  const T xx = x.squaredNorm();
  const T& rho = sp.radius;
  res.intersect = xx <= rho * rho;
  if (w & want_closest) res.closest = lift<S>(Vec3<T>(x + sp.center));
  if (!(w & (want_distance | want_depth | want_witnesses))) return res;

  const S len = root(xx);
  if (w & want_distance) res.distance = detail::max_of(S(len - S(rho)), S(0));
  if (w & want_depth) res.depth = detail::max_of(S(S(rho) - len), S(0));
  if (w & want_witnesses) {
    res.on_a = lift<S>(Vec3<T>(x + sp.center));
    if (xx != T(0)) {
      res.on_b = offset(sp.center, S(rho), detail::divided(x, len));
    } else {
      Vec3<T> y = detail::is_zero(r) ? Vec3<T>(T(1), T(0), T(0))
                                     : Vec3<T>(r.cross(Vec3<T>::Unit(detail::smallest_abs_axis(r))));
      const S ylen = root(T(y.squaredNorm()));
      res.on_b = offset(sp.center, S(rho), detail::divided(y, ylen));
    }
  }
  return res;
}

}  // namespace cdref::book
