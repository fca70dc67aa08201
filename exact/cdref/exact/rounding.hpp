// cdref/exact/rounding.hpp - correctly rounded conversion of an exact value to float or
// double: round to nearest, ties to even, with overflow to infinity as IEEE 754 has it.
//
// The value v is known only through an exact comparator cmp(t) = sign(v - t) for exact
// field elements t. Nonnegative IEEE values are ordered like their bit patterns, so:
//   1. find the floor x, the largest finite F with x <= |v|, by a search over the bit
//      patterns (galloping from a guess, then bisection: at most ~2 * 64 comparisons,
//      usually two when the guess is good);
//   2. if |v| = x, return x; otherwise compare |v| with the midpoint m = (x + x+) / 2,
//      an exact dyadic rational (for x = max, m = max + ulp(max)/2, the overflow
//      threshold): below m gives x, above gives x+ (infinity past max), on m the one
//      with an even significand (infinity counts as even, as IEEE 754 says).
// Every step is an exact comparison, so the result is proven, not estimated. A guess
// from a truncating conversion (CGAL::to_double) or an MPFR evaluation only saves time.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>

namespace cdref::exact {

template <class F, class T, class Cmp>
F round_nearest(Cmp&& cmp, F guess) {
  static_assert(std::is_same_v<F, float> || std::is_same_v<F, double>, "rounds to float or double");
  using U = std::conditional_t<std::is_same_v<F, double>, std::uint64_t, std::uint32_t>;
  const int s = cmp(T(0));
  if (s == 0) return F(0);
  // sign(|v| - x) for x >= 0
  auto cmp_abs = [&](const T& x) { return s > 0 ? cmp(x) : -cmp(T(-x)); };
  auto exact_of = [](U u) { return T(static_cast<double>(std::bit_cast<F>(u))); };
  const U max_bits = std::bit_cast<U>(std::numeric_limits<F>::max());

  // Invariant: value(lo) <= |v|, and the floor lies in [lo, hi].
  U lo = 0, hi = max_bits;
  const F g = std::fabs(guess);
  if (std::isfinite(g) && g > F(0)) {
    const U ug = std::bit_cast<U>(g);
    if (cmp_abs(exact_of(ug)) >= 0) {
      lo = ug;
      U step = 1;
      while (true) {  // gallop upward
        if (lo >= max_bits) break;
        const U probe = (max_bits - lo < step) ? max_bits : U(lo + step);
        if (cmp_abs(exact_of(probe)) >= 0) {
          lo = probe;
          step = U(step * 2);
        } else {
          hi = U(probe - 1);
          break;
        }
      }
    } else {
      hi = U(ug - 1);
      U step = 1;
      while (true) {  // gallop downward
        const U probe = (hi < step) ? U(0) : U(hi - step + 1);
        if (probe == 0 || cmp_abs(exact_of(probe)) >= 0) {
          lo = probe;
          break;
        }
        hi = U(probe - 1);
        step = U(step * 2);
      }
    }
  }
  while (lo < hi) {
    const U mid = U(lo + (hi - lo + 1) / 2);
    if (cmp_abs(exact_of(mid)) >= 0)
      lo = mid;
    else
      hi = U(mid - 1);
  }

  const T x = exact_of(lo);
  F out;
  if (cmp_abs(x) == 0) {
    out = std::bit_cast<F>(lo);
  } else {
    T midpoint;
    if (lo == max_bits) {
      const F mx = std::numeric_limits<F>::max();
      const F ulp = mx - std::nextafter(mx, F(0));
      midpoint = T(static_cast<double>(mx)) + T(static_cast<double>(ulp)) / T(2);
    } else {
      midpoint = (x + exact_of(U(lo + 1))) / T(2);
    }
    const int cm = cmp_abs(midpoint);
    const U pick = cm < 0 ? lo : (cm > 0 ? U(lo + 1) : (lo % 2 == 0 ? lo : U(lo + 1)));
    out = std::bit_cast<F>(pick);  // lo + 1 past max is +infinity
  }
  return s > 0 ? out : -out;
}

}  // namespace cdref::exact
