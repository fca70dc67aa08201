// cdref/stable/obb.hpp - the chapter's tests on an oriented box as careful float code writes
// them: the other primitive moved into the box's frame, then the axis-aligned test of the
// stable tier (as book/obb.hpp does with the book's). F = float, double, long double; same
// signatures and results as cdref::book.
//
//   cast / hit(Segment | Ray, OrientedBox)   the slab test of stable/ray_box.hpp on
//                                            f = A^T (s - c) and r' = A^T r (the box [-h, h]
//                                            about the origin): lambda is the same in both
//                                            frames; the entry point is formed in the frame
//                                            (its face coordinate -+h_i exactly, the others
//                                            f_j + lambda r'_j) and mapped back as
//                                            c + sum_i p_i a_i; the normal is -+a_i.
//   separate(Segment | Ray | Triangle, OBB)  book::separate (the separating axes in the
//                                            frame, what engines ship: stable/segment_box.hpp,
//                                            stable/triangle_box.hpp);
//   proximity / intersect(Sphere, OBB)       book::proximity / book::intersect (Section 3.2.2
//                                            in the frame: stable/sphere_box.hpp).
//
// Error bound of the cast (first order in u, the unit roundoff of F). Moving into the frame
// rounds s - c once (u |s - c|) and each dot product with an axis (3u |a_i| |s - c| with
// |a_i| = 1 to rounding), so f_i is off by about 4u |s - c| and r'_i by 3u |r|; the slab's
// crossing parameters (-+h_i - f_i) / r'_i (a product by the reciprocal: stable/ray_box.hpp)
// are then off by
//     4u |t| + 4u |s - c| / |r'_i| + 3u |t| |r| / |r'_i|,
// and a shot is decided right outside the bands where two of them (or 0, or 1 for a segment)
// are within the sum of their errors. Against the exact parallelepiped (the truth: axes
// given as floats are orthonormal only to rounding) the transpose is not the inverse: the
// frame itself is off by |A^T A - I| |s - c|, a few u |s - c| for axes rounded from a
// rotation, of the same order as the rounding above. Every formulation that moves the shot
// into the frame carries these bands; they grow with the source's distance from the box
// relative to the box's size, as for the axis-aligned box (stable/ray_box.hpp). A segment is
// first rejected where both ends' frame coordinates lie beyond one face plane (ray_box.hpp,
// step 0; the target's taken as A^T (t - c), rounded as f is): each is off by about
// 4u |p - c| plus the frame's |A^T A - I| |p - c|, so the reject is right outside bands of
// that width about the face planes, which the slab's bands above contain.
// Outputs: the entry point's face coordinate in the frame is exact, so its distance from the
// face plane is only the mapping's rounding (u (|c| + 3 h) per component), where the book's
// s + lambda r carries lambda's error times |r| (of the order of u |s - c| at range); the
// other two coordinates carry lambda's error times |r'_j| as in the book.
#pragma once

#include <cdref/book/obb.hpp>
#include <cdref/stable/ray_box.hpp>

namespace cdref::stable {

namespace detail {

// The axis-aligned slab cast (ray_box.hpp) on the shot in the frame and the box [-h, h] about
// the origin (f - 0 and 0 -+ h are exact, so the entry point's face coordinate is -+h_i), its
// point and normal then moved back to world coordinates, as book::detail::cast_in_frame does.
template <class F>
Cast<F> cast_in_frame(const Vec3<F>& s_world, const Vec3<F>& r_world, const OrientedBox<F>& b, bool bounded,
                      unsigned w) {
  Cast<F> c = cast_slab(book::detail::frame_point(b, s_world), book::detail::frame_vector(b, r_world),
                        book::detail::frame_box(b), bounded, w | want_normal);
  if (!c.hit) return c;
  if (w & want_point) c.point = c.enters ? book::detail::world_point(b, c.point) : s_world;
  if (c.enters) {
    int axis = 0;
    while (c.normal[axis] == F(0)) ++axis;
    const Vec3<F>& ax = b.axis[axis];
    c.normal = !(w & want_normal) ? zero_vec<F>() : c.normal[axis] > F(0) ? ax : Vec3<F>(-ax);
  }
  return c;
}

}  // namespace detail

namespace unchecked {
template <class F>
bool hit(const Segment<F>& seg, const OrientedBox<F>& b) {
  const Vec3<F> f = book::detail::frame_point(b, seg.source);
  if (detail::ends_beyond_one_plane(f, book::detail::frame_point(b, seg.target), b.extent)) return false;
  return detail::slab(f, book::detail::frame_vector(b, Vec3<F>(seg.target - seg.source)), b.extent, true).hit;
}
template <class F>
bool hit(const Ray<F>& ray, const OrientedBox<F>& b) {
  return detail::slab(book::detail::frame_point(b, ray.source), book::detail::frame_vector(b, ray.direction), b.extent,
                      false)
      .hit;
}
template <class F>
bool intersect(const Sphere<F>& sp, const OrientedBox<F>& b) {
  return book::unchecked::intersect(sp, b);
}
}  // namespace unchecked

template <class F>
bool hit(const Segment<F>& seg, const OrientedBox<F>& b) {
  check(seg, "segment");
  check(b, "oriented box");
  return unchecked::hit(seg, b);
}
template <class F>
bool hit(const Ray<F>& ray, const OrientedBox<F>& b) {
  check(ray, "ray");
  check(b, "oriented box");
  return unchecked::hit(ray, b);
}
template <class F>
Cast<F> cast(const Segment<F>& seg, const OrientedBox<F>& b, unsigned w = want_cast) {
  check(seg, "segment");
  check(b, "oriented box");
  if (detail::ends_beyond_one_plane(book::detail::frame_point(b, seg.source), book::detail::frame_point(b, seg.target),
                                    b.extent))
    return Cast<F>{};  // (as unchecked::hit)
  return detail::cast_in_frame(seg.source, Vec3<F>(seg.target - seg.source), b, true, w);
}
template <class F>
Cast<F> cast(const Ray<F>& ray, const OrientedBox<F>& b, unsigned w = want_cast) {
  check(ray, "ray");
  check(b, "oriented box");
  return detail::cast_in_frame(ray.source, ray.direction, b, false, w);
}

template <class F>
Separation<F> separate(const Segment<F>& seg, const OrientedBox<F>& b) {
  return book::separate(seg, b);
}
template <class F>
Separation<F> separate(const Ray<F>& ray, const OrientedBox<F>& b) {
  return book::separate(ray, b);
}
template <class F>
Separation<F> separate(const Triangle<F>& tri, const OrientedBox<F>& b) {
  return book::separate(tri, b);
}

template <class F>
bool intersect(const Sphere<F>& sp, const OrientedBox<F>& b) {
  return book::intersect(sp, b);
}
template <class F>
Proximity<F> proximity(const Sphere<F>& sp, const OrientedBox<F>& b, unsigned w = want_proximity) {
  return book::proximity(sp, b, w);
}

}  // namespace cdref::stable
