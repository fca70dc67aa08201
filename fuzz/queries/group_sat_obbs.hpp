// fuzz/queries/group_sat_obbs.hpp - the group of the separating-axis queries on oriented boxes
// (Section 3.3): its specs and its list, one X(spec, Result, name, A, B) line a query (groups.hpp
// says what the fields are). Adding a query to the group is its spec's include and its line here;
// unit_boxes.cpp describes the group (with the others it shares most with) and exact_paths.cpp
// compiles each query's evaluations at the exact types.
#pragma once

#include "obb_obb.hpp"
#include "shape_obb.hpp"

#define CDREF_OBB_QUERIES(X)                                      \
  X(ObbObb, Separation, separate, OrientedBox, OrientedBox)       \
  X(ShapeObb<false>, Separation, separate, Segment, OrientedBox)  \
  X(ShapeObb<true>, Separation, separate, Triangle, OrientedBox)
