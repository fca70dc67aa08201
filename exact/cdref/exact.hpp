// cdref/exact.hpp - the exact side: the generic core plus number_traits for CGAL::Gmpq,
// CGAL::Epeck::FT, CORE::Expr and quadratic-field values, with correct rounding.
#pragma once

#include <cdref/cdref.hpp>

#include "exact/quadratic.hpp"
#include "exact/rounding.hpp"
#include "exact/traits.hpp"
