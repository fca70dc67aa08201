// fuzz/queries/core_rows.cpp - the cost report's row "book at CORE::Expr" (the truth's
// formulation where the book is not the truth) for every query: the one translation unit of
// the campaign library that includes CORE. CGAL ships CORE header-only, and a unit that
// includes it compiles most of CORE's functions (cdref/exact/core_expr.hpp); here that is
// paid once instead of once per query group. The queries come from the groups' lists
// (groups.hpp), so a query added to a group has its row here too.
#include <cdref/exact/core_expr.hpp>
#include <cdref/fuzz/describe.hpp>

#include "box_box.hpp"
#include "box_casts.hpp"
#include "fan_casts.hpp"
#include "groups.hpp"
#include "obb_casts.hpp"
#include "obb_obb.hpp"
#include "polygons.hpp"
#include "segment_box.hpp"
#include "segment_sphere.hpp"
#include "shape_obb.hpp"
#include "sphere_box.hpp"
#include "sphere_casts.hpp"
#include "sphere_obb.hpp"
#include "sphere_sphere.hpp"
#include "sphere_triangle.hpp"
#include "triangle_box.hpp"
#include "triangle_casts.hpp"
#include "triangle_triangle.hpp"

namespace cdref::fuzz::spec {

template <class Spec>
TimedRow::Batch core_expr_row(const std::vector<Inputs>& cases, Mode m) {
  return exact_row<Spec, CORE::Expr>(cases, m);
}

#define CDREF_CORE_ROW(S, ...) \
  template TimedRow::Batch core_expr_row<queries::S>(const std::vector<Inputs>&, Mode);
CDREF_SPHERE_QUERIES(CDREF_CORE_ROW)
CDREF_BOX_QUERIES(CDREF_CORE_ROW)
CDREF_SAT_BOX_QUERIES(CDREF_CORE_ROW)
CDREF_OBB_QUERIES(CDREF_CORE_ROW)
CDREF_TRIANGLE_QUERIES(CDREF_CORE_ROW)
CDREF_TRIANGLE_CAST_QUERIES(CDREF_CORE_ROW)
CDREF_POLYGON_QUERIES(CDREF_CORE_ROW)

}  // namespace cdref::fuzz::spec
