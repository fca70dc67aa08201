// cdref/robust/triangle_triangle.hpp - the robust triangle-triangle test (Section 3.4) at float,
// double and long double: intersect, the intersection segment, and decide.
//
// Formulation: the book's (book/triangle_triangle.hpp: Moller's interval test with exact zero
// tests, Theorem 3.1 with the side normals for coplanar pairs, zero-area triangles as their
// spans) evaluated on double words (robust/words.hpp: exact inputs, every length scaled by a
// power of two, a rigorous running error bound). The plane distances are of degree 3 and the
// cut points divide by their differences; every comparison (a sign of a distance, the order of
// the cut points along D, a zero test of a normal) is certain when its double word's sign is,
// and then the evaluation completes: the classification, and whether the pair is coplanar, equal
// the book's at an exact type (decide() is certain), and p, q are the double words rounded to F
// (not claimed correctly rounded: that is the oracle's job). Otherwise (a vertex on or a hair
// from the other plane, cut points that tie along D, triangles of nearly zero area) the book
// runs in F and the answer is uncertain.
#pragma once

#include <cdref/book/triangle_triangle.hpp>

#include "words.hpp"

namespace cdref::robust {

namespace detail {

template <class F>
std::pair<TriangleIntersection<F>, Decision> triangle_triangle_eval(const Triangle<F>& a, const Triangle<F>& b) {
  Scale used;
  const auto w = on_words(a, b, [](const auto& x, const auto& y) {
    return book::detail::intersect_triangles(x, y, W(0.0));
  }, &used);
  if (w) {
    const Scale back{-used.k};
    TriangleIntersection<F> r;
    r.intersect = w->intersect;
    r.coplanar = w->coplanar;
    r.p = back.len(value<F>(w->p));
    r.q = back.len(value<F>(w->q));
    return {r, {r.intersect, true}};
  }
  const TriangleIntersection<F> r = book::detail::intersect_triangles(a, b, F(0));
  return {r, {r.intersect, false}};
}

}  // namespace detail

template <class F>
TriangleIntersection<F> intersect(const Triangle<F>& a, const Triangle<F>& b) {
  check(a, "triangle A");
  check(b, "triangle B");
  return detail::triangle_triangle_eval(a, b).first;
}
template <class F>
Decision decide(const Triangle<F>& a, const Triangle<F>& b) {
  check(a, "triangle A");
  check(b, "triangle B");
  return detail::triangle_triangle_eval(a, b).second;
}

}  // namespace cdref::robust
