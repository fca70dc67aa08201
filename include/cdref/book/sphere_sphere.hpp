/// \file
/// cdref/book/sphere_sphere.hpp - Section 3.1.1, sphere-sphere.
///
/// A and B intersect iff |cA - cB|^2 <= (rhoA + rhoB)^2 (no square root).
///   distance d = max(|v| - (rhoA + rhoB), 0),  depth p = max(rhoA + rhoB - |v|, 0),
///   witnesses pA = cA - rhoA v/|v|,  pB = cB + rhoB v/|v|,  with v = cA - cB.
/// For concentric spheres (v = 0) the chapter lets any unit vector stand for v/|v|;
/// cdref takes e_x, so pA = cA - rhoA e_x and pB = cB + rhoB e_x (|pA - pB| = depth).
#pragma once

#include "common.hpp"

namespace cdref::book {

namespace unchecked {
/// The test on input already checked (see common.hpp).
template <class T>
bool intersect(const Sphere<T>& a, const Sphere<T>& b) {
  const Vec3<T> v = a.center - b.center;
  const T sum = a.radius + b.radius;
  return v.squaredNorm() <= sum * sum;
}
}  // namespace unchecked

/// Whether the closed sphere and sphere share a point (touching counts). Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
bool intersect(const Sphere<T>& a, const Sphere<T>& b) {
  check(a, "sphere A");
  check(b, "sphere B");
  return unchecked::intersect(a, b);
}

/// Distance, penetration depth and witness points of the sphere and the sphere (a cdref::Proximity;
/// only what the mask `w` asks for is computed, the rest stays 0). Throws cdref::invalid_input
/// naming a bad argument.
template <class T>
Proximity<sqrt_t<T>> proximity(const Sphere<T>& a, const Sphere<T>& b, unsigned w = want_proximity) {
  using S = sqrt_t<T>;
  check(a, "sphere A");
  check(b, "sphere B");
  Proximity<S> res;
  const Vec3<T> v = a.center - b.center;
  const T vv = v.squaredNorm();
  const T sum = a.radius + b.radius;
  res.intersect = vv <= sum * sum;
  if (!(w & (want_distance | want_depth | want_witnesses))) return res;

  const S len = root(vv);
  if (w & want_distance) res.distance = detail::max_of(S(len - S(sum)), S(0));
  if (w & want_depth) res.depth = detail::max_of(S(S(sum) - len), S(0));
  if (w & want_witnesses) {
    const Vec3<S> u = vv == T(0) ? unit_vec<S>(0) : detail::divided(v, len);
    res.on_a = offset(a.center, S(-a.radius), u);
    res.on_b = offset(b.center, S(b.radius), u);
  }
  return res;
}

}  // namespace cdref::book
