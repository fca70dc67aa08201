// cdref/robust/triangle_triangle.hpp - the robust triangle-triangle test (Section 3.4) at float,
// double and long double: intersect, the intersection segment, and decide.
//
// At double the oracle's first stage runs first (filters/triangle_filter.hpp: a separating
// plane, then the six edge-triangle casts, static error bounds): where it decides, the
// classification is exact and certain, and disjoint triangles return at once.
//
// At float and double, next, a plane that separates them or a coplanar pair whole, exactly on
// the inputs read as integers on a grid per coordinate axis (filters/triangle_grid.hpp): the
// book's answer, classification, `coplanar` and p = q = 0 alike.
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
// runs in F and the answer is uncertain (certain where the first stage decided), and where the
// double words with lenient signs complete on the same answer, p and q are theirs (F's kept
// where they lie within the double word's enclosure: words.hpp, word_or_enclosed).
#pragma once

#include <cdref/book/triangle_triangle.hpp>
#include <cdref/filters/triangle_filter.hpp>
#include <cdref/filters/triangle_grid.hpp>
#include <cdref/filters/triangle_words.hpp>

#include "words.hpp"

namespace cdref::robust {

namespace detail {

// At double, the oracle's first stage (filters/triangle_filter.hpp: a separating plane, then the
// six edge-triangle casts) before the double words: 1 (they meet), 0 (disjoint) or 2
// (undecided; always at float and long double). Where it decides, its answer is the book's at
// an exact type, so every entry point takes it; disjoint triangles have no values (coplanar is
// false, p = q = 0), so intersect() then returns at once.
// (Where the static bounds leave it, the same tests with those signs on double words:
// filters/triangle_words.hpp.)
template <class F>
int triangle_triangle_first_stage(const Triangle<F>& a, const Triangle<F>& b) {
  if constexpr (std::is_same_v<F, double>) {
    const int f = filters::triangle_triangle::filter(a, b);
    if (f != filters::triangle_triangle::unknown) return f;
    // a pair that may be coplanar exactly first (the oracle's order: oracle/triangle_triangle.hpp)
    if (filters::triangle_triangle::maybe_coplanar(a, b))
      if (const int g = filters::triangle_triangle::on_grid(a, b); g != filters::triangle_triangle::unknown) return g;
    return filters::triangle_triangle::tests_on_words(a, b);
  } else {
    return filters::triangle_triangle::unknown;
  }
}

// The evaluation after the first stage's answer `first` (2: undecided).
template <class F>
std::pair<TriangleIntersection<F>, Decision> triangle_triangle_eval(const Triangle<F>& a, const Triangle<F>& b,
                                                                    int first) {
  if (first == 0) return {TriangleIntersection<F>{}, {false, true}};
  if constexpr (std::is_same_v<F, double> || std::is_same_v<F, float>) {
    // a separating plane, or a coplanar pair whole, exactly (filters/triangle_grid.hpp): the
    // book's answer, p = q = 0 (header)
    const auto dv = [](const Triangle<F>& t) {
      Triangle<double> d;
      for (int k = 0; k < 3; ++k) d.vertex[k] = Vec3<double>(t.vertex[k][0], t.vertex[k][1], t.vertex[k][2]);
      return d;
    };
    const int g = filters::triangle_triangle::on_grid(dv(a), dv(b), first == 1);
    if (g == 0) return {TriangleIntersection<F>{}, {false, true}};
    if (g == 1) {
      TriangleIntersection<F> r;
      r.intersect = r.coplanar = true;
      return {r, {true, true}};
    }
  }
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
  TriangleIntersection<F> r = book::detail::intersect_triangles(a, b, F(0));
  if (first == 1) r.intersect = true;
  // the ends from the double words with lenient signs where they complete on the same answer
  // (words.hpp: F's value kept where it lies within their enclosure): F's cut points carry
  // its rounding (11 ulps on the degenerate family, a zero-area triangle's span through the
  // other triangle, the classification certain from the first stage)
  if (r.intersect) {
    const auto lw = on_words_lenient(a, b, [](const auto& x, const auto& y) {
      return book::detail::intersect_triangles(x, y, W(0.0));
    }, &used);
    if (lw && lw->intersect && lw->coplanar == r.coplanar) {
      r.p = word_or_enclosed(lw->p, r.p, used.k);
      r.q = word_or_enclosed(lw->q, r.q, used.k);
    }
  }
  return {r, {r.intersect, first == 1}};
}

}  // namespace detail

template <class F>
TriangleIntersection<F> intersect(const Triangle<F>& a, const Triangle<F>& b) {
  check(a, "triangle A");
  check(b, "triangle B");
  return detail::triangle_triangle_eval(a, b, detail::triangle_triangle_first_stage(a, b)).first;
}
template <class F>
Decision decide(const Triangle<F>& a, const Triangle<F>& b) {
  check(a, "triangle A");
  check(b, "triangle B");
  if (const int f = detail::triangle_triangle_first_stage(a, b); f != filters::triangle_triangle::unknown)
    return {f != 0, true};
  return detail::triangle_triangle_eval(a, b, 2).second;
}

}  // namespace cdref::robust
