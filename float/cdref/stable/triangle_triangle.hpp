// cdref/stable/triangle_triangle.hpp - two triangles as careful float code writes them:
// Moller's interval test for the intersection segment and the classification (book::intersect
// with eps = 0: no snapping of small plane distances to 0); separate() is the book's
// division-free separating-axis test (17 axes), another formulation, not the tier's. F = float, double, long double; same
// signatures and results as cdref::book.
//
// The chapter's formulations are already these, so the stable tier is the book's; what it
// leaves out is Moller's absolute epsilon (|d| < 1e-6 snapped to 0), right for triangles of
// one size only. Error bound (first order in u, the unit roundoff of F; e the longest edge of
// the two triangles, q the largest distance between their vertices).
//  - nA = (a1 - a0) x (a2 - a0) is off by about 4u |e|^2 per component, and the plane
//    distances dB_k = nA . (b_k - a0) by about u (4 |e|^2 q + 4 |nA| q): a vertex within
//    that of the other's plane (divided by |nA|: about 4u q |e|^2 / |nA| in length) may be put
//    on the wrong side. Where all three of B's vertices are outside that band the plane test
//    is right.
//  - The cut points a_i + (a_j - a_i) dA_i / (dA_i - dA_j) divide by the difference of two
//    plane distances of opposite signs (no cancellation), so their parameter carries the
//    distances' relative error; the overlap test compares the cuts' projections on
//    D = nA x nB, of size |nA| |nB| sin(theta) for the planes' angle theta: two nearly
//    coplanar triangles (sin(theta) ~ u q |e|^2 / |nA|) have a line of intersection that the
//    rounding decides, and the segment [p, q] may move along it by its whole length.
//  - separate(): each axis's projections are dot products of vectors of size |e|^2 (nA, nB,
//    e x e') or |e|^3 (the side normals nA x e) with vertices of size q, compared with each
//    other: decided right unless the gap along the axis is within a few u of |L| q.
// At range (vertices far from the origin relative to their edges) the vertex differences are
// exact only to u |vertex|, which is the problem's own condition; the campaigns measure both
// formulations on the long-range, grazing and coplanar families.
#pragma once

#include <cdref/book/triangle_triangle.hpp>

namespace cdref::stable {

template <class F>
TriangleIntersection<F> intersect(const Triangle<F>& a, const Triangle<F>& b) {
  return book::intersect(a, b);
}
template <class F>
Separation<F> separate(const Triangle<F>& a, const Triangle<F>& b) {
  return book::separate(a, b);
}

// The classification without the input checks (see book/common.hpp): the interval test's, as
// intersect() decides it (the separating axes decide the same exact question, but in F the
// two formulations can disagree, and the tier's classification is its full query's).
namespace unchecked {
template <class F>
bool intersect(const Triangle<F>& a, const Triangle<F>& b) {
  return book::detail::intersect_triangles(a, b, F(0)).intersect;
}
}  // namespace unchecked

}  // namespace cdref::stable
