/// \file
/// cdref/book/obb.hpp - the chapter's tests on an oriented box as engines write them: the
/// other primitive moved into the box's frame (p -> (a_0 . (p - c), a_1 . (p - c),
/// a_2 . (p - c))), then the axis-aligned test of Sections 3.2-3.3 on the box [-h, h].
///   separate(Segment | Ray | Triangle, OrientedBox)   segment_box.hpp / triangle_box.hpp in
///                                                     the frame (6 or 13 axes, same order:
///                                                     the box's faces are its axes a_i);
///   cast / hit(Segment | Ray, OrientedBox)            Algorithm 3.3 in the frame; lambda is
///                                                     the same in both frames, the entry
///                                                     point s + lambda r is computed in world
///                                                     coordinates, the normal is -+a_i for the
///                                                     entering face (x-, x+, y-, ... order);
///   proximity / intersect(Sphere, OrientedBox)        Section 3.2.2 in the frame, witnesses
///                                                     and the closest point mapped back
///                                                     (c + sum_i p_i a_i).
/// The moved primitive is not checked again: at a float type its coordinates may overflow where
/// the inputs do not, and the answer then drifts (as every float formulation does), it is not
/// refused. Moving into the frame with the transpose inverts the frame only when it is
/// orthonormal.
/// Axes given as floats are orthonormal only to rounding, and the box is then the
/// parallelepiped they span (primitives.hpp): these formulations approximate that solid even
/// at an exact type. The solid's own answers are in cdref/solid/obb.hpp.
/// Separation::direction is in world coordinates.
#pragma once

#include "common.hpp"
#include "ray_box.hpp"
#include "segment_box.hpp"
#include "sphere_box.hpp"
#include "triangle_box.hpp"

namespace cdref::book {

namespace detail {

/// A point and a direction in the box's frame (A^T (p - c) and A^T v).
template <class T>
Vec3<T> frame_point(const OrientedBox<T>& b, const Vec3<T>& p) {
  const Vec3<T> d = p - b.center;
  return Vec3<T>(b.axis[0].dot(d), b.axis[1].dot(d), b.axis[2].dot(d));
}
template <class T>
Vec3<T> frame_vector(const OrientedBox<T>& b, const Vec3<T>& v) {
  return Vec3<T>(b.axis[0].dot(v), b.axis[1].dot(v), b.axis[2].dot(v));
}
/// Back to world coordinates: c + sum_i p_i a_i (over the sqrt type S of p).
template <class S, class T>
Vec3<S> world_point(const OrientedBox<T>& b, const Vec3<S>& p) {
  Vec3<S> w = lift<S>(b.center);
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) w[k] += p[i] * S(b.axis[i][k]);
  return w;
}
template <class T>
Box<T> frame_box(const OrientedBox<T>& b) {
  return {zero_vec<T>(), b.extent};
}

/// An axis of the frame's Separation back in world coordinates; `edge_k` gives the world
/// direction of the other primitive's edge k (the segment's r, the triangle's e_k).
template <class T, class EdgeOf>
Separation<T> world_separation(Separation<T> s, const OrientedBox<T>& b, int faces_before, const Vec3<T>& normal,
                               EdgeOf edge_k) {
  if (s.intersect) return s;
  if (s.axis < faces_before)
    s.direction = normal;
  else if (s.axis < faces_before + 3)
    s.direction = b.axis[s.axis - faces_before];
  else {
    const int e = s.axis - faces_before - 3;
    s.direction = edge_k(e / 3).cross(b.axis[e % 3]);
  }
  return s;
}

template <class T>
Cast<T> cast_in_frame(const Vec3<T>& s_world, const Vec3<T>& r_world, const OrientedBox<T>& b, bool bounded,
                      unsigned w) {
  const Vec3<T> s = frame_point(b, s_world);
  const Vec3<T> r = frame_vector(b, r_world);
  const Box<T> box = frame_box(b);
  const unsigned bt = bounded ? outcode(Vec3<T>(s + r), box.extent) : outcode_at_infinity(s, r, box.extent);
  Cast<T> c = cast_box_local(s, r, box, outcode(s, box.extent), bt, bounded, w | want_normal);
  if (!c.hit) return c;
  if (w & want_point) c.point = affine(s_world, c.lambda_enter, r_world);
  if (c.enters) {
    int axis = 0;
    while (c.normal[axis] == T(0)) ++axis;
    const bool upper = c.normal[axis] > T(0);
    c.normal = (w & want_normal) ? Vec3<T>(upper ? b.axis[axis] : Vec3<T>(-b.axis[axis])) : zero_vec<T>();
  }
  return c;
}

}  // namespace detail

namespace unchecked {
/// The same as the checked `separate` of these arguments, on input already checked: no input
/// checks (see book/common.hpp). For loops over bodies checked once.
template <class T>
Separation<T> separate(const Segment<T>& seg, const OrientedBox<T>& b) {
  const Segment<T> local{detail::frame_point(b, seg.source), detail::frame_point(b, seg.target)};
  const Vec3<T> r = seg.target - seg.source;
  return detail::world_separation(detail::segment_box(local, detail::frame_box(b)), b, 0, r, [&](int) { return r; });
}

/// The same as the checked `separate` of these arguments, on input already checked: no input
/// checks (see book/common.hpp). For loops over bodies checked once.
template <class T>
Separation<T> separate(const Ray<T>& ray, const OrientedBox<T>& b) {
  const Ray<T> local{detail::frame_point(b, ray.source), detail::frame_vector(b, ray.direction)};
  return detail::world_separation(detail::ray_box(local, detail::frame_box(b)), b, 0, ray.direction,
                                  [&](int) { return ray.direction; });
}

/// The same as the checked `separate` of these arguments, on input already checked: no input
/// checks (see book/common.hpp). For loops over bodies checked once.
template <class T>
Separation<T> separate(const Triangle<T>& tri, const OrientedBox<T>& b) {
  const Triangle<T> local{{detail::frame_point(b, tri.vertex[0]), detail::frame_point(b, tri.vertex[1]),
                           detail::frame_point(b, tri.vertex[2])}};
  const Vec3<T> n = Vec3<T>(tri.vertex[1] - tri.vertex[0]).cross(Vec3<T>(tri.vertex[2] - tri.vertex[0]));
  return detail::world_separation(detail::triangle_box(local, detail::frame_box(b)), b, 1, n,
                                  [&](int k) { return Vec3<T>(tri.vertex[(k + 1) % 3] - tri.vertex[k]); });
}
/// The same as the checked `hit` of these arguments, on input already checked: no input
/// checks (see book/common.hpp). For loops over bodies checked once.
template <class T>
bool hit(const Segment<T>& seg, const OrientedBox<T>& b) {
  const Vec3<T> s = detail::frame_point(b, seg.source), t = detail::frame_point(b, seg.target);
  return detail::hit_box_local(s, Vec3<T>(t - s), b.extent, detail::outcode(s, b.extent), detail::outcode(t, b.extent),
                               true);
}

/// The same as the checked `hit` of these arguments, on input already checked: no input
/// checks (see book/common.hpp). For loops over bodies checked once.
template <class T>
bool hit(const Ray<T>& ray, const OrientedBox<T>& b) {
  const Vec3<T> s = detail::frame_point(b, ray.source), d = detail::frame_vector(b, ray.direction);
  return detail::hit_box_local(s, d, b.extent, detail::outcode(s, b.extent), detail::outcode_at_infinity(s, d, b.extent),
                               false);
}
/// The same as the checked `intersect` of these arguments, on input already checked: no input
/// checks (see book/common.hpp). For loops over bodies checked once.
template <class T>
bool intersect(const Sphere<T>& sp, const OrientedBox<T>& b) {
  return detail::sphere_box_intersect(Sphere<T>{detail::frame_point(b, sp.center), sp.radius}, detail::frame_box(b));
}
}  // namespace unchecked

/// Theorem 3.1 on the segment and the oriented box: whether they intersect, else the first
/// separating axis in this file's order and its direction (a cdref::Separation). Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
Separation<T> separate(const Segment<T>& seg, const OrientedBox<T>& b) {
  check(seg, "segment");
  check(b, "oriented box");
  return unchecked::separate(seg, b);
}
/// Theorem 3.1 on the ray and the oriented box: whether they intersect, else the first separating
/// axis in this file's order and its direction (a cdref::Separation). Throws cdref::invalid_input
/// naming a bad argument.
template <class T>
Separation<T> separate(const Ray<T>& ray, const OrientedBox<T>& b) {
  check(ray, "ray");
  check(b, "oriented box");
  return unchecked::separate(ray, b);
}
/// Theorem 3.1 on the triangle and the oriented box: whether they intersect, else the first
/// separating axis in this file's order and its direction (a cdref::Separation). Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
Separation<T> separate(const Triangle<T>& tri, const OrientedBox<T>& b) {
  check(tri, "triangle");
  check(b, "oriented box");
  return unchecked::separate(tri, b);
}

/// Whether the closed segment and oriented box share a point (touching counts). Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
bool intersect(const Segment<T>& seg, const OrientedBox<T>& b) {
  return separate(seg, b).intersect;
}
/// Whether the closed triangle and oriented box share a point (touching counts). Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
bool intersect(const Triangle<T>& tri, const OrientedBox<T>& b) {
  return separate(tri, b).intersect;
}

/// The segment (lambda in [0, 1]) cast on the closed oriented box: hit, entry and exit parameters,
/// entry point and normal (only what the mask `w` asks for is computed). Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
Cast<T> cast(const Segment<T>& seg, const OrientedBox<T>& b, unsigned w = want_cast) {
  check(seg, "segment");
  check(b, "oriented box");
  return detail::cast_in_frame(seg.source, Vec3<T>(seg.target - seg.source), b, true, w);
}

/// The ray (lambda >= 0 in units of |direction|) cast on the closed oriented box: hit, entry and
/// exit parameters, entry point and normal (only what the mask `w` asks for is computed). Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
Cast<T> cast(const Ray<T>& ray, const OrientedBox<T>& b, unsigned w = want_cast) {
  check(ray, "ray");
  check(b, "oriented box");
  return detail::cast_in_frame(ray.source, ray.direction, b, false, w);
}

/// Whether the segment meets the closed oriented box: the cast's classification alone. Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
bool hit(const Segment<T>& seg, const OrientedBox<T>& b) {
  check(seg, "segment");
  check(b, "oriented box");
  return unchecked::hit(seg, b);
}
/// Whether the ray meets the closed oriented box: the cast's classification alone. Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
bool hit(const Ray<T>& ray, const OrientedBox<T>& b) {
  check(ray, "ray");
  check(b, "oriented box");
  return unchecked::hit(ray, b);
}
/// Whether the closed sphere and oriented box share a point (touching counts). Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
bool intersect(const Sphere<T>& sp, const OrientedBox<T>& b) {
  check(sp, "sphere");
  check(b, "oriented box");
  return unchecked::intersect(sp, b);
}

/// Distance, penetration depth and witness points of the sphere and the oriented box (a
/// cdref::Proximity; only what the mask `w` asks for is computed, the rest stays 0). Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
Proximity<sqrt_t<T>> proximity(const Sphere<T>& sp, const OrientedBox<T>& b, unsigned w = want_proximity) {
  check(sp, "sphere");
  check(b, "oriented box");
  Proximity<sqrt_t<T>> p =
      detail::sphere_box_proximity(Sphere<T>{detail::frame_point(b, sp.center), sp.radius}, detail::frame_box(b), w);
  if (w & want_closest) p.closest = detail::world_point(b, p.closest);
  if (w & want_witnesses) {
    p.on_a = detail::world_point(b, p.on_a);
    p.on_b = detail::world_point(b, p.on_b);
  }
  return p;
}

}  // namespace cdref::book
