// cdref/oracle/triangle_triangle.hpp - the fast exact classification oracle for two triangles
// (Section 3.4) at double inputs: what book::intersect (book/triangle_triangle.hpp) returns at
// CGAL::Gmpq, in three stages.
//
//   1. filter    a separating plane, then the six edge-triangle casts, in double with
//                static error bounds (filters/triangle_filter.hpp derives them; the robust
//                tier runs the same stage first);
//   2. double word  a separating plane, and the whole test of a coplanar pair, exactly on the
//                inputs read as integers on a grid per coordinate axis (filters/triangle_grid.hpp);
//                stage 1's tests with the signs it leaves on double words
//                (filters/triangle_words.hpp), then the robust version's evaluation
//                (robust/triangle_triangle.hpp), certain when every comparison is
//                (Stage::expansion names this stage here);
//   3. rational  book::intersect at CGAL::Gmpq.
#pragma once

#include <cdref/cdref.hpp>
#include <cdref/exact/rationals.hpp>
#include <cdref/oracle/ray_triangle.hpp>
#include <cdref/oracle/rational.hpp>
#include <cdref/oracle/stage.hpp>
#include <cdref/filters/triangle_filter.hpp>
#include <cdref/filters/triangle_grid.hpp>
#include <cdref/filters/triangle_words.hpp>
#include <cdref/robust/triangle_triangle.hpp>

namespace cdref::oracle {

namespace triangle_triangle {

using namespace cdref::filters::triangle_triangle;  // the filter and the double words (the first stages)

inline int double_word(const Triangle<double>& a, const Triangle<double>& b) {
  // a pair that may be coplanar on the grid first: stage 1's tests on words took about 1,000 ns
  // a case on the coplanar family and left it open
  const bool flat = maybe_coplanar(a, b);
  if (const int r = flat ? on_grid(a, b) : unknown; r != unknown) return r;
  if (const int r = tests_on_words(a, b); r != unknown) return r;
  if (const int r = flat ? unknown : on_grid(a, b); r != unknown) return r;
  const robust::Decision d = robust::detail::triangle_triangle_eval(a, b, 2).second;
  return d.certain ? int(d.value) : unknown;
}
inline bool rational(const Triangle<double>& a, const Triangle<double>& b) {
  return book::intersect(rational_inputs::toq(a), rational_inputs::toq(b)).intersect;
}
inline int at_stage(Stage st, const Triangle<double>& a, const Triangle<double>& b) {
  return st == Stage::filter ? filter(a, b) : st == Stage::expansion ? double_word(a, b) : int(rational(a, b));
}

}  // namespace triangle_triangle

inline bool classify(const Triangle<double>& a, const Triangle<double>& b, Stage* used = nullptr) {
  check(a, "triangle A");
  check(b, "triangle B");
  for (Stage st : {Stage::filter, Stage::expansion}) {
    const int r = triangle_triangle::at_stage(st, a, b);
    if (r != triangle_triangle::unknown) {
      if (used) *used = st;
      return r != 0;
    }
  }
  if (used) *used = Stage::rational;
  return triangle_triangle::rational(a, b);
}

}  // namespace cdref::oracle
