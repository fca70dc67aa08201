// fuzz/queries/group_polygons.hpp - the group of the polygon queries (Section 3.4): its specs and
// its list, one X(spec, Result, name, A, B) line a query (groups.hpp says what the fields are).
// Adding a query to the group is its spec's include and its line here; unit_triangles.cpp describes
// the group (with the others it shares most with) and exact_paths.cpp compiles each query's
// evaluations at the exact types.
#pragma once

#include "polygon_obb.hpp"
#include "polygons.hpp"

#define CDREF_POLYGON_QUERIES(X)                                \
  X(PolygonCast<true>, Cast, cast, Ray, Polygon)                \
  X(PolygonCast<false>, Cast, cast, Segment, Polygon)           \
  X(PolygonPolygon, detail::Bool, intersect, Polygon, Polygon)  \
  X(PolygonBox, detail::Bool, intersect, Polygon, Box)          \
  X(PolygonSphere, Proximity, proximity, Sphere, Polygon)       \
  X(PolygonObb, detail::Bool, intersect, Polygon, OrientedBox)
