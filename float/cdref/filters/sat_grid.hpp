// cdref/filters/sat_grid.hpp - a triangle, a segment or a ray and an axis-aligned box
// (book/triangle_box.hpp, Akenine-Moller's 13 axes; book/segment_box.hpp, 6 axes) evaluated
// exactly on integers, the inputs read as integers on a grid per coordinate axis (grid.hpp).
// Where it applies it gives the book's answer at an exact type: whether they meet and, if not,
// the first separating axis in the book's order and its direction.
//
// With X_k the vertices, C the centre and H the extents, the values one axis carries are
// X_0,i, X_1,i, X_2,i, C_i and H_i (a length along axis i). On their grid 2^G_i they are
// integers below 2^125 (coordinates 10^12 from the origin beside extents near 1 span about 96
// bits), and what the formulas take is required below 2^62: H, V_k = X_k - C and the edges
// e_0 = X_1 - X_0, e_1 = X_2 - X_1, e_2 = X_0 - X_2 (f = X_2 - X_0 = -e_2). So:
//   axis 0        N = e_0 x f, p = N . V_0, r = sum_i H_i |N_i|, separating iff |p| > r.
//                 N_i takes one factor from each of the other two axes (below 2^127, exact in
//                 a signed 128-bit integer), p and r one from each of the three: both scale by
//                 2^(G_0 + G_1 + G_2), so p - r and p + r (|p| > r iff p - r > 0 or p + r < 0)
//                 keep their signs on the integers. Each of their six terms is below 2^190:
//                 Sum256.
//   axes 1-3      min_k V_k,i > H_i or max_k V_k,i < -H_i: one axis, compared as integers.
//   axis 4+3k+j   L = e_k x e_j (two nonzero components, +-e_k on the other two axes a, b),
//                 p = V . L over the vertices k and k + 2, r = H_a |L_a| + H_b |L_b|: every
//                 term takes one factor from axis a and one from b (scale 2^(G_a + G_b)), each
//                 product below 2^126, so p and r are exact in 128 bits (|p| < 2^127, r < 2^126)
//                 and compared there.
// A zero-area triangle is no exception (N = 0 gives p = r = 0: not separating, as the book
// says exactly), nor is a flat box, a subnormal input or a triangle in a face's plane: the
// comparisons that tie there are decided as ties. Where an axis's values span more than 125
// bits, a difference or an extent needs more than 62 (a vertex 10^12 away from a box of size
// 0.1), or an input is not finite, `ok` is false and the next stage answers.
//
// The direction, where an axis separates: axis 0 N, axes 1-3 the unit vector, the others
// L = e_k x e_j; each nonzero component is an integer times 2^(G_a + G_b) (N) or 2^G_i (L),
// rounded to F once (scaled() below: subnormal results too). A component that overflows F
// leaves the direction to the caller (direction() returns false).
#pragma once

#include <bit>
#include <cdref/filters/grid.hpp>
#include <cdref/primitives.hpp>
#include <cmath>
#include <cstdint>
#include <limits>

namespace cdref::filters::sat_grid {

using grid::Wide;

struct TriangleBox {
  bool ok = false;  // the inputs lie on grids narrow enough
  int axis = -1;    // the first separating axis in the book's order; -1: they meet
  std::int64_t V[3][3] = {}, E[3][3] = {}, H[3] = {};
  int G[3] = {};
  Wide N[3] = {};

  TriangleBox(const Triangle<double>& t, const Box<double>& b) {
    for (int i = 0; i < 3; ++i) {
      const double x[5] = {t.vertex[0][i], t.vertex[1][i], t.vertex[2][i], b.center[i], b.extent[i]};
      Wide n[5];
      if (!grid::axis_on_grid(x, n, G[i], 125)) return;
      for (int k = 0; k < 3; ++k)
        if (!grid::narrow(n[k] - n[3], V[k][i]) || !grid::narrow(n[(k + 1) % 3] - n[k], E[k][i])) return;
      if (!grid::narrow(n[4], H[i])) return;
    }
    ok = true;
    axis = first_axis();
  }

  int first_axis() {
    // axis 0: N = e_0 x f, f = X_2 - X_0 = -e_2
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, l = (i + 2) % 3;
      N[i] = Wide(E[0][j]) * -E[2][l] - Wide(E[0][l]) * -E[2][j];
    }
    grid::Sum256 lo, hi;  // p - r, p + r
    for (int i = 0; i < 3; ++i) {
      const Wide a = N[i] < 0 ? -N[i] : N[i];
      lo.add(N[i], V[0][i]);
      lo.add(a, -H[i]);
      hi.add(N[i], V[0][i]);
      hi.add(a, H[i]);
    }
    if (lo.sign() > 0 || hi.sign() < 0) return 0;
    // axes 1-3: the triangle's bounding box against the box
    for (int i = 0; i < 3; ++i) {
      const std::int64_t mn = std::min(V[0][i], std::min(V[1][i], V[2][i]));
      const std::int64_t mx = std::max(V[0][i], std::max(V[1][i], V[2][i]));
      if (mn > H[i] || mx < -H[i]) return 1 + i;
    }
    // axes 4 + 3k + j: e_k x e_j has -+e_k on the two axes a = j + 1, b = j + 2:
    // (e_k x e_j)_a = e_k,b [a = j + 1], -e_k,a... written out: L_{j+1} = e_{j+2}, L_{j+2} = -e_{j+1}
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < 3; ++j) {
        const int a = (j + 1) % 3, bb = (j + 2) % 3;
        const std::int64_t La = E[k][bb], Lb = -E[k][a];
        const Wide p0 = Wide(V[k][a]) * La + Wide(V[k][bb]) * Lb;
        const Wide p1 = Wide(V[(k + 2) % 3][a]) * La + Wide(V[(k + 2) % 3][bb]) * Lb;
        const Wide r = Wide(H[a]) * (La < 0 ? -La : La) + Wide(H[bb]) * (Lb < 0 ? -Lb : Lb);
        const Wide mn = p0 < p1 ? p0 : p1, mx = p0 < p1 ? p1 : p0;
        if (mn > r || mx < -r) return 4 + 3 * k + j;
      }
    return -1;
  }

  // x 2^g in F, x an integer, rounded once to nearest (ties to even); false where it overflows.
  // Where the value is at least F's smallest normal number, F(x) rounds once (a conversion from an
  // integer is correctly rounded) and the power of two is exact; below it the integer is rounded
  // to the subnormal grid 2^(emin - p + 1) itself, so that nothing rounds twice.
  template <class F>
  static bool scaled(Wide x, int g, F& out) {
    using L = std::numeric_limits<F>;
    if (x == 0) {
      out = F(0);
      return true;
    }
    const grid::UWide m = x < 0 ? grid::UWide(-x) : grid::UWide(x);
    const int top = 127 - (m >> 64 ? std::countl_zero(std::uint64_t(m >> 64)) : 64 + std::countl_zero(std::uint64_t(m)));
    if (top + g >= L::min_exponent - 1) {  // |x| 2^g >= 2^(emin - 1) = F's smallest normal
      out = std::ldexp(F(x), g);
      return std::fabs(out) <= L::max();
    }
    const int lowest = L::min_exponent - L::digits;  // the subnormal grid 2^lowest
    const int shift = lowest - g;                    // > 0: x 2^g has bits below the grid
    if (shift <= 0) {  // on the grid already: |x| < 2^(digits - 1), exact
      out = std::ldexp(F(x), g);
      return true;
    }
    grid::UWide q = 0;
    if (shift < 128) {
      const grid::UWide rem = m & ((grid::UWide(1) << shift) - 1), half = grid::UWide(1) << (shift - 1);
      q = m >> shift;
      if (rem > half || (rem == half && (q & 1))) ++q;
    }  // else |x| < 2^127 <= half the grid step: 0
    out = std::ldexp(F(q), lowest);  // q <= 2^(digits - 1): exact
    if (x < 0) out = -out;
    return true;
  }

  // The separating axis's direction as the book gives it at an exact type, each component
  // rounded once to F; false where one overflows F (or no axis separates).
  template <class F>
  bool direction(Vec3<F>& d) const {
    if (axis < 0) return false;
    if (axis >= 1 && axis <= 3) {
      d = Vec3<F>(F(axis == 1), F(axis == 2), F(axis == 3));
      return true;
    }
    if (axis == 0) {
      for (int i = 0; i < 3; ++i)
        if (!scaled<F>(N[i], G[(i + 1) % 3] + G[(i + 2) % 3], d[i])) return false;
      return true;
    }
    const int k = (axis - 4) / 3, j = (axis - 4) % 3, a = (j + 1) % 3, bb = (j + 2) % 3;
    d[j] = F(0);
    return scaled<F>(Wide(E[k][bb]), G[bb], d[a]) && scaled<F>(-Wide(E[k][a]), G[a], d[bb]);
  }
};

// A segment or a ray and an axis-aligned box (book/segment_box.hpp: the box's three faces, then
// r x e_j), exactly on the grid: every value of an axis below 2^124 on its grid (a shot from
// 10^12 away toward a box of extents near 1 spans about 96 bits), so s - c, t - c and h are
// below 2^125. A segment: with M = s + t - 2c = 2m (below 2^126) and W = t - s = 2w (below
// 2^125), face i separates iff |M_i| > 2 H_i + |W_i| (128 bits), and r x e_j iff |P| > R with
// P = M_a W_b - M_b W_a and R = 2 (H_a |W_b| + H_b |W_a|), (a, b) = (j + 1, j + 2): four times
// the book's m_a w_b - m_b w_a and h_a |w_b| + h_b |w_a|. Every term takes one factor from axis
// a and one from b (scale 2^(G_a + G_b)), each product below 2^251, so |P| > R is taken as P - R
// > 0 or P + R < 0 in 256 bits (Sum256). A ray: m = s - c and the direction on grids of its own
// (grid.hpp, direction_on_grid: 2^(G_i + delta) on axis i, one delta for the three, each below
// 2^62), face i separates iff m_i > H_i and d_i >= 0 or m_i < -H_i and d_i <= 0, and r x e_j
// iff |m_a d_b - m_b d_a| > H_a |d_b| + H_b |d_a|: one factor from axis a and one from b in
// every term, each below 2^187, in 256 bits. The direction: e_i, or r x e_j with the components
// -+r_a, -+r_b (a segment's differences, rounded once; a ray's own, exact).
struct ShotBox {
  bool ok = false;
  int axis = -1;
  bool segment = false;
  Wide W[3] = {};  // a segment's t - s
  int G[3] = {};

  ShotBox(const Vec3<double>& src, const Vec3<double>& rt, const Box<double>& b, bool seg) : segment(seg) {
    Wide SC[3], TC[3], H[3];  // s - c, t - c, h: below 2^125
    for (int i = 0; i < 3; ++i) {
      const double x[4] = {src[i], seg ? rt[i] : src[i], b.center[i], b.extent[i]};
      Wide n[4];
      if (!grid::axis_on_grid(x, n, G[i], 124)) return;
      SC[i] = n[0] - n[2], TC[i] = n[1] - n[2], H[i] = n[3];
    }
    const auto abs = [](Wide x) { return x < 0 ? -x : x; };
    // every difference and extent below 2^62 (all but a shot from far away): the cheaper
    // products, 128 x 64 bits or 64 x 64, serve
    bool small = true;
    for (int i = 0; i < 3; ++i) {
      std::int64_t t;
      small = small && grid::narrow(SC[i], t) && grid::narrow(TC[i], t) && grid::narrow(H[i], t);
    }
    if (seg) {
      Wide M[3];  // below 2^126
      for (int i = 0; i < 3; ++i) {
        M[i] = SC[i] + TC[i];
        W[i] = TC[i] - SC[i];
      }
      ok = true;
      for (int i = 0; i < 3; ++i)
        if (abs(M[i]) > 2 * H[i] + abs(W[i])) {  // the right side below 2^126
          axis = i;
          return;
        }
      for (int j = 0; j < 3; ++j) {
        const int a = (j + 1) % 3, bb = (j + 2) % 3;
        grid::Sum256 lo, hi;  // P - R, P + R: four products below 2^251 each
        for (grid::Sum256* acc : {&lo, &hi}) {
          const int sgn = acc == &lo ? -1 : 1;
          if (small) {  // W below 2^63
            acc->add(M[a], std::int64_t(W[bb]));
            acc->add(-M[bb], std::int64_t(W[a]));
            acc->add(2 * H[a], std::int64_t(sgn * abs(W[bb])));
            acc->add(2 * H[bb], std::int64_t(sgn * abs(W[a])));
          } else {
            acc->add_product(M[a], W[bb]);
            acc->add_product(-M[bb], W[a]);
            acc->add_product(2 * H[a], sgn * abs(W[bb]));
            acc->add_product(2 * H[bb], sgn * abs(W[a]));
          }
        }
        if (lo.sign() > 0 || hi.sign() < 0) {
          axis = 3 + j;
          return;
        }
      }
    } else {
      std::int64_t d[3];
      if (!grid::direction_on_grid(rt, G, d)) return;
      ok = true;
      const Wide (&m)[3] = SC;
      for (int i = 0; i < 3; ++i)
        if ((m[i] > H[i] && d[i] >= 0) || (m[i] < -H[i] && d[i] <= 0)) {
          axis = i;
          return;
        }
      if (small) {  // each product below 2^124: P and R in 128 bits, from 64-bit factors
        std::int64_t m64[3], h64[3];
        for (int i = 0; i < 3; ++i) m64[i] = std::int64_t(m[i]), h64[i] = std::int64_t(H[i]);
        for (int j = 0; j < 3; ++j) {
          const int a = (j + 1) % 3, bb = (j + 2) % 3;
          const Wide P = Wide(m64[a]) * d[bb] - Wide(m64[bb]) * d[a];
          const Wide R = Wide(h64[a]) * (d[bb] < 0 ? -d[bb] : d[bb]) + Wide(h64[bb]) * (d[a] < 0 ? -d[a] : d[a]);
          if (abs(P) > R) {
            axis = 3 + j;
            return;
          }
        }
        return;
      }
      for (int j = 0; j < 3; ++j) {
        const int a = (j + 1) % 3, bb = (j + 2) % 3;
        grid::Sum256 lo, hi;  // P - R, P + R: four products below 2^188 each
        for (grid::Sum256* acc : {&lo, &hi}) {
          const std::int64_t sgn = acc == &lo ? -1 : 1;
          acc->add(m[a], d[bb]);
          acc->add(-m[bb], d[a]);
          acc->add(H[a], sgn * (d[bb] < 0 ? -d[bb] : d[bb]));
          acc->add(H[bb], sgn * (d[a] < 0 ? -d[a] : d[a]));
        }
        if (lo.sign() > 0 || hi.sign() < 0) {
          axis = 3 + j;
          return;
        }
      }
    }
  }
  // The separating axis's direction as the book gives it at an exact type, rounded once to F
  // (`dir`: a ray's direction, in F); false where a component overflows F or none separates.
  template <class F>
  bool direction(const Vec3<F>& dir, Vec3<F>& out) const {
    if (axis < 0) return false;
    if (axis < 3) {
      out = Vec3<F>(F(axis == 0), F(axis == 1), F(axis == 2));
      return true;
    }
    const int j = axis - 3, a = (j + 1) % 3, bb = (j + 2) % 3;
    out[j] = F(0);
    if (!segment) {
      out[a] = dir[bb];
      out[bb] = -dir[a];
      return true;
    }
    return TriangleBox::scaled<F>(W[bb], G[bb], out[a]) && TriangleBox::scaled<F>(-W[a], G[a], out[bb]);
  }
};

}  // namespace cdref::filters::sat_grid
