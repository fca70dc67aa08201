// cdref/stable/sphere_box.hpp - sphere-box as careful float code writes it: the box's point
// closest to the centre first (clamping), then one comparison (Box2D, Ericson's
// ClosestPtPointAABB). F = float, double, long double; same signatures and results as
// cdref::book.
//
// The chapter's formulation (Section 3.2.2) is already this one, so the stable tier is
// book::intersect and book::proximity. Error bound of the classification (first order in u,
// the unit roundoff of F): c = centre - box centre rounds once per component (u |c_i|), the
// clamp is exact, v = x - c rounds once more (u |v_i|), v.v adds 3u relative and rho^2 u:
// |v|^2 <= rho^2 is decided right unless |v| is within about u (|c| + 2 |v|) of rho. At range
// (|c| >> rho) the band grows like u |c|: the offset of the sphere from the box is the
// problem's own condition there.
// Inside the box the depth is the smallest eta_i - |gamma_i| plus rho: one rounding each.
#pragma once

#include <cdref/book/sphere_box.hpp>

namespace cdref::stable {

template <class F>
bool intersect(const Sphere<F>& sp, const Box<F>& box) {
  return book::intersect(sp, box);
}
template <class F>
Proximity<F> proximity(const Sphere<F>& sp, const Box<F>& box, unsigned w = want_proximity) {
  return book::proximity(sp, box, w);
}

// The classification without the input checks (see book/common.hpp).
namespace unchecked {
template <class F>
bool intersect(const Sphere<F>& sp, const Box<F>& box) {
  return book::unchecked::intersect(sp, box);
}
}  // namespace unchecked

}  // namespace cdref::stable
