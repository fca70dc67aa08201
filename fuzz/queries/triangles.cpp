// fuzz/queries/triangles.cpp - the descriptors of the Section 3.4 queries: one of the few
// translation units that instantiate the exact types.
#include <cdref/fuzz/describe.hpp>
#include <cdref/fuzz/truth_api.hpp>

#include "groups.hpp"
#include "sphere_triangle.hpp"
#include "triangle_triangle.hpp"

CDREF_TRIANGLE_QUERIES(CDREF_TRUTH)

namespace cdref::fuzz {

std::vector<QueryInfo> triangle_queries() { return {CDREF_TRIANGLE_QUERIES(CDREF_DESCRIBE)}; }

}  // namespace cdref::fuzz
