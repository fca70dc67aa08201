// fuzz/queries/group_triangles.hpp - the group of sphere-triangle and triangle-triangle (Section
// 3.4): its specs and its list, one X(spec, Result, name, A, B) line a query (groups.hpp says what
// the fields are). Adding a query to the group is its spec's include and its line here;
// unit_triangles.cpp describes the group (with the others it shares most with) and exact_paths.cpp
// compiles each query's evaluations at the exact types.
#pragma once

#include "sphere_triangle.hpp"
#include "triangle_triangle.hpp"

#define CDREF_TRIANGLE_QUERIES(X)                                           \
  X(SphereTriangle, Proximity, proximity, Sphere, Triangle)                 \
  X(TriangleTriangle, TriangleIntersection, intersect, Triangle, Triangle)
