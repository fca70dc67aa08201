// fuzz/queries/sat_obbs.cpp - the descriptors of the queries on oriented boxes: one of the few
// translation units that instantiate the exact types.
#include <cdref/fuzz/describe.hpp>
#include <cdref/fuzz/truth_api.hpp>

#include "groups.hpp"
#include "obb_casts.hpp"
#include "obb_obb.hpp"
#include "shape_obb.hpp"
#include "sphere_obb.hpp"

CDREF_OBB_QUERIES(CDREF_TRUTH)

namespace cdref::fuzz {

std::vector<QueryInfo> obb_queries() { return {CDREF_OBB_QUERIES(CDREF_DESCRIBE)}; }

}  // namespace cdref::fuzz
