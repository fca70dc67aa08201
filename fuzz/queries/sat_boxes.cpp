// fuzz/queries/sat_boxes.cpp - the descriptors of the separating-axis queries on axis-aligned boxes
// (Section 3.3): one of the few translation units that instantiate the exact types (groups.hpp).
#include <cdref/fuzz/describe.hpp>
#include <cdref/fuzz/truth_api.hpp>

#include "group_sat_boxes.hpp"
#include "groups.hpp"

CDREF_GROUP_UNIT(sat_box_queries, CDREF_SAT_BOX_QUERIES)
