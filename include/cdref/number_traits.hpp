/// \file
/// cdref/number_traits.hpp - the one traits point for every number type cdref runs on.
///
/// number_traits<T> tells, for a number type T:
///   is_exact     whether + - * / and comparisons are exact;
///   sqrt_kind    rounded (float types: sqrt is the nearest representable value),
///                exact   (CORE::Expr: sqrt is an exact algebraic number),
///                absent  (rationals: no square root in the field);
///   sqrt_type    the type that holds a value with a square root in it: T itself
///                when sqrt is rounded or exact, a quadratic-field value
///                a + b*sqrt(d) over T (cdref::Quad<T>, exact/) when it is absent;
///   sqrt(x)      that value, never std::sqrt(double(x)) for an exact type;
///   name()       a name for reports;
///   to_double(x), to_float(x)
///                round to nearest, ties to even, from the value x denotes. For an
///                exact type this is proven by exact comparison with the rounding
///                midpoints (exact/cdref/exact/rounding.hpp);
///   is_finite(x) false for NaN and infinities (always true for exact types).
///   to_rational(q, x)  (binary floating-point types) the exact value of x as a GMP rational;
///   unit_roundoff(), denorm_min()  (binary floating-point types) u = 2^-p and the smallest
///                positive value, for error bounds.
///
/// The primary template is left undefined: a number type that cdref does not know
/// fails to compile instead of silently going through double.
#pragma once

#include <cstdint>  // before mpfr.h: MPFR_USE_INTMAX_T declares its intmax_t functions
#include <gmp.h>
#include <mpfr.h>

#include <cmath>
#include <limits>
#include <string>

namespace cdref {

/// How a number type takes a square root: rounded (IEEE, MPFR), exact (CORE::Expr), or absent
/// (the rationals: their roots live in a quadratic field, cdref::Quad).
enum class sqrt_support { rounded, exact, absent };

template <class T, class Enable = void>
struct number_traits;  // undefined on purpose

namespace detail {
template <class F>
struct ieee_traits {
  static constexpr bool is_exact = false;
  static constexpr sqrt_support sqrt_kind = sqrt_support::rounded;
  using sqrt_type = F;
  static F sqrt(const F& x) { return std::sqrt(x); }
  static bool is_finite(const F& x) { return std::isfinite(x); }
  /// float -> double and double -> double are exact; long double -> double and any
  /// -> float are one IEEE conversion, which rounds to nearest, ties to even.
  static double to_double(const F& x) { return static_cast<double>(x); }
  static float to_float(const F& x) { return static_cast<float>(x); }
  /// u = 2^-p = epsilon / 2 (epsilon = 2^(1-p)), exact and a compile-time constant
  static constexpr F unit_roundoff() { return std::numeric_limits<F>::epsilon() / 2; }
  static constexpr F denorm_min() { return std::numeric_limits<F>::denorm_min(); }
  /// Exact: a float, double or x87 long double has at most 64 significant bits.
  static void to_rational(mpq_t q, const F& x) {
    mpfr_t m;
    mpfr_init2(m, 64);
    mpfr_set_ld(m, static_cast<long double>(x), MPFR_RNDN);
    mpfr_get_q(q, m);
    mpfr_clear(m);
  }
};
}  // namespace detail

/// IEEE float: not exact, a rounded square root, conversions by one IEEE rounding.
template <>
struct number_traits<float> : detail::ieee_traits<float> {
  static std::string name() { return "float"; }  ///< the name reports use
};
/// IEEE double: not exact, a rounded square root, conversions by one IEEE rounding.
template <>
struct number_traits<double> : detail::ieee_traits<double> {
  static std::string name() { return "double"; }  ///< the name reports use
};
/// IEEE long double: not exact, a rounded square root, conversions by one IEEE rounding.
template <>
struct number_traits<long double> : detail::ieee_traits<long double> {
  static std::string name() { return "long double"; }  ///< the name reports use
};

/// The type of a value of T that may hold a square root: T for the float types and CORE::Expr,
/// cdref::Quad<T> for the rationals.
template <class T>
using sqrt_t = typename number_traits<T>::sqrt_type;

/// Whether T computes + - * / exactly.
template <class T>
inline constexpr bool is_exact_v = number_traits<T>::is_exact;

/// The square root of x >= 0 as number_traits<T> defines it.
template <class T>
sqrt_t<T> root(const T& x) {
  return number_traits<T>::sqrt(x);
}

/// Correctly rounded conversions (named apart from CGAL::to_double, which truncates).
template <class T>
double round_double(const T& x) {
  return number_traits<T>::to_double(x);
}

/// x rounded to the nearest float, ties to even (overflow to infinity).
template <class T>
float round_float(const T& x) {
  return number_traits<T>::to_float(x);
}

/// Round to the IEEE type F (float or double), correctly.
template <class F, class T>
F round_to(const T& x) {
  if constexpr (std::is_same_v<F, float>)
    return number_traits<T>::to_float(x);
  else
    return number_traits<T>::to_double(x);
}

}  // namespace cdref
