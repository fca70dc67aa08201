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

}  // namespace cdref::fuzz
