// fuzz/queries/exact_paths.cpp - every query's evaluations at the exact types, in one translation
// unit of the campaign library compiled at -O1: the truth at CGAL::Gmpq (the exact path of `cdref
// oracle`, of the truth API and of the staged path's last stage), the book at CGAL::Gmpq and
// CGAL::Epeck::FT, and the cost report's rows at CGAL::Gmpq, CGAL::Epeck::FT, CORE::Expr and MPFR.
// The query units (unit_*.cpp) call them through their declarations in cdref/fuzz/spec.hpp,
// describe.hpp and truth_api.hpp and compile none of them.
//
// Why apart, and why -O1: an exact evaluation's time is GMP's, MPFR's and CGAL's arithmetic, not
// what -O3's inlining and loop passes do to cdref's own code, and these instantiations were nearly
// a third of the query units' compile at -O3 (groups.hpp: the figures). This is also the one unit
// of the library that includes CORE: CGAL ships it header-only and a unit that includes it compiles
// most of CORE's functions (cdref/exact/core_expr.hpp). The queries come from the groups' lists
// (groups.hpp), so a query added to a group has its exact paths here too; a new group adds its
// header below.
#include <cdref/exact/core_expr.hpp>
#include <cdref/fuzz/describe.hpp>
#include <cdref/fuzz/truth_api.hpp>

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

template <class Spec, class F>
Answer gmpq_truth_at(const Inputs& in, bool values, bool certified) {
  return truth_at<Spec, CGAL::Gmpq, F>(in, values, certified);
}

template <class Spec, class T>
Answer exact_book_at(const Inputs& in) {
  return book_at<Spec, T, double>(in, true);
}

template <class Spec>
bool gmpq_classification(const DoubleA<Spec>& a, const DoubleB<Spec>& b) {
  return classification_at<Spec, CGAL::Gmpq>(a, b);
}

template <class Spec>
double gmpq_enter(const Inputs& in) {
  if constexpr (is_cast<Spec>) {
    return entry_at<Spec, CGAL::Gmpq>(in);
  } else {
    throw std::logic_error(std::string(Spec::name) + " is not a cast: it has no lambda_enter");
  }
}

template <class Spec, class F>
TruthResult<Spec, F, DoubleA<Spec>, DoubleB<Spec>> gmpq_result(const DoubleA<Spec>& a, const DoubleB<Spec>& b) {
  return rounded<F>(truth_formulation<Spec>(rebind<CGAL::Gmpq>(a), rebind<CGAL::Gmpq>(b), unsigned(want_all)));
}

template <class Spec, class T>
TimedRow::Batch exact_type_row(const std::vector<Inputs>& cases) {
  return exact_row<Spec, T, exact_mode<Spec>>(cases);
}

template <class Spec>
TimedRow::Batch mpfr_book_row(const std::vector<Inputs>& cases) {
  return book_row<Spec, mpfr::mpreal, full_mode<Spec>>(cases);
}

// every query's instantiations
#define CDREF_EXACT_PATHS(S, ...)                                                                        \
  template Answer gmpq_truth_at<queries::S, float>(const Inputs&, bool, bool);                            \
  template Answer gmpq_truth_at<queries::S, double>(const Inputs&, bool, bool);                           \
  template Answer gmpq_truth_at<queries::S, long double>(const Inputs&, bool, bool);                      \
  template Answer exact_book_at<queries::S, CGAL::Gmpq>(const Inputs&);                                   \
  template Answer exact_book_at<queries::S, CGAL::Epeck::FT>(const Inputs&);                              \
  template bool gmpq_classification<queries::S>(const DoubleA<queries::S>&, const DoubleB<queries::S>&); \
  template double gmpq_enter<queries::S>(const Inputs&);                                                  \
  template TruthResult<queries::S, float, DoubleA<queries::S>, DoubleB<queries::S>>                       \
  gmpq_result<queries::S, float>(const DoubleA<queries::S>&, const DoubleB<queries::S>&);                 \
  template TruthResult<queries::S, double, DoubleA<queries::S>, DoubleB<queries::S>>                      \
  gmpq_result<queries::S, double>(const DoubleA<queries::S>&, const DoubleB<queries::S>&);                \
  template TimedRow::Batch exact_type_row<queries::S, CGAL::Gmpq>(const std::vector<Inputs>&);            \
  template TimedRow::Batch exact_type_row<queries::S, CGAL::Epeck::FT>(const std::vector<Inputs>&);       \
  template TimedRow::Batch exact_type_row<queries::S, CORE::Expr>(const std::vector<Inputs>&);            \
  template TimedRow::Batch mpfr_book_row<queries::S>(const std::vector<Inputs>&);
#define CDREF_EXACT_GROUP(fn, list) list(CDREF_EXACT_PATHS)
CDREF_QUERY_GROUPS(CDREF_EXACT_GROUP)

}  // namespace cdref::fuzz::spec
