// fuzz/queries/obb_casts.cpp - the descriptors of the casts on an oriented box (Section 3.3): one
// of the few translation units that instantiate the exact types (groups.hpp).
#include <cdref/fuzz/describe.hpp>
#include <cdref/fuzz/truth_api.hpp>

#include "group_obb_casts.hpp"
#include "groups.hpp"

CDREF_GROUP_UNIT(obb_cast_queries, CDREF_OBB_CAST_QUERIES)
