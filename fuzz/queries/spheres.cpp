// fuzz/queries/spheres.cpp - the descriptors of the sphere queries (Section 3.1) and sphere-box:
// one of the few translation units that instantiate the exact types (groups.hpp).
#include <cdref/fuzz/describe.hpp>
#include <cdref/fuzz/truth_api.hpp>

#include "group_spheres.hpp"
#include "groups.hpp"

CDREF_GROUP_UNIT(sphere_queries, CDREF_SPHERE_QUERIES)
