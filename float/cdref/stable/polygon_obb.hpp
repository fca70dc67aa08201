// cdref/stable/polygon_obb.hpp - polygon-obb as careful float code writes it: triangle-obb's
// separating axes in the box's frame, no epsilon, on every fan triangle (book/polygon_obb.hpp).
// F = float, double, long double; same signatures as cdref::book.
//
// Triangle-obb's stable tier is the book's (stable/obb.hpp states its error bound), and so is
// this one: a polygon is misclassified only where one of its fan triangles is within that bound
// of touching the box, or where the box's axes are orthonormal only to within rounding (the
// frame transform's own assumption, as for every oriented-box query).
#pragma once

#include <cdref/book/polygon_obb.hpp>

namespace cdref::stable {

/// Whether the polygon and the oriented box share a point (closed sets): book::intersect in F.
template <class F>
bool intersect(const Polygon<F>& p, const OrientedBox<F>& b) {
  return book::intersect(p, b);
}

// The classification without the input checks (see book/common.hpp).
namespace unchecked {
/// book::unchecked::intersect in F.
template <class F>
bool intersect(const Polygon<F>& p, const OrientedBox<F>& b) {
  return book::unchecked::intersect(p, b);
}
}  // namespace unchecked

}  // namespace cdref::stable
