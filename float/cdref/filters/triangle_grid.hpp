// cdref/filters/triangle_grid.hpp - two triangles (book/triangle_triangle.hpp) exactly on
// integers, the inputs read as integers on a grid per coordinate axis (grid.hpp): a plane that
// separates them, and the whole answer where they lie in one plane. Where it decides it gives
// the book's answer at an exact type.
//
// With the six vertices of an axis as integers below 2^62 on its grid 2^G_i, the edges
// a_1 - a_0, a_2 - a_0 are below 2^63 and nA = (a_1 - a_0) x (a_2 - a_0) below 2^127 (each
// component takes one factor from each of the other two axes: scale 2^(G_j + G_l), exact in a
// signed 128-bit integer); dB_k = nA . (b_k - a_0) takes one factor from each axis (scale
// 2^(G_0 + G_1 + G_2)), each term below 2^190: Sum256. Then, in the book's order:
//   - a triangle of zero area (nA = 0 or nB = 0 exactly): left to the next stage (the book
//     takes it as the segment or point it spans);
//   - all dB_k of one strict sign, or all dA_k: a plane separates them (0);
//   - all dA_k = 0: coplanar, decided by Theorem 3.1 with the 17 axes. Over one plane the
//     normals and the edge crosses (parallel to the normal, or 0) give every point the same
//     projection and never separate; the side normal L = nA x e of edge e = a_j - a_i gives
//     L . (x - a_i) = ((e x (x - a_i)) . nA, and for x in the plane e x (x - a_i) = t nA, so
//     that value is t |nA|^2 while the component of e x (x - a_i) along a coordinate axis c with
//     nA_c != 0 is t nA_c: the projections on L are the 2-D orientations o(x) = (e x (x - a_i))_c
//     times one factor, the same for every x (and for B's side normals, nB parallel to nA). The
//     axis separates iff B's values all lie above max(0, o(a_k)) or all below min(0, o(a_k))
//     (A projects onto the edge's value 0 and the third vertex's), each o a degree-2 integer
//     below 2^127 (one factor from each of the two axes besides c). The pair meets iff none of
//     the six separates: intersect = coplanar = that, p = q = 0, as the book returns it;
//   - otherwise the planes cross: left to the next stage (the cut points divide). Where the
//     first stage's signs already show each plane crossed by the other triangle (or, for a
//     pair known to meet, a vertex of B certainly off A's plane or a bound not finite), on_grid
//     returns at once.
// An axis whose values span more than 62 bits, or a non-finite input, leaves the case to the
// next stage too.
#pragma once

#include <cdref/filters/grid.hpp>
#include <cdref/filters/triangle_filter.hpp>
#include <cdref/primitives.hpp>
#include <cstdint>

namespace cdref::filters::triangle_triangle {

// Every vertex of b within the first stage's bound of a's plane (triangle_filter.hpp), the
// bound finite: the pair may be coplanar (it is not otherwise).
inline bool maybe_coplanar(const Triangle<double>& a, const Triangle<double>& b) {
  bool finite = true;
  int s[3];
  plane_signs(a, b, s, finite);
  return finite && s[0] == 0 && s[1] == 0 && s[2] == 0;
}

// 0 apart, 1 coplanar and meeting, `unknown` otherwise. `meeting`: the caller knows they meet,
// and only a coplanar pair is of use.
inline int on_grid(const Triangle<double>& a, const Triangle<double>& b, bool meeting = false) {
  using grid::Wide;
  constexpr int undecided = unknown;
  // Where each plane certainly has vertices of the other triangle on both sides (the first
  // stage's signs and bounds, triangle_filter.hpp), no plane separates them and they are not
  // coplanar: nothing to decide here (about 30 ns against 120 for the integers). A coplanar
  // pair has every sign of B against A's plane uncertain there.
  bool finite = true;
  if (meeting) {
    if (!maybe_coplanar(a, b)) return undecided;
  } else if (plane_crosses(a, b, finite) && plane_crosses(b, a, finite) && finite) {
    return undecided;
  }
  std::int64_t A[3][3], B[3][3];  // [vertex][axis]
  for (int i = 0; i < 3; ++i) {
    const double x[6] = {a.vertex[0][i], a.vertex[1][i], a.vertex[2][i], b.vertex[0][i], b.vertex[1][i], b.vertex[2][i]};
    std::int64_t n[6];
    int g;
    if (!grid::axis_on_grid(x, n, g)) return undecided;
    for (int k = 0; k < 3; ++k) A[k][i] = n[k], B[k][i] = n[3 + k];
  }
  const auto normal = [](const std::int64_t (&P)[3][3], Wide (&n)[3]) {
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, l = (i + 2) % 3;
      n[i] = Wide(P[1][j] - P[0][j]) * (P[2][l] - P[0][l]) - Wide(P[1][l] - P[0][l]) * (P[2][j] - P[0][j]);
    }
    return n[0] != 0 || n[1] != 0 || n[2] != 0;
  };
  Wide nA[3], nB[3];
  if (!normal(A, nA) || !normal(B, nB)) return undecided;  // a zero-area triangle
  // the signs of n . (x_k - o) for the other triangle's vertices x_k
  const auto sides = [](const Wide (&n)[3], const std::int64_t (&o)[3], const std::int64_t (&X)[3][3], int (&s)[3]) {
    for (int k = 0; k < 3; ++k) {
      grid::Sum256 d;
      for (int i = 0; i < 3; ++i) d.add(n[i], X[k][i] - o[i]);
      s[k] = d.sign();
    }
  };
  const auto strict = [](const int (&s)[3]) {
    return (s[0] > 0 && s[1] > 0 && s[2] > 0) || (s[0] < 0 && s[1] < 0 && s[2] < 0);
  };
  int dB[3], dA[3];
  sides(nA, A[0], B, dB);
  if (strict(dB)) return 0;
  sides(nB, B[0], A, dA);
  if (strict(dA)) return 0;
  if (dA[0] != 0 || dA[1] != 0 || dA[2] != 0) return undecided;  // the planes cross
  int c = 0;  // a coordinate axis along which nA (and nB, parallel) has a nonzero component
  while (nA[c] == 0) ++c;
  const int x = (c + 1) % 3, y = (c + 2) % 3;
  // o(p, q, r) = ((q - p) x (r - p))_c
  const auto orient = [x, y](const std::int64_t (&p)[3], const std::int64_t (&q)[3], const std::int64_t (&r)[3]) {
    return Wide(q[x] - p[x]) * (r[y] - p[y]) - Wide(q[y] - p[y]) * (r[x] - p[x]);
  };
  // one triangle's three side normals against the other's vertices: true where one separates
  const auto separated = [&orient](const std::int64_t (&P)[3][3], const std::int64_t (&Q)[3][3]) {
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      const Wide third = orient(P[i], P[j], P[k]);
      const Wide lo = third < 0 ? third : 0, hi = third < 0 ? 0 : third;
      bool above = true, below = true;
      for (int m = 0; m < 3; ++m) {
        const Wide o = orient(P[i], P[j], Q[m]);
        above = above && o > hi;
        below = below && o < lo;
      }
      if (above || below) return true;
    }
    return false;
  };
  return separated(A, B) || separated(B, A) ? 0 : 1;
}

}  // namespace cdref::filters::triangle_triangle
