// cdref/robust/polygon_obb.hpp - the robust polygon-obb query (Section 3.4) at float, double
// and long double: intersect and decide.
//
// Formulation: the truth's own (book/polygon_obb.hpp's solid::intersect: Theorem 3.1 on every
// fan triangle and the parallelepiped the box's inputs define), run through the bounded stages
// of cdref/robust/staged.hpp: a double with a running error bound, then a double word with one.
// No error analysis of its own: every sign of the separating-axis test (the projections'
// differences, of degree 3 in the coordinates for the face axes and 4 for the edge crosses) is
// either certain at a stage or sends the evaluation to the next. decide() is certain where a
// stage completed, and its value is then the exact classification. It is uncertain where the
// polygon touches the box or comes within about 2^-100 of its size of touching it, and for long
// double inputs that are not doubles; there the same formulation runs in F, uncertified.
// Boundary cases: as the book's (zero-area fan triangles, flat boxes); the input checks (the
// vertex count, a non-finite coordinate, a negative extent, dependent axes) refuse as the
// book does.
#pragma once

#include <cdref/book/polygon_obb.hpp>
#include <cdref/robust/staged.hpp>

namespace cdref::robust {

/// Whether the polygon meets the box's solid, with the certificate (decision.hpp).
template <class F>
Decision decide(const Polygon<F>& p, const OrientedBox<F>& b) {
  return staged::decide<F>([](const auto& x, const auto& y) { return solid::intersect(x, y); }, p, b);
}

/// Whether the polygon meets the box's solid: decide()'s value.
template <class F>
bool intersect(const Polygon<F>& p, const OrientedBox<F>& b) {
  return decide(p, b).value;
}

}  // namespace cdref::robust
