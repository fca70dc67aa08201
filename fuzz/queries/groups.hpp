// fuzz/queries/groups.hpp - the translation units that describe the queries, each a group of
// specs (fuzz/queries/<query>.hpp) instantiated together to keep the exact types' compile
// time in few units, and the one list of those groups.
//
// A group is a header, group_<name>.hpp, that includes its specs and lists them, one line a
// query: X(spec, Result, name, A, B), the spec (in cdref::fuzz::queries), then its function of
// <cdref/truth.hpp>: the result template, the book's name for it and its two primitives
// (CDREF_TRUTH_FUNCTIONS, cdref/fuzz/truth_api.hpp); and a translation unit, <name>.cpp, that
// includes that header and says CDREF_GROUP_UNIT(function, list). Adding a query to a group is
// its spec and its two lines in the group's header: the group's unit describes it, the registry
// (fuzz/queries.cpp) orders it by id, fuzz/queries/core_rows.cpp (the one unit of the library
// that includes CORE) instantiates its CORE::Expr row of the cost report.
//
// What an edit recompiles: a spec's header (or an algorithm only its queries include), its
// group's unit, core_rows.cpp and the test units whose files include that spec (the hand
// filters' tests in test_oracle_classify.cpp, test_campaign.cpp, test_triangles.cpp; the
// query's own test; test_truth.cpp, which checks every line's public declaration); a group's
// header, its unit, core_rows.cpp and test_truth.cpp; a query's declarations in
// <cdref/truth.hpp>, the units that call them (the tests, users' code), no group (the groups
// include cdref/truth/basics.hpp); this file, every group, the registry and core_rows.cpp; cdref/fuzz/describe.hpp, spec.hpp, campaign.hpp or a header every
// spec includes (cdref.hpp, results.hpp, the number types), every group and most of the library.
// (CMakeLists.txt lists the groups' units heaviest first, so that the longest compiles start
// first; the order here does not matter: the registry sorts the queries by id.)
#pragma once

#include <cdref/fuzz/campaign.hpp>
#include <vector>

// G(function, list) for every group: the function that describes it and its list's macro.
#define CDREF_QUERY_GROUPS(G)                          \
  G(sphere_obb_queries, CDREF_SPHERE_OBB_QUERIES)      \
  G(obb_queries, CDREF_OBB_QUERIES)                    \
  G(obb_cast_queries, CDREF_OBB_CAST_QUERIES)          \
  G(triangle_queries, CDREF_TRIANGLE_QUERIES)          \
  G(polygon_queries, CDREF_POLYGON_QUERIES)            \
  G(sphere_queries, CDREF_SPHERE_QUERIES)              \
  G(sat_box_queries, CDREF_SAT_BOX_QUERIES)            \
  G(triangle_cast_queries, CDREF_TRIANGLE_CAST_QUERIES) \
  G(box_queries, CDREF_BOX_QUERIES)

namespace cdref::fuzz {

// each group's descriptors (fuzz/queries/<group>.cpp)
#define CDREF_DECLARE_GROUP(fn, list) std::vector<QueryInfo> fn();
CDREF_QUERY_GROUPS(CDREF_DECLARE_GROUP)
#undef CDREF_DECLARE_GROUP

}  // namespace cdref::fuzz

// a group's descriptors, as the elements of a braced list, each with its truth API attached
#define CDREF_DESCRIBE(S, ...) spec::describe_with_truth_api<queries::S>(),
// a group's functions of <cdref/truth.hpp> (at file scope)
#define CDREF_TRUTH(S, ...) CDREF_TRUTH_FUNCTIONS(S, __VA_ARGS__)
// A group's translation unit: its functions of <cdref/truth.hpp> and its descriptors.
#define CDREF_GROUP_UNIT(fn, list) \
  list(CDREF_TRUTH)                \
  namespace cdref::fuzz {          \
  std::vector<QueryInfo> fn() { return {list(CDREF_DESCRIBE)}; } \
  }
