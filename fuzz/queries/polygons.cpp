// fuzz/queries/polygons.cpp - the descriptors of the Section 3.4 polygon queries: one of the few
// translation units that instantiate the exact types.
#include <cdref/fuzz/describe.hpp>

#include "groups.hpp"
#include "polygons.hpp"

namespace cdref::fuzz {

std::vector<QueryInfo> polygon_queries() {
  return {spec::describe<queries::PolygonCast<true>>(), spec::describe<queries::PolygonCast<false>>(),
          spec::describe<queries::PolygonPolygon>(), spec::describe<queries::PolygonBox>(),
          spec::describe<queries::PolygonSphere>()};
}

}  // namespace cdref::fuzz
