// fuzz/queries/group_sphere_obb.hpp - the group of sphere-obb (Section 3.3), alone: its
// instantiations are among the heaviest of any query (about as much compile time as the three other
// oriented-box separating-axis queries together). Its spec and its list, one X(spec, Result, name,
// A, B) line a query (groups.hpp says what the fields are); unit_boxes.cpp describes the group,
// with the oriented-box groups it shares most with, and exact_paths.cpp compiles each query's
// evaluations at the exact types.
#pragma once

#include "sphere_obb.hpp"

#define CDREF_SPHERE_OBB_QUERIES(X) X(SphereObb, Proximity, proximity, Sphere, OrientedBox)
