// fuzz/queries/triangles.cpp - the descriptors of sphere-triangle and triangle-triangle (Section
// 3.4): one of the few translation units that instantiate the exact types (groups.hpp).
#include <cdref/fuzz/describe.hpp>
#include <cdref/fuzz/truth_api.hpp>

#include "group_triangles.hpp"
#include "groups.hpp"

CDREF_GROUP_UNIT(triangle_queries, CDREF_TRIANGLE_QUERIES)
