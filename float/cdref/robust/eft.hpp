// cdref/robust/eft.hpp - error-free transformations and a compensated dot product, for the
// robust float formulations (float, double, long double; never with -ffast-math).
//
//   two_sum(a, b) = (s, e) with s = fl(a + b) and a + b = s + e exactly (Knuth; 6 flops);
//   two_prod(a, b) = (p, e) with p = fl(a b) and a b = p + e exactly (one std::fma),
//     barring underflow;
//   dot2(x, y) = the dot product computed as if in twice the precision, then rounded
//     (Ogita, Rump and Oishi, "Accurate sum and dot product", 2005, Algorithm Dot2): its
//     error is at most u |x.y| + gamma_n^2 sum |x_i y_i| (u the unit roundoff, gamma_n =
//     n u / (1 - n u)), so a difference of nearly equal products such as |s|^2 - rho^2
//     keeps its digits as long as the cancellation is smaller than 1/u.
#pragma once

#include <cmath>
#include <cstddef>

namespace cdref::robust {

template <class F>
struct Pair {
  F hi, lo;
};

template <class F>
Pair<F> two_sum(F a, F b) {
  const F s = a + b;
  const F bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}

template <class F>
Pair<F> two_prod(F a, F b) {
  const F p = a * b;
  return {p, std::fma(a, b, -p)};
}

template <class F, std::size_t N>
F dot2(const F (&x)[N], const F (&y)[N]) {
  Pair<F> acc = two_prod(x[0], y[0]);
  F err = acc.lo;
  for (std::size_t i = 1; i < N; ++i) {
    const Pair<F> p = two_prod(x[i], y[i]);
    const Pair<F> s = two_sum(acc.hi, p.hi);
    acc.hi = s.hi;
    err += p.lo + s.lo;
  }
  return acc.hi + err;
}

}  // namespace cdref::robust
