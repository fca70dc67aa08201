// cdref/exact/traits.hpp - number_traits for the exact types:
//   CGAL::Gmpq                       rational, no square root: sqrt_type = Quad<Gmpq>
//   CGAL::Lazy_exact_nt<ET>          (CGAL::Epeck::FT) lazy rational, sqrt_type = Quad<...>
//   cdref::Quad<T>                   a + b sqrt(d) over one of the rationals above
// to_double / to_float round correctly through exact/cdref/exact/rounding.hpp.
// CORE::Expr's traits are in core_expr.hpp, which says why they are apart.
#pragma once

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Lazy_exact_nt.h>
#include <gmpxx.h>
#include <mpfr.h>

// cdref's own build compiles for the FMA extension with the feature macros that imply SSE4.1 and
// AVX undefined (CMakeLists.txt, CDREF_HOST_FMA), so that CGAL's interval arithmetic takes its
// SSE2 code: its SSE4.1 and AVX code gave wrong exact answers near the double range.
#if defined(CDREF_FMA_REQUIRED) && (defined(__SSE4_1__) || defined(__AVX__))
#error "cdref's build: CGAL's interval arithmetic must see SSE2 alone (CMakeLists.txt, CDREF_HOST_FMA)"
#endif

#include <boost/multiprecision/gmp.hpp>
#include <cdref/number_traits.hpp>
#include <string>

#include "quadratic.hpp"
#include "rounding.hpp"

namespace cdref {

namespace exact {

using Rational = CGAL::Gmpq;
using LazyRational = CGAL::Epeck::FT;

// The GMP rational behind each exact rational type (Epeck::FT's exact type is gmpxx's
// mpq_class when CGAL is built with gmpxx, Boost's mpq_rational otherwise).
inline mpq_srcptr mpq_of(const CGAL::Gmpq& q) { return q.mpq(); }
inline mpq_srcptr mpq_of(const mpq_class& q) { return q.get_mpq_t(); }
inline mpq_srcptr mpq_of(const boost::multiprecision::mpq_rational& q) { return q.backend().data(); }
template <class ET>
mpq_srcptr mpq_of(const CGAL::Lazy_exact_nt<ET>& q) {
  return mpq_of(q.exact());
}

// A rational into MPFR, rounded to nearest at the target's precision.
template <class T>
void set_mpfr(mpfr_t out, const T& q) {
  mpfr_set_q(out, mpq_of(q), MPFR_RNDN);
}

// A guess for a + b sqrt(d), from a 256-bit MPFR evaluation.
template <class F, class T>
F quad_guess(const Quad<T>& q) {
  mpfr_t a, b, d;
  mpfr_inits2(256, a, b, d, static_cast<mpfr_ptr>(nullptr));
  set_mpfr(a, q.a());
  set_mpfr(b, q.b());
  set_mpfr(d, q.d());
  mpfr_sqrt(d, d, MPFR_RNDN);
  mpfr_fma(a, b, d, a, MPFR_RNDN);
  F g;
  if constexpr (std::is_same_v<F, float>)
    g = mpfr_get_flt(a, MPFR_RNDN);
  else
    g = mpfr_get_d(a, MPFR_RNDN);
  mpfr_clears(a, b, d, static_cast<mpfr_ptr>(nullptr));
  return g;
}

template <class T>
int compare_sign(const T& x, const T& y) {
  return static_cast<int>(CGAL::compare(x, y));
}

// Shared body for the exact field types: rounding by exact comparison.
template <class T>
struct field_rounding {
  static constexpr bool is_exact = true;
  static bool is_finite(const T&) { return true; }
  static double to_double(const T& x) {
    return round_nearest<double, T>([&](const T& t) { return compare_sign(x, t); }, CGAL::to_double(x));
  }
  static float to_float(const T& x) {
    return round_nearest<float, T>([&](const T& t) { return compare_sign(x, t); },
                                   static_cast<float>(CGAL::to_double(x)));
  }
};

}  // namespace exact

template <>
struct number_traits<CGAL::Gmpq> : exact::field_rounding<CGAL::Gmpq> {
  static constexpr sqrt_support sqrt_kind = sqrt_support::absent;
  using sqrt_type = Quad<CGAL::Gmpq>;
  static sqrt_type sqrt(const CGAL::Gmpq& x) { return sqrt_type::sqrt_of(x); }
  static std::string name() { return "Gmpq"; }
};

template <class ET>
struct number_traits<CGAL::Lazy_exact_nt<ET>> : exact::field_rounding<CGAL::Lazy_exact_nt<ET>> {
  static constexpr sqrt_support sqrt_kind = sqrt_support::absent;
  using sqrt_type = Quad<CGAL::Lazy_exact_nt<ET>>;
  static sqrt_type sqrt(const CGAL::Lazy_exact_nt<ET>& x) { return sqrt_type::sqrt_of(x); }
  static std::string name() { return "Epeck::FT"; }
};

template <class T>
struct number_traits<Quad<T>> {
  static constexpr bool is_exact = true;
  static constexpr sqrt_support sqrt_kind = sqrt_support::absent;
  using sqrt_type = void;  // a value in Q(sqrt d) has no square root in cdref
  static std::string name() { return "Q(sqrt)<" + number_traits<T>::name() + ">"; }
  static bool is_finite(const Quad<T>&) { return true; }
  static double to_double(const Quad<T>& q) {
    return exact::round_nearest<double, T>([&](const T& t) { return q.compare(t); }, exact::quad_guess<double>(q));
  }
  static float to_float(const Quad<T>& q) {
    return exact::round_nearest<float, T>([&](const T& t) { return q.compare(t); }, exact::quad_guess<float>(q));
  }
};

}  // namespace cdref
