// fuzz/queries/group_triangle_casts.hpp - the group of the casts on a triangle and on a fan of
// triangles (Section 3.4): its specs and its list, one X(spec, Result, name, A, B) line a query
// (groups.hpp says what the fields are). Adding a query to the group is its spec's include and its
// line here; unit_triangles.cpp describes the group (with the others it shares most with) and
// exact_paths.cpp compiles each query's evaluations at the exact types.
#pragma once

#include "fan_casts.hpp"
#include "triangle_casts.hpp"

#define CDREF_TRIANGLE_CAST_QUERIES(X)                           \
  X(TriangleCast<true>, TriangleCast, cast, Ray, Triangle)       \
  X(TriangleCast<false>, TriangleCast, cast, Segment, Triangle)  \
  X(FanCastQuery<true>, FanCast, cast, Ray, Fan)                 \
  X(FanCastQuery<false>, FanCast, cast, Segment, Fan)
