// cdref/stable/ray_triangle.hpp - ray and segment casts on a triangle as careful float code
// writes them: Woop, Benthin and Wald, "Watertight Ray/Triangle Intersection" (JCGT 2013), the
// test pbrt-v4 ships, in plain F arithmetic (float, double, long double), no certificate. Same
// signatures and results as cdref::book (hit, cast; a segment s->t or a ray s + lambda d). The
// robust tier (robust/ray_triangle.hpp) runs the same arithmetic on scaled inputs for its
// values where its double words cannot decide.
//
// Formulation (r the direction: t - s for a segment, d for a ray):
//  1. The vertices moved to the source, P_k = v_k - s (one rounding per coordinate); the axes
//     permuted cyclically so that z is the direction's largest coordinate (kz; the cyclic
//     permutation keeps the orientation); the shear Sx = -r_x/r_z, Sy = -r_y/r_z (|S| <= 1)
//     applied: p_k = (P_kx + Sx P_kz, P_ky + Sy P_kz). The shot is now the origin of the
//     sheared plane, looking down z.
//  2. The edge functions e0 = p1 x p2, e1 = p2 x p0, e2 = p0 x p1 (2D cross products, one
//     rounding per product and one for the difference) are, exactly, w_k / r_z with
//     w_0 = r . (B x C), w_1 = r . (C x A), w_2 = r . (A x B) of book/ray_triangle.hpp
//     (A, B, C = P_0, P_1, P_2). The line meets the closed triangle iff they do not have
//     opposite signs.
//  3. det = e0 + e1 + e2 (= r . n / r_z, n = (v1 - v0) x (v2 - v0)) and t = e0 z0 + e1 z1 +
//     e2 z2 with z_k = P_kz / r_z (as Sz P_kz, Sz = 1 / r_z): lambda = t / det, tested by sign
//     against [0, 1] (segment) or [0, inf) (closed: lambda = 0 and 1 are hits).
//  4. det = 0 as computed: if all three e_k are 0 the line lies in the plane as rounded and the
//     book's coplanar clip runs in F (book::detail::cast_flat); otherwise the shot is parallel
//     to the plane: a miss. A zero-length segment is the book's point test in F.
//  5. Values: lambda = t / det; the barycentric weights b_k = e_k / det (u = b1, v = b2); the
//     point b0 v0 + b1 v1 + b2 v2 (on the triangle to rounding, at any range of the source,
//     where s + lambda r carries lambda's error times |r|); the normal (v1 - v0) x (v2 - v0)
//     normalised and turned to face the source (0 when the source is in the plane as computed).
//
// Why no ray leaks between two triangles that share an edge: every vertex is translated and
// sheared the same way in every triangle that holds it (the same rounded sheared coordinates),
// so the triangles' projections form a mesh again; a shared edge's function is computed from
// the same two products in both triangles, with its operands swapped, and fl(a b) - fl(c d) is
// exactly -(fl(c d) - fl(a b)); and its sign is never the wrong one for the sheared coordinates
// (rounding is monotonic: a b > c d implies fl(a b) >= fl(c d)), only possibly 0, which a
// closed test counts as inside. So the origin, which lies in the sheared mesh, lies in some
// triangle's closed projection as computed. (pbrt-v4 recomputes in double where a float edge
// function is 0 to avoid a double hit; with closed triangles a double hit is allowed, and cdref
// does not.) This holds against the mesh as rounded, not against the exact inputs: the
// classification of one triangle can still differ from the exact one, within the bands below.
//
// Error bound of the classification (first order in u, the unit roundoff of F; m_k = |P_kx| +
// |P_ky| + |P_kz|, the exact P_k). Each sheared coordinate is off by at most
//     u |P_kx| + u |Sx| |P_kz| (P's rounding) + 2u |Sx P_kz| (Sx and the product) + u |p_kx|
//     <= 4u m_k   (|Sx| <= 1, |p_kx| <= m_k),
// so e0's error is at most 4 * 4u m1 m2 (the operands) + 2u m1 m2 (the products) + 2u m1 m2
// (the difference): |e0^ - e0| <= E_0 = 20u m1 m2, likewise E_1 = 20u m2 m0, E_2 = 20u m0 m1.
// With every e_k's sign right the line test is right and det^ has det's sign (a sum of terms
// of one sign); t^ is off by at most Et = sum_k |z_k| (E_k + 6u |e_k|) (z_k's three roundings,
// the product and the sums, first order), det^ by Edet = sum_k E_k + 2u |det|. So the stable
// test can differ from the exact one only if some |e_k| <= E_k (the shot within about
// 20u m m' / |n| of an edge's line, or parallel to the plane: then every e_k is small), or
// |t| <= Et (lambda near 0: the source near the plane), or, for a segment, |t - det| <= Et +
// Edet (the target near the plane). Where a triangle's edge functions are all 0 (a shot in its
// plane, a zero-area triangle seen edge-on) the e bands hold trivially and the book's flat
// cases run in F. A zero-length segment is the book's point test at F. tests/test_triangles.cpp
// ("[stable]") checks that every misclassified generated case lies in one of these bands,
// computed exactly.
// Range: e_k and t are products of two coordinates (z_k is a ratio): inputs past about 10^150
// (double; 10^19 at float) overflow them, and below about 10^-150 they underflow; the robust
// tier scales by a power of two first.
// Measured (`cdref campaign --query ray-triangle-cast --impl book-double --impl stable-double
// --n 1000`, misclassified of 15,000 per family unless said): near-edge 18 (Moller-Trumbore 33),
// grazing 177 (262), long-range 363 of 13,000 (724); but coplanar 214 of 1,000 (0) and
// degenerate 41 of 1,000 (0): a shot in the triangle's plane, or a zero-area triangle, gives
// sheared edge functions that are not all exactly 0, and their rounding decides, where the
// book's det is exactly 0 and its flat cases decide exactly. The magnitude family: 10^200 and
// beyond overflow here (521-554 of 1,000 a scale), not in the book; both underflow from
// 10^-200 down.
// Cost (`cdref_bench --benchmark_filter='triangle-cast/uniform-0/(bare|stable-double-unchecked)'`,
// g++ 12 Release, this 2-core machine, 2026-11-23, medians of 3): the unchecked classification
// 0.34x (ray) and 0.41x (segment) the book's unchecked hit(), whose three triple products and
// two more for the range cost 26.8 and 27.5 us per 1,024 cases against 9.0 and 11.3.
//
// Outputs: the weights and lambda carry the e_k's error relative to det (a few ulps unless the
// triangle is seen edge-on or the shot nears an edge, where the problem itself amplifies it).
#pragma once

#include <cdref/book/ray_triangle.hpp>
#include <cmath>

namespace cdref::stable {

namespace detail {

// Steps 1-3: the edge functions, det and t, and the classification (with `values`, a miss
// still carries the values at the plane's crossing or at the source: robust's uncertain hit).
template <class F>
struct Sheared {
  F e[3], det, t, Sz;
  bool flat;  // det = 0 and every e_k = 0: the book's coplanar clip decides
  bool out;   // a miss (when not flat)
};

template <class F>
Sheared<F> shear(const Vec3<F>& s, const Vec3<F>& d, const Triangle<F>& tri, bool bounded) {
  int kz = 0;
  for (int i = 1; i < 3; ++i)
    if (std::fabs(d[i]) > std::fabs(d[kz])) kz = i;
  const int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
  const F Sx = -d[kx] / d[kz], Sy = -d[ky] / d[kz];
  F px[3], py[3], pz[3];
  for (int k = 0; k < 3; ++k) {
    const Vec3<F> P = tri.vertex[k] - s;
    px[k] = P[kx] + Sx * P[kz];
    py[k] = P[ky] + Sy * P[kz];
    pz[k] = P[kz];
  }
  Sheared<F> w;
  w.e[0] = px[1] * py[2] - py[1] * px[2];
  w.e[1] = px[2] * py[0] - py[2] * px[0];
  w.e[2] = px[0] * py[1] - py[0] * px[1];
  w.det = w.e[0] + w.e[1] + w.e[2];
  w.Sz = F(1) / d[kz];
  w.t = w.e[0] * (w.Sz * pz[0]) + w.e[1] * (w.Sz * pz[1]) + w.e[2] * (w.Sz * pz[2]);
  w.flat = w.det == F(0) && w.e[0] == F(0) && w.e[1] == F(0) && w.e[2] == F(0);
  const bool mixed = (w.e[0] < F(0) || w.e[1] < F(0) || w.e[2] < F(0)) && (w.e[0] > F(0) || w.e[1] > F(0) || w.e[2] > F(0));
  w.out = w.det == F(0) || mixed ||
          (w.det > F(0) ? (w.t < F(0) || (bounded && w.t > w.det)) : (w.t > F(0) || (bounded && w.t < w.det)));
  return w;
}

template <class F>
bool watertight_hit(const Vec3<F>& s, const Vec3<F>& d, const Triangle<F>& tri, bool bounded) {
  if (book::detail::is_zero(d)) return book::detail::cast_triangle(s, d, tri, bounded, 0u).hit;
  const Sheared<F> w = shear(s, d, tri, bounded);
  if (w.flat) return book::detail::cast_flat(s, d, tri, bounded, 0u).hit;
  return !w.out;
}

// The cast (steps 1-5). With `values`, a miss still carries the values at the plane's
// crossing (or at the source): robust's uncertain hit.
template <class F>
TriangleCast<F> watertight(const Vec3<F>& s, const Vec3<F>& d, const Triangle<F>& tri, bool bounded, unsigned want,
                           bool values = false) {
  if (book::detail::is_zero(d)) return book::detail::cast_triangle(s, d, tri, bounded, want);
  const Sheared<F> w = shear(s, d, tri, bounded);
  TriangleCast<F> r;
  if (w.flat) return book::detail::cast_flat(s, d, tri, bounded, want);
  if (w.det == F(0)) {
    if (values) r.point = s;
    return r;
  }
  if (w.out && !values) return r;
  r.hit = !w.out;
  const F lambda = w.t / w.det;
  const F b0 = w.e[0] / w.det, b1 = w.e[1] / w.det, b2 = w.e[2] / w.det;
  r.lambda_enter = r.lambda_exit = lambda;
  r.enters = lambda != F(0);
  r.u = b1, r.v = b2;
  if (want & want_point) r.point = tri.vertex[0] * b0 + tri.vertex[1] * b1 + tri.vertex[2] * b2;
  if (want & want_normal) {
    const Vec3<F> n = Vec3<F>(tri.vertex[1] - tri.vertex[0]).cross(Vec3<F>(tri.vertex[2] - tri.vertex[0]));
    const F side = Vec3<F>(s - tri.vertex[0]).dot(n), nn = n.norm();
    if (side != F(0) && nn > F(0) && std::isfinite(nn)) r.normal = (side > F(0) ? n : Vec3<F>(-n)) / nn;
  }
  return r;
}

}  // namespace detail

// The classification without the input checks (see book/common.hpp).
namespace unchecked {
template <class F>
bool hit(const Segment<F>& seg, const Triangle<F>& tri) {
  return detail::watertight_hit(seg.source, Vec3<F>(seg.target - seg.source), tri, true);
}
template <class F>
bool hit(const Ray<F>& ray, const Triangle<F>& tri) {
  return detail::watertight_hit(ray.source, ray.direction, tri, false);
}
}  // namespace unchecked

template <class F>
bool hit(const Segment<F>& seg, const Triangle<F>& tri) {
  check(seg, "segment");
  check(tri, "triangle");
  return unchecked::hit(seg, tri);
}
template <class F>
bool hit(const Ray<F>& ray, const Triangle<F>& tri) {
  check(ray, "ray");
  check(tri, "triangle");
  return unchecked::hit(ray, tri);
}
template <class F>
TriangleCast<F> cast(const Segment<F>& seg, const Triangle<F>& tri, unsigned w = want_all) {
  check(seg, "segment");
  check(tri, "triangle");
  return detail::watertight(seg.source, Vec3<F>(seg.target - seg.source), tri, true, w);
}
template <class F>
TriangleCast<F> cast(const Ray<F>& ray, const Triangle<F>& tri, unsigned w = want_all) {
  check(ray, "ray");
  check(tri, "triangle");
  return detail::watertight(ray.source, ray.direction, tri, false, w);
}

}  // namespace cdref::stable
