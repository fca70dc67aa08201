/// \file
/// cdref/book/triangle_triangle.hpp - Section 3.4: do two triangles intersect, and where?
///
/// intersect(A, B) follows Moller's interval test ("A Fast Triangle-Triangle Intersection Test",
/// JGT 1997) with the plane distances compared with 0 (Moller's code snaps |d| < 1e-6 to 0; the
/// `eps` argument reproduces that, 0 is the exact test):
///   nA = (a1 - a0) x (a2 - a0), dB_k = nA . (b_k - a0): B's vertices against A's plane, and dA_k
///   = nB . (a_k - b0) the other way. All dB_k of one strict sign (or all dA_k): a plane separates
///   them. All dA_k = 0: the triangles are coplanar. Otherwise each triangle meets the other's
///   plane in a segment on the line L = the planes' intersection, direction D = nA x nB:
///   cut(A) = the vertices of A with dA_k = 0 and the points a_i + (a_j - a_i) dA_i / (dA_i - dA_j)
///   of the edges whose ends have strictly opposite signs, the extreme two along D. The triangles
///   meet iff the two cuts overlap along D, and the overlap [p, q] is their intersection (a
///   segment, or a point where they touch).
/// Coplanar triangles (an area in common, or none) are decided by Theorem 3.1 with the side
/// normals nA x e of their six edges (the in-plane separating axes; book/separating_axes.hpp);
/// the result then says `coplanar` and gives no segment.
/// A triangle of zero area is the segment or point it spans: against a triangle that is the
/// segment cast of book/ray_triangle.hpp (the hit interval gives [p, q]), and two of them meet
/// as two segments (or points) do.
///
/// Result: intersect; coplanar (both triangles in one plane, neither of zero area, meeting: the
/// intersection is then a convex polygon, and p = q = 0); p and q, the ends of the intersection
/// segment, p first in lexicographic order of (x, y, z) (p = q where they touch at a point).
///
/// separate(A, B) is the other formulation of the classification, division-free: Theorem 3.1
/// with 17 candidate axes in this order: nA (0), nB (1), e_A[i] x e_B[j] (2 + 3i + j), the side
/// normals nA x e_A[i] (11 + i) and nB x e_B[j] (14 + j); for a triangle of zero area it answers
/// as intersect() does.
///
/// Floating point: the cut points divide by dA_i - dA_j; two nearly parallel triangles, or a
/// vertex a hair from the other plane, leave the signs and the overlap to rounding (and an
/// absolute epsilon, as in Moller's code, misjudges every pair whose size is far from 1). Where
/// the products overflow (coordinates past ~1e100 at double) the signs can be NaN and a cut then
/// takes no point at all: its ends and its extent along D stay 0, so such a pair is answered as
/// meeting at p = q = 0 (every run alike; the exact answer grades it).
#pragma once

#include "common.hpp"
#include "ray_triangle.hpp"
#include "separating_axes.hpp"

namespace cdref::book {

namespace detail {

template <class T>
bool lex_less(const Vec3<T>& a, const Vec3<T>& b) {
  for (int i = 0; i < 3; ++i) {
    if (a[i] < b[i]) return true;
    if (b[i] < a[i]) return false;
  }
  return false;
}
template <class T>
TriangleIntersection<T> meeting(const Vec3<T>& a, const Vec3<T>& b) {
  TriangleIntersection<T> r;
  r.intersect = true;
  if (lex_less(b, a)) r.p = b, r.q = a;
  else r.p = a, r.q = b;
  return r;
}

/// A value of sqrt_t<T> known to be rational, as a T.
template <class T, class S>
T rational_of(const S& x) {
  if constexpr (std::is_same_v<S, T>)
    return x;
  else
    return x.a();
}

/// The segment (or point) a zero-area triangle spans.
template <class T>
Segment<T> span_of(const Triangle<T>& t) {
  int i, j;
  farthest_pair(t, i, j);
  return {t.vertex[i], t.vertex[j]};
}

/// A segment (a zero-area triangle's span) against a triangle, or against another span.
template <class T>
TriangleIntersection<T> span_meets(const Segment<T>& s, const Triangle<T>& t, bool t_is_span) {
  const Vec3<T> d = s.target - s.source;
  TriangleCast<sqrt_t<T>> c;
  if (t_is_span) {
    const Segment<T> u = span_of(t);
    c = cast_on_segment(s.source, d, true, u.source, u.target, 0, 1, want_lambda_enter | want_lambda_exit);
  } else {
    c = cast_triangle(s.source, d, t, true, want_lambda_enter | want_lambda_exit);
  }
  if (!c.hit) return {};
  // lambdas are rational here (no square root in a triangle cast's lambdas)
  const T le = rational_of<T>(c.lambda_enter), lx = rational_of<T>(c.lambda_exit);
  if (is_zero(d)) return meeting(s.source, s.source);
  return meeting(Vec3<T>(s.source + d * le), Vec3<T>(s.source + d * lx));
}

/// The cut of triangle `t` (signed distances `d` of its vertices) by the other's plane: its two
/// extreme points along D.
template <class T>
void cut(const Triangle<T>& t, const T (&d)[3], const Vec3<T>& D, Vec3<T>& lo, Vec3<T>& hi, T& tlo, T& thi) {
  bool any = false;
  auto add = [&](const Vec3<T>& x) {
    const T s = D.dot(x);
    if (!any || s < tlo) tlo = s, lo = x;
    if (!any || s > thi) thi = s, hi = x;
    any = true;
  };
  for (int k = 0; k < 3; ++k)
    if (d[k] == T(0)) add(t.vertex[k]);
  for (int k = 0; k < 3; ++k) {
    const int j = (k + 1) % 3;
    if ((d[k] < T(0) && d[j] > T(0)) || (d[k] > T(0) && d[j] < T(0)))
      add(Vec3<T>(t.vertex[k] + Vec3<T>(t.vertex[j] - t.vertex[k]) * (d[k] / (d[k] - d[j]))));
  }
}

template <class T>
bool same_strict_sign(const T (&d)[3]) {
  return (d[0] > T(0) && d[1] > T(0) && d[2] > T(0)) || (d[0] < T(0) && d[1] < T(0) && d[2] < T(0));
}

/// Theorem 3.1 with the 17 axes of the header (both triangles of nonzero area).
template <class T>
Separation<T> separate_triangles(const Triangle<T>& a, const Triangle<T>& b) {
  const Polytope<T> pa = polytope(a), pb = polytope(b);
  Separation<T> res;
  int index = 0;
  auto try_axis = [&](const Vec3<T>& L) {
    const int at = index++;
    if (is_zero(L)) return false;
    if (!apart(project(pa, L), project(pb, L))) return false;
    res.axis = at;
    res.direction = L;
    return true;
  };
  if (try_axis(pa.face[0]) || try_axis(pb.face[0])) return res;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (try_axis(Vec3<T>(pa.edge[i].cross(pb.edge[j])))) return res;
  for (int i = 0; i < 3; ++i)
    if (try_axis(Vec3<T>(pa.face[0].cross(pa.edge[i])))) return res;
  for (int j = 0; j < 3; ++j)
    if (try_axis(Vec3<T>(pb.face[0].cross(pb.edge[j])))) return res;
  res.intersect = true;
  return res;
}

template <class T>
TriangleIntersection<T> intersect_triangles(const Triangle<T>& A, const Triangle<T>& B, const T& eps) {
  const Vec3<T> nA = Vec3<T>(A.vertex[1] - A.vertex[0]).cross(Vec3<T>(A.vertex[2] - A.vertex[0]));
  const Vec3<T> nB = Vec3<T>(B.vertex[1] - B.vertex[0]).cross(Vec3<T>(B.vertex[2] - B.vertex[0]));
  const bool flatA = is_zero(nA), flatB = is_zero(nB);
  if (flatA) return span_meets(span_of(A), B, flatB);
  if (flatB) return span_meets(span_of(B), A, false);
  T dB[3], dA[3];
  auto snap = [&](T x) { return abs_of(x) < eps ? T(0) : x; };
  for (int k = 0; k < 3; ++k) dB[k] = snap(nA.dot(Vec3<T>(B.vertex[k] - A.vertex[0])));
  if (same_strict_sign(dB)) return {};
  for (int k = 0; k < 3; ++k) dA[k] = snap(nB.dot(Vec3<T>(A.vertex[k] - B.vertex[0])));
  if (same_strict_sign(dA)) return {};
  if (dA[0] == T(0) && dA[1] == T(0) && dA[2] == T(0)) {
    TriangleIntersection<T> r;
    r.intersect = r.coplanar = separate_triangles(A, B).intersect;
    return r;
  }
  const Vec3<T> D = nA.cross(nB);
  // (a cut that takes no point, its signs NaN, leaves these as they start: the header says)
  Vec3<T> a0 = zero_vec<T>(), a1 = zero_vec<T>(), b0 = zero_vec<T>(), b1 = zero_vec<T>();
  T ta0(0), ta1(0), tb0(0), tb1(0);
  cut(A, dA, D, a0, a1, ta0, ta1);
  cut(B, dB, D, b0, b1, tb0, tb1);
  if (ta1 < tb0 || tb1 < ta0) return {};
  const Vec3<T>& p = ta0 < tb0 ? b0 : a0;
  const Vec3<T>& q = ta1 < tb1 ? a1 : b1;
  return meeting(p, q);
}

}  // namespace detail

/// Whether the closed triangle and triangle share a point (touching counts). Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
TriangleIntersection<T> intersect(const Triangle<T>& a, const Triangle<T>& b, const T& eps = T(0)) {
  check(a, "triangle A");
  check(b, "triangle B");
  return detail::intersect_triangles(a, b, eps);
}

namespace unchecked {
/// separate() on input already checked (see common.hpp).
template <class T>
Separation<T> separate(const Triangle<T>& a, const Triangle<T>& b) {
  const Vec3<T> nA = Vec3<T>(a.vertex[1] - a.vertex[0]).cross(Vec3<T>(a.vertex[2] - a.vertex[0]));
  const Vec3<T> nB = Vec3<T>(b.vertex[1] - b.vertex[0]).cross(Vec3<T>(b.vertex[2] - b.vertex[0]));
  if (detail::is_zero(nA) || detail::is_zero(nB)) {
    Separation<T> s;
    s.intersect = detail::intersect_triangles(a, b, T(0)).intersect;
    return s;
  }
  return detail::separate_triangles(a, b);
}
}  // namespace unchecked

/// Theorem 3.1 on the triangle and the triangle: whether they intersect, else the first separating
/// axis in this file's order and its direction (a cdref::Separation). Throws cdref::invalid_input
/// naming a bad argument.
template <class T>
Separation<T> separate(const Triangle<T>& a, const Triangle<T>& b) {
  check(a, "triangle A");
  check(b, "triangle B");
  return unchecked::separate(a, b);
}

}  // namespace cdref::book
