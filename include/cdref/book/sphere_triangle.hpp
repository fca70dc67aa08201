/// \file
/// cdref/book/sphere_triangle.hpp - Section 3.4: a sphere and a triangle (intersect, distance,
/// penetration depth, witness points).
///
/// As for the segment (Section 3.1.3) and the box (3.2.2), the test is built on the point x of
/// the triangle closest to the sphere's centre c: they meet iff |x - c|^2 <= rho^2.
/// The closest point x is point_triangle.hpp's (region by region, a zero-area triangle as the
/// segment or point it spans).
/// With v = x - c:
///   x != c   distance max(|v| - rho, 0), depth max(rho - |v|, 0) (the ball's distance to
///            the boundary of the triangle grown by rho: rho minus the distance of c), witnesses
///            c + rho v/|v| on the sphere and x on the triangle;
///   x == c   the centre lies on the triangle: distance 0, depth rho, witnesses c (triangle)
///            and c + rho n/|n| (sphere), n = ab x ac; for a zero-area triangle n = e x e_i
///            with e its direction and e_i the axis of e's smallest coordinate (as Algorithm
///            3.2 does), and for a point the axis e_x.
/// Range: va, vb, vc are of degree 4 in the coordinates. In double, coordinates (relative to
/// each other) beyond about 2^250 overflow them and the answer is not finite; below about
/// 2^-250 they underflow to 0 and the region tests pick a wrong edge (tests/test_triangles.cpp
/// states both). The robust version and the oracle work on scaled double words instead.
/// In proximity(), A is the sphere and B the triangle; `closest` is x.
#pragma once

#include "common.hpp"
#include "point_triangle.hpp"

namespace cdref::book {

namespace detail {

/// The closest point on checked input.
template <class T>
bool sphere_triangle_intersect(const Sphere<T>& sp, const Triangle<T>& tri) {
  const Vec3<T> v = closest_on_triangle(tri, sp.center) - sp.center;
  return v.squaredNorm() <= sp.radius * sp.radius;
}

}  // namespace detail

namespace unchecked {
/// The same as the checked `intersect` of these arguments, on input already checked: no input
/// checks (see book/common.hpp). For loops over bodies checked once.
template <class T>
bool intersect(const Sphere<T>& sp, const Triangle<T>& tri) {
  return detail::sphere_triangle_intersect(sp, tri);
}
}  // namespace unchecked

/// Whether the closed sphere and triangle share a point (touching counts). Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
bool intersect(const Sphere<T>& sp, const Triangle<T>& tri) {
  check(sp, "sphere");
  check(tri, "triangle");
  return detail::sphere_triangle_intersect(sp, tri);
}

namespace detail {

/// proximity()'s outputs from the closest point x of the triangle (dir as closest_on_triangle's).
template <class T>
Proximity<sqrt_t<T>> sphere_triangle_outputs(const Sphere<T>& sp, const Triangle<T>& tri, const Vec3<T>& x,
                                             const Vec3<T>& dir, unsigned w) {
  using S = sqrt_t<T>;
  Proximity<S> res;
  const Vec3<T> v = x - sp.center;
  const T vv = v.squaredNorm();
  const T& rho = sp.radius;
  res.intersect = vv <= rho * rho;
  if (w & want_closest) res.closest = lift<S>(x);
  if (!(w & (want_distance | want_depth | want_witnesses))) return res;
  if (vv != T(0)) {  // the centre is off the triangle
    const S len = root(vv);
    if (w & want_distance) res.distance = detail::max_of(S(len - S(rho)), S(0));
    if (w & want_depth) res.depth = detail::max_of(S(S(rho) - len), S(0));
    if (w & want_witnesses) {
      res.on_a = offset(sp.center, S(rho), detail::divided(v, len));
      res.on_b = lift<S>(x);
    }
    return res;
  }
  // the centre lies on the triangle: the normal, or a direction perpendicular to a
  // zero-area triangle's segment
  Vec3<T> n = Vec3<T>(tri.vertex[1] - tri.vertex[0]).cross(Vec3<T>(tri.vertex[2] - tri.vertex[0]));
  if (detail::is_zero(n)) n = detail::is_zero(dir) ? unit_vec<T>(0) : Vec3<T>(dir.cross(unit_vec<T>(detail::smallest_abs_axis(dir))));
  if (w & want_depth) res.depth = S(rho);
  if (w & want_witnesses) {
    res.on_a = offset(sp.center, S(rho), detail::divided(n, root(T(n.squaredNorm()))));
    res.on_b = lift<S>(x);
  }
  return res;
}

}  // namespace detail

/// Distance, penetration depth and witness points of the sphere and the triangle (a
/// cdref::Proximity; only what the mask `w` asks for is computed, the rest stays 0). Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
Proximity<sqrt_t<T>> proximity(const Sphere<T>& sp, const Triangle<T>& tri, unsigned w = want_proximity) {
  check(sp, "sphere");
  check(tri, "triangle");
  Vec3<T> dir = zero_vec<T>();
  const Vec3<T> x = detail::closest_on_triangle(tri, sp.center, &dir);
  return detail::sphere_triangle_outputs(sp, tri, x, dir, w);
}

}  // namespace cdref::book
