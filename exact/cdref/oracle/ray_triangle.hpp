// cdref/oracle/ray_triangle.hpp - the fast exact classification oracle for ray and segment casts
// on a triangle (Section 3.4) at double inputs: what book::hit (book/ray_triangle.hpp) returns at
// CGAL::Gmpq, in three stages.
//
//   1. filter    the orientation form of the test (w0, w1, w2, Ns, Nt) in double with static
//                error bounds (filters/triangle_filter.hpp derives them; the robust
//                tier runs the same stage first);
//   2. double word  the signs stage 1 left, on double words with rigorous bounds
//                (filters/triangle_words.hpp: a shot 2^-52 from an edge), then the book's hit()
//                run on double words (robust/words.hpp), certain when every comparison is
//                (Stage::expansion names this stage here);
//   3. rational  book::hit at CGAL::Gmpq (coplanar shots, shots through an edge or a vertex,
//                zero-area triangles).
#pragma once

#include <cdref/cdref.hpp>
#include <cdref/exact/rationals.hpp>
#include <cdref/oracle/rational.hpp>
#include <cdref/oracle/stage.hpp>
#include <cdref/filters/triangle_filter.hpp>
#include <cdref/filters/triangle_words.hpp>
#include <cdref/robust/ray_triangle.hpp>
#include <cmath>

namespace cdref::oracle {

namespace ray_triangle {

using namespace cdref::filters::ray_triangle;  // the filter and the double words (the first stages)

inline int orientation_words(const Segment<double>& s, const Triangle<double>& t) {
  return orientation_on_words(s.source, &s.target, s.target, t);
}
inline int orientation_words(const Ray<double>& r, const Triangle<double>& t) {
  return orientation_on_words(r.source, nullptr, r.direction, t);
}
template <class Shot>
int double_word(const Shot& shot, const Triangle<double>& t) {
  if (const int w = orientation_words(shot, t); w != unknown) return w;
  const auto r = robust::detail::on_words(shot, t, [](const auto& a, const auto& b) { return book::hit(a, b); });
  return r ? int(*r) : unknown;
}
template <class Shot>
bool rational(const Shot& shot, const Triangle<double>& t) {
  return book::hit(rational_inputs::toq(shot), rational_inputs::toq(t));
}
inline int at_stage(Stage st, const Segment<double>& s, const Triangle<double>& t) {
  if (st == Stage::filter) return filter(s.source, &s.target, s.target, t);
  return st == Stage::expansion ? double_word(s, t) : int(rational(s, t));
}
inline int at_stage(Stage st, const Ray<double>& r, const Triangle<double>& t) {
  if (st == Stage::filter) return filter(r.source, nullptr, r.direction, t);
  return st == Stage::expansion ? double_word(r, t) : int(rational(r, t));
}

}  // namespace ray_triangle

template <class Shot>
bool classify_triangle_cast(const Shot& shot, const Triangle<double>& t, Stage* used) {
  for (Stage st : {Stage::filter, Stage::expansion}) {
    const int r = ray_triangle::at_stage(st, shot, t);
    if (r != ray_triangle::unknown) {
      if (used) *used = st;
      return r != 0;
    }
  }
  if (used) *used = Stage::rational;
  return ray_triangle::rational(shot, t);
}
inline bool classify(const Segment<double>& s, const Triangle<double>& t, Stage* used = nullptr) {
  check(s, "segment");
  check(t, "triangle");
  return classify_triangle_cast(s, t, used);
}
inline bool classify(const Ray<double>& r, const Triangle<double>& t, Stage* used = nullptr) {
  check(r, "ray");
  check(t, "triangle");
  return classify_triangle_cast(r, t, used);
}

}  // namespace cdref::oracle
