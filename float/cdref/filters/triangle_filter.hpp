// cdref/filters/triangle_filter.hpp - the first stage of the Section 3.4 classification oracles:
// the orientation form of a ray or segment cast on a triangle, two certificates from one point
// of a triangle for a sphere, and a plane and six edge casts for two triangles, each evaluated in
// double against static error bounds. Plain double arithmetic on the query's inputs, so that both
// the oracles (exact/cdref/oracle/ray_triangle.hpp, sphere_triangle.hpp, triangle_triangle.hpp,
// polygon.hpp: then the double words, then CGAL::Gmpq) and the robust tier's certified decisions
// (robust/ray_triangle.hpp, sphere_triangle.hpp, triangle_triangle.hpp, at double) run it first:
// where it decides (1 meets, 0 apart; `unknown` leaves the case to the next stage), its answer
// is the book's at an exact type.
//
// ---- Ray and segment casts on a triangle (book/ray_triangle.hpp) ---------------------------
// First a coordinate plane, by exact comparisons of the inputs: the triangle's bounding box
// apart from the segment's, or on the far side of the ray's source along an axis the ray does
// not climb (d_i >= 0 and every v_k,i < s_i, or d_i <= 0 and every v_k,i > s_i): a miss.
// Then the orientation form of the test. With A, B, C the vertices relative to the
// source s, d the direction (t - s for a segment) and n = (v1 - v0) x (v2 - v0):
//   w0 = d . (B x C), w1 = d . (C x A), w2 = d . (A x B)   (sum D = d . n),
//   Ns = (v0 - s) . n, and for the segment Nt = (v0 - t) . n.
// The line meets the triangle iff the w_k do not have opposite signs; with D > 0
// the ray then hits iff Ns >= 0, the segment iff moreover Nt <= 0 (D < 0: the
// signs turn). Each of these is a sum of six monomials of degree 3 in rounded
// differences of inputs; evaluated in double each monomial carries at most 7
// roundings (two differences, two products, a difference in the cross product,
// two sums in the dot product), so |computed - exact| <= gamma_7 P, P the same
// expression on absolute values; the filter takes 10u (1 + 16u) P~ (P~ computed in
// double: at most 7 more roundings upward of P) plus 2^-1022 (1 + |a|_1) for
// underflow: a rounding that underflows errs by up to 2^-1075 absolute, and one
// inside the cross product b x c is then multiplied by a's coordinate (found by the
// fuzz target: a subnormal product scaled by 2^1009), so 64 * 2^-1074 (1 + |a|_1) would
// do. The term is taken at 2^-1022, the smallest normal double, because a product with
// a subnormal operand or result takes a microcode assist on these machines, about 30 ns
// against 2. With the term at 64 * 2^-1074 the ray-triangle cast's filter took 81 ns a case
// on the long-range cases at 10^12 that its bound decides, 29 ns with it normal (a
// standalone loop), and polygon-polygon's oracle 1,054 ns against 402 (cdref_bench). It decides a miss when two
// w_k have opposite certain signs, and a hit or a miss when all three w_k have the
// same certain sign and Ns (and Nt) certainly have theirs. A non-finite value leaves the case to the next stage.
//
// Where a sign is left undecided, a second look, exact: each axis's coordinates (the source,
// the target, the three vertices) as integers on the coarsest grid 2^G_i they share, read off
// their bits (x = m 2^e with m odd; G_i the smallest e), so that no scaling rounds and
// subnormals are no exception. Every monomial of a triple product takes one coordinate from
// each axis, so the grids scale it by the positive constant 2^-(G_0 + G_1 + G_2) and keep its
// sign. A ray's direction is not a difference of positions, and a unit direction has bits far
// below the grid of coordinates 10^6 from the origin: it takes grids of its own, 2^(G_i + delta)
// with one delta for the three axes (each monomial of d . (A x B) takes d from one axis and A, B
// from the other two: the scale is again common). Each integer has at most 62 bits, so each
// difference fits in 64; the triple products are evaluated in 128-bit integers where the axes'
// widths sum to at most 124 (every partial sum below 2^127), in 192-bit magnitudes summed in 256
// bits otherwise. An axis whose values span more than 62 bits (1e12 beside 0.1), a direction
// too wide for its grids, or a non-finite input leaves the case to the next stage. So a mesh
// 10^12 from the origin (multiples of 2^-13 there), integer lattices, decimal coordinates of
// like magnitude and a unit direction through a vertex 10^6 away are all decided here. A shot
// through a vertex or along an edge is exactly degenerate
// there, and the bound above cannot decide a sign that is exactly 0. With the exact signs the
// book's test is decided as it stands: opposite signs miss; all three w_k zero is the shot's
// line in the plane, decided by 2-D orientations there (coplanar_shot below; a zero-area
// triangle is left to the next stage); otherwise
// D has the sign sD of the w_k that are not zero, and the ray hits iff Ns is not -sD (Ns = 0:
// lambda = 0), the segment iff moreover Nt is not sD (Nt = 0: lambda = 1).
//
// ---- A sphere and a triangle (book/sphere_triangle.hpp) -------------------------------------
// First a plane x_i = c_i +- rho: with X = fl(v - c) (rounding is monotone and errs by at most
// u |v_i - c_i|, none where it underflows), X_k,i > fl(rho (1 + 2u)) >= rho (1 + u) for the three
// vertices proves v_k,i - c_i > rho: the triangle lies beyond the plane, the sphere on its
// side (also when rho is subnormal: a normal X_k,i then exceeds rho by more than its error).
// Then two certificates from one point of the triangle, with static error bounds:
// X_k = fl(v_k - c) (the vertices relative to the centre, one rounding each);
// (u, v) the barycentric coordinates of the book's closest point computed in
// double, clamped so that u, v >= 0 and u + v <= 1 hold exactly; the point
// x = v0 + u (v1 - v0) + v (v2 - v0) then lies in the triangle exactly, and
// w = x - c = X0 + u (X1 - X0) + v (X2 - X0) is computed with at most 5 roundings
// a monomial against W+_c = |X0_c| + u (|X1_c| + |X0_c|) + v (|X2_c| + |X0_c|):
// |w~_c - w_c| <= gamma_5 W+_c <= e_c = 6u W+~_c (1 + 16u).
//   intersect  |w|^2 <= |w~|^2 (1 + 4u) + sum_c e_c (2 |w~_c| + e_c) < rho^2;
//   disjoint   along v = w~: every point t of the triangle has
//              v . (t - c) >= G = min_k v . X_k (a linear function's minimum over
//              a triangle is at a vertex), and the sphere lies within rho |v| of c
//              along v, so G > rho |v| separates them; G~ carries 4 roundings a
//              monomial (v exact, X a leaf): G_lo = G~ - 5u (1 + 16u) max_k |v|.|X_k|,
//              and G_lo > 0 with G_lo^2 (1 - 8u) > rho^2 |v|^2 (1 + 8u) decides.
// Roundings that underflow are covered by 64 * 2^-1074; a non-finite value leaves
// the case to the next stage.
//
// ---- Two triangles (book/triangle_triangle.hpp) ---------------------------------------------
// First the bounding boxes, by exact comparisons of the inputs: apart along an axis, the
// triangles are apart.
// (a) A plane: the signs of dB_k = (b_k - a0) . ((a1 - a0) x (a2 - a0)), and of
// dA_k the other way, each a triple product of rounded differences with the
// static bound above; three certain signs alike separate.
// (b) The edges: two closed triangles meet iff an edge of one meets the other
// (non-coplanar: an end of their common segment lies on an edge of one of them;
// coplanar: edges cross, or one triangle holds the other and with it its edges;
// a zero-area triangle's edges cover its span). Each of the six edge-triangle
// pairs is the segment-triangle filter above: one certain hit proves the triangles
// meet, six certain misses that they do not.
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cdref/cdref.hpp>
#include <cdref/filters/grid.hpp>
#include <cdref/filters/minmax.hpp>
#include <cmath>
#include <limits>

namespace cdref::filters {

namespace ray_triangle {

inline constexpr int unknown = 2;

// The sign of a . (b x c) with its bound: +1, -1, or 0 when the bound does not decide. Inlined
// always: an out-of-line call (GCC's choice once the exact look below calls it too) made the
// segment cast's filter half as fast again (cdref_bench, 23 -> 34 ns on uniform cases).
[[gnu::always_inline]] inline int triple_sign(const double (&a)[3], const double (&b)[3], const double (&c)[3], bool& finite) {
  constexpr double u_ = 0x1p-53, grow = 1 + 16 * u_, eta = 0x1p-1022;  // normal: see above
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

// ---- the second look: the inputs as integers on a grid, one grid an axis ----
namespace exact_eval {

using grid::axis_on_grid;
using grid::direction_on_grid;
using grid::dyadic;
using grid::Dyadic;
using grid::no_grid;
using grid::Wide;

// The exact sign of a . (b x c) for integer vectors whose i-th coordinates are below 2^L_i in
// magnitude with L_0 + L_1 + L_2 <= 124: each of the six monomials is below 2^124, their
// sum below 2^127, every partial sum too (a cross product's component is below 2^(L_j+L_k+1)).
inline int triple(const std::int64_t (&a)[3], const std::int64_t (&b)[3], const std::int64_t (&c)[3]) {
  const Wide x0 = Wide(b[1]) * c[2] - Wide(b[2]) * c[1];
  const Wide x1 = Wide(b[2]) * c[0] - Wide(b[0]) * c[2];
  const Wide x2 = Wide(b[0]) * c[1] - Wide(b[1]) * c[0];
  const Wide v = a[0] * x0 + a[1] * x1 + a[2] * x2;
  return int(v > 0) - int(v < 0);
}

// The same for any coordinates below 2^63 in magnitude (differences of 62-bit integers): a
// cross product's component b_j c_k - b_k c_j is below 2^127 and exact in a signed 128-bit
// integer; each a_i x_i is below 2^190, taken as a 192-bit magnitude (two 64 x 64 -> 128-bit
// products) and added to or subtracted from a 256-bit two's-complement sum, below 2^192.
inline int triple_wide(const std::int64_t (&a)[3], const std::int64_t (&b)[3], const std::int64_t (&c)[3]) {
  grid::Sum256 acc;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    acc.add(Wide(b[j]) * c[k] - Wide(b[k]) * c[j], a[i]);
  }
  return acc.sign();
}

// Every w_k = 0: the shot's line lies in the triangle's plane (or the shot is a point, d = 0).
// A point off the plane (Ns != 0) is a miss, a triangle of zero area is left to the next stage.
// Otherwise the closed segment or ray and the closed triangle lie in one plane, and they meet iff
// no axis of Theorem 3.1 in that plane separates them: the triangle's three side normals and the
// shot's line normal (a ray is the limit of ever longer segments, each with these axes). On a
// side normal of edge (p, q) with third vertex r every point x of the plane projects to
// f(x) = ((q - p) x (x - p)) . n times one positive factor, and for x in the plane that is the
// component along an axis c with n_c != 0, times n_c / |n|^2 (the 2-D orientation the
// coplanar triangles take too: triangle_grid.hpp): the triangle covers [min(0, f(r)), max(0,
// f(r))], the segment [f(s), f(t)], the ray f(s) + lambda g, g = ((q - p) x d)_c, over lambda >=
// 0. On the line normal the triangle's vertices v project to (d x (v - s))_c, the shot to 0.
// Each f, g and line value is a difference of two products of integers below 2^63: exact in 128
// bits, whichever scale the direction's grid takes (only signs and values of one kind compared).
inline int coplanar_shot(const std::int64_t (&A)[3][3], const std::int64_t (&d)[3], const std::int64_t (&e1)[3],
                         const std::int64_t (&e2)[3], bool segment, int Ns) {
  Wide n[3];
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, l = (i + 2) % 3;
    n[i] = Wide(e1[j]) * e2[l] - Wide(e1[l]) * e2[j];
  }
  if (n[0] == 0 && n[1] == 0 && n[2] == 0) return unknown;  // a triangle of zero area
  if (Ns != 0) return 0;                                    // a point off the plane
  int c = 0;
  while (n[c] == 0) ++c;
  const int x = (c + 1) % 3, y = (c + 2) % 3;
  // positions relative to the source: the vertices A[k], the source 0, a segment's target d
  const auto cross_c = [](std::int64_t ux, std::int64_t uy, std::int64_t vx, std::int64_t vy) {
    return Wide(ux) * vy - Wide(uy) * vx;
  };
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    const std::int64_t ex = A[j][x] - A[i][x], ey = A[j][y] - A[i][y];  // q - p: v_j - v_i
    const auto f = [&](std::int64_t px, std::int64_t py) { return cross_c(ex, ey, px - A[i][x], py - A[i][y]); };
    const Wide third = f(A[k][x], A[k][y]), lo = third < 0 ? third : 0, hi = third < 0 ? 0 : third;
    const Wide fs = f(0, 0);
    if (segment) {
      const Wide ft = f(d[x], d[y]);
      if ((fs > hi && ft > hi) || (fs < lo && ft < lo)) return 0;
    } else {
      const Wide g = cross_c(ex, ey, d[x], d[y]);
      if ((g >= 0 && fs > hi) || (g <= 0 && fs < lo)) return 0;
    }
  }
  bool above = true, below = true;
  for (int k = 0; k < 3; ++k) {
    const Wide h = cross_c(d[x], d[y], A[k][x], A[k][y]);
    above = above && h > 0;
    below = below && h < 0;
  }
  return above || below ? 0 : 1;
}

// The cast decided from the static signs (nonzero: certain; 0: undecided) and the exact ones
// where those are undecided; `unknown` where the inputs are on no grid narrow enough (an axis
// spanning more than 62 bits) or the shot lies in the triangle's plane.
[[gnu::noinline]] inline int settle(const Vec3<double>& s, const Vec3<double>* t, const Vec3<double>& dir, const Triangle<double>& tri,
                                    int w0, int w1, int w2) {
  // per axis: the source, the target (a segment; a ray's source again, unused), the three vertices
  std::int64_t A[3][3], d[3], e1[3], e2[3], T0[3];
  int grid[3];
  for (int i = 0; i < 3; ++i) {
    const double x[5] = {s[i], t ? (*t)[i] : s[i], tri.vertex[0][i], tri.vertex[1][i], tri.vertex[2][i]};
    std::int64_t n[5];
    if (!axis_on_grid(x, n, grid[i])) return unknown;
    for (int k = 0; k < 3; ++k) A[k][i] = n[2 + k] - n[0];
    d[i] = n[1] - n[0];  // a segment's t - s
    e1[i] = n[3] - n[2];
    e2[i] = n[4] - n[2];
    T0[i] = t ? n[2] - n[1] : 0;
  }
  if (!t && !direction_on_grid(dir, grid, d)) return unknown;
  // the values a triple product below takes on axis i, or'd (each below 2^63 in magnitude)
  const auto all = [&](int i, auto f) { return f(A[0][i]) | f(A[1][i]) | f(A[2][i]) | f(d[i]) | f(e1[i]) | f(e2[i]) | f(T0[i]); };
  const auto magnitude = [](std::int64_t x) { return std::uint64_t(std::llabs(x)); };
  int bits = 0;
  for (int i = 0; i < 3; ++i) bits += std::bit_width(all(i, magnitude));
  if (bits > 124) {
    // too wide for 128 bits as they stand (a lattice's differences can have more trailing
    // zeros than its coordinates): divide each axis by the power of two its values have in
    // common (-x has the trailing zeros of x)
    bits = 0;
    for (int i = 0; i < 3; ++i) {
      const std::uint64_t any = all(i, [](std::int64_t x) { return std::uint64_t(x); });
      const int common = any == 0 ? 0 : std::countr_zero(any);
      for (int k = 0; k < 3; ++k) A[k][i] >>= common;  // exact: those bits are zero
      d[i] >>= common, e1[i] >>= common, e2[i] >>= common, T0[i] >>= common;
      bits += std::bit_width(all(i, magnitude));
    }
  }
  // 128-bit products where the widths allow, 192-bit ones otherwise
  const auto sign = [wide = bits > 124](const std::int64_t (&a)[3], const std::int64_t (&b)[3], const std::int64_t (&c)[3]) {
    return wide ? triple_wide(a, b, c) : triple(a, b, c);
  };
  int w[3] = {w0, w1, w2};
  for (int k = 0; k < 3; ++k)
    if (w[k] == 0) w[k] = sign(d, A[(k + 1) % 3], A[(k + 2) % 3]);
  const bool neg = w[0] < 0 || w[1] < 0 || w[2] < 0, pos = w[0] > 0 || w[1] > 0 || w[2] > 0;
  if (neg && pos) return 0;
  if (!(neg || pos)) return coplanar_shot(A, d, e1, e2, t != nullptr, sign(A[0], e1, e2));
  const int sD = pos ? 1 : -1;
  // Ns = (v0 - s) . (e1 x e2): lambda's numerator; Nt = (v0 - t) . (e1 x e2)
  if (sign(A[0], e1, e2) == -sD) return 0;        // lambda < 0
  if (t && sign(T0, e1, e2) == sD) return 0;      // lambda > 1
  return 1;
}

}  // namespace exact_eval

inline int filter(const Vec3<double>& s, const Vec3<double>* t, const Vec3<double>& dir, const Triangle<double>& tri) {
  // a coordinate plane first (exact comparisons of inputs): the triangle beyond the segment's
  // box, or behind the ray's source along an axis it does not climb
  // (the three axes' tests combined with no branch but the one on the answer)
  bool beyond = false;
  for (int i = 0; i < 3; ++i) {
    const double lo = min_value(min_value(tri.vertex[0][i], tri.vertex[1][i]), tri.vertex[2][i]);
    const double hi = max_value(max_value(tri.vertex[0][i], tri.vertex[1][i]), tri.vertex[2][i]);
    const double si = s[i], di = dir[i];
    if (t) {
      const double ti = (*t)[i], lo_st = min_value(si, ti), hi_st = max_value(si, ti);
      beyond |= (hi < lo_st) | (lo > hi_st);
    } else {
      beyond |= ((di >= 0) & (hi < si)) | ((di <= 0) & (lo > si));
    }
  }
  if (beyond) return 0;
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
  if (w0 == 0 || w0 != w1 || w0 != w2) return exact_eval::settle(s, t, dir, tri, w0, w1, w2);
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
  if (ns == sD && nt == -sD) return 1;
  return exact_eval::settle(s, t, dir, tri, w0, w1, w2);
}

}  // namespace ray_triangle

namespace sphere_triangle {

inline constexpr int unknown = 2;

// Barycentric (u, v) of the book's closest point to the origin, in double (any values do: they
// are clamped into the triangle exactly). Inlined always: the call and u, v through memory
// cost 3 of 44 ns a case (the filter alone over 16,384 long-range cases at 10^12).
[[gnu::always_inline]] inline void closest_barycentric(const double (&X)[3][3], double& u, double& v) {
  // plain scalars: building Eigen vectors from them costs store-forwarding stalls here
  double ab[3], ac[3];
  for (int i = 0; i < 3; ++i) ab[i] = X[1][i] - X[0][i], ac[i] = X[2][i] - X[0][i];
  const auto dot = [](const double (&p)[3], const double (&q)[3]) { return p[0] * q[0] + p[1] * q[1] + p[2] * q[2]; };
  const double d1 = -dot(ab, X[0]), d2 = -dot(ac, X[0]);  // ab . (0 - a), ac . (0 - a)
  u = v = 0;
  if (d1 <= 0 && d2 <= 0) return;
  const double d3 = -dot(ab, X[1]), d4 = -dot(ac, X[1]);
  if (d3 >= 0 && d4 <= d3) { u = 1; return; }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) { u = d1 / (d1 - d3); return; }
  const double d5 = -dot(ab, X[2]), d6 = -dot(ac, X[2]);
  if (d6 >= 0 && d5 <= d6) { v = 1; return; }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) { v = d2 / (d2 - d6); return; }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
    v = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    u = 1 - v;
    return;
  }
  const double inv = 1 / (va + vb + vc);  // one division for both
  u = vb * inv;
  v = vc * inv;
}

inline int filter(const Sphere<double>& s, const Triangle<double>& t) {
  constexpr double u_ = 0x1p-53, grow = 1 + 16 * u_, eta = 64 * 0x1p-1074;
  double X[3][3];
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 3; ++i) X[k][i] = t.vertex[k][i] - s.center[i];
  // a coordinate plane first: every vertex beyond c_i + rho (or below c_i - rho) along some
  // axis, that is the largest of the axes' minima above rho or the smallest maximum below -rho
  // (one branch for the three axes)
  const double r1 = s.radius * (1 + 2 * u_);
  double lo = -r1, hi = r1;
  for (int i = 0; i < 3; ++i) {
    lo = max_value(lo, min_value(min_value(X[0][i], X[1][i]), X[2][i]));
    hi = min_value(hi, max_value(max_value(X[0][i], X[1][i]), X[2][i]));
  }
  if ((lo > r1) | (hi < -r1)) return 0;
  double u, v;
  closest_barycentric(X, u, v);
  // clamp: u in [0, 1], v in [0, 1 - u] with u + v <= 1 exactly
  if (!(u >= 0)) u = 0;  // NaN included
  if (!(u <= 1)) u = 1;
  // room = 1 - u rounded towards 0: r0 = fl(1 - u) and its error (1 - u) - r0 exactly by
  // Fast-Two-Sum (|1| >= |u|); where r0 rounded up (error < 0), the next double towards 0 is
  // at most 1 - u (r0 is the nearest double, so 1 - u lies within half an ulp below it, the
  // ulp of the binade below where r0 is a power of 2). Then u + room <= 1 exactly; no branch.
  const double r0 = 1 - u, r0_err = -u - (r0 - 1);
  const double room = std::bit_cast<double>(std::bit_cast<std::uint64_t>(r0) - std::uint64_t(r0_err < 0));
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
  // Both certificates are evaluated and combined without a branch: near contact either one
  // decides about half the cases, and a branch on the first cost 2-3 of 41 ns a case (as above).
  const bool meets = (ww * (1 + 4 * u_) + e2 * grow + eta) * grow < rr * (1 - 2 * u_);
  double g[3], gp[3];
  for (int k = 0; k < 3; ++k) {
    g[k] = w[0] * X[k][0] + w[1] * X[k][1] + w[2] * X[k][2];
    gp[k] = std::fabs(w[0] * X[k][0]) + std::fabs(w[1] * X[k][1]) + std::fabs(w[2] * X[k][2]);
  }
  const double G = min_value(min_value(g[0], g[1]), g[2]), Gp = max_value(max_value(gp[0], gp[1]), gp[2]);
  const double Glo = G - (5 * u_ * grow * Gp + eta);
  // Glo finite (a NaN fails every comparison), positive, and its square above rho^2 |v|^2
  const bool apart = (std::fabs(Glo) <= std::numeric_limits<double>::max()) & (Glo > 0) &
                     (Glo * Glo * (1 - 8 * u_) > (rr * ww) * (1 + 8 * u_) + eta);
  // meets and apart cannot both hold (the exact |v| would be both below and above rho)
  static_assert(unknown == 2);
  return 2 - int(meets) - 2 * int(apart);
}
}  // namespace sphere_triangle

namespace triangle_triangle {

inline constexpr int unknown = 2;

// The signs of t's vertices against the plane of p, certain or 0.
[[gnu::always_inline]] inline void plane_signs(const Triangle<double>& p, const Triangle<double>& t, int (&s)[3], bool& finite) {
  double e1[3], e2[3], x[3];
  for (int i = 0; i < 3; ++i) {
    e1[i] = p.vertex[1][i] - p.vertex[0][i];
    e2[i] = p.vertex[2][i] - p.vertex[0][i];
  }
  for (int k = 0; k < 3; ++k) {
    for (int i = 0; i < 3; ++i) x[i] = t.vertex[k][i] - p.vertex[0][i];
    s[k] = ray_triangle::triple_sign(x, e1, e2, finite);
  }
}
inline bool plane_separates(const Triangle<double>& p, const Triangle<double>& t, bool& finite) {
  int s[3];
  plane_signs(p, t, s, finite);
  return s[0] != 0 && s[0] == s[1] && s[0] == s[2];
}
// t certainly has vertices on both sides of p's plane
inline bool plane_crosses(const Triangle<double>& p, const Triangle<double>& t, bool& finite) {
  int s[3];
  plane_signs(p, t, s, finite);
  return (s[0] > 0 || s[1] > 0 || s[2] > 0) && (s[0] < 0 || s[1] < 0 || s[2] < 0);
}

// The triangles' boxes apart along a coordinate axis (exact comparisons of inputs; the three
// axes' tests combined, for one branch at the caller).
inline bool boxes_apart(const Triangle<double>& a, const Triangle<double>& b) {
  bool apart = false;
  for (int i = 0; i < 3; ++i) {
    const double alo = min_value(min_value(a.vertex[0][i], a.vertex[1][i]), a.vertex[2][i]);
    const double ahi = max_value(max_value(a.vertex[0][i], a.vertex[1][i]), a.vertex[2][i]);
    const double blo = min_value(min_value(b.vertex[0][i], b.vertex[1][i]), b.vertex[2][i]);
    const double bhi = max_value(max_value(b.vertex[0][i], b.vertex[1][i]), b.vertex[2][i]);
    apart |= (ahi < blo) | (bhi < alo);
  }
  return apart;
}

inline int filter(const Triangle<double>& a, const Triangle<double>& b) {
  // a coordinate plane first: boxes apart along an axis
  if (boxes_apart(a, b)) return 0;
  bool finite = true;
  if (plane_separates(a, b, finite) || plane_separates(b, a, finite)) return finite ? 0 : unknown;
  if (!finite) return unknown;
  int misses = 0;
  for (const auto* pair : {&a, &b}) {
    const Triangle<double>& from = *pair;
    const Triangle<double>& other = pair == &a ? b : a;
    for (int k = 0; k < 3; ++k) {
      const Vec3<double>& s = from.vertex[k];
      const Vec3<double>& t = from.vertex[(k + 1) % 3];
      const int r = ray_triangle::filter(s, &t, t, other);
      if (r == 1) return 1;
      misses += r == 0;
    }
  }
  return misses == 6 ? 0 : unknown;
}

// Two polygons (book/polygon.hpp: each the union of its fan triangles (v0, v_k+1, v_k+2)) meet
// iff some pair of fan triangles does: the filter above on every pair, sharing what pairs have
// in common. First the polygons' boxes (exact comparisons). Then each fan triangle's plane
// against a vertex of the other polygon, once (the same triple_sign, on the same rounded
// differences, as plane_separates, each computed where a pair first asks for it). Then, for a pair
// neither box nor plane separates, its six edge-triangle filters, each (edge, triangle) once: a
// diagonal (v0, v_k) belongs to two fan triangles, and its filter is exact wherever it is
// certain, in either direction. 1 where a pair certainly meets, 0 where every pair is
// certainly apart, unknown otherwise (the pairs then go through the stages one by one).
// `resolve(w, i, k)` is asked for each plane sign the static bound cannot tell (polygon w's fan
// triangle i against the other's vertex k) and returns it certain (1, -1) or 0: none here
// (polygon_filter), the sign on double words in polygon_on_words (triangle_words.hpp).
template <class Resolve>
int polygon_pairs(const Polygon<double>& a, const Polygon<double>& b, const Resolve& resolve) {
  bool apart = false;
  for (int i = 0; i < 3; ++i) {
    double alo = a.vertex[0][i], ahi = alo, blo = b.vertex[0][i], bhi = blo;
    for (int k = 1; k < a.n; ++k) alo = min_value(alo, a.vertex[k][i]), ahi = max_value(ahi, a.vertex[k][i]);
    for (int k = 1; k < b.n; ++k) blo = min_value(blo, b.vertex[k][i]), bhi = max_value(bhi, b.vertex[k][i]);
    apart |= (ahi < blo) | (bhi < alo);
  }
  if (apart) return 0;
  constexpr int M = Polygon<double>::max_vertices;
  // side[0][i][k]: b's vertex k against the plane of a's triangle i; side[1][j][k]: a's vertex k
  // against b's triangle j; 2 until asked for
  signed char side[2][M - 2][M];
  for (auto& t : side)
    for (auto& r : t)
      for (auto& x : r) x = 2;
  bool finite = true;
  const auto sign_of = [&](int w, int i, int k) {
    signed char& r = side[w][i][k];
    if (r == 2) {
      const Polygon<double>& p = w == 0 ? a : b;
      const Polygon<double>& q = w == 0 ? b : a;
      double e1[3], e2[3], x[3];
      for (int c = 0; c < 3; ++c) {
        e1[c] = p.vertex[i + 1][c] - p.vertex[0][c];
        e2[c] = p.vertex[i + 2][c] - p.vertex[0][c];
        x[c] = q.vertex[k][c] - p.vertex[0][c];
      }
      int sg = ray_triangle::triple_sign(x, e1, e2, finite);
      if (sg == 0 && finite) sg = resolve(w, i, k);
      r = static_cast<signed char>(sg);
    }
    return r;
  };
  const auto plane_apart = [&](int w, int i, int j) {  // triangle j's vertices 0, j+1, j+2
    const int s0 = sign_of(w, i, 0);
    return s0 != 0 && s0 == sign_of(w, i, j + 1) && s0 == sign_of(w, i, j + 2);
  };
  // edge e of one polygon against triangle j of the other: -1 not yet filtered, else the
  // filter's answer. Edges: (v_k, v_k+1) is k (k < n, v_n = v0), the diagonal (v0, v_k) n + k.
  signed char edge[2][2 * M][M - 2];
  for (auto& t : edge)
    for (auto& e : t)
      for (auto& x : e) x = -1;
  const auto edge_id = [](int n, int u, int v) {  // u, v vertices of a fan triangle's edge
    if (u > v) std::swap(u, v);
    if (u == 0 && v == n - 1) return n - 1;
    if (u == 0 && v != 1) return n + v;
    return u;
  };
  bool unsure = false;
  for (int i = 0; i < a.n - 2; ++i)
    for (int j = 0; j < b.n - 2; ++j) {
      const Triangle<double> ta = a.triangle(i), tb = b.triangle(j);
      if (boxes_apart(ta, tb)) continue;
      if (plane_apart(0, i, j) || plane_apart(1, j, i)) {
        if (!finite) return unknown;
        continue;
      }
      if (!finite) return unknown;
      int misses = 0;
      for (int w = 0; w < 2; ++w) {
        const Polygon<double>& p = w == 0 ? a : b;
        const int tri = w == 0 ? i : j;
        const Triangle<double>& other = w == 0 ? tb : ta;
        const int other_id = w == 0 ? j : i;
        const int vs[3] = {0, tri + 1, tri + 2};
        for (int k = 0; k < 3; ++k) {
          const int u = vs[k], v = vs[(k + 1) % 3];
          signed char& r = edge[w][edge_id(p.n, u, v)][other_id];
          if (r < 0) r = static_cast<signed char>(ray_triangle::filter(p.vertex[u], &p.vertex[v], p.vertex[v], other));
          if (r == 1) return 1;
          misses += r == 0;
        }
      }
      unsure = unsure || misses != 6;
    }
  return unsure ? unknown : 0;
}
inline int polygon_filter(const Polygon<double>& a, const Polygon<double>& b) {
  return polygon_pairs(a, b, [](int, int, int) { return 0; });
}
}  // namespace triangle_triangle

}  // namespace cdref::filters
