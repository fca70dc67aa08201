/// \file
/// cdref/book/point_triangle.hpp - Section 3.4: the point of a closed triangle closest to a
/// point (squared distance, distance, the closest point; intersect: the point lies on the
/// triangle). The first step of every sphere-triangle and capsule-triangle test
/// (book/sphere_triangle.hpp builds on it).
///
/// The closest point, region by region (Ericson, Real-Time Collision Detection 5.1.5): with
/// a = v0, b = v1, c = v2 and p the point,
///   d1 = ab . ap, d2 = ac . ap          vertex a      if d1 <= 0 and d2 <= 0;
///   d3 = ab . bp, d4 = ac . bp          vertex b      if d3 >= 0 and d4 <= d3;
///   vc = d1 d4 - d3 d2                  edge ab       if vc <= 0, d1 >= 0, d3 <= 0, at
///                                                     a + ab d1 / (d1 - d3);
///   d5 = ab . cp, d6 = ac . cp          vertex c      if d6 >= 0 and d5 <= d6;
///   vb = d5 d2 - d1 d6                  edge ac       if vb <= 0, d2 >= 0, d6 <= 0, at
///                                                     a + ac d2 / (d2 - d6);
///   va = d3 d6 - d5 d4                  edge bc       if va <= 0, d4 - d3 >= 0, d5 - d6 >= 0,
///                                                     at b + bc (d4 - d3) / ((d4 - d3) + (d5 - d6));
///   otherwise the face: a + ab vb / (va + vb + vc) + ac vc / (va + vb + vc).
/// (va, vb, vc are the barycentric coordinates times |ab x ac|^2; the tests are the Voronoi
/// regions of the vertices and edges, closed, so a point on a region's boundary takes the first
/// region listed: the closest point is continuous across the boundaries, so the choice does not
/// change it.) Every quantity is rational in the inputs: at an exact type x is exact.
///
/// Boundary cases.
///  - A triangle of zero area (ab x ac = 0, decided in T) is the segment between its two
///    farthest vertices, or a point, and x is the closest point of that segment (Algorithm 3.2)
///    or the point: the region formulas would divide by zero.
///  - The point on the triangle: x = p, distance 0, intersect. At float a point computed on an
///    edge or the face (a + t (b - a)) is seldom exactly on it: the exact answer is then
///    "not on it, at a distance of a few ulps", and the campaigns count float code that says
///    otherwise.
///  - A point in the triangle's plane, outside it: x on an edge or a vertex, as off the plane.
///
/// Outputs (a Proximity, A the point, B the triangle): intersect (p lies on the closed
/// triangle), distance |x - p|, depth 0 (a point has no volume), witness_a = p, witness_b = x,
/// closest = x.
///
/// Range: va, vb, vc are of degree 4 in the coordinates. In double, coordinates (relative to
/// each other) beyond about 2^250 overflow them and the answer is not finite; below about 2^-250
/// they underflow to 0 and the region tests pick a wrong edge. The robust tier and the oracle
/// evaluate the same formulas on bounded number types (cdref/robust/staged.hpp).
#pragma once

#include "common.hpp"

namespace cdref::book {

namespace detail {

/// The two vertices of a triangle farthest apart (i < j; the first pair of 01, 02, 12 on ties):
/// a zero-area triangle is the segment between them, or the point.
template <class T>
void farthest_pair(const Triangle<T>& t, int& i, int& j) {
  i = 0, j = 1;
  T far = Vec3<T>(t.vertex[1] - t.vertex[0]).squaredNorm();
  const T d02 = Vec3<T>(t.vertex[2] - t.vertex[0]).squaredNorm(), d12 = Vec3<T>(t.vertex[2] - t.vertex[1]).squaredNorm();
  if (far < d02) i = 0, j = 2, far = d02;
  if (far < d12) i = 1, j = 2;
}

/// The point of the triangle closest to p, and for a zero-area triangle whether it is one
/// (its segment's direction); *in_face, when asked, says whether the point is the face's (p's
/// projection on the plane: x - p is then parallel to ab x ac).
template <class T>
Vec3<T> closest_on_triangle(const Triangle<T>& tri, const Vec3<T>& p, Vec3<T>* degenerate_direction = nullptr,
                            bool* in_face = nullptr) {
  const Vec3<T>& a = tri.vertex[0];
  const Vec3<T>& b = tri.vertex[1];
  const Vec3<T>& c = tri.vertex[2];
  const Vec3<T> ab = b - a, ac = c - a;
  if (is_zero(Vec3<T>(ab.cross(ac)))) {
    // the segment between the two farthest vertices (or the point)
    int i, j;
    farthest_pair(tri, i, j);
    const Vec3<T>* s = &tri.vertex[i];
    const Vec3<T>* t = &tri.vertex[j];
    const Vec3<T> r = *t - *s;
    const T far = r.squaredNorm();
    if (degenerate_direction) *degenerate_direction = r;
    const T delta = -Vec3<T>(*s - p).dot(r);
    if (delta <= T(0)) return *s;
    if (delta >= far) return *t;
    return Vec3<T>(*s + (delta / far) * r);
  }
  const Vec3<T> ap = p - a;
  const T d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= T(0) && d2 <= T(0)) return a;
  const Vec3<T> bp = p - b;
  const T d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= T(0) && d4 <= d3) return b;
  const T vc = d1 * d4 - d3 * d2;
  if (vc <= T(0) && d1 >= T(0) && d3 <= T(0)) return Vec3<T>(a + (d1 / (d1 - d3)) * ab);
  const Vec3<T> cp = p - c;
  const T d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= T(0) && d5 <= d6) return c;
  const T vb = d5 * d2 - d1 * d6;
  if (vb <= T(0) && d2 >= T(0) && d6 <= T(0)) return Vec3<T>(a + (d2 / (d2 - d6)) * ac);
  const T va = d3 * d6 - d5 * d4;
  if (va <= T(0) && T(d4 - d3) >= T(0) && T(d5 - d6) >= T(0))
    return Vec3<T>(b + (T(d4 - d3) / T(T(d4 - d3) + T(d5 - d6))) * Vec3<T>(c - b));
  const T denom = va + vb + vc;
  if (in_face) *in_face = true;
  return Vec3<T>(a + (vb / denom) * ab + (vc / denom) * ac);
}

template <class T>
bool point_triangle_intersect(const Vec3<T>& p, const Triangle<T>& tri) {
  return is_zero(Vec3<T>(closest_on_triangle(tri, p) - p));
}

}  // namespace detail

/// The classification without the input checks (see common.hpp).
namespace unchecked {
/// The same as the checked `intersect` of these arguments, on input already checked: no input
/// checks (see book/common.hpp). For loops over bodies checked once.
template <class T>
bool intersect(const Vec3<T>& p, const Triangle<T>& tri) {
  return detail::point_triangle_intersect(p, tri);
}
}  // namespace unchecked

/// Whether the point p lies on the closed triangle (its closest point is p itself).
template <class T>
bool intersect(const Vec3<T>& p, const Triangle<T>& tri) {
  check(p, "point");
  check(tri, "triangle");
  return detail::point_triangle_intersect(p, tri);
}

/// The triangle's point x closest to p, |x - p| and whether p lies on the triangle (the
/// header's outputs; w: the want_* mask of the outputs to compute).
template <class T>
Proximity<sqrt_t<T>> proximity(const Vec3<T>& p, const Triangle<T>& tri, unsigned w = want_proximity) {
  using S = sqrt_t<T>;
  check(p, "point");
  check(tri, "triangle");
  const Vec3<T> x = detail::closest_on_triangle(tri, p);
  const Vec3<T> v = x - p;
  Proximity<S> res;
  res.intersect = detail::is_zero(v);
  if (w & want_closest) res.closest = lift<S>(x);
  if ((w & want_distance) && !res.intersect) res.distance = root(T(v.squaredNorm()));
  if (w & want_witnesses) {
    res.on_a = lift<S>(p);
    res.on_b = lift<S>(x);
  }
  return res;
}

/// The triangle's point x closest to p: exact at an exact type (rational in the inputs).
template <class T>
Vec3<T> closest_point(const Vec3<T>& p, const Triangle<T>& tri) {
  check(p, "point");
  check(tri, "triangle");
  return detail::closest_on_triangle(tri, p);
}

/// |x - p|^2, exact at an exact type (rational in the inputs: no square root).
template <class T>
T squared_distance(const Vec3<T>& p, const Triangle<T>& tri) {
  return Vec3<T>(closest_point(p, tri) - p).squaredNorm();
}

}  // namespace cdref::book
