/// \file
/// cdref/book/sphere_box.hpp - Section 3.2.2: sphere-box.
///
/// In the box's local coordinates (centre at the origin, extent h), with the sphere's
/// centre c, the point of the box closest to c is x = clamp(c, -h, h) component-wise, and
/// the sphere meets the box iff |x - c|^2 <= rho^2 (no square root).
/// With v = x - c:
///   centre outside the box (v != 0): distance max(|v| - rho, 0), depth max(rho - |v|, 0),
///     witness on the sphere c + rho v/|v|, witness on the box x;
///   centre in the closed box (v = 0): distance 0; the axis e_i with the smallest
///     delta_i = eta_i - |gamma_i| (first on ties) gives the witness on the box
///     y = c + delta_i sign(gamma_i) e_i, the witness on the sphere c - rho sign(gamma_i) e_i,
///     and depth delta_i + rho; sign(0) = +1, as in the chapter.
/// In proximity(), A is the sphere and B the box; `closest` is x in world coordinates.
#pragma once

#include "common.hpp"

namespace cdref::book {

namespace detail {
template <class T>
Vec3<T> clamp_to_box(const Vec3<T>& c, const Vec3<T>& h) {
  Vec3<T> x;
  // min(max(c, -h), h): the same value as the chapter's two comparisons (h >= 0), written so
  // that a float build compiles it to minimum and maximum instructions, not branches
  for (int i = 0; i < 3; ++i) x[i] = detail::min_of(detail::max_of(T(c[i]), T(-h[i])), T(h[i]));
  return x;
}
}  // namespace detail

namespace detail {

/// The queries on checked input (also the oriented box's, on the centre moved into its frame).
/// |v|^2 is summed coordinate by coordinate, in the order squaredNorm() sums: the same value,
/// without writing the clamped point to memory and reading it back as a vector (g++ stores two
/// coordinates one by one and loads them as a pair, a store it cannot forward: 2x the time).
template <class T>
bool sphere_box_intersect(const Sphere<T>& sp, const Box<T>& box) {
  const Vec3<T> c = sp.center - box.center;
  T vv = T(0);
  for (int i = 0; i < 3; ++i) {
    const T d = min_of(max_of(T(c[i]), T(-box.extent[i])), T(box.extent[i])) - c[i];
    vv += d * d;
  }
  return vv <= sp.radius * sp.radius;
}

template <class T>
Proximity<sqrt_t<T>> sphere_box_proximity(const Sphere<T>& sp, const Box<T>& box, unsigned w) {
  using S = sqrt_t<T>;
  Proximity<S> res;
  const Vec3<T> c = sp.center - box.center;
  const Vec3<T> x = clamp_to_box(c, box.extent);
  const Vec3<T> v = x - c;
  const T vv = v.squaredNorm();
  const T& rho = sp.radius;
  res.intersect = vv <= rho * rho;
  if (w & want_closest) res.closest = lift<S>(Vec3<T>(x + box.center));
  if (!(w & (want_distance | want_depth | want_witnesses))) return res;

  if (vv != T(0)) {  // centre outside the box
    const S len = root(vv);
    if (w & want_distance) res.distance = max_of(S(len - S(rho)), S(0));
    if (w & want_depth) res.depth = max_of(S(S(rho) - len), S(0));
    if (w & want_witnesses) {
      res.on_a = offset(sp.center, S(rho), divided(v, len));
      res.on_b = lift<S>(Vec3<T>(x + box.center));
    }
    return res;
  }
  // centre in the closed box
  int axis = 0;
  T delta(0);
  for (int i = 0; i < 3; ++i) {
    const T a = c[i] < T(0) ? T(-c[i]) : T(c[i]);
    const T d = box.extent[i] - a;
    if (i == 0 || d < delta) axis = i, delta = d;
  }
  const int sg = c[axis] < T(0) ? -1 : 1;
  if (w & want_depth) res.depth = S(T(delta + rho));
  if (w & want_witnesses) {
    Vec3<T> y = sp.center;
    y[axis] += sg > 0 ? delta : T(-delta);
    Vec3<T> r = sp.center;
    r[axis] -= sg > 0 ? rho : T(-rho);
    res.on_a = lift<S>(r);
    res.on_b = lift<S>(y);
  }
  return res;
}

}  // namespace detail

namespace unchecked {
/// The same as the checked `intersect` of these arguments, on input already checked: no input
/// checks (see book/common.hpp). For loops over bodies checked once.
template <class T>
bool intersect(const Sphere<T>& sp, const Box<T>& box) {
  return detail::sphere_box_intersect(sp, box);
}
}  // namespace unchecked

/// Whether the closed sphere and axis-aligned box share a point (touching counts). Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
bool intersect(const Sphere<T>& sp, const Box<T>& box) {
  check(sp, "sphere");
  check(box, "box");
  return detail::sphere_box_intersect(sp, box);
}

/// Distance, penetration depth and witness points of the sphere and the axis-aligned box (a
/// cdref::Proximity; only what the mask `w` asks for is computed, the rest stays 0). Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
Proximity<sqrt_t<T>> proximity(const Sphere<T>& sp, const Box<T>& box, unsigned w = want_proximity) {
  check(sp, "sphere");
  check(box, "box");
  return detail::sphere_box_proximity(sp, box, w);
}

}  // namespace cdref::book
