// cdref/robust/point_triangle.hpp - the robust point-triangle query (Section 3.4) at float,
// double and long double: proximity, intersect and decide.
//
// Formulation: the book's own (book/point_triangle.hpp: the closest point region by region, a
// zero-area triangle as its segment or point), run through the bounded stages of
// cdref/robust/staged.hpp: a double with a running error bound, then a double word with one.
// No error analysis of its own: every comparison of the book is either certain at a stage or
// sends the evaluation to the next. decide() is certain where a stage completed; its value is
// then the book's classification at an exact type. It is uncertain where the point lies on
// the triangle or within about 2^-100 of its size from it (on it: every coordinate of x - p
// must be certified exactly zero, which only the exact rationals can), and for long double
// inputs that are not doubles; there the book runs in F. proximity() takes every value from
// the double word rounded correctly to F where it is certain, else the book's in F, and
// classifies as decide() does.
// Boundary cases: as the book's (a zero-area triangle, the point on an edge or a vertex); the
// input checks (a non-finite coordinate) refuse as the book does.
#pragma once

#include <cdref/book/point_triangle.hpp>
#include <cdref/robust/staged.hpp>

namespace cdref::robust {

/// Whether p lies on the closed triangle, with the certificate (decision.hpp).
template <class F>
Decision decide(const Vec3<F>& p, const Triangle<F>& tri) {
  return staged::decide<F>([](const auto& x, const auto& y) { return book::intersect(x, y); }, p, tri);
}

/// Whether p lies on the closed triangle: decide()'s value.
template <class F>
bool intersect(const Vec3<F>& p, const Triangle<F>& tri) {
  return decide(p, tri).value;
}

/// The book's outputs (book/point_triangle.hpp), correctly rounded to F where the double word
/// is certain, else F's own.
template <class F>
Proximity<F> proximity(const Vec3<F>& p, const Triangle<F>& tri, unsigned w = want_proximity) {
  return staged::result<F>([](const auto& x, const auto& y) { return book::intersect(x, y); },
                           [w](const auto& x, const auto& y) { return book::proximity(x, y, w); }, p, tri);
}

}  // namespace cdref::robust
