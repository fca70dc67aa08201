// cdref/stable/sphere_triangle.hpp - sphere-triangle as careful float code writes it: the
// triangle's point closest to the centre by Voronoi regions (Ericson, Real-Time Collision
// Detection 5.1.5; book/sphere_triangle.hpp), then one comparison. F = float, double, long
// double; same signatures and results as cdref::book.
//
// The chapter's formulation is already this one, so the stable tier is book::proximity and
// book::intersect. Error bound (first order in u, the unit roundoff of F; e the longest edge,
// q = |p - a| the centre's distance from vertex a, n = ab x ac, |n| twice the area).
//  - d1 ... d6 (edges dotted with the centre's offsets) are off by about 4u |e| (q + |e|).
//  - The region tests compare them with 0 and with each other: near a region's boundary the
//    wrong region may be chosen, but the closest point is continuous across the boundaries, so
//    the choice moves x only by the band's width (about 4u (q + |e|) on an edge or a vertex).
//  - va, vb, vc (the barycentric coordinates times |n|^2, differences of products of the d's)
//    are off by about 20u |e|^2 (q + |e|)^2, and the face point a + ab vb/D + ac vc/D
//    (D = va + vb + vc = |n|^2 exactly) by about 20u |e|^3 (q + |e|)^2 / |n|^2: for a triangle
//    of fair shape (|n| ~ |e|^2) and a centre near it, some tens of u |e|; for a sliver
//    (|n| << |e|^2) the weights lose digits like 1/sin^2 of the smallest angle.
//  - |x - c|^2 <= rho^2 is then decided right unless |x - c| is within |x^ - x| + u (|x| +
//    3 rho) of rho.
// At range (q >> |e|) every band carries u q relative to the triangle's size: a sphere near
// the triangle is decided at random once u q reaches the triangle's size, as for every
// formulation in F. The degree-4 va, vb, vc also overflow (about 2^250 in double, 2^30 in
// float) and underflow (2^-250, 2^-30) where the inputs do not (book/sphere_triangle.hpp);
// the campaigns' magnitude family shows it.
// Distance and depth |x - c| - rho cancel near touching (the problem's own condition); the
// witness on the sphere, c + rho v / |v|, carries |x^ - x| / |v| relative.
#pragma once

#include <cdref/book/sphere_triangle.hpp>

namespace cdref::stable {

template <class F>
bool intersect(const Sphere<F>& sp, const Triangle<F>& tri) {
  return book::intersect(sp, tri);
}
template <class F>
Proximity<F> proximity(const Sphere<F>& sp, const Triangle<F>& tri, unsigned w = want_proximity) {
  return book::proximity(sp, tri, w);
}

// The classification without the input checks (see book/common.hpp).
namespace unchecked {
template <class F>
bool intersect(const Sphere<F>& sp, const Triangle<F>& tri) {
  return book::unchecked::intersect(sp, tri);
}
}  // namespace unchecked

}  // namespace cdref::stable
