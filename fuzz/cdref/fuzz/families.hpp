// cdref/fuzz/families.hpp - the case families of the queries, by the primitives they place
// (fuzz/families.cpp). A query's spec names its families from here.
#pragma once

#include <cdref/fuzz/campaign.hpp>
#include <vector>

namespace cdref::fuzz {

std::vector<Family> sphere_sphere_family_list();
std::vector<Family> sphere_shot_family_list(bool ray);  // a segment (or a ray) and a sphere
std::vector<Family> sphere_box_family_list();
std::vector<Family> box_box_family_list();
std::vector<Family> box_shot_family_list(bool ray);     // a segment (or a ray) and a box
// fuzz/families_sat.cpp
std::vector<Family> segment_box_family_list(bool ray);  // the box-shot families and near-parallel
std::vector<Family> triangle_box_family_list();
std::vector<Family> obb_obb_family_list();
// fuzz/families_triangles.cpp
std::vector<Family> sphere_triangle_family_list();
std::vector<Family> triangle_shot_family_list(bool ray);  // a segment (or a ray) and a triangle
std::vector<Family> fan_shot_family_list(bool ray);       // a segment (or a ray) and a fan of triangles
std::vector<Family> triangle_triangle_family_list();
// fuzz/families_polygons.cpp
std::vector<Family> polygon_shot_family_list(bool ray);  // a segment (or a ray) and a polygon
std::vector<Family> polygon_polygon_family_list();
std::vector<Family> polygon_box_family_list();
std::vector<Family> polygon_sphere_family_list();
// An axis-aligned family as one against an oriented box (see families_sat.cpp).
std::vector<Family> rotated_family_list(std::vector<Family> base, std::vector<int> points, std::vector<int> vectors,
                                        std::vector<int> scalars, int center, int extent, int box_at);

}  // namespace cdref::fuzz
