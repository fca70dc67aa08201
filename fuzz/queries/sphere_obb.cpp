// fuzz/queries/sphere_obb.cpp - the descriptor of sphere-obb (Section 3.3): one of the few
// translation units that instantiate the exact types (groups.hpp).
#include <cdref/fuzz/describe.hpp>
#include <cdref/fuzz/truth_api.hpp>

#include "group_sphere_obb.hpp"
#include "groups.hpp"

CDREF_GROUP_UNIT(sphere_obb_queries, CDREF_SPHERE_OBB_QUERIES)
