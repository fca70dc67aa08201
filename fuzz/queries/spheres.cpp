// fuzz/queries/spheres.cpp - the descriptors of the sphere queries (Section 3.1) and
// sphere-box: one of the few translation units that instantiate the exact types.
#include <cdref/fuzz/describe.hpp>
#include <cdref/fuzz/truth_api.hpp>

#include "groups.hpp"
#include "segment_sphere.hpp"
#include "sphere_box.hpp"
#include "sphere_casts.hpp"
#include "sphere_sphere.hpp"

CDREF_SPHERE_QUERIES(CDREF_TRUTH)

namespace cdref::fuzz {

std::vector<QueryInfo> sphere_queries() { return {CDREF_SPHERE_QUERIES(CDREF_DESCRIBE)}; }

}  // namespace cdref::fuzz
