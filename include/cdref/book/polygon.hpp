/// \file
/// cdref/book/polygon.hpp - Section 3.4: convex planar polygons against rays, segments, spheres,
/// boxes and polygons.
///
/// A polygon (primitives.hpp) is the union of its fan triangles (v0, v_i, v_i+1); a convex planar
/// polygon is exactly that union, and so every query here is its triangle query taken over the
/// fan: exact at an exact type whatever the vertex list, and for the chapter's polygons the
/// polygon's own answer.
///   cast(shot, polygon)       the fan triangles' casts: hit if any hits; lambda_enter the smallest
///                             over the hits (point and normal from that triangle, the first on
///                             ties), lambda_exit the largest (for a convex planar polygon the hit
///                             parameters form one interval: a shot in its plane enters at one edge
///                             and leaves at another); hit() by the triangles' division-free tests.
///   proximity(sphere, polygon) the closest point of the polygon is the closest of the fan
///                             triangles' closest points (|x - c|^2 compared exactly at exact
///                             types; the first triangle on ties), and the query is the sphere-
///                             triangle query on that triangle (book/sphere_triangle.hpp).
///   intersect(polygon, box)   the separating-axis test of triangle-box (Akenine-Moller's 13 axes)
///                             on each fan triangle: for a convex planar polygon with normal n
///                             this is Theorem 3.1 with n, the box's faces and the polygon's edges
///                             crossed with the box's, taken triangle by triangle (an axis that
///                             separates the polygon separates each triangle, and a box that meets
///                             a triangle meets the polygon).
///   intersect(polygon, polygon) any pair of fan triangles meets (book/triangle_triangle.hpp).
/// A fan of n vertices has n - 2 triangles, so a query costs up to 6 (36 for two polygons)
/// triangle queries; repeated or collinear vertices make zero-area triangles, which are the
/// segments they span.
#pragma once

#include "common.hpp"
#include "ray_triangle.hpp"
#include "sphere_triangle.hpp"
#include "triangle_box.hpp"
#include "triangle_triangle.hpp"

namespace cdref::book {

namespace detail {

/// The fan's first hit (smallest lambda_enter, first on ties) with the largest lambda_exit;
/// before(k, j, lk, lj) says whether triangle k, entered at lk, comes before triangle j, entered
/// at lj (lk < lj here; the robust casts order near-ties exactly: robust::enters_before).
template <class Cast1, class T, class Before>
auto polygon_cast(const Polygon<T>& p, Cast1 cast1, Before before) {
  using C = decltype(cast1(p.triangle(0)));
  Cast<std::decay_t<decltype(std::declval<C>().lambda_enter)>> r;
  int rk = -1;
  for (int k = 0; k < p.triangles(); ++k) {
    const C c = cast1(p.triangle(k));
    if (!c.hit) continue;
    if (!r.hit) {
      r = c, rk = k;
      continue;
    }
    const auto exit = max_of(r.lambda_exit, c.lambda_exit);
    if (before(k, rk, c.lambda_enter, r.lambda_enter)) r = c, rk = k;
    r.lambda_exit = exit;
  }
  return r;
}
template <class Cast1, class T>
auto polygon_cast(const Polygon<T>& p, Cast1 cast1) {
  return polygon_cast(p, cast1, [](int, int, const auto& lk, const auto& lj) { return lk < lj; });
}

/// The index of the fan triangle whose closest point to c is nearest (the first on ties).
template <class T>
int nearest_triangle(const Polygon<T>& p, const Vec3<T>& c) {
  int best = 0;
  T best_d(0);
  for (int k = 0; k < p.triangles(); ++k) {
    const Vec3<T> x = closest_on_triangle(p.triangle(k), c);
    const T d = Vec3<T>(x - c).squaredNorm();
    if (k == 0 || d < best_d) best = k, best_d = d;
  }
  return best;
}

}  // namespace detail

/// The segment (lambda in [0, 1]) cast on the closed polygon: hit, entry and exit parameters, entry
/// point and normal (only what the mask `w` asks for is computed). Throws cdref::invalid_input
/// naming a bad argument.
template <class T>
Cast<sqrt_t<T>> cast(const Segment<T>& s, const Polygon<T>& p, unsigned w = want_all) {
  check(s, "segment");
  check(p);
  return detail::polygon_cast(p, [&](const Triangle<T>& t) { return cast(s, t, w | want_lambda_enter | want_lambda_exit); });
}
/// The ray (lambda >= 0 in units of |direction|) cast on the closed polygon: hit, entry and exit
/// parameters, entry point and normal (only what the mask `w` asks for is computed). Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
Cast<sqrt_t<T>> cast(const Ray<T>& r, const Polygon<T>& p, unsigned w = want_all) {
  check(r, "ray");
  check(p);
  return detail::polygon_cast(p, [&](const Triangle<T>& t) { return cast(r, t, w | want_lambda_enter | want_lambda_exit); });
}
namespace unchecked {
/// The same as the checked `hit` of these arguments, on input already checked: no input
/// checks (see book/common.hpp). For loops over bodies checked once.
template <class Shot, class T>
bool hit(const Shot& s, const Polygon<T>& p) {
  for (int k = 0; k < p.triangles(); ++k)
    if (unchecked::hit(s, p.triangle(k))) return true;
  return false;
}
/// The same as the checked `intersect` of these arguments, on input already checked: no input
/// checks (see book/common.hpp). For loops over bodies checked once.
template <class T>
bool intersect(const Sphere<T>& s, const Polygon<T>& p) {
  for (int k = 0; k < p.triangles(); ++k)
    if (unchecked::intersect(s, p.triangle(k))) return true;
  return false;
}
/// The same as the checked `intersect` of these arguments, on input already checked: no input
/// checks (see book/common.hpp). For loops over bodies checked once.
template <class T>
bool intersect(const Polygon<T>& p, const Box<T>& b) {
  for (int k = 0; k < p.triangles(); ++k)
    if (unchecked::separate(p.triangle(k), b).intersect) return true;
  return false;
}
/// The same as the checked `intersect` of these arguments, on input already checked: no input
/// checks (see book/common.hpp). For loops over bodies checked once.
template <class T>
bool intersect(const Polygon<T>& a, const Polygon<T>& b) {
  for (int i = 0; i < a.triangles(); ++i)
    for (int j = 0; j < b.triangles(); ++j)
      if (detail::intersect_triangles(a.triangle(i), b.triangle(j), T(0)).intersect) return true;
  return false;
}
}  // namespace unchecked

/// Whether the segment meets the closed polygon: the cast's classification alone. Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
bool hit(const Segment<T>& s, const Polygon<T>& p) {
  check(s, "segment");
  check(p);
  return unchecked::hit(s, p);
}
/// Whether the ray meets the closed polygon: the cast's classification alone. Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
bool hit(const Ray<T>& r, const Polygon<T>& p) {
  check(r, "ray");
  check(p);
  return unchecked::hit(r, p);
}

/// Distance, penetration depth and witness points of the sphere and the polygon (a
/// cdref::Proximity; only what the mask `w` asks for is computed, the rest stays 0). Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
Proximity<sqrt_t<T>> proximity(const Sphere<T>& s, const Polygon<T>& p, unsigned w = want_proximity) {
  check(s, "sphere");
  check(p);
  return proximity(s, p.triangle(detail::nearest_triangle(p, s.center)), w);
}
/// Whether the closed sphere and polygon share a point (touching counts). Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
bool intersect(const Sphere<T>& s, const Polygon<T>& p) {
  check(s, "sphere");
  check(p);
  return unchecked::intersect(s, p);
}

/// Whether the closed polygon and axis-aligned box share a point (touching counts). Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
bool intersect(const Polygon<T>& p, const Box<T>& b) {
  check(p);
  check(b, "box");
  return unchecked::intersect(p, b);
}

/// Whether the closed polygon and polygon share a point (touching counts). Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
bool intersect(const Polygon<T>& a, const Polygon<T>& b) {
  check(a, "polygon A");
  check(b, "polygon B");
  return unchecked::intersect(a, b);
}

}  // namespace cdref::book
