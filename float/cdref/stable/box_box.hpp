// cdref/stable/box_box.hpp - axis-aligned box-box as careful float code writes it: per axis
// the centres' offset against the sum of the extents (Ericson, Real-Time Collision Detection
// 4.2.1, centre-radius form; Bullet's and Box2D's min-max form is the same comparison once
// min = c - h and max = c + h are rounded). F = float, double, long double; same signatures
// and results as cdref::book.
//
// The chapter's formulation (Section 3.2) is already this one, so the stable tier is
// book::intersect. Error bound of the classification (first order in u, the unit roundoff of
// F): per axis d = c_A - c_B rounds once (u |d|) and s = h_A + h_B once (u s); rounding is
// monotonic, so |d| <= s is decided right unless ||d| - s| <= u (|d| + s), that is unless the
// boxes' faces on some axis are within about 2u s of touching. Nothing cancels but the
// centres' own difference: the band is relative to the boxes' size at every range, and d is
// exact when the centres are within a factor 2 of each other (Sterbenz), leaving only u s.
// The min-max form (book_pred, c -+ h rounded) carries u |c| instead: at range (|c| >> h)
// it is the worse of the two, which the campaigns' long-range family shows.
#pragma once

#include <cdref/book/box_box.hpp>

namespace cdref::stable {

template <class F>
bool intersect(const Box<F>& a, const Box<F>& b) {
  return book::intersect(a, b);
}

// The classification without the input checks (see book/common.hpp).
namespace unchecked {
template <class F>
bool intersect(const Box<F>& a, const Box<F>& b) {
  return book::unchecked::intersect(a, b);
}
}  // namespace unchecked

}  // namespace cdref::stable
