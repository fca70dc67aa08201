// fuzz/queries/triangle_casts.cpp - the descriptors of the Section 3.4 casts on a triangle and on
// a fan of triangles (mesh level): one
// of the few translation units that instantiate the exact types.
#include <cdref/fuzz/describe.hpp>
#include <cdref/fuzz/truth_api.hpp>

#include "groups.hpp"
#include "fan_casts.hpp"
#include "triangle_casts.hpp"

CDREF_TRIANGLE_CAST_QUERIES(CDREF_TRUTH)

namespace cdref::fuzz {

std::vector<QueryInfo> triangle_cast_queries() { return {CDREF_TRIANGLE_CAST_QUERIES(CDREF_DESCRIBE)}; }

}  // namespace cdref::fuzz
