// cdref/exact/long_double.hpp - correct rounding of exact values to long double (x87
// extended: 64-bit significand), for the campaigns' long double implementations.
//
// A guess from MPFR (the rational itself at 64 bits, or a + b sqrt d at 256 bits, then
// rounded) is verified exactly: v must lie between the midpoints with the guess's two
// neighbours, a tie going to the even significand; otherwise the guess moves one step
// toward v and is checked again. Values here stay far inside long double's range.
#pragma once

#include <CGAL/Gmpq.h>
#include <mpfr.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>

#include "quadratic.hpp"

namespace cdref::exact {

// The exact value of a long double.
inline CGAL::Gmpq gmpq_of(long double x) {
  mpfr_t m;
  mpfr_init2(m, 64);
  mpfr_set_ld(m, x, MPFR_RNDN);  // exact: 64 bits hold it
  CGAL::Gmpq q;
  mpfr_get_q(q.mpq(), m);
  mpfr_clear(m);
  return q;
}

namespace detail {
inline bool even_significand(long double x) {
  std::uint64_t mant;
  std::memcpy(&mant, &x, sizeof mant);  // x87 extended: the low 8 bytes are the significand
  return (mant & 1) == 0;
}

// cmp(t) = sign(v - t) for a rational t. Returns false if x is not within a few steps.
template <class Cmp>
bool verify_nearest(Cmp cmp, long double& x) {
  const long double inf = HUGE_VALL;
  for (int step = 0; step < 4; ++step) {
    const long double lo = std::nextafter(x, -inf), hi = std::nextafter(x, inf);
    const CGAL::Gmpq qx = gmpq_of(x);
    const int c_lo = cmp(CGAL::Gmpq((gmpq_of(lo) + qx) / 2));
    if (c_lo < 0) {
      x = lo;
      continue;
    }
    const int c_hi = cmp(CGAL::Gmpq((qx + gmpq_of(hi)) / 2));
    if (c_hi > 0) {
      x = hi;
      continue;
    }
    if (c_lo == 0 && !even_significand(x)) x = lo;
    else if (c_hi == 0 && !even_significand(x)) x = hi;
    return true;
  }
  return false;
}
}  // namespace detail

inline long double round_long_double(const CGAL::Gmpq& v) {
  mpfr_t m;
  mpfr_init2(m, 64);
  mpfr_set_q(m, v.mpq(), MPFR_RNDN);  // correctly rounded already; verified all the same
  long double x = mpfr_get_ld(m, MPFR_RNDN);
  mpfr_clear(m);
  if (!detail::verify_nearest([&](const CGAL::Gmpq& t) { return int(CGAL::compare(v, t)); }, x))
    throw std::logic_error("cdref: rounding a rational to long double did not converge");
  return x;
}

// a + b sqrt d: an MPFR evaluation at rising precision until the verification holds (an
// exact zero is recognised first; cancellation of a nonzero value is bounded, so enough
// precision always lands within a step of the answer).
inline long double round_long_double(const Quad<CGAL::Gmpq>& v) {
  if (v.sign() == 0) return 0.0L;
  for (mpfr_prec_t prec = 256; prec <= (mpfr_prec_t(1) << 20); prec *= 4) {
    mpfr_t a, b, d;
    mpfr_inits2(prec, a, b, d, static_cast<mpfr_ptr>(nullptr));
    mpfr_set_q(a, v.a().mpq(), MPFR_RNDN);
    mpfr_set_q(b, v.b().mpq(), MPFR_RNDN);
    mpfr_set_q(d, v.d().mpq(), MPFR_RNDN);
    mpfr_sqrt(d, d, MPFR_RNDN);
    mpfr_fma(a, b, d, a, MPFR_RNDN);
    long double x = mpfr_get_ld(a, MPFR_RNDN);
    mpfr_clears(a, b, d, static_cast<mpfr_ptr>(nullptr));
    if (detail::verify_nearest([&](const CGAL::Gmpq& t) { return v.compare(t); }, x)) return x;
  }
  throw std::logic_error("cdref: rounding a + b sqrt d to long double did not converge");
}

}  // namespace cdref::exact
