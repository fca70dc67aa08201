/// \file
/// cdref/book/box_box.hpp - Section 3.2: axis-aligned box-box.
///   min-max:       [p1, q1] and [p2, q2] meet iff p1 <= q2 and p2 <= q1 (every axis);
///   centre-extent: [c1 - h1, c1 + h1] and [c2 - h2, c2 + h2] meet iff |c1 - c2| <= h1 + h2.
/// Boxes are closed: touching faces, edges or corners intersect.
#pragma once

#include "common.hpp"

namespace cdref::book {

/// Whether the closed axis-aligned box (min-max) and axis-aligned box (min-max) share a point
/// (touching counts). Throws cdref::invalid_input naming a bad argument.
template <class T>
bool intersect(const MinMaxBox<T>& a, const MinMaxBox<T>& b) {
  check(a, "box A");
  check(b, "box B");
  for (int i = 0; i < 3; ++i)
    if (!(a.min[i] <= b.max[i] && b.min[i] <= a.max[i])) return false;
  return true;
}

namespace unchecked {
/// The centre-extent test on input already checked (see common.hpp).
template <class T>
bool intersect(const Box<T>& a, const Box<T>& b) {
  for (int i = 0; i < 3; ++i) {
    const T d = a.center[i] - b.center[i];
    const T ad = d < T(0) ? T(-d) : d;
    if (!(ad <= a.extent[i] + b.extent[i])) return false;
  }
  return true;
}
}  // namespace unchecked

/// Whether the closed axis-aligned box and axis-aligned box share a point (touching counts). Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
bool intersect(const Box<T>& a, const Box<T>& b) {
  check(a, "box A");
  check(b, "box B");
  return unchecked::intersect(a, b);
}

}  // namespace cdref::book
