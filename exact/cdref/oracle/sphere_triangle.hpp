// cdref/oracle/sphere_triangle.hpp - the fast exact classification oracle for a sphere and a
// triangle (Section 3.4) at double inputs: what the book (book/sphere_triangle.hpp) returns at
// CGAL::Gmpq, in three stages.
//
//   1. filter    two certificates from one point of the triangle in double with static
//                error bounds (filters/triangle_filter.hpp derives them; the robust
//                tier runs the same stage first);
//   2. double word  stage 1's two certificates on double words (filters/triangle_words.hpp: a
//                sphere 2^-52 from tangency), then the robust version's evaluation
//                (robust/sphere_triangle.hpp), certain when every decisive comparison is
//                (Stage::expansion names this stage here);
//   3. rational  the book at CGAL::Gmpq.
#pragma once

#include <cdref/cdref.hpp>
#include <cdref/exact/rationals.hpp>
#include <cdref/oracle/rational.hpp>
#include <cdref/oracle/stage.hpp>
#include <cdref/filters/triangle_filter.hpp>
#include <cdref/filters/triangle_words.hpp>
#include <cdref/robust/sphere_triangle.hpp>
#include <cmath>

namespace cdref::oracle {

namespace sphere_triangle {

using namespace cdref::filters::sphere_triangle;  // the filter and the double words (the first stages)

inline int double_word(const Sphere<double>& s, const Triangle<double>& t) {
  if (const int r = certificates_on_words(s, t); r != unknown) return r;
  const robust::Decision d = robust::detail::sphere_triangle_words(s, t, want_proximity).second;
  return d.certain ? int(d.value) : unknown;
}
inline bool rational(const Sphere<double>& s, const Triangle<double>& t) {
  return book::intersect(rational_inputs::toq(s), rational_inputs::toq(t));
}
inline int at_stage(Stage st, const Sphere<double>& s, const Triangle<double>& t) {
  return st == Stage::filter ? filter(s, t) : st == Stage::expansion ? double_word(s, t) : int(rational(s, t));
}

}  // namespace sphere_triangle

// The stages on inputs already checked (the polygon's fan triangles: polygon.hpp).
inline bool classify_checked(const Sphere<double>& s, const Triangle<double>& t, Stage* used = nullptr) {
  for (Stage st : {Stage::filter, Stage::expansion}) {
    const int r = sphere_triangle::at_stage(st, s, t);
    if (r != sphere_triangle::unknown) {
      if (used) *used = st;
      return r != 0;
    }
  }
  if (used) *used = Stage::rational;
  return sphere_triangle::rational(s, t);
}
inline bool classify(const Sphere<double>& s, const Triangle<double>& t, Stage* used = nullptr) {
  check(s, "sphere");
  check(t, "triangle");
  return classify_checked(s, t, used);
}

}  // namespace cdref::oracle
