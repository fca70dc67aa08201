// cdref/oracle/stages.hpp - the runner of the exact classification oracle's stages, for the
// queries whose stages are written out by hand: sphere-sphere, the sphere casts, segment-sphere,
// box-box, the box casts and sphere-box. Each of those queries' files (sphere_sphere.hpp,
// sphere_casts.hpp, box_box.hpp, box_casts.hpp, sphere_box.hpp) holds its stages and its
// classify(), and includes this file; expansions.hpp says what the stages share and how each is
// exact.
//
// The stages in order: the filter (`unknown` where it cannot decide), the robust tier's double
// words where the query has them (`double_word`, reported as the expansion stage), the
// expansions (`unknown` outside their range), then the rationals, which always decide. The
// runner finds a query's functions by argument-dependent lookup through the tag it passes
// (below; the filters' own functions through the tag's base, cdref/filters/stage_tags.hpp), so a
// query's file needs this file alone, and an edit to one query's stages recompiles the units
// that use that query.
#pragma once

#include <cdref/filters/stage_tags.hpp>
#include <cdref/oracle/expansions.hpp>
#include <cdref/oracle/stage.hpp>
#include <cdref/primitives.hpp>

namespace cdref::oracle::staged {

using namespace cdref::filters::staged;  // the filters (the first stage) and `unknown`

// The tags that name a formulation to the stages (each stage function's last argument, passed
// on by the runner): `plain`, the query's own algorithm, derived from the filters' tag so that
// argument-dependent lookup finds the filters' functions too; `alg32`, Algorithm 3.2's
// formulation of segment-sphere (book::intersect(Segment, Sphere); the cast's hit decides it too).
struct plain : filters::staged::plain {};
struct alg32 {};

// One stage alone on validated inputs: 0 or 1, or `unknown` when that stage cannot decide
// (the filter) or does not apply (expansion outside its range). For tests and benchmarks.
template <class A, class B, class Tag = plain>
int at_stage(Stage st, const A& a, const B& b, Tag tag = {}) {
  switch (st) {
    case Stage::filter:
      return filter(a, b, tag);
    case Stage::expansion:
      return expansion(a, b, tag);
    default:
      return int(rational(a, b, tag));
  }
}

// All the stages in order (the filter's answer given where the caller has it: `unknown`).
template <class A, class B, class Tag>
bool run(Stage* used, int filtered, const A& a, const B& b, Tag tag) {
  int r = filtered;
  if (r != unknown) {
    if (used) *used = Stage::filter;
    return r != 0;
  }
  if constexpr (requires { double_word(a, b, tag); }) {
    r = double_word(a, b, tag);
    if (r != unknown) {
      if (used) *used = Stage::expansion;
      return r != 0;
    }
  }
  r = expansion(a, b, tag);
  if (r != unknown) {
    if (used) *used = Stage::expansion;
    return r != 0;
  }
  if (used) *used = Stage::rational;
  return rational(a, b, tag);
}

// ---- The input checks folded into the filter: sphere-sphere, the sphere casts, Algorithm
// 3.2, sphere-box, box-box, the box casts ----
// For these filters a valid input pays the filter alone: the checks (a branch per vector)
// cost as much as the filter's arithmetic on sphere-sphere and half of it on the casts. Sound
// because each of them decides only where its range tests passed, and those tests fail on
// every infinity or NaN among the inputs (an infinite or NaN operand makes the tested sum
// infinite or NaN):
//   sphere-sphere   m = |cA - cB|^2 + (rhoA + rhoB)^2 in range: every coordinate and radius;
//   the casts       every decided path of hit_sphere_logic passes sigma's range test (|s|^2,
//                   |r|^2 in [2^-480, 2^480], rho^2 <= 2^480: source, centre, target or
//                   direction, radius; a ray's zero direction fails |r|^2 >= 2^-480), or, for a
//                   segment whose target equals its source, ss_rho2's (source, centre, radius);
//   Algorithm 3.2   sr's test on |s|^2 + |r|^2 first (source, centre, target), then ss_rho2's,
//                   tt_rho2's or sigma's, each of which bounds rho^2 too;
//   sphere-box      m = sum (|c_i - b_i| + h_i)^2 + rho^2: both centres, the extents, the radius;
//   box-box         per axis m = |cA - cB| + eA + eB in range, or 0 (with eA, eB >= 0 both
//                   extents and the difference are then 0, and a difference of two infinities
//                   is NaN): both centres and both extents.
//   the box casts   hit_box_logic takes every outcode's sign before it decides anything, and
//                   outcode_sign refuses |L~| > 2^1000, NaN included: L~ = fl(p_i - c_i) -+ h_i
//                   at the source and (a segment) at the target cover both points, the centre
//                   and the extents; a ray's direction only enters through its signs and the
//                   pairs, so it is tested first (finite, not zero) with the extents' signs.
//                   The separating axes before them (axes_filter) decide only where
//                   sum |fl(p_i - c_i)| + h_i over both points and |r|_1 are finite: every
//                   input.
// What no range test sees, a negative radius or extent (its square or its sum with |c_i| can be
// in range), is tested before the filter (a NaN fails that test too): signs_valid, and
// unseen_valid for a pair (box_casts.hpp gives the ray and the box theirs: the direction too).
// Every input the filter leaves undecided, and every bad one, takes the checks
// (cdref::invalid_input naming what is wrong, the same message as before) and then all the
// stages, out of line.
// (signs_valid(Box) and direction_valid: filters/box_cast_filter.hpp)
inline bool signs_valid(const Sphere<double>& s, plain = {}) { return s.radius >= 0; }
inline bool signs_valid(const Segment<double>&, plain = {}) { return true; }
inline bool signs_valid(const Ray<double>&, plain = {}) { return true; }  // a zero direction: sigma's range test
template <class A, class B, class Tag>
bool unseen_valid(const A& a, const B& b, Tag) {
  return signs_valid(a, plain{}) && signs_valid(b, plain{});
}

// `filtered`: the filter's answer where it ran (then `unknown`), else run it after the checks.
template <class A, class B, class Tag>
[[gnu::noinline]] bool checked_run(Stage* used, bool filtered, const A& a, const char* na, const B& b, const char* nb,
                                   Tag tag) {
  check(a, na);
  check(b, nb);
  return run(used, filtered ? unknown : filter(a, b, tag), a, b, tag);
}
// The classification with the checks after the filter (for the pairs above only).
template <class A, class B, class Tag = plain>
bool filter_first(Stage* used, const A& a, const char* na, const B& b, const char* nb, Tag tag = {}) {
  const bool valid = unseen_valid(a, b, tag);
  if (valid) {
    const int r = filter(a, b, tag);
    if (r != unknown) [[likely]] {
      if (used) *used = Stage::filter;
      return r != 0;
    }
  }
  return checked_run(used, valid, a, na, b, nb, tag);
}

}  // namespace cdref::oracle::staged
