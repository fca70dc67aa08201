// fuzz/queries/group_boxes.hpp - the group of the axis-aligned box queries (Section 3.2): its specs
// and its list, one X(spec, Result, name, A, B) line a query (groups.hpp says what the fields are).
// Adding a query to the group is its spec's include and its line here; unit_boxes.cpp describes the
// group (with the others it shares most with) and exact_paths.cpp compiles each query's evaluations
// at the exact types.
#pragma once

#include "box_box.hpp"
#include "box_casts.hpp"

#define CDREF_BOX_QUERIES(X)                    \
  X(BoxBox, detail::Bool, intersect, Box, Box)  \
  X(BoxCast<false>, Cast, cast, Segment, Box)   \
  X(BoxCast<true>, Cast, cast, Ray, Box)
