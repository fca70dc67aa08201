// cdref/stable/segment_sphere.hpp - segment-sphere as careful float code writes it: the
// closest point of the segment first (Box2D's and Ericson's segment tests), then one
// comparison. F = float, double, long double; same signatures and results as cdref::book.
//
// Algorithm 3.2's listing (book::proximity) is already this formulation: x = s + (delta/rr) r
// clamped to the segment (s, t relative to the centre, r = t - s, delta = -s.r, rr = r.r), and
// the segment meets the sphere iff x.x <= rho^2. The book's intersect() trades the division
// for |s|^2 rr - delta^2 <= rho^2 rr, which subtracts numbers of size |s|^2 |r|^2 to decide
// one of size rho^2 |r|^2 (Lagrange's identity |s|^2 |r|^2 - (s.r)^2 = |s x r|^2); the stable
// tier keeps the division. So stable::proximity is book::proximity, and stable::intersect is
// its classification alone (the same closest point, then the comparison).
//
// Error bound of the classification (first order in u, the unit roundoff of F; s and t as
// computed, i.e. moved by at most u |s| and u |t|): delta^ off by 3u |s||r|, rr relative 3u,
// lambda = delta / rr off by (3u |s||r| + 5u |delta|) / rr <= 8u |s| / |r| (|delta| <= |s||r|
// on the open segment), so |x^ - x| <= 9u |s| + u |x| as for the ray's foot
// (stable/ray_sphere.hpp) and x.x <= rho^2 is decided right unless |x| is within about
// u (9 |s| + 5 rho) of rho. The book's intersect() is off by about 4u |s|^2 rr: its band is
// about 2u |s|^2 / rho wide. At the ends (x = s or x = t) both decide |s|^2 or |t|^2 against
// rho^2 with relative error 5u.
// Witness points, distance and depth: |x| - rho cancels near touching (the problem's own
// condition: an ulp of input moves it by as much); the witness on the sphere is
// centre + rho x / |x| with relative error a few u of |x|.
#pragma once

#include <cdref/book/segment_sphere.hpp>

namespace cdref::stable {

template <class F>
Proximity<F> proximity(const Segment<F>& seg, const Sphere<F>& sp, unsigned w = want_proximity) {
  return book::proximity(seg, sp, w);
}
template <class F>
bool intersect(const Segment<F>& seg, const Sphere<F>& sp) {
  check(seg, "segment");
  check(sp, "sphere");
  return book::detail::closest_point_intersect(seg, sp);
}

// The classification without the input checks (see book/common.hpp).
namespace unchecked {
template <class F>
bool intersect(const Segment<F>& seg, const Sphere<F>& sp) {
  return book::detail::closest_point_intersect(seg, sp);
}
}  // namespace unchecked

}  // namespace cdref::stable
