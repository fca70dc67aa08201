/// \file
/// cdref/book/common.hpp - small helpers shared by the chapter's algorithms.
///
/// Input checks: every query in cdref::book checks its arguments (finite, radius and extents
/// not negative, ...) and throws cdref::invalid_input naming what is wrong. Its classification
/// is also in cdref::book::unchecked under the same name, without the checks, for a loop that
/// checks its bodies once (an engine does when it creates them) and then queries them many
/// times: the `bare` row of `cdref report` and `cdref_bench` times those. On input the checks
/// would refuse, the unchecked versions' answers mean nothing.
#pragma once

#include "../number_traits.hpp"
#include "../primitives.hpp"
#include "../results.hpp"
#include "../vec.hpp"

namespace cdref::book::detail {

template <class S>
S abs_of(const S& x) {
  return x < S(0) ? S(-x) : x;
}

template <class S>
S max_of(const S& a, const S& b) {
  return a < b ? b : a;
}

template <class S>
S min_of(const S& a, const S& b) {
  return b < a ? b : a;
}

/// Whether x > 0 is certain: x > 0 at an exact type or a float; a number type whose signs may be
/// too close to call provides its own (found by argument-dependent lookup: cdref::Bounded2,
/// false there, never throwing and never lenient). For a shortcut taken only where it is certain,
/// with the general formulation behind it.
template <class S>
bool surely_positive(const S& x) {
  return S(0) < x;
}

/// v / k component-wise, v over T lifted to S.
template <class S, class T>
Vec3<S> divided(const Vec3<T>& v, const S& k) {
  return Vec3<S>(S(v[0]) / k, S(v[1]) / k, S(v[2]) / k);
}

/// The index of the coordinate of v with the smallest absolute value (first on ties).
template <class T>
int smallest_abs_axis(const Vec3<T>& v) {
  int best = 0;
  T best_abs = v[0] < T(0) ? T(-v[0]) : T(v[0]);
  for (int i = 1; i < 3; ++i) {
    T a = v[i] < T(0) ? T(-v[i]) : T(v[i]);
    if (a < best_abs) {
      best = i;
      best_abs = a;
    }
  }
  return best;
}

template <class T>
bool is_zero(const Vec3<T>& v) {
  return v[0] == T(0) && v[1] == T(0) && v[2] == T(0);
}

}  // namespace cdref::book::detail
