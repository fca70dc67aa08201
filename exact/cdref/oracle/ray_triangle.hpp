// cdref/oracle/ray_triangle.hpp - the fast exact classification oracle for ray and segment casts
// on a triangle (Section 3.4) at double inputs: what book::hit (book/ray_triangle.hpp) returns at
// CGAL::Gmpq, in three stages.
//
//   1. filter    the orientation form of the test. With A, B, C the vertices relative to the
//                source s, d the direction (t - s for a segment) and n = (v1 - v0) x (v2 - v0):
//                  w0 = d . (B x C), w1 = d . (C x A), w2 = d . (A x B)   (sum D = d . n),
//                  Ns = (v0 - s) . n, and for the segment Nt = (v0 - t) . n.
//                The line meets the triangle iff the w_k do not have opposite signs; with D > 0
//                the ray then hits iff Ns >= 0, the segment iff moreover Nt <= 0 (D < 0: the
//                signs turn). Each of these is a sum of six monomials of degree 3 in rounded
//                differences of inputs; evaluated in double each monomial carries at most 7
//                roundings (two differences, two products, a difference in the cross product,
//                two sums in the dot product), so |computed - exact| <= gamma_7 P, P the same
//                expression on absolute values; the filter takes 10u (1 + 16u) P~ (P~ computed in
//                double: at most 7 more roundings upward of P) plus 64 * 2^-1074 (1 + |a|_1) for
//                underflow: a rounding that underflows errs by up to 2^-1075 absolute, and one
//                inside the cross product b x c is then multiplied by a's coordinate (found by the
//                fuzz target: a subnormal product scaled by 2^1009). It decides a miss when two
//                w_k have opposite certain signs,
//                and a hit or a miss when all three w_k have the same certain sign and Ns (and
//                Nt) certainly have theirs. A non-finite value leaves the case to stage 2.
//   2. double word  the book's hit() run on double words (robust/words.hpp), certain when every
//                comparison is (Stage::expansion names this stage here);
//   3. rational  book::hit at CGAL::Gmpq (coplanar shots, shots through an edge or a vertex,
//                zero-area triangles).
#pragma once

#include <cdref/cdref.hpp>
#include <cdref/exact.hpp>
#include <cdref/oracle/rational.hpp>
#include <cdref/oracle/stage.hpp>
#include <cdref/robust/ray_triangle.hpp>
#include <cmath>

namespace cdref::oracle {

namespace ray_triangle {

inline constexpr int unknown = 2;

// The sign of a . (b x c) with its bound: +1, -1, or 0 when the bound does not decide.
inline int triple_sign(const double (&a)[3], const double (&b)[3], const double (&c)[3], bool& finite) {
  constexpr double u_ = 0x1p-53, grow = 1 + 16 * u_, eta = 64 * 0x1p-1074;
  const double x0 = b[1] * c[2] - b[2] * c[1], x1 = b[2] * c[0] - b[0] * c[2], x2 = b[0] * c[1] - b[1] * c[0];
  const double v = a[0] * x0 + a[1] * x1 + a[2] * x2;
  const double p0 = std::fabs(b[1] * c[2]) + std::fabs(b[2] * c[1]);
  const double p1 = std::fabs(b[2] * c[0]) + std::fabs(b[0] * c[2]);
  const double p2 = std::fabs(b[0] * c[1]) + std::fabs(b[1] * c[0]);
  const double P = std::fabs(a[0]) * p0 + std::fabs(a[1]) * p1 + std::fabs(a[2]) * p2;
  // a rounding that underflows errs by at most 2^-1075 absolute; in a cross product component
  // that error is then multiplied by a's coordinate, so it enters scaled by |a|
  const double sa = std::fabs(a[0]) + std::fabs(a[1]) + std::fabs(a[2]);
  const double e = 10 * u_ * grow * P + eta * (1 + sa);
  if (!std::isfinite(v) || !std::isfinite(e)) finite = false;
  return v > e ? 1 : v < -e ? -1 : 0;
}

inline int filter(const Vec3<double>& s, const Vec3<double>* t, const Vec3<double>& dir, const Triangle<double>& tri) {
  double A[3][3], d[3], e1[3], e2[3];
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 3; ++k) A[k][i] = tri.vertex[k][i] - s[i];
    d[i] = t ? (*t)[i] - s[i] : dir[i];
    e1[i] = tri.vertex[1][i] - tri.vertex[0][i];
    e2[i] = tri.vertex[2][i] - tri.vertex[0][i];
  }
  bool finite = true;
  const int w0 = triple_sign(d, A[1], A[2], finite), w1 = triple_sign(d, A[2], A[0], finite),
            w2 = triple_sign(d, A[0], A[1], finite);
  if (!finite) return unknown;
  if ((w0 < 0 || w1 < 0 || w2 < 0) && (w0 > 0 || w1 > 0 || w2 > 0)) return 0;
  if (w0 == 0 || w0 != w1 || w0 != w2) return unknown;
  const int sD = w0;
  // Ns = (v0 - s) . (e1 x e2): the sign of lambda's numerator
  const int ns = triple_sign(A[0], e1, e2, finite);
  if (!finite) return unknown;
  if (ns == -sD) return 0;  // lambda < 0
  int nt = -sD;
  if (t) {
    double T0[3];
    for (int i = 0; i < 3; ++i) T0[i] = tri.vertex[0][i] - (*t)[i];
    nt = triple_sign(T0, e1, e2, finite);
    if (!finite) return unknown;
    if (nt == sD) return 0;  // lambda > 1
  }
  return ns == sD && nt == -sD ? 1 : unknown;
}

template <class Shot>
int double_word(const Shot& shot, const Triangle<double>& t) {
  const auto r = robust::detail::on_words(shot, t, [](const auto& a, const auto& b) { return book::hit(a, b); });
  return r ? int(*r) : unknown;
}
template <class Shot>
bool rational(const Shot& shot, const Triangle<double>& t) {
  return book::hit(rational_inputs::toq(shot), rational_inputs::toq(t));
}
inline int at_stage(Stage st, const Segment<double>& s, const Triangle<double>& t) {
  if (st == Stage::filter) return filter(s.source, &s.target, s.target, t);
  return st == Stage::expansion ? double_word(s, t) : int(rational(s, t));
}
inline int at_stage(Stage st, const Ray<double>& r, const Triangle<double>& t) {
  if (st == Stage::filter) return filter(r.source, nullptr, r.direction, t);
  return st == Stage::expansion ? double_word(r, t) : int(rational(r, t));
}

}  // namespace ray_triangle

template <class Shot>
bool classify_triangle_cast(const Shot& shot, const Triangle<double>& t, Stage* used) {
  for (Stage st : {Stage::filter, Stage::expansion}) {
    const int r = ray_triangle::at_stage(st, shot, t);
    if (r != ray_triangle::unknown) {
      if (used) *used = st;
      return r != 0;
    }
  }
  if (used) *used = Stage::rational;
  return ray_triangle::rational(shot, t);
}
inline bool classify(const Segment<double>& s, const Triangle<double>& t, Stage* used = nullptr) {
  check(s, "segment");
  check(t, "triangle");
  return classify_triangle_cast(s, t, used);
}
inline bool classify(const Ray<double>& r, const Triangle<double>& t, Stage* used = nullptr) {
  check(r, "ray");
  check(t, "triangle");
  return classify_triangle_cast(r, t, used);
}

}  // namespace cdref::oracle
