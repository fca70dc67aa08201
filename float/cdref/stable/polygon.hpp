// cdref/stable/polygon.hpp - convex planar polygons as careful float code writes them: the
// union of the fan triangles (v0, v_i, v_i+1), each answered by the stable tier's triangle
// query. F = float, double, long double; same signatures and results as cdref::book
// (book/polygon.hpp combines the fan's answers the same way).
//   cast / hit(shot, polygon)     the watertight cast of stable/ray_triangle.hpp on each fan
//                                 triangle, first hit and last exit over the fan
//                                 (book::detail::polygon_cast). The fan's diagonals are edges
//                                 shared by two triangles, and the watertight test lets no shot
//                                 through a shared edge (stable/ray_triangle.hpp: the sheared
//                                 vertices are the same in both triangles, the shared edge's
//                                 function is computed from the same products): a shot through
//                                 the polygon's interior hits some triangle as rounded, where the
//                                 book's per-triangle tests can miss both triangles at a
//                                 diagonal.
//   proximity / intersect(sphere, polygon)   book::proximity (stable/sphere_triangle.hpp is the
//                                 book's): the nearest fan triangle by the triangles' closest
//                                 points, and intersect() that triangle's test (the book's
//                                 intersect() asks every triangle, which in F can disagree).
//   intersect(polygon, box)       book's (stable/triangle_box.hpp) over the fan.
//   intersect(polygon, polygon)   book's (stable/triangle_triangle.hpp) over the fan pairs.
// Error bounds: each triangle's (the headers named above); a union is decided right wherever
// each triangle is, and wrong only where some triangle's own band holds the answer - except
// that the cast's shared edges never lose a shot (above). The nearest triangle of the
// proximity is chosen by squared distances in F: two triangles whose distances are within
// their rounding may be swapped, which moves the answer only by that rounding (both are
// closest points to within it).
#pragma once

#include <cdref/book/polygon.hpp>
#include <cdref/stable/ray_triangle.hpp>

namespace cdref::stable {

template <class F>
Cast<F> cast(const Segment<F>& s, const Polygon<F>& p, unsigned w = want_all) {
  check(s, "segment");
  check(p);
  return book::detail::polygon_cast(p, [&](const Triangle<F>& t) {
    return detail::watertight(s.source, Vec3<F>(s.target - s.source), t, true, w | want_lambda_enter | want_lambda_exit);
  });
}
template <class F>
Cast<F> cast(const Ray<F>& r, const Polygon<F>& p, unsigned w = want_all) {
  check(r, "ray");
  check(p);
  return book::detail::polygon_cast(p, [&](const Triangle<F>& t) {
    return detail::watertight(r.source, r.direction, t, false, w | want_lambda_enter | want_lambda_exit);
  });
}

namespace unchecked {
// The nearest fan triangle's test, |x - c|^2 <= rho^2 for its closest point x: that squared
// distance is the smallest of the fan's (nearest_triangle's own values, each computed once),
// so it is within rho^2 exactly when some triangle's is, and the first such ends the loop. (A
// NaN distance, from inputs whose squares overflow, is never taken as the nearest after the
// first triangle; a NaN first one is, and its test fails: as nearest_triangle's.)
template <class F>
bool intersect(const Sphere<F>& s, const Polygon<F>& p) {
  const F rr = s.radius * s.radius;
  for (int k = 0; k < p.triangles(); ++k) {
    const Vec3<F> x = book::detail::closest_on_triangle(p.triangle(k), s.center);
    const F d = Vec3<F>(x - s.center).squaredNorm();
    if (d <= rr) return true;
    if (k == 0 && d != d) return false;
  }
  return false;
}
template <class Shot, class F>
bool hit(const Shot& s, const Polygon<F>& p) {
  for (int k = 0; k < p.triangles(); ++k)
    if (unchecked::hit(s, p.triangle(k))) return true;
  return false;
}
}  // namespace unchecked

template <class F>
bool hit(const Segment<F>& s, const Polygon<F>& p) {
  check(s, "segment");
  check(p);
  return unchecked::hit(s, p);
}
template <class F>
bool hit(const Ray<F>& r, const Polygon<F>& p) {
  check(r, "ray");
  check(p);
  return unchecked::hit(r, p);
}

template <class F>
Proximity<F> proximity(const Sphere<F>& s, const Polygon<F>& p, unsigned w = want_proximity) {
  return book::proximity(s, p, w);
}
// The classification of proximity(): the nearest fan triangle's (not the book's "any
// triangle meets", which at float can disagree with the nearest triangle's own test).
template <class F>
bool intersect(const Sphere<F>& s, const Polygon<F>& p) {
  return book::proximity(s, p, 0u).intersect;
}
template <class F>
bool intersect(const Polygon<F>& p, const Box<F>& b) {
  return book::intersect(p, b);
}
template <class F>
bool intersect(const Polygon<F>& a, const Polygon<F>& b) {
  return book::intersect(a, b);
}

}  // namespace cdref::stable
