// fuzz/queries/boxes.cpp - the descriptors of the axis-aligned box queries (Section 3.2):
// one of the few translation units that instantiate the exact types.
#include <cdref/fuzz/describe.hpp>
#include <cdref/fuzz/truth_api.hpp>

#include "box_box.hpp"
#include "box_casts.hpp"
#include "groups.hpp"

CDREF_BOX_QUERIES(CDREF_TRUTH)

namespace cdref::fuzz {

std::vector<QueryInfo> box_queries() { return {CDREF_BOX_QUERIES(CDREF_DESCRIBE)}; }

}  // namespace cdref::fuzz
