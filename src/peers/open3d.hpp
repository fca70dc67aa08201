// src/peers/open3d.hpp - Open3D's RaycastingScene in `cdref peers` (libopen3d-dev, float): its
// adapters, built in their own translation unit (src/peers/open3d.cpp: Open3D's headers are heavy).
#pragma once

#include <vector>

#include "adapter.hpp"

namespace cdref::peers {

/// Open3D's adapters: RaycastingScene::CastRays on one triangle and on a fan's triangles (with
/// CountIntersections), and ComputeClosestPoints with ComputeDistance from a point to one triangle.
std::vector<Adapter> open3d_adapters();

}  // namespace cdref::peers
