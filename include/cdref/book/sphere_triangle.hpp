// cdref/book/sphere_triangle.hpp - Section 3.4: a sphere and a triangle (intersect, distance,
// penetration depth, witness points).
//
// As for the segment (Section 3.1.3) and the box (3.2.2), the test is built on the point x of
// the triangle closest to the sphere's centre c: they meet iff |x - c|^2 <= rho^2.
// The closest point, region by region (Ericson, Real-Time Collision Detection 5.1.5): with
// a = v0, b = v1, c' = v2 and p the centre,
//   d1 = ab . ap, d2 = ac . ap          vertex a      if d1 <= 0 and d2 <= 0;
//   d3 = ab . bp, d4 = ac . bp          vertex b      if d3 >= 0 and d4 <= d3;
//   vc = d1 d4 - d3 d2                  edge ab       if vc <= 0, d1 >= 0, d3 <= 0, at
//                                                     a + ab d1 / (d1 - d3);
//   d5 = ab . cp, d6 = ac . cp          vertex c'     if d6 >= 0 and d5 <= d6;
//   vb = d5 d2 - d1 d6                  edge ac       if vb <= 0, d2 >= 0, d6 <= 0, at
//                                                     a + ac d2 / (d2 - d6);
//   va = d3 d6 - d5 d4                  edge bc       if va <= 0, d4 - d3 >= 0, d5 - d6 >= 0,
//                                                     at b + bc (d4 - d3) / ((d4 - d3) + (d5 - d6));
//   otherwise the face: a + ab vb / (va + vb + vc) + ac vc / (va + vb + vc).
// (va, vb, vc are the barycentric coordinates times |ab x ac|^2; the tests are the Voronoi
// regions of the vertices and edges.) A triangle of zero area (ab x ac = 0, decided in T) is
// the segment between its two farthest vertices, or a point, and x is the closest point of
// that segment (Algorithm 3.2) or the point: the region formulas would divide by zero.
// With v = x - c:
//   x != c   distance max(|v| - rho, 0), depth max(rho - |v|, 0) (the ball's distance to
//            the boundary of the triangle grown by rho: rho minus the distance of c), witnesses
//            c + rho v/|v| on the sphere and x on the triangle;
//   x == c   the centre lies on the triangle: distance 0, depth rho, witnesses c (triangle)
//            and c + rho n/|n| (sphere), n = ab x ac; for a zero-area triangle n = e x e_i
//            with e its direction and e_i the axis of e's smallest coordinate (as Algorithm
//            3.2 does), and for a point the axis e_x.
// Range: va, vb, vc are of degree 4 in the coordinates. In double, coordinates (relative to
// each other) beyond about 2^250 overflow them and the answer is not finite; below about
// 2^-250 they underflow to 0 and the region tests pick a wrong edge (tests/test_triangles.cpp
// states both). The robust version and the oracle work on scaled double words instead.
// In proximity(), A is the sphere and B the triangle; `closest` is x.
#pragma once

#include "common.hpp"

namespace cdref::book {

namespace detail {

// The two vertices of a triangle farthest apart (i < j; the first pair of 01, 02, 12 on ties):
// a zero-area triangle is the segment between them, or the point.
template <class T>
void farthest_pair(const Triangle<T>& t, int& i, int& j) {
  i = 0, j = 1;
  T far = Vec3<T>(t.vertex[1] - t.vertex[0]).squaredNorm();
  const T d02 = Vec3<T>(t.vertex[2] - t.vertex[0]).squaredNorm(), d12 = Vec3<T>(t.vertex[2] - t.vertex[1]).squaredNorm();
  if (far < d02) i = 0, j = 2, far = d02;
  if (far < d12) i = 1, j = 2;
}

// The point of the triangle closest to p, and for a zero-area triangle whether it is one
// (its segment's direction); *in_face, when asked, says whether the point is the face's (p's
// projection on the plane: x - p is then parallel to ab x ac).
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

// The closest point on checked input.
template <class T>
bool sphere_triangle_intersect(const Sphere<T>& sp, const Triangle<T>& tri) {
  const Vec3<T> v = closest_on_triangle(tri, sp.center) - sp.center;
  return v.squaredNorm() <= sp.radius * sp.radius;
}

}  // namespace detail

namespace unchecked {
template <class T>
bool intersect(const Sphere<T>& sp, const Triangle<T>& tri) {
  return detail::sphere_triangle_intersect(sp, tri);
}
}  // namespace unchecked

template <class T>
bool intersect(const Sphere<T>& sp, const Triangle<T>& tri) {
  check(sp, "sphere");
  check(tri, "triangle");
  return detail::sphere_triangle_intersect(sp, tri);
}

namespace detail {

// proximity()'s outputs from the closest point x of the triangle (dir as closest_on_triangle's).
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

template <class T>
Proximity<sqrt_t<T>> proximity(const Sphere<T>& sp, const Triangle<T>& tri, unsigned w = want_proximity) {
  check(sp, "sphere");
  check(tri, "triangle");
  Vec3<T> dir = zero_vec<T>();
  const Vec3<T> x = detail::closest_on_triangle(tri, sp.center, &dir);
  return detail::sphere_triangle_outputs(sp, tri, x, dir, w);
}

}  // namespace cdref::book
