// cdref/oracle/separating_axes.hpp - the fast exact classification oracle for the Section 3.3
// queries at double inputs: segment, ray and triangle against an axis-aligned or an oriented
// box, and oriented box against oriented box (Theorem 3.1 with the true face normals: the
// casts on an oriented box hit exactly when the segment or ray meets it, so they share it),
// and a sphere against an oriented box. classify() returns exactly what the solid's own
// formulation (cdref::solid, book::separate on the polytopes) returns at CGAL::Gmpq, in three
// stages:
//
//   1. filter    (separating axes) every candidate axis in double with one static error bound
//                for the whole query; (a segment or a ray and an oriented box) Algorithm 3.3
//                in the box's face coordinates with static bounds (box_cast_filter.hpp);
//                (two oriented boxes, a triangle and a box) Theorem 3.1 in B's face
//                coordinates first (sat_filter.hpp, filter_face_coordinates);
//                (sphere) a point of the box and a direction, each a certificate with a
//                static bound (filters/sat_filter.hpp, with their derivations: the robust
//                tier's certified decisions run them first too);
//   2. double word  (a segment or a ray and an oriented box) Algorithm 3.3 in the box's face
//                coordinates on double words, then the solid's cast decision on them; the axes
//                stage 1 left open on double words with rigorous bounds (sat_words.hpp: near
//                touching one axis of the 13 or 15); (sphere) a box with the coordinate
//                axes as sphere-box does it (sphere_box.hpp: double words, then the exact sign
//                on expansions), any other stage 1's point and direction on double words
//                (sat_words.hpp); (a triangle, a segment or a ray and a box) the 13 or 6 axes
//                exactly on the inputs read as integers on a grid per coordinate axis
//                (sat_grid.hpp: every tie of a zero-area triangle, a flat box or a face's plane
//                decided); then the robust
//                versions' evaluation of
//                the whole formulation on cdref::Bounded2 (robust/separating_axes.hpp),
//                certain when every decisive comparison is (Stage::expansion names this stage);
//   3. rational  the formulation at CGAL::Gmpq.
// classify() interleaves stages 1 and 2 where that decides sooner: the double words of what the
// cheapest filter leaves open come before the other filters (run below, and the robust tier's
// stages_before_whole, which it calls). Each stage alone (at_stage) is what the tests compare.
//
#pragma once

#include <cdref/cdref.hpp>
#include <cdref/exact/rationals.hpp>
#include <cdref/bounded/bounded.hpp>
#include <cdref/oracle/sphere_box.hpp>
#include <cdref/oracle/rational.hpp>
#include <cdref/filters/sat_filter.hpp>
#include <cdref/filters/sat_words.hpp>
#include <cdref/oracle/stage.hpp>
#include <cdref/robust/separating_axes.hpp>
#include <cmath>

namespace cdref::oracle {

namespace sat {

using namespace cdref::filters::sat;  // the filter (the first stage), its axes and `unknown`

// Stage 2: the double words: 1, 0 or unknown. (A segment or a ray and an oriented box: the
// solid's cast decision first, as in the robust tier.) `open`: the axes stage 1 left open
// (sat::filter); run on its own (at_stage), stage 2 asks stage 1 for them.
template <class A, class B>
int double_word(const A& a, const B& b, unsigned open) {
  if constexpr (robust::detail::has_cast_decision<A, B, double>)
    if (const auto h = robust::detail::cast_decision_on_words(a, b)) return int(*h);
  if (const int r = filters::sat_words::decide(a, b, open); r != unknown) return r;
  if (Separation<double> g; robust::detail::separation_on_grid(a, b, g)) return int(g.intersect);
  const auto [s, certain] = robust::detail::separation<double>(a, b);
  return certain ? int(s.intersect) : unknown;
}
template <class A, class B>
int double_word(const A& a, const B& b) {
  unsigned open = 0;
  filter(a, b, nullptr, &open);  // 0 where stage 1 decides: then only the whole formulation runs
  return double_word(a, b, open);
}

// Stage 3: Theorem 3.1 on the true normals at CGAL::Gmpq.
using rational_inputs::toq;
template <class A, class B>
bool rational(const A& a, const B& b) {
  return book::separate(book::polytope(toq(a)), book::polytope(toq(b))).intersect;
}

template <class A, class B>
int at_stage(Stage st, const A& a, const B& b) {
  switch (st) {
    case Stage::filter:
      return filter(a, b);
    case Stage::expansion:
      return double_word(a, b);
    default:
      return int(rational(a, b));
  }
}

// Stages 1 and 2 as the robust tier's certified decisions take them (robust/separating_axes.hpp,
// stages_before_whole: the double words of what the cheapest filter leaves open come before the
// other filters), then the whole formulation on double words, then CGAL::Gmpq.
template <class A, class B>
bool run(Stage* used, const A& a, const B& b) {
  bool words = false;
  int r = robust::detail::stages_before_whole<double>(a, b, &words);
  Stage st = words ? Stage::expansion : Stage::filter;
  if (Separation<double> g; r == unknown && robust::detail::separation_on_grid(a, b, g)) {
    r = int(g.intersect);
    st = Stage::expansion;
  }
  if (r == unknown) {
    const auto [s, certain] = robust::detail::separation<double>(a, b);
    if (certain) r = int(s.intersect);
    st = Stage::expansion;
  }
  if (r != unknown) {
    if (used) *used = st;
    return r != 0;
  }
  if (used) *used = Stage::rational;
  return rational(a, b);
}

}  // namespace sat

// ---- the oracle: validation as the book does it, then the stages ----
inline bool classify(const Triangle<double>& t, const Box<double>& b, Stage* used = nullptr) {
  check(t, "triangle");
  check(b, "box");
  return sat::run(used, t, b);
}
inline bool classify(const Segment<double>& s, const OrientedBox<double>& b, Stage* used = nullptr) {
  check(s, "segment");
  check(b, "oriented box");
  return sat::run(used, s, b);
}
inline bool classify(const Ray<double>& r, const OrientedBox<double>& b, Stage* used = nullptr) {
  check(r, "ray");
  check(b, "oriented box");
  return sat::run(used, r, b);
}
inline bool classify(const Triangle<double>& t, const OrientedBox<double>& b, Stage* used = nullptr) {
  check(t, "triangle");
  check(b, "oriented box");
  return sat::run(used, t, b);
}
inline bool classify(const OrientedBox<double>& a, const OrientedBox<double>& b, Stage* used = nullptr) {
  check(a, "oriented box A");
  check(b, "oriented box B");
  return sat::run(used, a, b);
}

// ---- a sphere and an oriented box ----
namespace sphere_obb {

using namespace cdref::filters::sphere_obb;  // the filter (the first stage)
// (as_axis_aligned: filters/sat_filter.hpp)
// Stage 2: an axis-aligned box takes sphere-box's second stage and then its exact sign on
// expansions (oracle/sphere_box.hpp: unknown only out of its scaled range); any other box the two
// certificates on double words, then the robust tier's evaluation of the whole formulation.
inline int double_word(const Sphere<double>& s, const OrientedBox<double>& b) {
  if (Box<double> box; as_axis_aligned(b, box)) {
    if (const int r = staged::double_word(s, box); r != unknown) return r;
    if (const int r = staged::expansion(s, box); r != unknown) return r;
  }
  if (const int r = filters::sat_words::decide(s, b); r != unknown) return r;  // the two certificates
  const robust::Decision d = robust::decide(s, b);
  return d.certain ? int(d.value) : unknown;
}
inline bool rational(const Sphere<double>& s, const OrientedBox<double>& b) {
  return solid::intersect(rational_inputs::toq(s), rational_inputs::toq(b));
}
inline int at_stage(Stage st, const Sphere<double>& s, const OrientedBox<double>& b) {
  return st == Stage::filter ? filter(s, b) : st == Stage::expansion ? double_word(s, b) : int(rational(s, b));
}
}  // namespace sphere_obb

inline bool classify(const Sphere<double>& s, const OrientedBox<double>& b, Stage* used = nullptr) {
  check(s, "sphere");
  check(b, "oriented box");
  for (Stage st : {Stage::filter, Stage::expansion}) {
    const int r = sphere_obb::at_stage(st, s, b);
    if (r != sphere_obb::unknown) {
      if (used) *used = st;
      return r != 0;
    }
  }
  if (used) *used = Stage::rational;
  return sphere_obb::rational(s, b);
}

}  // namespace cdref::oracle
