/// \file
/// cdref/book/ray_box.hpp - Section 3.2.1, Algorithm 3.3: ray casts on an axis-aligned box,
/// Cohen-Sutherland outcodes with Liang-Barsky parameters.
///
/// In the box's local coordinates (centre at the origin, extent h = (eta_i)), the outcode
/// of a point p has bit 1 << 2i set iff p_i < -eta_i (outside the lower plane of axis i)
/// and bit 1 << (2i+1) set iff p_i > eta_i (outside the upper plane). If the outcodes of
/// s and t share a bit, that plane separates the segment from the box. Otherwise, for
/// every plane whose bit is set in s's outcode the crossing is entering, for every plane
/// whose bit is set in t's outcode it is exiting, at
///   lambda_- = (-sigma_i - eta_i) / (tau_i - sigma_i)   (lower plane),
///   lambda_+ = (-sigma_i + eta_i) / (tau_i - sigma_i)   (upper plane),
/// and the segment hits iff max(0, entering) <= min(1, exiting). Both planes of each axis
/// are tested inside the loop (the converted listing has the upper-plane block outside
/// it: see the errata).
///
/// The infinite ray s + lambda d uses the outcode of "t at infinity": the lower bit of
/// axis i is set iff d_i < 0, or d_i = 0 and s_i < -eta_i (upper: d_i > 0, or d_i = 0 and
/// s_i > eta_i), and tau_i - sigma_i is replaced by d_i; there is no exit at lambda = 1.
///
/// cast(): lambda_enter, lambda_exit, the entry point, and the outward normal of the
/// entering face (-e_i for a lower plane, +e_i for an upper one; on a tie between planes,
/// as at an edge or corner, the first in the order x-, x+, y-, y+, z-, z+). When the
/// source lies in the closed box no face is entered: enters = false, normal = 0.
/// hit(): the same decision with no division: the parameters are compared as fractions
/// by cross-multiplication with positive denominators.
#pragma once

#include "common.hpp"

namespace cdref::book {

namespace detail {

template <class T>
unsigned outcode(const Vec3<T>& p, const Vec3<T>& h) {
  unsigned bits = 0;
  for (int i = 0; i < 3; ++i) {
    if (p[i] < -h[i]) bits |= 1u << (2 * i);
    if (p[i] > h[i]) bits |= 1u << (2 * i + 1);
  }
  return bits;
}

template <class T>
unsigned outcode_at_infinity(const Vec3<T>& s, const Vec3<T>& d, const Vec3<T>& h) {
  unsigned bits = 0;
  for (int i = 0; i < 3; ++i) {
    if (d[i] < T(0) || (d[i] == T(0) && s[i] < -h[i])) bits |= 1u << (2 * i);
    if (d[i] > T(0) || (d[i] == T(0) && s[i] > h[i])) bits |= 1u << (2 * i + 1);
  }
  return bits;
}

/// Numerator of the crossing parameter with plane `plane` (2i lower, 2i+1 upper).
template <class T>
T plane_numerator(const Vec3<T>& s, const Vec3<T>& h, int plane) {
  const int i = plane / 2;
  return (plane % 2 == 0) ? T(-s[i] - h[i]) : T(-s[i] + h[i]);
}

/// r: t - s for a segment, d for a ray.
template <class T>
bool hit_box_local(const Vec3<T>& s, const Vec3<T>& r, const Vec3<T>& h, unsigned bs, unsigned bt, bool bounded) {
  if (bs & bt) return false;
  // Fractions num/den with den > 0. enter starts at 0/1; exit at 1/1 or "none".
  T en(0), ed(1), xn(1), xd(1);
  bool has_exit = bounded;
  for (int plane = 0; plane < 6; ++plane) {
    const unsigned bit = 1u << plane;
    if (!((bs | bt) & bit)) continue;
    T num = plane_numerator(s, h, plane);
    T den = r[plane / 2];
    if (den < T(0)) {
      num = -num;
      den = -den;
    }
    if (bs & bit) {
      if (num * ed > en * den) en = num, ed = den;
    } else if (!has_exit || num * xd < xn * den) {
      xn = num, xd = den, has_exit = true;
    }
  }
  return !has_exit || en * xd <= xn * ed;
}

template <class T>
Cast<T> cast_box_local(const Vec3<T>& s, const Vec3<T>& r, const Box<T>& box, unsigned bs, unsigned bt,
                       bool bounded, unsigned w) {
  Cast<T> res;
  if (bs & bt) return res;
  const Vec3<T>& h = box.extent;
  T enter(0), exit(1);
  bool has_exit = bounded;
  int face = -1;
  for (int plane = 0; plane < 6; ++plane) {
    const unsigned bit = 1u << plane;
    if (bs & bit) {  // entering
      const T lambda = plane_numerator(s, h, plane) / r[plane / 2];
      if (face < 0 || lambda > enter) enter = lambda, face = plane;
    } else if (bt & bit) {  // exiting
      const T lambda = plane_numerator(s, h, plane) / r[plane / 2];
      if (!has_exit || lambda < exit) exit = lambda, has_exit = true;
    }
  }
  if (has_exit && !(enter <= exit)) return res;
  res.hit = true;
  res.enters = face >= 0;
  res.lambda_enter = enter;
  res.lambda_exit = has_exit ? exit : T(0);
  res.unbounded_exit = !has_exit;
  if (w & want_point) res.point = Vec3<T>(affine(s, enter, r) + box.center);
  if ((w & want_normal) && face >= 0) res.normal = unit_vec<T>(face / 2, face % 2 == 0 ? -1 : 1);
  return res;
}

}  // namespace detail

namespace unchecked {
/// The same as the checked `hit` of these arguments, on input already checked: no input
/// checks (see book/common.hpp). For loops over bodies checked once.
template <class T>
bool hit(const Segment<T>& seg, const Box<T>& box) {
  const Vec3<T> s = seg.source - box.center;
  const Vec3<T> t = seg.target - box.center;
  return detail::hit_box_local(s, Vec3<T>(t - s), box.extent, detail::outcode(s, box.extent),
                               detail::outcode(t, box.extent), true);
}
/// The same as the checked `hit` of these arguments, on input already checked: no input
/// checks (see book/common.hpp). For loops over bodies checked once.
template <class T>
bool hit(const Ray<T>& ray, const Box<T>& box) {
  const Vec3<T> s = ray.source - box.center;
  return detail::hit_box_local(s, ray.direction, box.extent, detail::outcode(s, box.extent),
                               detail::outcode_at_infinity(s, ray.direction, box.extent), false);
}
}  // namespace unchecked

/// Whether the segment meets the closed axis-aligned box: the cast's classification alone. Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
bool hit(const Segment<T>& seg, const Box<T>& box) {
  check(seg, "segment");
  check(box, "box");
  return unchecked::hit(seg, box);
}
/// Whether the ray meets the closed axis-aligned box: the cast's classification alone. Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
bool hit(const Ray<T>& ray, const Box<T>& box) {
  check(ray, "ray");
  check(box, "box");
  return unchecked::hit(ray, box);
}

/// The segment (lambda in [0, 1]) cast on the closed axis-aligned box: hit, entry and exit
/// parameters, entry point and normal (only what the mask `w` asks for is computed). Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
Cast<T> cast(const Segment<T>& seg, const Box<T>& box, unsigned w = want_cast) {
  check(seg, "segment");
  check(box, "box");
  const Vec3<T> s = seg.source - box.center;
  const Vec3<T> t = seg.target - box.center;
  return detail::cast_box_local(s, Vec3<T>(t - s), box, detail::outcode(s, box.extent),
                                detail::outcode(t, box.extent), true, w);
}

/// The ray (lambda >= 0 in units of |direction|) cast on the closed axis-aligned box: hit, entry
/// and exit parameters, entry point and normal (only what the mask `w` asks for is computed).
/// Throws cdref::invalid_input naming a bad argument.
template <class T>
Cast<T> cast(const Ray<T>& ray, const Box<T>& box, unsigned w = want_cast) {
  check(ray, "ray");
  check(box, "box");
  const Vec3<T> s = ray.source - box.center;
  return detail::cast_box_local(s, ray.direction, box, detail::outcode(s, box.extent),
                                detail::outcode_at_infinity(s, ray.direction, box.extent), false, w);
}

}  // namespace cdref::book
