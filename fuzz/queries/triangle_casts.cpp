// fuzz/queries/triangle_casts.cpp - the descriptors of the casts on a triangle and on a fan of
// triangles (Section 3.4): one of the few translation units that instantiate the exact types
// (groups.hpp).
#include <cdref/fuzz/describe.hpp>
#include <cdref/fuzz/truth_api.hpp>

#include "group_triangle_casts.hpp"
#include "groups.hpp"

CDREF_GROUP_UNIT(triangle_cast_queries, CDREF_TRIANGLE_CAST_QUERIES)
