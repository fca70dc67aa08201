// fuzz/queries/groups.hpp - the translation units that describe the queries, each a group of
// specs (fuzz/queries/<query>.hpp) instantiated together to keep the exact types' compile
// time in few units. The registry (fuzz/queries.cpp) orders them by id. Each group's specs are
// listed once, below: the group describes them, and fuzz/queries/core_rows.cpp (the one unit of
// the library that includes CORE) instantiates their CORE::Expr row of the cost report; a
// spec's header is included by its group's file and by core_rows.cpp.
#pragma once

#include <cdref/fuzz/campaign.hpp>
#include <vector>

namespace cdref::fuzz {

std::vector<QueryInfo> sphere_queries();  // fuzz/queries/spheres.cpp
std::vector<QueryInfo> box_queries();     // fuzz/queries/boxes.cpp
std::vector<QueryInfo> sat_box_queries();  // fuzz/queries/sat_boxes.cpp
std::vector<QueryInfo> obb_queries();      // fuzz/queries/sat_obbs.cpp
std::vector<QueryInfo> triangle_queries(); // fuzz/queries/triangles.cpp
std::vector<QueryInfo> triangle_cast_queries();  // fuzz/queries/triangle_casts.cpp
std::vector<QueryInfo> polygon_queries();        // fuzz/queries/polygons.cpp

}  // namespace cdref::fuzz

// X(spec) for every spec (in cdref::fuzz::queries) of each group, in the group's order
#define CDREF_SPHERE_QUERIES(X) X(SphereSphere) X(SphereCast<false>) X(SphereCast<true>) X(SegmentSphere) X(SphereBox)
#define CDREF_BOX_QUERIES(X) X(BoxBox) X(BoxCast<false>) X(BoxCast<true>)
#define CDREF_SAT_BOX_QUERIES(X) X(SegmentBox<false>) X(SegmentBox<true>) X(TriangleBox)
#define CDREF_OBB_QUERIES(X) \
  X(ObbObb) X(ShapeObb<false>) X(ShapeObb<true>) X(ObbCast<false>) X(ObbCast<true>) X(SphereObb)
#define CDREF_TRIANGLE_QUERIES(X) X(SphereTriangle) X(TriangleTriangle)
#define CDREF_TRIANGLE_CAST_QUERIES(X) \
  X(TriangleCast<true>) X(TriangleCast<false>) X(FanCastQuery<true>) X(FanCastQuery<false>)
#define CDREF_POLYGON_QUERIES(X) \
  X(PolygonCast<true>) X(PolygonCast<false>) X(PolygonPolygon) X(PolygonBox) X(PolygonSphere)
// a group's descriptors, as the elements of a braced list
#define CDREF_DESCRIBE(S) spec::describe<queries::S>(),
