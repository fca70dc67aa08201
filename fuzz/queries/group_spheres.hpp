// fuzz/queries/group_spheres.hpp - the group of the sphere queries (Section 3.1), sphere-box and
// point-triangle (the light closest-point queries): its specs and its list, one X(spec, Result,
// name, A, B) line a query (groups.hpp says what the fields are). Adding a query to the group is
// its spec's include and its line here; unit_spheres.cpp describes the group (a unit of its own: it
// shares little with the others) and exact_paths.cpp compiles each query's evaluations at the exact
// types.
#pragma once

#include "point_triangle.hpp"
#include "segment_sphere.hpp"
#include "sphere_box.hpp"
#include "sphere_casts.hpp"
#include "sphere_sphere.hpp"

#define CDREF_SPHERE_QUERIES(X)                            \
  X(SphereSphere, Proximity, proximity, Sphere, Sphere)    \
  X(SphereCast<false>, Cast, cast, Segment, Sphere)        \
  X(SphereCast<true>, Cast, cast, Ray, Sphere)             \
  X(SegmentSphere, Proximity, proximity, Segment, Sphere)  \
  X(SphereBox, Proximity, proximity, Sphere, Box)          \
  X(PointTriangle, Proximity, proximity, Vec3, Triangle)
