// cdref/exact/core_expr.hpp - number_traits for CORE::Expr (CGAL::Epeck_with_sqrt::FT): exact
// real algebraic numbers, sqrt_type = Expr; to_double / to_float round correctly by exact
// comparison (exact/cdref/exact/rounding.hpp). CGAL::to_double(CORE::Expr) truncates and is
// used only as a guess.
//
// Apart from the rationals (rationals.hpp) because of what including CORE costs: CGAL ships it
// header-only, with namespace-scope objects (its memory pools, its extLong constants) whose
// initialisers reach most of CORE, so every translation unit that includes it compiles about
// 330 of CORE's functions whether it uses CORE::Expr or not: 5 s of CPU at -O3 on these
// machines (g++ 12.2, a file including CGAL/CORE_Expr.h alone against one including Gmpq and
// Lazy_exact_nt). cdref's own library code includes rationals.hpp; <cdref/exact.hpp> gives both.
#pragma once

#include <CGAL/CORE_Expr.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel_with_sqrt.h>

#include "traits.hpp"

namespace cdref {

namespace exact {
using Real = CORE::Expr;
}  // namespace exact

template <>
struct number_traits<CORE::Expr> : exact::field_rounding<CORE::Expr> {
  static constexpr sqrt_support sqrt_kind = sqrt_support::exact;
  using sqrt_type = CORE::Expr;
  static CORE::Expr sqrt(const CORE::Expr& x) { return CGAL::sqrt(x); }
  static std::string name() { return "CORE::Expr"; }
};

}  // namespace cdref
