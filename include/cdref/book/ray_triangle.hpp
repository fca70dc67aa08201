/// \file
/// cdref/book/ray_triangle.hpp - Section 3.4: ray casts on a triangle (the segment s->t,
/// lambda in [0, 1], and the infinite ray s + lambda d, lambda >= 0).
///
/// The triangle is closed and two-sided. With e1 = v1 - v0, e2 = v2 - v0 and the shot
/// x(lambda) = s + lambda d, the point x = v0 + u e1 + v e2 solves
///   [-d  e1  e2] (lambda, u, v)^T = s - v0,
/// and Cramer's rule with det = e1 . (d x e2) (the scalar triple product) gives, with p = d x e2,
/// q = (s - v0) x e1:
///   u = (s - v0) . p / det,   v = d . q / det,   lambda = e2 . q / det.
/// That is Moller and Trumbore's formulation (1997), as GLM, Embree's default intersector and most
/// renderers ship it: the shot meets the triangle iff u >= 0, v >= 0, u + v <= 1 and lambda in
/// range (all closed). cast() follows it with one division by det, as they do.
///
/// det = 0 is where the listing stops (it reports a miss); the closed triangle is met there too:
///   - n = e1 x e2 = 0: the triangle has zero area and is the segment [P, Q] between its two
///     farthest vertices (or the point P): the shot meets it where the two lines meet
///     (m = d x (Q - P) != 0: coplanar iff (P - s) . m = 0, then lambda = ((P - s) x r) . m / m.m and
///     mu = ((P - s) x d) . m / m.m, mu in [0, 1]) or along their common line (m = 0, collinear:
///     lambda over [(P - s) . d, (Q - s) . d] / d.d, clipped to the range);
///   - n != 0 and (s - v0) . n != 0: the shot is parallel to the plane, off it: a miss;
///   - n != 0 and (s - v0) . n = 0: the shot lies in the plane, and x(lambda) is in the triangle
///     iff ((b - a) x (x(lambda) - a)) . n >= 0 for its three edges (a, b): a linear function
///     alpha + lambda beta of lambda each, so the hits form an interval that the three half-lines
///     clip (as Algorithm 3.3 clips a box's slabs): [lambda_enter, lambda_exit].
/// A zero-length segment (d = 0) is the point s: hit iff s lies in the triangle, with
/// lambda_enter = 0, lambda_exit = 1 (as for the sphere and the box).
///
/// Outputs: lambda_enter, lambda_exit (equal unless the shot lies in the triangle's plane), point
/// = s + lambda_enter d (as engines compute it), u and v (the barycentric weights of v1 and v2 at
/// the point: point = (1 - u - v) v0 + u v1 + v v2; for a zero-area triangle the weights of the
/// segment [P, Q] that it spans, the third vertex 0), normal = n/|n| turned to face the source
/// ((s - v0) . normal > 0). The normal is 0 when the source lies in the triangle's plane (no side
/// faces it: the source in the triangle, or a shot in the plane) and for a zero-area triangle.
/// enters is false when the source lies in the triangle (lambda_enter = 0).
///
/// hit() decides the same with no division, from the signs of three scalar triple products
/// w_k = d . (B x C), d . (C x A), d . (A x B) with A = v0 - s, B = v1 - s, C = v2 - s (the
/// shot's line passes through the triangle iff they do not have opposite signs), their sum
/// D = d . n, and N = A . n: lambda = N / D, so lambda >= 0 iff N D >= 0 and, for the segment,
/// lambda <= 1 iff N <= D (D > 0) or N >= D (D < 0). Where D = 0 it answers as cast() does.
///
/// Floating point: det is a difference of products of differences; for a shot nearly parallel
/// to the plane, or aimed at an edge, rounding decides, and two triangles that share an edge can
/// both report a miss for a ray through it (a leak). robust/ray_triangle.hpp is watertight.
#pragma once

#include "common.hpp"
#include "sphere_triangle.hpp"

namespace cdref::book {

namespace detail {

template <class T>
bool within(const T& lambda, bool bounded) {
  return lambda >= T(0) && (!bounded || lambda <= T(1));
}

/// Fills the values of a hit at lambda_enter (u, v given as the weights of v1, v2).
template <class T>
void finish_triangle_cast(TriangleCast<sqrt_t<T>>& r, const Vec3<T>& s, const Vec3<T>& d, const T& lo, const T& hi,
                          const T& u, const T& v, const Vec3<T>& facing, unsigned w) {
  using S = sqrt_t<T>;
  r.hit = true;
  r.enters = lo != T(0);
  if (w & want_lambda_enter) r.lambda_enter = S(lo);
  if (w & want_lambda_exit) r.lambda_exit = S(hi);
  if (w & want_point) r.point = lift<S>(Vec3<T>(s + d * lo));
  if (w & want_barycentric) r.u = S(u), r.v = S(v);
  if ((w & want_normal) && !is_zero(facing)) r.normal = divided(facing, root(T(facing.squaredNorm())));
}

/// The shot meets the segment [P, Q] (P = Q: the point) of a zero-area triangle; iP, iQ are the
/// vertex indices of P and Q.
template <class T>
TriangleCast<sqrt_t<T>> cast_on_segment(const Vec3<T>& s, const Vec3<T>& d, bool bounded, const Vec3<T>& P,
                                        const Vec3<T>& Q, int iP, int iQ, unsigned w) {
  TriangleCast<sqrt_t<T>> r;
  const Vec3<T> rr = Q - P, ps = P - s;
  T lo, hi, mu;  // the hit interval, and where the entry point lies on [P, Q]
  auto weights = [&](const T& m, T& u, T& v) {
    T wgt[3] = {T(0), T(0), T(0)};
    wgt[iP] += T(1) - m;
    wgt[iQ] += m;
    u = wgt[1], v = wgt[2];
  };
  if (is_zero(d)) {  // a zero-length segment: the point s on [P, Q]
    const Vec3<T> sp = s - P;
    if (!is_zero(Vec3<T>(sp.cross(rr)))) return r;
    const T a = sp.dot(rr), rr2 = rr.squaredNorm();
    if (rr2 == T(0)) {
      if (!is_zero(sp)) return r;
      mu = T(0);
    } else {
      if (a < T(0) || a > rr2) return r;
      mu = a / rr2;
    }
    T u, v;
    weights(mu, u, v);
    finish_triangle_cast(r, s, d, T(0), T(1), u, v, zero_vec<T>(), w);
    return r;
  }
  const Vec3<T> m = d.cross(rr);
  if (!is_zero(m)) {
    if (ps.dot(m) != T(0)) return r;  // skew lines
    const T mm = m.squaredNorm();
    const T lambda = Vec3<T>(ps.cross(rr)).dot(m) / mm;
    mu = Vec3<T>(ps.cross(d)).dot(m) / mm;
    if (!within(lambda, bounded) || mu < T(0) || mu > T(1)) return r;
    lo = hi = lambda;
  } else {
    if (!is_zero(Vec3<T>(ps.cross(d)))) return r;  // parallel lines apart
    const T dd = d.squaredNorm();
    const T lp = ps.dot(d) / dd, lq = Vec3<T>(Q - s).dot(d) / dd;
    lo = min_of(lp, lq), hi = max_of(lp, lq);
    if (lo < T(0)) lo = T(0);
    if (bounded && hi > T(1)) hi = T(1);
    if (lo > hi) return r;
    const T rr2 = rr.squaredNorm();
    mu = rr2 == T(0) ? T(0) : Vec3<T>(s + d * lo - P).dot(rr) / rr2;
  }
  T u, v;
  weights(mu, u, v);
  finish_triangle_cast(r, s, d, lo, hi, u, v, zero_vec<T>(), w);
  return r;
}

/// det = 0: a zero-area triangle, or a shot parallel to the triangle's plane (off it or in it).
template <class T>
TriangleCast<sqrt_t<T>> cast_flat(const Vec3<T>& s, const Vec3<T>& d, const Triangle<T>& tri, bool bounded,
                                  unsigned w) {
  TriangleCast<sqrt_t<T>> r;
  const Vec3<T>& v0 = tri.vertex[0];
  const Vec3<T> e1 = tri.vertex[1] - v0, e2 = tri.vertex[2] - v0;
  const Vec3<T> n = e1.cross(e2);
  if (is_zero(n)) {
    int iP, iQ;
    farthest_pair(tri, iP, iQ);
    return cast_on_segment(s, d, bounded, tri.vertex[iP], tri.vertex[iQ], iP, iQ, w);
  }
  if (Vec3<T>(s - v0).dot(n) != T(0)) return r;  // parallel to the plane, off it
  // in the plane: clip [0, 1] or [0, inf) by the three edges' half-planes
  T lo(0), hi(1);
  bool open = !bounded;  // hi is +infinity
  for (int k = 0; k < 3; ++k) {
    const Vec3<T>& a = tri.vertex[k];
    const Vec3<T> ab = tri.vertex[(k + 1) % 3] - a;
    const T alpha = Vec3<T>(ab.cross(Vec3<T>(s - a))).dot(n);
    const T beta = Vec3<T>(ab.cross(d)).dot(n);
    if (beta == T(0)) {
      if (alpha < T(0)) return r;
    } else if (beta > T(0)) {
      const T l = -alpha / beta;
      if (l > lo) lo = l;
    } else {
      const T l = -alpha / beta;
      if (open || l < hi) hi = l, open = false;
    }
  }
  // (a ray's d != 0 lies in the plane, so some edge has beta < 0 and hi is finite)
  if (open || lo > hi) return r;
  const Vec3<T> x = s + d * lo;
  const Vec3<T> xv = x - v0;
  const T nn = n.squaredNorm();
  const T u = Vec3<T>(xv.cross(e2)).dot(n) / nn, v = Vec3<T>(e1.cross(xv)).dot(n) / nn;
  finish_triangle_cast(r, s, d, lo, hi, u, v, zero_vec<T>(), w);
  return r;
}

template <class T>
TriangleCast<sqrt_t<T>> cast_triangle(const Vec3<T>& s, const Vec3<T>& d, const Triangle<T>& tri, bool bounded,
                                      unsigned w) {
  const Vec3<T>& v0 = tri.vertex[0];
  const Vec3<T> e1 = tri.vertex[1] - v0, e2 = tri.vertex[2] - v0;
  const Vec3<T> p = d.cross(e2);
  const T det = e1.dot(p);
  if (det == T(0)) return cast_flat(s, d, tri, bounded, w);
  TriangleCast<sqrt_t<T>> r;
  const T inv = T(1) / det;
  const Vec3<T> sv = s - v0;
  const T u = sv.dot(p) * inv;
  if (u < T(0) || u > T(1)) return r;
  const Vec3<T> q = sv.cross(e1);
  const T v = d.dot(q) * inv;
  if (v < T(0) || u + v > T(1)) return r;
  const T lambda = e2.dot(q) * inv;
  if (!within(lambda, bounded)) return r;
  Vec3<T> facing = zero_vec<T>();
  if (w & want_normal) {
    const Vec3<T> n = e1.cross(e2);
    const T side = sv.dot(n);
    if (side > T(0)) facing = n;
    if (side < T(0)) facing = -n;
  }
  finish_triangle_cast(r, s, d, lambda, lambda, u, v, facing, w);
  return r;
}

template <class T>
bool hit_triangle(const Vec3<T>& s, const Vec3<T>& d, const Triangle<T>& tri, bool bounded) {
  const Vec3<T> A = tri.vertex[0] - s, B = tri.vertex[1] - s, C = tri.vertex[2] - s;
  const T w0 = d.dot(Vec3<T>(B.cross(C))), w1 = d.dot(Vec3<T>(C.cross(A))), w2 = d.dot(Vec3<T>(A.cross(B)));
  if ((w0 < T(0) || w1 < T(0) || w2 < T(0)) && (w0 > T(0) || w1 > T(0) || w2 > T(0))) return false;
  const T D = w0 + w1 + w2;
  if (D == T(0)) return cast_triangle(s, d, tri, bounded, 0u).hit;
  const Vec3<T> n = Vec3<T>(tri.vertex[1] - tri.vertex[0]).cross(Vec3<T>(tri.vertex[2] - tri.vertex[0]));
  const T N = A.dot(n);
  if (D > T(0)) return N >= T(0) && (!bounded || N <= D);
  return N <= T(0) && (!bounded || N >= D);
}

}  // namespace detail

/// The segment (lambda in [0, 1]) cast on the closed triangle: hit, entry and exit parameters,
/// entry point and normal (only what the mask `w` asks for is computed). Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
TriangleCast<sqrt_t<T>> cast(const Segment<T>& seg, const Triangle<T>& tri, unsigned w = want_all) {
  check(seg, "segment");
  check(tri, "triangle");
  return detail::cast_triangle(seg.source, Vec3<T>(seg.target - seg.source), tri, true, w);
}
/// The ray (lambda >= 0 in units of |direction|) cast on the closed triangle: hit, entry and exit
/// parameters, entry point and normal (only what the mask `w` asks for is computed). Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
TriangleCast<sqrt_t<T>> cast(const Ray<T>& ray, const Triangle<T>& tri, unsigned w = want_all) {
  check(ray, "ray");
  check(tri, "triangle");
  return detail::cast_triangle(ray.source, ray.direction, tri, false, w);
}
namespace unchecked {
/// The same as the checked `hit` of these arguments, on input already checked: no input
/// checks (see book/common.hpp). For loops over bodies checked once.
template <class T>
bool hit(const Segment<T>& seg, const Triangle<T>& tri) {
  return detail::hit_triangle(seg.source, Vec3<T>(seg.target - seg.source), tri, true);
}
/// The same as the checked `hit` of these arguments, on input already checked: no input
/// checks (see book/common.hpp). For loops over bodies checked once.
template <class T>
bool hit(const Ray<T>& ray, const Triangle<T>& tri) {
  return detail::hit_triangle(ray.source, ray.direction, tri, false);
}
}  // namespace unchecked

/// Whether the segment meets the closed triangle: the cast's classification alone. Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
bool hit(const Segment<T>& seg, const Triangle<T>& tri) {
  check(seg, "segment");
  check(tri, "triangle");
  return detail::hit_triangle(seg.source, Vec3<T>(seg.target - seg.source), tri, true);
}
/// Whether the ray meets the closed triangle: the cast's classification alone. Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
bool hit(const Ray<T>& ray, const Triangle<T>& tri) {
  check(ray, "ray");
  check(tri, "triangle");
  return detail::hit_triangle(ray.source, ray.direction, tri, false);
}

}  // namespace cdref::book
