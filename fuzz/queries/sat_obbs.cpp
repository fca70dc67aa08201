// fuzz/queries/sat_obbs.cpp - the descriptors of the separating-axis queries on oriented boxes
// (Section 3.3): one of the few translation units that instantiate the exact types
// (groups.hpp).
#include <cdref/fuzz/describe.hpp>
#include <cdref/fuzz/truth_api.hpp>

#include "group_sat_obbs.hpp"
#include "groups.hpp"

CDREF_GROUP_UNIT(obb_queries, CDREF_OBB_QUERIES)
