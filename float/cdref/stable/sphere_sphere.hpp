// cdref/stable/sphere_sphere.hpp - sphere-sphere as careful float code writes it (Box2D's
// b2CollideCircles: the centres' difference first, then |v| against the sum of the radii).
// F = float, double, long double; same signatures and results as cdref::book.
//
// The chapter's formulation is already this one, so the stable tier is book::intersect and
// book::proximity. Error bound of the classification (first order in u, the unit roundoff of
// F): v = cA - cB rounds each component once (u |v_i|), v.v adds 3u relative, the sum of the
// radii u and its square u: |v|^2 <= (rhoA + rhoB)^2 is decided right unless |v| is within
// about 3u |v| of rhoA + rhoB. Nothing cancels but the inputs' own difference, so the
// band is relative to the distance of the centres at every range.
// Distance and depth |v| - (rhoA + rhoB) cancel near touching by the problem's own condition;
// the witnesses c -+ rho v / |v| carry a few u relative.
#pragma once

#include <cdref/book/sphere_sphere.hpp>

namespace cdref::stable {

template <class F>
bool intersect(const Sphere<F>& a, const Sphere<F>& b) {
  return book::intersect(a, b);
}
template <class F>
Proximity<F> proximity(const Sphere<F>& a, const Sphere<F>& b, unsigned w = want_proximity) {
  return book::proximity(a, b, w);
}

// The classification without the input checks (see book/common.hpp).
namespace unchecked {
template <class F>
bool intersect(const Sphere<F>& a, const Sphere<F>& b) {
  return book::unchecked::intersect(a, b);
}
}  // namespace unchecked

}  // namespace cdref::stable
