// cdref/robust/rational.hpp - exact rationals for the robust tier's rare exact values (GMP's C
// interface, as det_sign.hpp; MPFR for the one rounding at the end). Called only where a double
// word's enclosure leaves a value's rounding loose: an exact 0 at a vertex, a shot in a
// triangle's plane (ray_triangle.hpp), a distance of a few ulps of the radius next to a
// sphere's surface (segment_sphere.hpp, words.hpp). Each call costs a few microseconds.
//
//   round_rational(x): x rounded to nearest double (MPFR at 53 bits, correctly rounded in its
//     unbounded exponent range), or nothing below the normal range (a second rounding there)
//     or above it;
//   pair_of<F>(x): x as a pair hi + lo of F, hi = x rounded to 3p bits then to F, lo the rest
//     rounded to F: |hi + lo - x| <= (2^-3p + u^2)|x| (exact where x has at most 2p bits),
//     barring underflow and overflow;
//   sphere_gap<F>(xx, rho): sqrt(xx) - rho for an exact xx >= 0 (a squared distance from a
//     sphere's centre) and rho >= 0, as (xx - rho^2) / (sqrt(xx) + rho) in MPFR at 3p bits
//     (three roundings of 2^-3p: no cancellation is left, the numerator is exact) and rounded
//     once to F: within an ulp of the truth wherever it lies in F's normal range.
#pragma once

#include <cstdint>  // before mpfr.h: its intmax_t functions (MPFR_USE_INTMAX_T)
#include <gmp.h>
#include <mpfr.h>

#include <cdref/number_traits.hpp>
#include <cdref/primitives.hpp>
#include <cdref/results.hpp>
#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>

#include <cdref/bounded/eft.hpp>

namespace cdref::robust::detail {

using namespace cdref::eft;  // the error-free transformations (bounded/eft.hpp)

struct Rational {
  mpq_t q;
  Rational() { mpq_init(q); }
  ~Rational() { mpq_clear(q); }
  Rational(const Rational&) = delete;
  Rational& operator=(const Rational&) = delete;
};
using RVec = Rational[3];

template <class F>
void set_rational(Rational& o, F x) {
  number_traits<F>::to_rational(o.q, x);
}
// o = hi + lo exactly
template <class F>
void set_pair(Rational& o, F hi, F lo) {
  Rational t;
  set_rational(o, hi);
  set_rational(t, lo);
  mpq_add(o.q, o.q, t.q);
}
template <class F>
void set_vec(RVec& o, const Vec3<F>& v) {
  for (int i = 0; i < 3; ++i) set_rational(o[i], v[i]);
}
inline void sub_vec(RVec& o, const RVec& a, const RVec& b) {
  for (int i = 0; i < 3; ++i) mpq_sub(o[i].q, a[i].q, b[i].q);
}
inline void cross_vec(RVec& o, const RVec& a, const RVec& b) {
  Rational t;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, l = (i + 2) % 3;
    mpq_mul(o[i].q, a[j].q, b[l].q);
    mpq_mul(t.q, a[l].q, b[j].q);
    mpq_sub(o[i].q, o[i].q, t.q);
  }
}
inline void dot_vec(Rational& o, const RVec& a, const RVec& b) {
  Rational t;
  mpq_mul(o.q, a[0].q, b[0].q);
  for (int i = 1; i < 3; ++i) {
    mpq_mul(t.q, a[i].q, b[i].q);
    mpq_add(o.q, o.q, t.q);
  }
}

inline std::optional<double> round_rational(const Rational& x) {
  if (mpq_sgn(x.q) == 0) return 0.0;
  mpfr_t m;
  mpfr_init2(m, 53);
  mpfr_set_q(m, x.q, MPFR_RNDN);
  const double d = mpfr_get_d(m, MPFR_RNDN);
  mpfr_clear(m);
  if (!(std::fabs(d) >= std::numeric_limits<double>::min() && std::fabs(d) <= std::numeric_limits<double>::max()))
    return std::nullopt;
  return d;
}

template <class F>
F mpfr_to(const mpfr_t m) {
  if constexpr (std::is_same_v<F, float>)
    return mpfr_get_flt(m, MPFR_RNDN);
  else if constexpr (std::is_same_v<F, double>)
    return mpfr_get_d(m, MPFR_RNDN);
  else
    return mpfr_get_ld(m, MPFR_RNDN);
}
template <class F>
void mpfr_from(mpfr_t m, F x) {
  if constexpr (std::is_same_v<F, long double>)
    mpfr_set_ld(m, x, MPFR_RNDN);
  else
    mpfr_set_d(m, double(x), MPFR_RNDN);
}

// x rounded to nearest F (MPFR at F's precision, correctly rounded in its unbounded exponent
// range; a value below F's normal range is rounded a second time there).
template <class F>
F rounded(const Rational& x) {
  if (mpq_sgn(x.q) == 0) return F(0);
  mpfr_t m;
  mpfr_init2(m, std::numeric_limits<F>::digits);
  mpfr_set_q(m, x.q, MPFR_RNDN);
  const F r = mpfr_to<F>(m);
  mpfr_clear(m);
  return r;
}

template <class F>
Pair<F> pair_of(const Rational& x) {
  constexpr int p = std::numeric_limits<F>::digits;
  mpfr_t m;
  mpfr_init2(m, 3 * p);
  mpfr_set_q(m, x.q, MPFR_RNDN);
  const F hi = mpfr_to<F>(m);
  mpfr_t h;
  mpfr_init2(h, p);
  mpfr_from(h, hi);
  mpfr_sub(m, m, h, MPFR_RNDN);  // exact: m and hi agree in their leading bits
  const F lo = mpfr_to<F>(m);
  mpfr_clear(h);
  mpfr_clear(m);
  return {hi, lo};
}

template <class F>
F sphere_gap(const Rational& xx, F rho) {
  constexpr int p = std::numeric_limits<F>::digits;
  Rational num, r2;
  set_rational(r2, rho);
  mpq_mul(r2.q, r2.q, r2.q);
  mpq_sub(num.q, xx.q, r2.q);
  if (mpq_sgn(num.q) == 0) return F(0);
  mpfr_t n, d, r;
  mpfr_inits2(3 * p, n, d, r, (mpfr_ptr)0);
  mpfr_set_q(n, num.q, MPFR_RNDN);
  mpfr_set_q(d, xx.q, MPFR_RNDN);
  mpfr_sqrt(d, d, MPFR_RNDN);
  mpfr_from(r, rho);
  mpfr_add(d, d, r, MPFR_RNDN);
  mpfr_div(n, n, d, MPFR_RNDN);
  const F g = mpfr_to<F>(n);
  mpfr_clears(n, d, r, (mpfr_ptr)0);
  return g;
}

}  // namespace cdref::robust::detail

namespace cdref::robust::detail {

// |p - x|^2 for x the point of the segment [a, b] closest to p, exactly: x = a + t (b - a), t
// = (p - a).e / e.e clamped to [0, 1] (e = b - a; a point where e = 0), and inside the segment
// |p - x|^2 = |p - a|^2 - ((p - a).e)^2 / e.e.
inline void segment_xx(Rational& out, const RVec& p, const RVec& a, const RVec& b) {
  RVec e, ap;
  sub_vec(e, b, a);
  sub_vec(ap, p, a);
  Rational t, ee;
  dot_vec(t, ap, e);
  dot_vec(ee, e, e);
  if (mpq_sgn(ee.q) == 0 || mpq_sgn(t.q) <= 0) return dot_vec(out, ap, ap);
  if (mpq_cmp(t.q, ee.q) >= 0) {
    RVec bp;
    sub_vec(bp, p, b);
    return dot_vec(out, bp, bp);
  }
  dot_vec(out, ap, ap);
  mpq_mul(t.q, t.q, t.q);
  mpq_div(t.q, t.q, ee.q);
  mpq_sub(out.q, out.q, t.q);
}

// The sphere's distance and depth (words.hpp, proximity_on_words) where the double words leave
// them loose: the double words' values carry about u^2 of the primitive's size, and next to the
// surface (a distance of a few ulps of the radius) that is tens of ulps of the value (sphere-obb
// 105, sphere-triangle 38, polygon-sphere 85 at 2^-52 of the radius from touching, `cdref
// campaign --impl robust-double`). Where the value's enclosure is wider than u/16 of it, the
// query's exact |x - c|^2 (xx(Rational&): false where it has none, e.g. a centre inside an
// oriented box, whose depth does not cancel) gives it within an ulp by sphere_gap; a sign other
// than the classification's (possible only where that is uncertain) leaves the value as it was.
template <class F, class P, class V, class XX>
void sharpen_gap(P& p, const V& wv, F rho, unsigned w, XX xx) {
  if (!wv.bounded || !(w & (p.intersect ? want_depth : want_distance))) return;
  const long double v = p.intersect ? wv.depth_hi + wv.depth_lo : wv.distance_hi + wv.distance_lo;
  const long double e = p.intersect ? wv.depth_err : wv.distance_err;
  if (!(e > std::ldexp(std::fabs(v), -(std::numeric_limits<F>::digits + 4)))) return;
  Rational x;
  if (!xx(x)) return;
  const F g = sphere_gap(x, rho);
  if (p.intersect && g <= F(0))
    p.depth = F(-g);
  else if (!p.intersect && g > F(0))
    p.distance = g;
}

}  // namespace cdref::robust::detail

namespace cdref::robust::detail {

// p0 - sqrt(disc) k rounded to F (p0, k rational, disc >= 0): exact where the value is
// rational (k = 0, or disc the square of a rational); otherwise it is irrational, hence not 0,
// and MPFR evaluates it at 3p bits, doubling the precision until the evaluation's error (at
// most 2^(3 - prec) (|p0| + |sqrt(disc) k|), three roundings) is below 2^-(p+6) of the
// result: within an ulp of the truth. A sphere cast's entry point where it cancels
// (ray_sphere.hpp, step 5).
template <class F>
F surd_rounded(const Rational& p0, const Rational& disc, const Rational& k) {
  constexpr int p = std::numeric_limits<F>::digits;
  if (mpq_sgn(k.q) == 0) return rounded<F>(p0);
  if (mpz_perfect_square_p(mpq_numref(disc.q)) && mpz_perfect_square_p(mpq_denref(disc.q))) {
    Rational r, v;
    mpz_sqrt(mpq_numref(r.q), mpq_numref(disc.q));
    mpz_sqrt(mpq_denref(r.q), mpq_denref(disc.q));
    mpq_canonicalize(r.q);
    mpq_mul(v.q, r.q, k.q);
    mpq_sub(v.q, p0.q, v.q);
    return rounded<F>(v);
  }
  for (mpfr_prec_t prec = 3 * p;; prec *= 2) {
    mpfr_t a, m, t;
    mpfr_inits2(prec, a, m, t, (mpfr_ptr)0);
    mpfr_set_q(m, disc.q, MPFR_RNDN);
    mpfr_sqrt(m, m, MPFR_RNDN);
    mpfr_mul_q(m, m, k.q, MPFR_RNDN);
    mpfr_set_q(a, p0.q, MPFR_RNDN);
    mpfr_sub(t, a, m, MPFR_RNDN);
    // accept where 2^(3 - prec) (|a| + |m|) <= 2^-(p + 6) |t|
    mpfr_abs(a, a, MPFR_RNDU);
    mpfr_abs(m, m, MPFR_RNDU);
    mpfr_add(a, a, m, MPFR_RNDU);
    mpfr_mul_2si(a, a, 3 - prec + p + 6, MPFR_RNDU);
    mpfr_abs(m, t, MPFR_RNDN);
    const bool ok = mpfr_cmp(a, m) <= 0 || prec >= (mpfr_prec_t(1) << 16);
    const F r = mpfr_to<F>(t);
    mpfr_clears(a, m, t, (mpfr_ptr)0);
    if (ok) return r;
  }
}

}  // namespace cdref::robust::detail
