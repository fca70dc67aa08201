// cdref/exact/rationals.hpp - the exact side without CORE::Expr: the generic core plus
// number_traits for CGAL::Gmpq, CGAL::Epeck::FT and quadratic-field values over them, with
// correct rounding. What cdref's own headers and libraries include (core_expr.hpp says why);
// <cdref/exact.hpp> adds CORE::Expr.
#pragma once

#include <cdref/cdref.hpp>

#include "quadratic.hpp"
#include "rounding.hpp"
#include "traits.hpp"
