// fuzz/queries/groups.hpp - the translation units that describe the queries, each a group of
// specs (fuzz/queries/<query>.hpp) instantiated together to keep the exact types' compile
// time in few units. The registry (fuzz/queries.cpp) orders them by id.
#pragma once

#include <cdref/fuzz/campaign.hpp>
#include <vector>

namespace cdref::fuzz {

std::vector<QueryInfo> sphere_queries();  // fuzz/queries/spheres.cpp
std::vector<QueryInfo> box_queries();     // fuzz/queries/boxes.cpp
std::vector<QueryInfo> sat_box_queries();  // fuzz/queries/sat_boxes.cpp
std::vector<QueryInfo> obb_queries();      // fuzz/queries/sat_obbs.cpp
std::vector<QueryInfo> triangle_queries(); // fuzz/queries/triangles.cpp
std::vector<QueryInfo> triangle_cast_queries();  // fuzz/queries/triangle_casts.cpp
std::vector<QueryInfo> polygon_queries();        // fuzz/queries/polygons.cpp

}  // namespace cdref::fuzz
