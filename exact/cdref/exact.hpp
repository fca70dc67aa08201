// cdref/exact.hpp - the exact side: the generic core plus number_traits for CGAL::Gmpq,
// CGAL::Epeck::FT, CORE::Expr and quadratic-field values, with correct rounding.
// (exact/rationals.hpp is the same without CORE::Expr, for translation units that do not use it.)
#pragma once

#include "exact/rationals.hpp"
#include "exact/core_expr.hpp"
