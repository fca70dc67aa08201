// fuzz/queries/core_rows.cpp - the cost report's row "book at CORE::Expr" (the truth's
// formulation where the book is not the truth) for every query: the one translation unit of
// the campaign library that includes CORE. CGAL ships CORE header-only, and a unit that
// includes it compiles most of CORE's functions (cdref/exact/core_expr.hpp); here that is
// paid once instead of once per query group. The queries come from the groups' lists
// (groups.hpp), so a query added to a group has its row here too; a new group adds its header
// below.
#include <cdref/exact/core_expr.hpp>
#include <cdref/fuzz/describe.hpp>

#include "group_boxes.hpp"
#include "group_obb_casts.hpp"
#include "group_polygons.hpp"
#include "group_sat_boxes.hpp"
#include "group_sat_obbs.hpp"
#include "group_sphere_obb.hpp"
#include "group_spheres.hpp"
#include "group_triangle_casts.hpp"
#include "group_triangles.hpp"
#include "groups.hpp"

namespace cdref::fuzz::spec {

template <class Spec>
TimedRow::Batch core_expr_row(const std::vector<Inputs>& cases) {
  return exact_row<Spec, CORE::Expr, exact_mode<Spec>>(cases);
}

#define CDREF_CORE_ROW(S, ...) \
  template TimedRow::Batch core_expr_row<queries::S>(const std::vector<Inputs>&);
#define CDREF_CORE_ROWS(fn, list) list(CDREF_CORE_ROW)
CDREF_QUERY_GROUPS(CDREF_CORE_ROWS)

}  // namespace cdref::fuzz::spec
