// fuzz/queries/unit_triangles.cpp - the descriptors of the polygon queries, sphere-triangle and
// triangle-triangle, the casts on a triangle and on a fan (Section 3.4) and the separating-axis
// queries on axis-aligned boxes (Section 3.2: triangle-box is the test polygon-box runs on each
// triangle of its fan): one of the three translation units that describe the queries (their
// evaluations at the exact types are exact_paths.cpp's), its groups together because they share
// most of what they instantiate (groups.hpp).
#include <cdref/fuzz/describe.hpp>
#include <cdref/fuzz/truth_api.hpp>

#include "group_polygons.hpp"
#include "group_sat_boxes.hpp"
#include "group_triangle_casts.hpp"
#include "group_triangles.hpp"
#include "groups.hpp"

CDREF_GROUP_UNIT(polygon_queries, CDREF_POLYGON_QUERIES)
CDREF_GROUP_UNIT(triangle_queries, CDREF_TRIANGLE_QUERIES)
CDREF_GROUP_UNIT(triangle_cast_queries, CDREF_TRIANGLE_CAST_QUERIES)
CDREF_GROUP_UNIT(sat_box_queries, CDREF_SAT_BOX_QUERIES)
