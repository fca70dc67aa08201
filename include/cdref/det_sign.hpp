/// \file
/// cdref/det_sign.hpp - the exact sign of a 3x3 determinant det[a b c] = a . (b x c), for
/// any number type cdref runs on. An oriented box's axes must be linearly independent, and
/// "independent" is decided exactly: no tolerance, whatever the inputs' type.
///
///   exact types          the determinant in T, compared with 0;
///   IEEE types, MPFR     a filter first: d~ = fl(a . (b x c)) with the absolute permanent
///                        p~ = fl(|a| . (|b| x |c|)). Each of the six products of three
///                        factors carries at most 3 roundings, the cross product's differences
///                        one more and the dot product's two sums two more: |d~ - d| <=
///                        gamma_6 p <= 7u p~ (the rounding of p~ itself is within the margin)
///                        while nothing overflows; an underflowing product is off by at most
///                        half the smallest subnormal eta. The three final products' are off by
///                        that much; the cross product's six are multiplied afterwards by a
///                        component of a, so their error reaches |a_i| eta for component i (the
///                        fuzz target found a frame with two equal axes of size 2^1020 and a
///                        subnormal third, whose determinant 0 the bound 16 eta alone called
///                        negative). So |d~| > 8u p~ + 16 eta + 2 eta (|a_0| + |a_1| + |a_2|)
///                        decides the sign (each eta |a_i| is exact or rounds below eta); at
///                        float, double and long double the bound takes 2^64 eta for eta, a
///                        normal number (see below). Otherwise (near a
///                        degenerate frame, or p~ not finite) the inputs are converted exactly
///                        to GMP rationals (number_traits<T>::to_rational) and the sign computed
///                        exactly;
///   other types          (the oracle's filter types) the determinant in T, whose comparison
///                        is certain or throws cdref::uncertain.
#pragma once

#include <gmp.h>

#include <cmath>
#include <limits>
#include <type_traits>

#include "number_traits.hpp"
#include "vec.hpp"

namespace cdref {

namespace detail {

/// det[a b c] over GMP rationals, from exact conversions of the entries.
template <class T>
[[gnu::noinline, gnu::cold]] int det3_sign_rational(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c) {
  mpq_t m[9], t, u, d;
  for (auto& q : m) mpq_init(q);
  mpq_init(t);
  mpq_init(u);
  mpq_init(d);
  for (int i = 0; i < 3; ++i) {
    number_traits<T>::to_rational(m[i], a[i]);
    number_traits<T>::to_rational(m[3 + i], b[i]);
    number_traits<T>::to_rational(m[6 + i], c[i]);
  }
  // d = sum_i a_i (b_{i+1} c_{i+2} - b_{i+2} c_{i+1})
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    mpq_mul(t, m[3 + j], m[6 + k]);
    mpq_mul(u, m[3 + k], m[6 + j]);
    mpq_sub(t, t, u);
    mpq_mul(t, t, m[i]);
    mpq_add(d, d, t);
  }
  const int s = mpq_sgn(d);
  for (auto& q : m) mpq_clear(q);
  mpq_clear(t);
  mpq_clear(u);
  mpq_clear(d);
  return s;
}

template <class T>
T abs_of(const T& x) {
  return x < T(0) ? T(-x) : x;
}

}  // namespace detail

/// The sign of det[a b c] = a . (b x c), decided exactly (-1, 0 or 1): a float filter, then GMP
/// rationals where the filter cannot decide.
template <class T>
int det3_sign(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c) {
  if constexpr (std::is_floating_point_v<T>) {
    // the filter below on plain scalars (every oriented box's input check runs it), its
    // result taken without a branch on the sign (a frame's handedness is data, not a pattern)
    using std::fabs;
    const T b12 = b[1] * c[2], b21 = b[2] * c[1], b20 = b[2] * c[0], b02 = b[0] * c[2];
    const T b01 = b[0] * c[1], b10 = b[1] * c[0];
    const T d = a[0] * (b12 - b21) + a[1] * (b20 - b02) + a[2] * (b01 - b10);
    const T a0 = fabs(a[0]), a1 = fabs(a[1]), a2 = fabs(a[2]);
    // (|fl(x y)| = fl(|x| |y|): rounding to nearest is symmetric, so the products are shared)
    const T p = a0 * (fabs(b12) + fabs(b21)) + a1 * (fabs(b20) + fabs(b02)) + a2 * (fabs(b01) + fabs(b10));
    // eta (16 + 2 (|a_0| + |a_1| + |a_2|)) with eta replaced by the normal number tiny = 2^64 eta
    // (arithmetic on subnormals is slow, and the larger bound only sends determinants below
    // ~tiny to the exact path; it also covers the bound's own roundings)
    constexpr T u = number_traits<T>::unit_roundoff();
    constexpr T tiny = number_traits<T>::denorm_min() * T(0x1p64);  // 2^64 eta: 2^-1010 for double
    const T bound = u * T(8) * p + tiny * (T(16) + T(2) * (a0 + a1 + a2));
    if (fabs(d) > bound && std::isfinite(p) && std::isfinite(d)) [[likely]]
      return int(d > 0) - int(d < 0);
    return detail::det3_sign_rational(a, b, c);
  }
  const T d = a.dot(b.cross(c));
  if constexpr (number_traits<T>::is_exact) {
    return d > T(0) ? 1 : (d < T(0) ? -1 : 0);
  } else if constexpr (requires(mpq_t q, const T& x) { number_traits<T>::to_rational(q, x); }) {
    using std::fabs;
    const Vec3<T> aa(detail::abs_of(a[0]), detail::abs_of(a[1]), detail::abs_of(a[2]));
    const Vec3<T> bb(detail::abs_of(b[0]), detail::abs_of(b[1]), detail::abs_of(b[2]));
    const Vec3<T> cc(detail::abs_of(c[0]), detail::abs_of(c[1]), detail::abs_of(c[2]));
    T p(0);
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      p += aa[i] * (bb[j] * cc[k] + bb[k] * cc[j]);
    }
    if (number_traits<T>::is_finite(p) && number_traits<T>::is_finite(d)) {
      const T eta = number_traits<T>::denorm_min();
      const T bound = number_traits<T>::unit_roundoff() * T(8) * p + eta * T(16) +
                      T(2) * (eta * aa[0] + eta * aa[1] + eta * aa[2]);
      if (d > bound) return 1;
      if (d < T(-bound)) return -1;
    }
    return detail::det3_sign_rational(a, b, c);
  } else {
    return d > T(0) ? 1 : (d < T(0) ? -1 : 0);  // certain, or the filter type throws
  }
}

}  // namespace cdref
