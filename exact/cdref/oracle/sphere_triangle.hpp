// cdref/oracle/sphere_triangle.hpp - the fast exact classification oracle for a sphere and a
// triangle (Section 3.4) at double inputs: what the book (book/sphere_triangle.hpp) returns at
// CGAL::Gmpq, in three stages.
//
//   1. filter    two certificates from one point of the triangle, with static error bounds:
//                X_k = fl(v_k - c) (the vertices relative to the centre, one rounding each);
//                (u, v) the barycentric coordinates of the book's closest point computed in
//                double, clamped so that u, v >= 0 and u + v <= 1 hold exactly; the point
//                x = v0 + u (v1 - v0) + v (v2 - v0) then lies in the triangle exactly, and
//                w = x - c = X0 + u (X1 - X0) + v (X2 - X0) is computed with at most 5 roundings
//                a monomial against W+_c = |X0_c| + u (|X1_c| + |X0_c|) + v (|X2_c| + |X0_c|):
//                |w~_c - w_c| <= gamma_5 W+_c <= e_c = 6u W+~_c (1 + 16u).
//                  intersect  |w|^2 <= |w~|^2 (1 + 4u) + sum_c e_c (2 |w~_c| + e_c) < rho^2;
//                  disjoint   along v = w~: every point t of the triangle has
//                             v . (t - c) >= G = min_k v . X_k (a linear function's minimum over
//                             a triangle is at a vertex), and the sphere lies within rho |v| of c
//                             along v, so G > rho |v| separates them; G~ carries 4 roundings a
//                             monomial (v exact, X a leaf): G_lo = G~ - 5u (1 + 16u) max_k |v|.|X_k|,
//                             and G_lo > 0 with G_lo^2 (1 - 8u) > rho^2 |v|^2 (1 + 8u) decides.
//                Roundings that underflow are covered by 64 * 2^-1074; a non-finite value leaves
//                the case to stage 2.
//   2. double word  the robust version's evaluation (robust/sphere_triangle.hpp), certain when
//                every decisive comparison is (Stage::expansion names this stage here);
//   3. rational  the book at CGAL::Gmpq.
#pragma once

#include <cdref/cdref.hpp>
#include <cdref/exact.hpp>
#include <cdref/oracle/rational.hpp>
#include <cdref/oracle/stage.hpp>
#include <cdref/robust/sphere_triangle.hpp>
#include <cmath>

namespace cdref::oracle {

namespace sphere_triangle {

inline constexpr int unknown = 2;

// Barycentric (u, v) of the book's closest point to the origin, in double (any values do: they
// are clamped into the triangle exactly).
inline void closest_barycentric(const double (&X)[3][3], double& u, double& v) {
  const Vec3<double> a(X[0][0], X[0][1], X[0][2]), b(X[1][0], X[1][1], X[1][2]), c(X[2][0], X[2][1], X[2][2]);
  const Vec3<double> ab = b - a, ac = c - a, ap = -a, bp = -b, cp = -c;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  u = v = 0;
  if (d1 <= 0 && d2 <= 0) return;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) { u = 1; return; }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) { u = d1 / (d1 - d3); return; }
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) { v = 1; return; }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) { v = d2 / (d2 - d6); return; }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
    v = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    u = 1 - v;
    return;
  }
  const double denom = va + vb + vc;
  u = vb / denom;
  v = vc / denom;
}

inline int filter(const Sphere<double>& s, const Triangle<double>& t) {
  constexpr double u_ = 0x1p-53, grow = 1 + 16 * u_, eta = 64 * 0x1p-1074;
  double X[3][3];
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 3; ++i) X[k][i] = t.vertex[k][i] - s.center[i];
  double u, v;
  closest_barycentric(X, u, v);
  // clamp: u in [0, 1], v in [0, 1 - u] with u + v <= 1 exactly
  if (!(u >= 0)) u = 0;  // NaN included
  if (!(u <= 1)) u = 1;
  double room = 1 - u;  // rounded: step it down until u + room <= 1 holds exactly (Two-Sum)
  for (;;) {
    const double sum = u + room, bv = sum - u, err = (u - (sum - bv)) + (room - bv);
    if (sum < 1 || (sum == 1 && err <= 0)) break;
    room = std::nextafter(room, 0.0);
  }
  if (!(v >= 0)) v = 0;
  if (!(v <= room)) v = room;
  double w[3], ww = 0, e2 = 0;
  for (int i = 0; i < 3; ++i) {
    const double e1 = X[1][i] - X[0][i], e2v = X[2][i] - X[0][i];
    w[i] = X[0][i] + u * e1 + v * e2v;
    const double Wp = std::fabs(X[0][i]) + u * (std::fabs(X[1][i]) + std::fabs(X[0][i])) +
                      v * (std::fabs(X[2][i]) + std::fabs(X[0][i]));
    const double e = 6 * u_ * grow * Wp;
    e2 += e * (2 * std::fabs(w[i]) + e);
    ww += w[i] * w[i];
  }
  const double rr = s.radius * s.radius;
  if (!std::isfinite(ww) || !std::isfinite(e2) || !std::isfinite(rr)) return unknown;
  if ((ww * (1 + 4 * u_) + e2 * grow + eta) * grow < rr * (1 - 2 * u_)) return 1;
  double G = 0, Gp = 0;
  for (int k = 0; k < 3; ++k) {
    const double g = w[0] * X[k][0] + w[1] * X[k][1] + w[2] * X[k][2];
    const double gp = std::fabs(w[0] * X[k][0]) + std::fabs(w[1] * X[k][1]) + std::fabs(w[2] * X[k][2]);
    G = k == 0 ? g : std::min(G, g);
    Gp = std::max(Gp, gp);
  }
  const double Glo = G - (5 * u_ * grow * Gp + eta);
  if (!std::isfinite(Glo)) return unknown;
  if (Glo > 0 && Glo * Glo * (1 - 8 * u_) > (rr * ww) * (1 + 8 * u_) + eta) return 0;
  return unknown;
}
inline int double_word(const Sphere<double>& s, const Triangle<double>& t) {
  const robust::Decision d = robust::decide(s, t);
  return d.certain ? int(d.value) : unknown;
}
inline bool rational(const Sphere<double>& s, const Triangle<double>& t) {
  return book::intersect(rational_inputs::toq(s), rational_inputs::toq(t));
}
inline int at_stage(Stage st, const Sphere<double>& s, const Triangle<double>& t) {
  return st == Stage::filter ? filter(s, t) : st == Stage::expansion ? double_word(s, t) : int(rational(s, t));
}

}  // namespace sphere_triangle

inline bool classify(const Sphere<double>& s, const Triangle<double>& t, Stage* used = nullptr) {
  check(s, "sphere");
  check(t, "triangle");
  for (Stage st : {Stage::filter, Stage::expansion}) {
    const int r = sphere_triangle::at_stage(st, s, t);
    if (r != sphere_triangle::unknown) {
      if (used) *used = st;
      return r != 0;
    }
  }
  if (used) *used = Stage::rational;
  return sphere_triangle::rational(s, t);
}

}  // namespace cdref::oracle
