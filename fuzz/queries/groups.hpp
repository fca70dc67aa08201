// fuzz/queries/groups.hpp - the query groups, each a list of specs (fuzz/queries/<query>.hpp),
// the translation units that instantiate them, and the one list of the groups.
//
// A group is a header, group_<name>.hpp, that includes its specs and lists them, one line a
// query: X(spec, Result, name, A, B), the spec (in cdref::fuzz::queries), then its function of
// <cdref/truth.hpp>: the result template, the book's name for it and its two primitives
// (CDREF_TRUTH_FUNCTIONS, cdref/fuzz/truth_api.hpp). A unit, unit_<name>.cpp, includes the
// headers of its groups and says CDREF_GROUP_UNIT(function, list) for each. Adding a query to a
// group is its spec and its two lines in the group's header: the group's unit describes it, the
// registry (fuzz/queries.cpp) orders it by id, fuzz/queries/exact_paths.cpp (compiled at -O1, the
// one unit of the library that includes CORE) compiles its evaluations at the exact types. A new
// group is its header, its line below, its CDREF_GROUP_UNIT line in the unit it shares most with
// and its header's include in exact_paths.cpp.
//
// The units (a template instantiated in two units is compiled twice):
//   unit_triangles.cpp  polygons, triangles, triangle casts, sat boxes: polygon-polygon runs
//                       triangle-triangle's tests, polygon-sphere sphere-triangle's, the polygon
//                       casts the triangle casts' and polygon-box triangle-box's axes
//   unit_boxes.cpp      boxes, sat obbs, obb casts, sphere-obb
//   unit_spheres.cpp    spheres (the sphere queries, sphere-box, point-triangle)
//   exact_paths.cpp     every query at CGAL::Gmpq, CGAL::Epeck::FT, CORE::Expr and MPFR (the
//                       truth's exact path, the book's exact variant, the report's exact rows),
//                       reached from the others through declarations (cdref/fuzz/spec.hpp)
// Measured (g++ 12.2, user CPU, each unit alone one after the other, 2026-12-05): the three group
// units with every exact instantiation in them at -O3, and CORE's rows in a unit of their own,
// took 123, 82, 50 and 18 s (273 s); with the exact paths in exact_paths.cpp at -O1, 90, 50, 36
// and 41 s (216 s). (Before that, the nine groups in units of their own took 349 s against 242 s
// for these three, compiled two side by side; all nine in one unit 237 s, one job of four minutes
// that would hold up the whole build.)
//
// What an edit recompiles: a spec's header (or an algorithm only its queries include), its
// unit, exact_paths.cpp and the test units whose files include that spec (the hand filters'
// tests in test_oracle_classify.cpp, test_campaign.cpp, test_triangles.cpp; the query's own
// test; test_truth.cpp, which checks every line's public declaration); a group's header, its
// unit, exact_paths.cpp and test_truth.cpp; a query's declarations in <cdref/truth.hpp>, the
// units that call them (the tests, users' code), no query unit (the units include
// cdref/truth/basics.hpp); this file, every unit, the registry and exact_paths.cpp;
// cdref/fuzz/describe.hpp, spec.hpp, campaign.hpp or a header every spec includes (cdref.hpp,
// results.hpp, the number types), every unit and most of the library. (the order of the list
// below does not matter: the registry sorts the queries by id)
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

// each group's descriptors (fuzz/queries/unit_<name>.cpp: the unit that holds the group)
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
