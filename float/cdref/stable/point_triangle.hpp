// cdref/stable/point_triangle.hpp - point-triangle as careful float code writes it: the
// triangle's point closest to p by Voronoi regions (Ericson, Real-Time Collision Detection
// 5.1.5; book/point_triangle.hpp). F = float, double, long double; same signatures and results
// as cdref::book.
//
// The chapter's formulation is already this one (it is sphere-triangle's first step, and
// stable/sphere_triangle.hpp states its error bound: d1 ... d6 off by about 4u |e| (q + |e|),
// e the longest edge and q the point's distance from v0; the face point by about
// 20u |e|^3 (q + |e|)^2 / |n|^2, n = ab x ac), so the stable tier is the book. The one
// classification, "p lies on the triangle", asks for x - p = 0 exactly: at float it holds for
// the vertices and for few other points, and float code answers it by a tolerance of its own
// choosing. cdref's stable tier keeps none: the campaigns report where F's answer and the exact
// one part, and by how much.
#pragma once

#include <cdref/book/point_triangle.hpp>

namespace cdref::stable {

/// Whether p lies on the closed triangle (book::intersect in F).
template <class F>
bool intersect(const Vec3<F>& p, const Triangle<F>& tri) {
  return book::intersect(p, tri);
}
/// The closest point, the distance and the classification (book::proximity in F).
template <class F>
Proximity<F> proximity(const Vec3<F>& p, const Triangle<F>& tri, unsigned w = want_proximity) {
  return book::proximity(p, tri, w);
}

// The classification without the input checks (see book/common.hpp).
namespace unchecked {
/// book::unchecked::intersect in F.
template <class F>
bool intersect(const Vec3<F>& p, const Triangle<F>& tri) {
  return book::unchecked::intersect(p, tri);
}
}  // namespace unchecked

}  // namespace cdref::stable
