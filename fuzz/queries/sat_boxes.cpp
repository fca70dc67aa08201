// fuzz/queries/sat_boxes.cpp - the descriptors of the Section 3.3 queries on axis-aligned
// boxes: one of the few translation units that instantiate the exact types.
#include <cdref/fuzz/describe.hpp>
#include <cdref/fuzz/truth_api.hpp>

#include "groups.hpp"
#include "segment_box.hpp"
#include "triangle_box.hpp"

CDREF_SAT_BOX_QUERIES(CDREF_TRUTH)

namespace cdref::fuzz {

std::vector<QueryInfo> sat_box_queries() { return {CDREF_SAT_BOX_QUERIES(CDREF_DESCRIBE)}; }

}  // namespace cdref::fuzz
