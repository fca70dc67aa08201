// fuzz/queries/polygons.cpp - the descriptors of the Section 3.4 polygon queries: one of the few
// translation units that instantiate the exact types.
#include <cdref/fuzz/describe.hpp>
#include <cdref/fuzz/truth_api.hpp>

#include "groups.hpp"
#include "polygons.hpp"

CDREF_POLYGON_QUERIES(CDREF_TRUTH)

namespace cdref::fuzz {

std::vector<QueryInfo> polygon_queries() { return {CDREF_POLYGON_QUERIES(CDREF_DESCRIBE)}; }

}  // namespace cdref::fuzz
