/// \file
/// cdref/book/polygon_obb.hpp - Section 3.4: a convex planar polygon against an oriented box.
///
/// As for the polygon and the axis-aligned box (book/polygon.hpp), the polygon is the union of
/// its fan triangles (v0, v_i, v_i+1) and the query is triangle-obb taken over the fan: the
/// polygon meets the box iff one of its fan triangles does. For a convex planar polygon with
/// normal n this is Theorem 3.1 with n, the box's three face normals and the polygon's edges
/// crossed with the box's axes, taken triangle by triangle (an axis that separates the polygon
/// separates each of its triangles, and a box that meets a triangle meets the polygon). A fan of
/// n vertices has n - 2 triangles: up to 6 triangle-obb tests of 13 axes.
///
/// Two formulations, as for every oriented-box query (book/obb.hpp, solid/obb.hpp):
///   book::intersect    each fan triangle moved into the box's frame by dot products with the
///                      axes (book::separate(Triangle, OrientedBox)), which assumes the axes
///                      orthonormal; in float they are orthonormal only to within rounding, and
///                      at an exact type the answer is that of the box the frame transform
///                      implies, not of the parallelepiped the inputs define.
///   solid::intersect   Theorem 3.1 on each fan triangle and the parallelepiped the axes span
///                      (solid::separate(Triangle, OrientedBox)): the truth, exact at an exact
///                      type for any linearly independent axes.
/// Both agree exactly where the axes are exactly orthonormal.
///
/// Boundary cases: closed sets, so a polygon touching a face, an edge or a corner of the box
/// meets it; repeated or collinear vertices make zero-area fan triangles, which are the
/// segments or points they span; a box of zero extent along an axis is a flat box (a rectangle,
/// a segment or a point). Inputs are checked once (the polygon's vertex count and coordinates,
/// the box's extents and its axes' independence) and named in the error.
#pragma once

#include "../solid/obb.hpp"
#include "obb.hpp"
#include "polygon.hpp"

namespace cdref::book {

/// The classification without the input checks (see common.hpp).
namespace unchecked {
/// Whether any fan triangle of p meets the box, each by book::separate in the box's frame.
template <class T>
bool intersect(const Polygon<T>& p, const OrientedBox<T>& b) {
  for (int k = 0; k < p.triangles(); ++k)
    if (unchecked::separate(p.triangle(k), b).intersect) return true;
  return false;
}
}  // namespace unchecked

/// Whether the polygon and the oriented box share a point (closed sets), by the book's frame
/// transform (header).
template <class T>
bool intersect(const Polygon<T>& p, const OrientedBox<T>& b) {
  check(p);
  check(b, "oriented box");
  return unchecked::intersect(p, b);
}

}  // namespace cdref::book

namespace cdref::solid {

/// Whether the polygon and the parallelepiped the box's inputs define share a point: Theorem 3.1
/// on each fan triangle (the truth, header).
template <class T>
bool intersect(const Polygon<T>& p, const OrientedBox<T>& b) {
  check(p);
  check(b, "oriented box");
  const auto box = book::polytope(b);
  for (int k = 0; k < p.triangles(); ++k)
    if (book::separate(book::polytope(p.triangle(k)), box).intersect) return true;
  return false;
}

}  // namespace cdref::solid
