// src/peers/fcl.hpp - FCL's functions in `cdref peers` (libfcl-dev, FCL 0.7 at double): their
// adapters, built in their own translation unit (src/peers/fcl.cpp: FCL's headers are heavy).
#pragma once

#include <vector>

#include "adapter.hpp"

namespace cdref::peers {

/// FCL's adapters: OBB<double>::overlap, fcl::collide on one-triangle meshes against a box (with
/// each of its narrow-phase solvers) and against a triangle, and fcl::collide with fcl::distance
/// on a sphere against a triangle, a box and a sphere.
std::vector<Adapter> fcl_adapters();

}  // namespace cdref::peers
