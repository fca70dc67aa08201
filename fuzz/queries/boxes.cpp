// fuzz/queries/boxes.cpp - the descriptors of the axis-aligned box queries (Section 3.2): one of
// the few translation units that instantiate the exact types (groups.hpp).
#include <cdref/fuzz/describe.hpp>
#include <cdref/fuzz/truth_api.hpp>

#include "group_boxes.hpp"
#include "groups.hpp"

CDREF_GROUP_UNIT(box_queries, CDREF_BOX_QUERIES)
