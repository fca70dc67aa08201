// fuzz/queries/group_sat_boxes.hpp - the group of the separating-axis queries on axis-aligned boxes
// (Section 3.3): its specs and its list, one X(spec, Result, name, A, B) line a query (groups.hpp
// says what the fields are). Adding a query to the group is its spec's include and its line here;
// unit_triangles.cpp describes the group (with the others it shares most with) and exact_paths.cpp
// compiles each query's evaluations at the exact types.
#pragma once

#include "segment_box.hpp"
#include "triangle_box.hpp"

#define CDREF_SAT_BOX_QUERIES(X)                            \
  X(SegmentBox<false>, Separation, separate, Segment, Box)  \
  X(SegmentBox<true>, Separation, separate, Ray, Box)       \
  X(TriangleBox, Separation, separate, Triangle, Box)
