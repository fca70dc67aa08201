// cdref/robust/box_box.hpp - axis-aligned box-box (Section 3.2) for F = float, double,
// long double, classifying exactly as the book does at an exact type. Same signatures as
// cdref::book.
//
// Centre-extent. The book tests, per axis, |cA - cB| <= eA + eB. At F both the difference
// and the sum round: at large offsets (cA - cB rounds) or large extents (eA + eB rounds,
// as at 2^53 + 3 in double) a pair 1 ulp apart is called touching, or touching ones apart.
// Here both sides are kept as exact pairs, d = cA - cB = dh + dl and e = eA + eB = eh + el
// (two_sum, bounded/eft.hpp: dh = fl(d), eh = fl(e), exact also in the subnormal range, where an
// addition never rounds), and compared exactly:
//   * rounding to nearest is monotone: x <= y implies fl(x) <= fl(y). So |dh| < eh proves
//     |d| < e and |dh| > eh proves |d| > e (|dh| = fl(|d|));
//   * if |dh| = eh, then |d| - e = sgn(dh) dl - el exactly, and both terms are floats, so
//     the sign is that of a float comparison: sgn(dh) dl <= el.
// Overflow: fl saturates to +-infinity, still monotonically, so a sum that overflows is
// compared correctly with one that does not (infinity > every finite value, and the
// exact sum exceeds every finite float it could be compared with). Only if both
// overflow (|dh| = eh = infinity, dl and el NaN) is the comparison redone on the halved
// inputs: a sum of two floats rounds to infinity only if both have magnitude at least
// half an ulp of the largest float (2^(emax-p), far above the subnormals), so halving
// them is exact, the four halves add without overflow, and the comparison is unchanged.
// The result is therefore exactly the book's classification at an exact type, on every
// finite input: there is no error bound to state, and decide() is always certain.
//
// Min-max. The book only compares the given corners (p1 <= q2 and p2 <= q1): exact at F.
// robust::intersect(MinMaxBox, MinMaxBox) is the book's, and its decide() is certain.
#pragma once

#include <cdref/book/box_box.hpp>
#include <cdref/primitives.hpp>
#include <cmath>
#include <limits>

#include "decision.hpp"
#include <cdref/bounded/eft.hpp>

namespace cdref::robust {

using namespace cdref::eft;  // the error-free transformations (bounded/eft.hpp)

namespace detail {

// Exactly |a - b| <= c + d for finite floats (a, b any sign; c, d >= 0).
template <class F>
bool abs_diff_at_most_sum(F a, F b, F c, F d) {
  Pair<F> x = two_sum(a, F(-b));
  Pair<F> y = two_sum(c, d);
  if (std::isinf(x.hi) && std::isinf(y.hi)) {  // both overflow: halve (exact, see above)
    x = two_sum(F(a / 2), F(-b / 2));
    y = two_sum(F(c / 2), F(d / 2));
  }
  const F ax = std::fabs(x.hi);
  if (ax != y.hi) return ax < y.hi;
  const F xl = x.hi < F(0) ? F(-x.lo) : x.lo;  // |d| = |dh| + sgn(dh) dl (dh = 0 gives dl = 0)
  return xl <= y.lo;
}

}  // namespace detail

template <class F>
[[gnu::noinline]] bool intersect_checked(const Box<F>& a, const Box<F>& b) {
  check(a, "box A");
  check(b, "box B");
  for (int i = 0; i < 3; ++i)
    if (!detail::abs_diff_at_most_sum(a.center[i], b.center[i], a.extent[i], b.extent[i])) return false;
  return true;
}

// Where no axis has |dh| = eh, monotone rounding decides every axis from dh and eh alone: the
// three answers combined without branches, and the input checks folded into the same loop (a
// valid input pays no separate pass over its coordinates): |dh| + eh is finite only where both
// centres' coordinates and both extents on that axis are (an infinity or a NaN makes it
// infinite or NaN), and the extents' signs are tested beside it. A tie on any axis, a sum that
// overflows and every bad input take the checks (their messages) and the exact comparison
// above on every axis, out of line.
template <class F>
bool intersect(const Box<F>& a, const Box<F>& b) {
  constexpr F big = std::numeric_limits<F>::max();
  bool all = true, tie = false, valid = true;
  for (int i = 0; i < 3; ++i) {
    const F ad = std::fabs(F(a.center[i] - b.center[i])), eh = a.extent[i] + b.extent[i];
    all &= ad < eh;
    tie |= ad == eh;
    valid &= int(F(ad + eh) <= big) & int(a.extent[i] >= F(0)) & int(b.extent[i] >= F(0));
  }
  if (valid && !tie) [[likely]]
    return all;
  return intersect_checked(a, b);
}

// Exact (see above): always certain.
template <class F>
Decision decide(const Box<F>& a, const Box<F>& b) {
  return {intersect(a, b), true};
}

// Comparisons of the given corners only: exact at F.
template <class F>
bool intersect(const MinMaxBox<F>& a, const MinMaxBox<F>& b) {
  return book::intersect(a, b);
}

template <class F>
Decision decide(const MinMaxBox<F>& a, const MinMaxBox<F>& b) {
  return {book::intersect(a, b), true};
}

}  // namespace cdref::robust
