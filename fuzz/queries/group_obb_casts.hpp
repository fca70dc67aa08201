// fuzz/queries/group_obb_casts.hpp - the group of the casts on an oriented box (Section 3.3): its
// specs and its list, one X(spec, Result, name, A, B) line a query (groups.hpp says what the fields
// are). Adding a query to the group is its spec's include and its line here; unit_boxes.cpp
// describes the group (with the others it shares most with) and exact_paths.cpp compiles each
// query's evaluations at the exact types.
#pragma once

#include "obb_casts.hpp"

#define CDREF_OBB_CAST_QUERIES(X)                          \
  X(ObbCast<false>, Cast, cast, Segment, OrientedBox)      \
  X(ObbCast<true>, Cast, cast, Ray, OrientedBox)
