/// \file
/// cdref/book/segment_box.hpp - Section 3.3: a segment (or an infinite ray) against an
/// axis-aligned box by separating axes.
///
/// Theorem 3.1 for a segment and a box: the segment has no faces and one edge direction
/// r = t - s, the box has the face normals e_0, e_1, e_2 and the same three edge directions,
/// so six axes decide: the box's faces (axes 0, 1, 2) and r x e_i (axes 3, 4, 5). The
/// formulation is the one engines ship (Gottschalk 2000; Ericson, Real-Time Collision
/// Detection 5.3.3): with the segment's midpoint relative to the box centre m = (s + t)/2 - c
/// and its half-vector w = (t - s)/2, the segment projects on an axis L onto m . L +- |w . L|
/// and the box onto +- sum_i h_i |L_i|, so
///   axis i       separates iff |m_i| > h_i + |w_i|;
///   r x e_0      = (0, w_z, -w_y) up to a factor 2: |m_y w_z - m_z w_y| > h_y |w_z| + h_z |w_y|
///                (the segment projects onto a single point), and cyclically for e_1, e_2.
/// The infinite ray s + lambda d, lambda >= 0 (m = s - c, w = d) projects on axis i onto
/// [m_i, inf) when d_i > 0, (-inf, m_i] when d_i < 0 and {m_i} when d_i = 0: it is separated by
/// face i iff m_i > h_i and d_i >= 0, or m_i < -h_i and d_i <= 0; on r x e_i it projects onto
/// one point, as the segment does.
/// A zero-length segment (s = t) has w = 0: the cross axes vanish (never separating) and the
/// faces decide whether the point lies in the box. A box of zero extent is a flat box, a
/// segment or a point. Boxes are closed: touching intersects.
/// Separation::direction is the axis in world coordinates: e_i, or (t - s) x e_i (d x e_i).
#pragma once

#include "common.hpp"

namespace cdref::book {

namespace detail {

/// The three cross axes w x e_i on m, w, |w| (shared by the segment and the ray).
template <class T>
int cross_axes_apart(const Vec3<T>& m, const Vec3<T>& w, const Vec3<T>& aw, const Vec3<T>& h) {
  if (abs_of(T(m[1] * w[2] - m[2] * w[1])) > h[1] * aw[2] + h[2] * aw[1]) return 3;
  if (abs_of(T(m[2] * w[0] - m[0] * w[2])) > h[0] * aw[2] + h[2] * aw[0]) return 4;
  if (abs_of(T(m[0] * w[1] - m[1] * w[0])) > h[0] * aw[1] + h[1] * aw[0]) return 5;
  return -1;
}

template <class T>
Separation<T> separation_of(int axis, const Vec3<T>& r) {
  Separation<T> s;
  s.intersect = axis < 0;
  s.axis = axis;
  if (axis >= 0) s.direction = axis < 3 ? unit_vec<T>(axis) : Vec3<T>(r.cross(unit_vec<T>(axis - 3)));
  return s;
}

/// The separations on checked input (also the oriented box's, in its frame).
template <class T>
Separation<T> segment_box(const Segment<T>& seg, const Box<T>& box) {
  const Vec3<T> m = (seg.source + seg.target) / T(2) - box.center;
  const Vec3<T> w = (seg.target - seg.source) / T(2);
  const Vec3<T> aw(abs_of(w[0]), abs_of(w[1]), abs_of(w[2]));
  const Vec3<T>& h = box.extent;
  int axis = -1;
  for (int i = 0; i < 3 && axis < 0; ++i)
    if (abs_of(m[i]) > h[i] + aw[i]) axis = i;
  if (axis < 0) axis = cross_axes_apart(m, w, aw, h);
  return separation_of(axis, Vec3<T>(seg.target - seg.source));
}

template <class T>
Separation<T> ray_box(const Ray<T>& ray, const Box<T>& box) {
  const Vec3<T> m = ray.source - box.center;
  const Vec3<T>& d = ray.direction;
  const Vec3<T> ad(abs_of(d[0]), abs_of(d[1]), abs_of(d[2]));
  const Vec3<T>& h = box.extent;
  int axis = -1;
  for (int i = 0; i < 3 && axis < 0; ++i)
    if ((m[i] > h[i] && d[i] >= T(0)) || (m[i] < T(-h[i]) && d[i] <= T(0))) axis = i;
  if (axis < 0) axis = cross_axes_apart(m, d, ad, h);
  return separation_of(axis, d);
}

}  // namespace detail

namespace unchecked {
/// The same as the checked `separate` of these arguments, on input already checked: no input
/// checks (see book/common.hpp). For loops over bodies checked once.
template <class T>
Separation<T> separate(const Segment<T>& seg, const Box<T>& box) {
  return detail::segment_box(seg, box);
}
/// The same as the checked `separate` of these arguments, on input already checked: no input
/// checks (see book/common.hpp). For loops over bodies checked once.
template <class T>
Separation<T> separate(const Ray<T>& ray, const Box<T>& box) {
  return detail::ray_box(ray, box);
}
}  // namespace unchecked

/// Theorem 3.1 on the segment and the axis-aligned box: whether they intersect, else the first
/// separating axis in this file's order and its direction (a cdref::Separation). Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
Separation<T> separate(const Segment<T>& seg, const Box<T>& box) {
  check(seg, "segment");
  check(box, "box");
  return detail::segment_box(seg, box);
}

/// Theorem 3.1 on the ray and the axis-aligned box: whether they intersect, else the first
/// separating axis in this file's order and its direction (a cdref::Separation). Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
Separation<T> separate(const Ray<T>& ray, const Box<T>& box) {
  check(ray, "ray");
  check(box, "box");
  return detail::ray_box(ray, box);
}

/// Whether the closed segment and axis-aligned box share a point (touching counts). Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
bool intersect(const Segment<T>& seg, const Box<T>& box) {
  return separate(seg, box).intersect;
}

/// Whether the closed ray and axis-aligned box share a point (touching counts). Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
bool intersect(const Ray<T>& ray, const Box<T>& box) {
  return separate(ray, box).intersect;
}

}  // namespace cdref::book
