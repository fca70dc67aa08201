// fuzz/queries/polygons.cpp - the descriptors of the polygon queries (Section 3.4): one of the few
// translation units that instantiate the exact types (groups.hpp).
#include <cdref/fuzz/describe.hpp>
#include <cdref/fuzz/truth_api.hpp>

#include "group_polygons.hpp"
#include "groups.hpp"

CDREF_GROUP_UNIT(polygon_queries, CDREF_POLYGON_QUERIES)
