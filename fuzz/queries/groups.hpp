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

// X(spec, Result, name, A, B) for every spec (in cdref::fuzz::queries) of each group, in the
// group's order: the spec, then its function of <cdref/truth.hpp>: the result template, the
// book's name for it and its two primitives (CDREF_TRUTH_FUNCTIONS, cdref/fuzz/truth_api.hpp)
#define CDREF_SPHERE_QUERIES(X)                                  \
  X(SphereSphere, Proximity, proximity, Sphere, Sphere)          \
  X(SphereCast<false>, Cast, cast, Segment, Sphere)              \
  X(SphereCast<true>, Cast, cast, Ray, Sphere)                   \
  X(SegmentSphere, Proximity, proximity, Segment, Sphere)        \
  X(SphereBox, Proximity, proximity, Sphere, Box)
#define CDREF_BOX_QUERIES(X)                                     \
  X(BoxBox, detail::Bool, intersect, Box, Box)                   \
  X(BoxCast<false>, Cast, cast, Segment, Box)                    \
  X(BoxCast<true>, Cast, cast, Ray, Box)
#define CDREF_SAT_BOX_QUERIES(X)                                 \
  X(SegmentBox<false>, Separation, separate, Segment, Box)       \
  X(SegmentBox<true>, Separation, separate, Ray, Box)            \
  X(TriangleBox, Separation, separate, Triangle, Box)
#define CDREF_OBB_QUERIES(X)                                            \
  X(ObbObb, Separation, separate, OrientedBox, OrientedBox)             \
  X(ShapeObb<false>, Separation, separate, Segment, OrientedBox)        \
  X(ShapeObb<true>, Separation, separate, Triangle, OrientedBox)        \
  X(ObbCast<false>, Cast, cast, Segment, OrientedBox)                   \
  X(ObbCast<true>, Cast, cast, Ray, OrientedBox)                        \
  X(SphereObb, Proximity, proximity, Sphere, OrientedBox)
#define CDREF_TRIANGLE_QUERIES(X)                                       \
  X(SphereTriangle, Proximity, proximity, Sphere, Triangle)             \
  X(TriangleTriangle, TriangleIntersection, intersect, Triangle, Triangle)
#define CDREF_TRIANGLE_CAST_QUERIES(X)                                  \
  X(TriangleCast<true>, TriangleCast, cast, Ray, Triangle)              \
  X(TriangleCast<false>, TriangleCast, cast, Segment, Triangle)         \
  X(FanCastQuery<true>, FanCast, cast, Ray, Fan)                        \
  X(FanCastQuery<false>, FanCast, cast, Segment, Fan)
#define CDREF_POLYGON_QUERIES(X)                                        \
  X(PolygonCast<true>, Cast, cast, Ray, Polygon)                        \
  X(PolygonCast<false>, Cast, cast, Segment, Polygon)                   \
  X(PolygonPolygon, detail::Bool, intersect, Polygon, Polygon)          \
  X(PolygonBox, detail::Bool, intersect, Polygon, Box)                  \
  X(PolygonSphere, Proximity, proximity, Sphere, Polygon)
// a group's descriptors, as the elements of a braced list, each with its truth API attached
#define CDREF_DESCRIBE(S, ...) spec::describe_with_truth_api<queries::S>(),
// a group's functions of <cdref/truth.hpp> (at file scope)
#define CDREF_TRUTH(S, ...) CDREF_TRUTH_FUNCTIONS(S, __VA_ARGS__)
