// cdref/float/mpfr.hpp - MPFR (through mpreal) as a float type of chosen precision.
//
// The precision is mpreal's default precision at the time values are made:
// set it with cdref::mpfr_precision (an RAII guard) before constructing inputs.
// Arithmetic rounds to nearest at that precision; sqrt is MPFR's correctly rounded one;
// to_double / to_float are MPFR's correctly rounded conversions (mpfr_get_d / _flt).
#pragma once

#include <unsupported/Eigen/MPRealSupport>
#include <cdref/number_traits.hpp>
#include <string>

namespace cdref {

template <>
struct number_traits<mpfr::mpreal> {
  static constexpr bool is_exact = false;
  static constexpr sqrt_support sqrt_kind = sqrt_support::rounded;
  using sqrt_type = mpfr::mpreal;
  static mpfr::mpreal sqrt(const mpfr::mpreal& x) { return mpfr::sqrt(x); }
  static bool is_finite(const mpfr::mpreal& x) { return mpfr::isfinite(x); }
  static double to_double(const mpfr::mpreal& x) { return mpfr_get_d(x.mpfr_srcptr(), MPFR_RNDN); }
  static float to_float(const mpfr::mpreal& x) { return mpfr_get_flt(x.mpfr_srcptr(), MPFR_RNDN); }
  static std::string name() { return "mpfr" + std::to_string(mpfr::mpreal::get_default_prec()); }
  static mpfr::mpreal unit_roundoff() { return mpfr::ldexp(mpfr::mpreal(1), -int(mpfr::mpreal::get_default_prec())); }
  static mpfr::mpreal denorm_min() { return mpfr::mpreal(0); }  // MPFR has no subnormals: a product never underflows here
  static void to_rational(mpq_t q, const mpfr::mpreal& x) { mpfr_get_q(q, x.mpfr_srcptr()); }
};

// Sets mpreal's default precision (in bits) for the guard's lifetime.
class mpfr_precision {
 public:
  explicit mpfr_precision(int bits) : saved_(mpfr::mpreal::get_default_prec()) {
    mpfr::mpreal::set_default_prec(bits);
  }
  ~mpfr_precision() { mpfr::mpreal::set_default_prec(saved_); }
  mpfr_precision(const mpfr_precision&) = delete;
  mpfr_precision& operator=(const mpfr_precision&) = delete;

 private:
  mpfr_prec_t saved_;
};

}  // namespace cdref
