// fuzz/queries/unit_spheres.cpp - the descriptors of the sphere queries (Section 3.1),
// sphere-box and point-triangle: one of the three translation units that describe the queries
// (their evaluations at the exact types are exact_paths.cpp's; groups.hpp says which groups each
// unit holds and why).
#include <cdref/fuzz/describe.hpp>
#include <cdref/fuzz/truth_api.hpp>

#include "group_spheres.hpp"
#include "groups.hpp"

CDREF_GROUP_UNIT(sphere_queries, CDREF_SPHERE_QUERIES)
