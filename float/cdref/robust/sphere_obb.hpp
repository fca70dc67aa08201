// cdref/robust/sphere_obb.hpp - the robust sphere-obb query's first look at double: every value
// of solid::proximity(Sphere, OrientedBox) (solid/obb.hpp, the truth: the parallelepiped P =
// {c + sum_m u_m a_m : |u_m| <= h_m} its inputs define) where rigorous bounds prove each within
// 3/4 of an ulp, in a few hundred operations where the solid's formulation on double words
// (separating_axes.hpp, proximity) takes over a microsecond; anything it cannot prove is left
// to that path, wholesale.
//
// Notation: q the sphere's centre, D = c - q (exact pairs), A_mn = a_m . a_n, G_m = a_m . (q - c),
// n_m = a_m+1 x a_m+2 turned by the sign of delta = a_0 . n_0, U_m = n_m . (q - c) and H_m =
// |delta| h_m (solid/obb.hpp: q lies in P iff |U_m| <= H_m for every m).
//  1. Scale. Where the largest of |D_c|, h_m and rho lies outside [2^-100, 2^100], every length
//     is scaled by the power of two that brings it into [1, 2) (as sphere_triangle.hpp's item F;
//     an underflowing low part errs by 2^-1074 at most, covered by `tiny` below). The axes are
//     not scaled: each axis's largest component must lie in [2^-20, 2^20] (else the path below),
//     so that no quantity here (of degree at most 10 in the axes and 2 in the lengths) overflows.
//  2. The feature, in double, each quantity with a bound on the sum of its monomials'
//     magnitudes (M below: computed beside the value from the absolute values). A program of
//     depth k (roundings along any path, an input's rounding to the high part of its pair
//     included) errs by at most gamma_k times that sum (Higham, Accuracy and Stability, 3.1);
//     no quantity here is deeper than 10, so 16u of the computed sum (which is within gamma_k
//     of the exact one) bounds it, plus 2^-600 for roundings below the normal range
//     (surely_positive). A sign is certain where the value exceeds that bound.
//     - The outcode, as solid/obb.hpp's closest_by_outcode: o_m = +1 where U_m > H_m, -1 where
//       U_m < -H_m, 0 where |U_m| < H_m, each certain (else the path below); delta's sign
//       certain.
//     - q outside (some o_m != 0): with the fixed axes F = {m : o_m != 0} and the point's
//       coordinates u_m = o_m h_m there, the closest point x = c + sum_m u_m a_m has the free
//       coordinates that make q - x orthogonal to the free axes, and x is the closest point iff
//       they lie strictly inside (|u_m| < h_m) and o_m a_m . (q - x) > 0 on every fixed axis (x's
//       normal cone; P is convex, so that point is the unique closest). With R_m = G_m - sum_{n
//       in F} A_mn o_n h_n (a_m . (q - x0), x0 = c + sum_F o_n h_n a_n):
//         vertex (3 fixed):     o_m R_m > 0 for every m;
//         edge (free axis i):   u_i = R_i / A_ii, so |R_i| < h_i A_ii, and o_j (A_ii R_j - A_ij R_i)
//                               > 0 for both fixed j (A_ii > 0 multiplies through);
//         face (fixed axis i):  the 2x2 Gram system of the free axes j, k: u_j det = A_kk R_j -
//                               A_jk R_k, u_k det = A_jj R_k - A_jk R_j, det = A_jj A_kk - A_jk^2 =
//                               |a_j x a_k|^2 > 0, so |u_j det| < h_j det and |u_k det| < h_k det;
//                               q - x is then a multiple of n_i, and o_i a_i . (q - x) has the sign
//                               of o_i U_i - H_i, positive by the outcode.
//     - q inside (every o_m = 0, certain): the nearest face, the i minimising (H_i - |U_i|)^2 /
//       |n_i|^2, strictly below every other (compared cross-multiplied; a tie, where the solid
//       takes the first, is left to the path below), and the side of U_i certain.
//  3. v = x - q in double words with a bound on each component (first_look.hpp): x0 - q = D +
//     sum_F o_n h_n a_n by word_bounds::dot_of_doubles and a two_sum (a vertex: v itself); an
//     edge's foot from x0 - q along a_i (first_look_edge); a face's foot on the plane through x0
//     normal to n_i
//     (first_look_face, n_i a cross product of the exact axes: word_bounds::cross_of_doubles);
//     inside, the foot on the nearest face's plane through q's side of it, x0 = c + s h_i a_i
//     with s the sign of U_i: then |v| = (H_i - |U_i|) / |n_i|, the depth is |v| + rho, the
//     sphere's witness q - rho v / |v| and the closest point q itself.
//  4. The values (first_look.hpp, first_look_values): the classification from g = |v| - rho
//     where its bound makes its sign certain (inside: they meet), else the first stage's; every
//     value asked where its bound proves it, or the path below for all of them.
//  5. A coordinate of x that the inputs give exactly is taken so (sphere_obb_exact): the sum of
//     c_i and one exact product fix_m h_m a_m[i] where the free axes have no component i (an
//     axis-aligned box's face or edge), rounded once; q_i on a face whose normal has an exact 0
//     there. The double words would leave such a value uncertain exactly where it matters: c_i
//     +- h_m often lies on a rounding midpoint (the sum of two doubles needs one bit more), and
//     the oracle's mode must then refuse the double word's interval (on the uniform family it
//     refused the witnesses of 16 of 300 cases before).
#pragma once

#include <cdref/bounded/word_bounds.hpp>
#include <cdref/primitives.hpp>
#include <cdref/results.hpp>

#include "first_look.hpp"
#include "rational.hpp"

namespace cdref::robust::detail {

// A value computed in double and a bound on the sum of its monomials' magnitudes (item 2).
struct MagnitudeValue {
  double v, m;
};
inline MagnitudeValue operator+(MagnitudeValue a, MagnitudeValue b) { return {a.v + b.v, a.m + b.m}; }
inline MagnitudeValue operator-(MagnitudeValue a, MagnitudeValue b) { return {a.v - b.v, a.m + b.m}; }
inline MagnitudeValue operator*(MagnitudeValue a, MagnitudeValue b) { return {a.v * b.v, a.m * b.m}; }
inline MagnitudeValue operator*(double s, MagnitudeValue a) { return {s * a.v, std::fabs(s) * a.m}; }
inline MagnitudeValue abs_of(MagnitudeValue a) { return {std::fabs(a.v), a.m}; }
// certainly positive: the value above its bound (16u of the magnitudes, with room for the
// bound's own rounding, plus 2^-600 for roundings below the normal range: each errs by at most
// 2^-1074, and what multiplies it afterwards is at most 2^400, degree 10 in axes below 2^20 and
// 2 in lengths below 2^100; a few hundred of them stay far below 2^-600)
inline bool surely_positive(MagnitudeValue a) {
  return a.v > 16 * first_look_u * a.m * first_look_grow + 0x1p-600;
}
inline MagnitudeValue dot_of(const MagnitudeValue (&x)[3], const MagnitudeValue (&y)[3]) {
  return (x[0] * y[0] + x[1] * y[1]) + x[2] * y[2];
}

// Items 1-3: the feature certified and v there; false where a test cannot tell (or out of range).
// The feature of x: fix[m] = +-1 on each fixed axis (u_m = fix[m] h_m), 0 on each free one.
struct ObbFeature {
  int fix[3] = {0, 0, 0};
};
template <class Mul>
bool sphere_obb_point(const Sphere<double>& sp, const OrientedBox<double>& b, FirstLookPoint& out, ObbFeature& feature) {
  using M = MagnitudeValue;
  constexpr double u = first_look_u, tiny = first_look_tiny, grow = first_look_grow;
  // 1. D = c - q as exact pairs, the lengths scaled
  double Dh[3], Dl[3], h[3];
  double top = sp.radius;
  for (int i = 0; i < 3; ++i) {
    const Pair<double> d = two_sum(b.center[i], -sp.center[i]);
    Dh[i] = d.hi, Dl[i] = d.lo, h[i] = b.extent[i];
    top = std::max({top, std::fabs(d.hi), h[i]});
    const double am = std::max({std::fabs(b.axis[i][0]), std::fabs(b.axis[i][1]), std::fabs(b.axis[i][2])});
    if (!(am >= 0x1p-20 && am <= 0x1p20)) return false;
  }
  if (!(top > 0x1p-1000 && top < 0x1p1000)) return false;
  const int scale = top >= 0x1p-100 && top <= 0x1p100 ? 0 : exponent_of(top);
  if (scale != 0) {
    const Pow2<double> down(scale);
    for (int i = 0; i < 3; ++i) Dh[i] = down(Dh[i]), Dl[i] = down(Dl[i]), h[i] = down(h[i]);
  }
  out.scale = scale;
  // 2. the feature
  M a[3][3], qc[3];  // the axes; q - c on the highs
  for (int m = 0; m < 3; ++m)
    for (int c = 0; c < 3; ++c) a[m][c] = {b.axis[m][c], std::fabs(b.axis[m][c])};
  for (int c = 0; c < 3; ++c) qc[c] = {-Dh[c], std::fabs(Dh[c])};
  M n[3][3];
  for (int m = 0; m < 3; ++m)
    for (int c = 0; c < 3; ++c) {
      const int j = (m + 1) % 3, k = (m + 2) % 3, c1 = (c + 1) % 3, c2 = (c + 2) % 3;
      n[m][c] = a[j][c1] * a[k][c2] - a[j][c2] * a[k][c1];
    }
  const M delta = dot_of(a[0], n[0]);
  const bool flip = !surely_positive(delta);
  if (flip && !surely_positive(-1.0 * delta)) return false;  // (degenerate axes: the path below)
  const double sd = flip ? -1.0 : 1.0;
  M U[3], H[3];
  int o[3], fixed = 0;
  for (int m = 0; m < 3; ++m) {
    U[m] = sd * dot_of(n[m], qc);
    H[m] = abs_of(delta) * M{h[m], h[m]};
    if (surely_positive(U[m] - H[m]))
      o[m] = 1;
    else if (surely_positive(M{0, 0} - H[m] - U[m]))
      o[m] = -1;
    else if (surely_positive(H[m] - U[m]) && surely_positive(H[m] + U[m]))
      o[m] = 0;
    else
      return false;
    fixed += o[m] != 0;
  }
  // x0 - q = D + sum o_n h_n a_n (item 3), for the fixed axes' signs s
  const auto base = [&](const int (&s)[3], double (&Ph)[3], double (&Pl)[3], double (&Pe)[3]) {
    const double sh[3] = {s[0] * h[0], s[1] * h[1], s[2] * h[2]};
    for (int c = 0; c < 3; ++c) {
      const double col[3] = {b.axis[0][c], b.axis[1][c], b.axis[2][c]};
      const word_bounds::Word t = word_bounds::dot_of_doubles<Mul>(sh, col);
      const Pair<double> x = two_sum(Dh[c], t.v.hi);
      const Pair<double> y = two_sum(x.hi, double(x.lo + double(Dl[c] + t.v.lo)));
      Ph[c] = y.hi, Pl[c] = y.lo;
      Pe[c] = (t.e + 6 * u * u * (std::fabs(Dh[c]) + std::fabs(t.v.hi))) * grow + tiny;
    }
  };
  const auto face_normal = [&](int i, double (&nh)[3], double (&nl)[3], double (&En)[3]) {
    word_bounds::Word nw[3];
    word_bounds::cross_of_doubles<Mul>(b.axis[(i + 1) % 3], b.axis[(i + 2) % 3], nw);
    for (int c = 0; c < 3; ++c) nh[c] = nw[c].v.hi, nl[c] = nw[c].v.lo, En[c] = nw[c].e * grow;
  };
  double Ph[3], Pl[3], Pe[3];
  if (fixed == 0) {
    // q inside: the nearest face, strictly
    out.inside = true;
    M gap2[3], nn[3];
    for (int m = 0; m < 3; ++m) {
      const M gap = H[m] - abs_of(U[m]);
      gap2[m] = gap * gap;
      nn[m] = dot_of(n[m], n[m]);
    }
    int i = 0;
    for (int m = 1; m < 3; ++m)
      if (gap2[m].v * nn[i].v < gap2[i].v * nn[m].v) i = m;
    for (int m = 0; m < 3; ++m)
      if (m != i && !surely_positive(gap2[m] * nn[i] - gap2[i] * nn[m])) return false;
    const int side = U[i].v > 0 ? 1 : -1;
    if (!surely_positive(double(side) * U[i])) return false;
    int s[3] = {0, 0, 0};
    s[i] = side;
    feature.fix[i] = side;
    base(s, Ph, Pl, Pe);
    double nh[3], nl[3], En[3];
    face_normal(i, nh, nl, En);
    return first_look_face<Mul>(Ph, Pl, Pe, nh, nl, En, out);
  }
  // q outside: the designated feature's point and its normal cone
  M A[3][3], R[3];
  for (int m = 0; m < 3; ++m)
    for (int k = m; k < 3; ++k) A[m][k] = A[k][m] = dot_of(a[m], a[k]);
  for (int m = 0; m < 3; ++m) {
    R[m] = dot_of(a[m], qc);  // G_m = a_m . (q - c)
    for (int k = 0; k < 3; ++k)
      if (o[k] != 0) R[m] = R[m] - A[m][k] * M{o[k] * h[k], h[k]};
  }
  base(o, Ph, Pl, Pe);
  for (int m = 0; m < 3; ++m) feature.fix[m] = o[m];
  if (fixed == 3) {
    for (int m = 0; m < 3; ++m)
      if (!surely_positive(double(o[m]) * R[m])) return false;
    for (int c = 0; c < 3; ++c) out.h[c] = Ph[c], out.l[c] = Pl[c], out.err[c] = Pe[c];
    return true;
  }
  if (fixed == 2) {
    const int i = o[0] == 0 ? 0 : o[1] == 0 ? 1 : 2;
    const M hA = M{h[i], h[i]} * A[i][i];
    if (!surely_positive(hA - R[i]) || !surely_positive(hA + R[i])) return false;
    for (int j = 0; j < 3; ++j)
      if (j != i && !surely_positive(double(o[j]) * (A[i][i] * R[j] - A[i][j] * R[i]))) return false;
    const double El[3] = {0, 0, 0};
    const double Eh[3] = {b.axis[i][0], b.axis[i][1], b.axis[i][2]};
    return first_look_edge<Mul>(Ph, Pl, Pe, Eh, El, out);
  }
  const int i = o[0] != 0 ? 0 : o[1] != 0 ? 1 : 2, j = (i + 1) % 3, k = (i + 2) % 3;
  const M det = A[j][j] * A[k][k] - A[j][k] * A[j][k];
  const M uj = A[k][k] * R[j] - A[j][k] * R[k], uk = A[j][j] * R[k] - A[j][k] * R[j];
  const M hj = M{h[j], h[j]} * det, hk = M{h[k], h[k]} * det;
  if (!surely_positive(det) || !surely_positive(hj - uj) || !surely_positive(hj + uj) || !surely_positive(hk - uk) ||
      !surely_positive(hk + uk))
    return false;
  double nh[3], nl[3], En[3];
  face_normal(i, nh, nl, En);
  return first_look_face<Mul>(Ph, Pl, Pe, nh, nl, En, out);
}

// A coordinate of x known exactly (item 5): where every free axis has a zero component i, x_i =
// c_i + sum over the fixed axes of fix[m] h_m a_m[i], rounded once where that sum has one
// nonzero term besides c_i and its product is exact (an axis-aligned box: a_m[i] = +-1); on a
// face (one axis fixed) whose normal's component i is exactly 0 (its two products equal, as
// exact pairs), x_i = q_i.
template <class Mul>
bool sphere_obb_exact(const Sphere<double>& sp, const OrientedBox<double>& b, const ObbFeature& f, int i, double& x) {
  int fixed = 0, free_nonzero = 0, terms = 0, face = -1;
  bool products_exact = true;
  double term = 0;
  for (int m = 0; m < 3; ++m) {
    if (f.fix[m] == 0) {
      free_nonzero += b.axis[m][i] != 0;
      continue;
    }
    ++fixed, face = m;
    if (b.axis[m][i] == 0) continue;
    const Pair<double> p = Mul::prod(f.fix[m] * b.extent[m], b.axis[m][i]);
    products_exact = products_exact && p.lo == 0;
    ++terms, term = p.hi;
  }
  if (free_nonzero == 0 && terms <= 1 && products_exact) {
    x = (b.center[i] + term) + 0.0;  // (+0 for -0, as the exact value rounds)
    return true;
  }
  if (fixed == 1) {
    const Vec3<double>&aj = b.axis[(face + 1) % 3], &ak = b.axis[(face + 2) % 3];
    const int c1 = (i + 1) % 3, c2 = (i + 2) % 3;
    const Pair<double> p = Mul::prod(aj[c1], ak[c2]), q = Mul::prod(aj[c2], ak[c1]);
    if (p.hi == q.hi && p.lo == q.lo) {
      x = sp.center[i] + 0.0;
      return true;
    }
  }
  return false;
}

// |x - q|^2 exactly for the certified feature, q outside (for rational.hpp's sharpen_gap where the
// double words leave the distance loose, in place of obb_xx's every feature): with x0 = c + sum over the fixed
// axes of fix[m] h_m a_m and w = q - x0, a vertex's |w|^2, an edge's |w|^2 - (a_i . w)^2 / a_i.a_i
// (i the free axis), a face's (n_i . w)^2 / n_i.n_i (i the fixed axis).
inline bool sphere_obb_xx(const Sphere<double>& sp, const OrientedBox<double>& b, const ObbFeature& f, Rational& xx) {
  RVec x0, q, a, w;
  Rational t;
  set_vec(x0, b.center);
  set_vec(q, sp.center);
  int fixed = 0, one = -1, free_axis = -1;
  for (int m = 0; m < 3; ++m) {
    if (f.fix[m] == 0) {
      free_axis = m;
      continue;
    }
    ++fixed, one = m;
    set_vec(a, b.axis[m]);
    set_rational(t, f.fix[m] * b.extent[m]);
    for (int c = 0; c < 3; ++c) {
      mpq_mul(a[c].q, a[c].q, t.q);
      mpq_add(x0[c].q, x0[c].q, a[c].q);
    }
  }
  sub_vec(w, q, x0);
  if (fixed == 1) {
    RVec aj, ak, n;
    set_vec(aj, b.axis[(one + 1) % 3]), set_vec(ak, b.axis[(one + 2) % 3]);
    cross_vec(n, aj, ak);
    Rational nw, nn;
    dot_vec(nw, n, w), dot_vec(nn, n, n);
    mpq_mul(xx.q, nw.q, nw.q);
    mpq_div(xx.q, xx.q, nn.q);
    return true;
  }
  dot_vec(xx, w, w);
  if (fixed == 2) {
    Rational aw, aa;
    set_vec(a, b.axis[free_axis]);
    dot_vec(aw, a, w), dot_vec(aa, a, a);
    mpq_mul(aw.q, aw.q, aw.q);
    mpq_div(aw.q, aw.q, aa.q);
    mpq_sub(xx.q, xx.q, aw.q);
  }
  return true;
}

// Items 4-5: the values where their bounds prove them (first_look.hpp, first_look_values); which
// of the asked values it set. cls as there: inside, they meet; else g's certain sign, else
// first_stage()'s. Correct: each value the truth correctly rounded, for the oracle.
// (feature, certified: where given, x's feature, and whether it was certified with q outside)
template <class Mul, bool Correct = false, class Stage>
unsigned sphere_obb_fast(const Sphere<double>& sp, const OrientedBox<double>& b, int& cls, int unknown, unsigned w,
                         Proximity<double>& res, Stage first_stage, ObbFeature* feature = nullptr,
                         bool* certified = nullptr) {
  FirstLookPoint P;
  ObbFeature local;
  ObbFeature& f = feature ? *feature : local;
  const bool point = sphere_obb_point<Mul>(sp, b, P, f);
  if (point && P.inside) cls = 1;
  if (certified) *certified = point && !P.inside;
  return first_look_values<Mul, Correct>(sp, P, point, cls, unknown, w, res, nullptr, first_stage,
                                         [&](int i, double& x) { return sphere_obb_exact<Mul>(sp, b, f, i, x); });
}

}  // namespace cdref::robust::detail
