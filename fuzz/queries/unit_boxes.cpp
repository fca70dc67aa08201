// fuzz/queries/unit_boxes.cpp - the descriptors of the axis-aligned box queries (Section 3.2) and
// of the oriented-box queries (Section 3.3: the separating-axis queries, the casts and
// sphere-obb): one of the three translation units that describe the queries (their evaluations at
// the exact types are exact_paths.cpp's), its groups together because they share much of what
// they instantiate (groups.hpp).
#include <cdref/fuzz/describe.hpp>
#include <cdref/fuzz/truth_api.hpp>

#include "group_boxes.hpp"
#include "group_obb_casts.hpp"
#include "group_sat_obbs.hpp"
#include "group_sphere_obb.hpp"
#include "groups.hpp"

CDREF_GROUP_UNIT(box_queries, CDREF_BOX_QUERIES)
CDREF_GROUP_UNIT(obb_queries, CDREF_OBB_QUERIES)
CDREF_GROUP_UNIT(obb_cast_queries, CDREF_OBB_CAST_QUERIES)
CDREF_GROUP_UNIT(sphere_obb_queries, CDREF_SPHERE_OBB_QUERIES)
