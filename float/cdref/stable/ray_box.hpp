// cdref/stable/ray_box.hpp - ray and segment casts on an axis-aligned box as careful float code
// writes them: the slab test of Kay and Kajiya in the box's frame (as in pbrt-v4's
// Bounds3::IntersectP, with its reciprocal of the direction; Williams, Barrus, Morley and Shirley, "An efficient
// and robust ray-box intersection algorithm", 2005): plain F arithmetic, no certificate. Same
// signatures and results as cdref::book (hit, cast; a segment s->t or a ray s + lambda d).
//
// Formulation (f = source - centre, each component rounded once; r the direction: t - s for
// a segment, d for a ray; h the extent):
//  1. Per axis i the crossing parameters of the two planes, t_lo = (-h_i - f_i) v_i and
//     t_hi = (h_i - f_i) v_i with v_i = 1 / r_i rounded once (the quotients themselves where
//     v_i overflows, |r_i| below 2^-1024 at double); the near one is t_lo when r_i is positive
//     (sign bit clear, +0 included) and t_hi otherwise. With r_i = 0, v_i is an infinity of
//     r_i's sign and they are infinities of the right sign
//     (the source outside the slab: +inf near or -inf far, a miss; inside: -inf near and
//     +inf far, no constraint), and NaN (0 inf) when the source lies on a plane: that plane
//     constrains nothing, as for the book's closed box (every comparison below is written
//     so that a NaN loses).
//  2. lambda_enter = max(0, near_i), lambda_exit = min(1 (segment) or +inf (ray), far_i);
//     the shot hits iff lambda_enter <= lambda_exit. The entering face is the axis whose
//     near value is largest (the first in x, y, z on a tie), strictly above 0: the source on
//     the face plane does not enter through it, as in the book.
//  3. The entry point: on the entering face its coordinate is the face's, c_i -+ h_i, rounded
//     once (the book's s + lambda r lands within rounding of the plane, not on it); the other
//     two are s_j + lambda r_j. A source in the box is its own entry point. The normal is
//     -e_i or +e_i.
// What differs from the book: the book decides hit() by comparing the parameters as
// fractions, cross-multiplied: the products overflow and underflow where the parameters do
// not (book-double's predicate is wrong on 6,843 of the magnitude family's 30,000 ray casts,
// `cdref campaign --query ray-box-cast --family magnitude --impl book-double`), and its outcode
// branches cost time. Here each parameter is one product by the direction's reciprocal (three
// divisions a query instead of six; a traversal of many boxes would precompute them) and the
// test is branch-free but for the reciprocal's overflow (subnormal directions), which adds
// one rounding to each parameter. Measured (`cdref_bench
// --benchmark_filter='box-cast/uniform-0/(bare|stable-double-unchecked)'`, g++ 12 Release, this
// 2-core machine, 2026-11-23, medians of 3): the unchecked classification with six quotients
// 1.22x the book's unchecked one on the segment and 0.95x on the ray; with the reciprocal 1.02x
// and 0.76x (the report of 52dcb4e had the quotients' segment cast at 2.17x its `bare`). Why f = s - c first rather than pbrt's corners
// c -+ h: the corner's rounding, u |c_i|, does not shrink as the source nears the box, while
// the rounding of f is u |f_i| <= u (|h_i -+ f_i| + h_i), of the size of the numerator and
// the box (and s - c is exact when s_i and c_i are within a factor 2: a source on a face plane
// of a box near it stays on it).
//
// Error bound (first order in u, the unit roundoff of F). Each computed parameter is
//     t^ = (-+h_i - f_i (1 + d0))(1 + d1) (1 + d3) (1 + d4) / (r_i (1 + d2)),
// d2 = 0 for a ray (r = d is an input), d3 the reciprocal's rounding and d4 the product's
// (where the quotient is taken, one of them), so, with f_i = s_i - c_i exactly,
//     |t^ - t| <= E(t) = 4u |t| + u |f_i| / |r_i|   (<= 5u |t| + u h_i / |r_i|).
// The exact answer is "every a in {0, near_i} is <= every b in {1 (segment), far_j}", and the
// computed one is the same test on t^: they differ only if some pair (a, b) is in the wrong
// order, that is |a - b| <= E(a) + E(b). For r_i = 0 only the rounding of f_i can move the
// source across a plane: |h_i -+ f_i| <= u |f_i|. Outside these bands the stable test is
// exact. The bands are relative to the parameters and the box, so they hold at every range and
// scale while the parameters are normal numbers (the magnitude family at 10^-310 makes the
// inputs subnormal, where f and the numerators are exact and only the quotients round).
// At range the band is what it is for any formulation in F: a parameter of size |f| / |r|
// carries u |f| / |r|, so once u |f| reaches the box's size (about 10^7 box sizes at float,
// 10^16 at double) shots near the box are decided at random (book-float and stable-float alike
// misclassify 262 of 2,000 ray casts at 10^7 box sizes and 720-730 from 10^9 on; at double
// neither misclassifies any up to 10^12). On every family the casts misclassify about as many
// cases as the book's casts (the same parameters, one rounding apart: `CDREF_TEST_REPORT=1
// cdref_tests "stable box casts*"`, 2026-11-24, float: 283 and 215 of 4,465 and 4,041 against
// the book's 282 and 219; double: 10 and 9 of 4,783 against 70 and 182, the book's products
// overflowing): what this tier adds is a predicate that does not overflow and a branch-free loop. Grazing shots (along a face or through an edge, the grazing family) lie in
// the bands by construction. tests/test_robust_boxes.cpp ("[stable]") checks that every
// misclassified generated case lies in one of these bands, computed exactly.
//
// Not pbrt's conservative factor: pbrt scales far by 1 + 2 gamma_3 so that a traversal never
// misses a box it touches. With corners that are inputs (pbrt's bounds), t^ lies within
// gamma_3 |t| of t (three roundings: numerator, reciprocal, product), and near <= far needs
// far^ (1 + k) >= near^ after the product's own rounding: (1 - 3u)(1 + k)(1 - u) >= 1 + 3u,
// i.e. k >= 7u to first order; 2 gamma_3 = 6u is one rounding short when near = far (a shot
// through an edge). cdref's stable tier reports its best estimate instead, whose error is the
// band above, and the campaign measures both sides (false hits and false misses).
//
// Outputs: lambda_enter has relative error 4u + u |f_i| / |h_i -+ f_i|: a few ulps unless the
// source is near the entering plane relative to its distance from the centre. The point's face
// coordinate is correctly rounded; the others carry lambda's error times |r_j| plus two
// roundings.
#pragma once

#include <cdref/book/common.hpp>
#include <cmath>
#include <limits>

namespace cdref::stable {

namespace detail {

template <class F>
struct Slab {
  F enter, exit;
  int face;  // -1: no face entered; 2i lower plane of axis i, 2i + 1 upper
  bool hit;
};

// Steps 1-2 for f = source - centre, the direction r and the extent h; bounded: a segment.
template <class F>
Slab<F> slab(const Vec3<F>& f, const Vec3<F>& r, const Vec3<F>& h, bool bounded) {
  Slab<F> k{F(0), bounded ? F(1) : std::numeric_limits<F>::infinity(), -1, false};
  for (int i = 0; i < 3; ++i) {
    // one reciprocal a component (pbrt's), the quotients where it overflows (r_i subnormal)
    const F inv = F(1) / r[i];
    F t_lo, t_hi;
    if (std::fabs(inv) <= std::numeric_limits<F>::max() || r[i] == F(0)) [[likely]] {
      t_lo = (-h[i] - f[i]) * inv;
      t_hi = (h[i] - f[i]) * inv;
    } else {
      t_lo = (-h[i] - f[i]) / r[i];
      t_hi = (h[i] - f[i]) / r[i];
    }
    const bool down = std::signbit(r[i]);
    const F near = down ? t_hi : t_lo, far = down ? t_lo : t_hi;
    if (near > k.enter) k.enter = near, k.face = 2 * i + (down ? 1 : 0);
    if (far < k.exit) k.exit = far;
  }
  k.hit = k.enter <= k.exit;
  return k;
}

// Step 0 for a segment: its two ends strictly beyond one face plane, with f = s - c and g =
// t - c each rounded once (in an oriented box's frame, the frame coordinates of the ends:
// obb.hpp). Then the segment misses, and for an axis-aligned box exactly so: rounding is
// monotone and h_i is a float, so fl(s_i - c_i) > h_i implies s_i - c_i > h_i. These are
// Algorithm 3.3's outcodes (and Bullet's btRayAabb reject): the three axes are tested without
// a branch, and the one branch on the answer skips the slab's divisions on most misses.
template <class F>
bool ends_beyond_one_plane(const Vec3<F>& f, const Vec3<F>& g, const Vec3<F>& h) {
  bool out = false;
  for (int i = 0; i < 3; ++i) {
    const F a = f[i], b = g[i], e = h[i];  // (plain values: no call inside the bitwise operators)
    out |= ((a > e) & (b > e)) | ((a < -e) & (b < -e));
  }
  return out;
}

template <class F>
Cast<F> cast_slab(const Vec3<F>& s, const Vec3<F>& r, const Box<F>& box, bool bounded, unsigned w) {
  Cast<F> res;
  const Slab<F> k = slab(Vec3<F>(s - box.center), r, box.extent, bounded);
  if (!k.hit) return res;
  res.hit = true;
  res.enters = k.face >= 0;
  res.lambda_enter = k.enter;
  res.lambda_exit = k.exit;
  if (w & want_point) {
    if (k.face < 0) {
      res.point = s;
    } else {
      const int a = k.face / 2;
      for (int j = 0; j < 3; ++j)
        res.point[j] = j == a ? F(k.face % 2 == 0 ? box.center[j] - box.extent[j] : box.center[j] + box.extent[j])
                              : F(s[j] + k.enter * r[j]);
    }
  }
  if ((w & want_normal) && k.face >= 0) res.normal = unit_vec<F>(k.face / 2, k.face % 2 == 0 ? -1 : 1);
  return res;
}

}  // namespace detail

// The classification without the input checks (see book/common.hpp).
namespace unchecked {
template <class F>
bool hit(const Segment<F>& seg, const Box<F>& box) {
  const Vec3<F> f(seg.source - box.center);
  if (detail::ends_beyond_one_plane(f, Vec3<F>(seg.target - box.center), box.extent)) return false;
  return detail::slab(f, Vec3<F>(seg.target - seg.source), box.extent, true).hit;
}
template <class F>
bool hit(const Ray<F>& ray, const Box<F>& box) {
  return detail::slab(Vec3<F>(ray.source - box.center), ray.direction, box.extent, false).hit;
}
}  // namespace unchecked

template <class F>
bool hit(const Segment<F>& seg, const Box<F>& box) {
  check(seg, "segment");
  check(box, "box");
  return unchecked::hit(seg, box);
}
template <class F>
bool hit(const Ray<F>& ray, const Box<F>& box) {
  check(ray, "ray");
  check(box, "box");
  return unchecked::hit(ray, box);
}
template <class F>
Cast<F> cast(const Segment<F>& seg, const Box<F>& box, unsigned w = want_cast) {
  check(seg, "segment");
  check(box, "box");
  if (detail::ends_beyond_one_plane(Vec3<F>(seg.source - box.center), Vec3<F>(seg.target - box.center), box.extent))
    return Cast<F>{};  // (step 0, as unchecked::hit)
  return detail::cast_slab(seg.source, Vec3<F>(seg.target - seg.source), box, true, w);
}
template <class F>
Cast<F> cast(const Ray<F>& ray, const Box<F>& box, unsigned w = want_cast) {
  check(ray, "ray");
  check(box, "box");
  return detail::cast_slab(ray.source, ray.direction, box, false, w);
}

}  // namespace cdref::stable
