// fuzz/queries/triangle_casts.cpp - the descriptors of the Section 3.4 casts on a triangle and on
// a fan of triangles (mesh level): one
// of the few translation units that instantiate the exact types.
#include <cdref/fuzz/describe.hpp>

#include "groups.hpp"
#include "fan_casts.hpp"
#include "triangle_casts.hpp"

namespace cdref::fuzz {

std::vector<QueryInfo> triangle_cast_queries() {
  return {spec::describe<queries::TriangleCast<true>>(), spec::describe<queries::TriangleCast<false>>(),
          spec::describe<queries::FanCastQuery<true>>(), spec::describe<queries::FanCastQuery<false>>()};
}

}  // namespace cdref::fuzz
