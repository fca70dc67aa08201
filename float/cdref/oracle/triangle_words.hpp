// cdref/oracle/triangle_words.hpp - the orientation form of a ray or segment cast on a triangle
// on double words: the second stage of the Section 3.4 cast oracles (exact/cdref/oracle/
// ray_triangle.hpp, and through it the polygon casts), and of the robust tier's certified
// decision on those casts (robust/ray_triangle.hpp), before the book's whole test on double words.
//
// The first stage (triangle_filter.hpp) takes the signs of the five triple products of the
// orientation form,
//   w0 = d . (B x C), w1 = d . (C x A), w2 = d . (A x B)   (A, B, C the vertices less the source s,
//                                                          d the direction, or t - s for a segment)
//   Ns = A . (e1 x e2), Nt = (v0 - t) . (e1 x e2)          (e1 = v1 - v0, e2 = v2 - v0),
// in double against static bounds, then exactly where the inputs lie on a coarse grid. A shot
// 2^-52 of an edge's length from the edge leaves that edge's w_k to neither: its value is about
// 2^-52 of its magnitude, below the static bound, and the inputs are general doubles. Here each
// sign the static bound leaves is taken on double words: A, B, C, d, e1, e2 and v0 - t are exact
// pairs (Two-Sum of two inputs; a ray's direction is an input), the cross product by cross_words
// and the dot product by dot_words (word_bounds.hpp derives both bounds: about u^2 of the
// magnitudes instead of 10u), and the sign is certain when the word's magnitude exceeds its bound.
// With every sign the test needs certain and nonzero, the book's test is decided as the first
// stage's exact look decides it (triangle_filter.hpp): w_k of opposite signs miss; otherwise D has
// the sign sD of the w_k, and the ray hits iff Ns is not -sD, the segment iff moreover Nt is not
// sD. An exact zero is never certain on words (a shot through an edge or a vertex, in the plane,
// from the plane): those go on to the next stages, which see exact zeros.
// Range: every input at most 2^100 after scaling (each triple product is of degree 3: no value
// overflows); where the largest input is beyond 2^100 or below 2^-100 every input is first scaled
// by the power of two that brings it to [1, 2) (robust/words.hpp, scale_of: exact, or not done),
// which multiplies each triple product by a positive power of two (a ray's direction is scaled
// too: each product is homogeneous of degree 3 in the scaled inputs).
#pragma once

#include <cdref/oracle/triangle_filter.hpp>
#include <cdref/oracle/word_bounds.hpp>
#include <cdref/robust/words.hpp>
#include <cmath>

namespace cdref::oracle::ray_triangle {

namespace words {

using robust::Pair;
using word_bounds::Word;

// The sign of a . (b x c) on exact pairs: 1, -1, or 0 when the bound does not decide it.
template <class Mul>
int triple_sign(const Pair<double> (&a)[3], const Pair<double> (&b)[3], const Pair<double> (&c)[3]) {
  static constexpr double zero[3] = {0, 0, 0};
  Word x[3];
  word_bounds::cross_words<Mul>(b, c, x);
  const int s = word_bounds::sign_of(word_bounds::dot_words<Mul>(a, zero, x));
  return s == staged::unknown ? 0 : s;
}

template <class Mul>
int decide(const Vec3<double>& s, const Vec3<double>* t, const Vec3<double>& dir, const Triangle<double>& tri) {
  Pair<double> A[3][3], d[3], e1[3], e2[3];
  double a[3][3], dd[3], f1[3], f2[3];  // the same in double, for the static signs
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 3; ++k) {
      A[k][i] = robust::two_sum(tri.vertex[k][i], -s[i]);
      a[k][i] = A[k][i].hi;
    }
    d[i] = t ? robust::two_sum((*t)[i], -s[i]) : Pair<double>{dir[i], 0.0};
    e1[i] = robust::two_sum(tri.vertex[1][i], -tri.vertex[0][i]);
    e2[i] = robust::two_sum(tri.vertex[2][i], -tri.vertex[0][i]);
    dd[i] = d[i].hi, f1[i] = e1[i].hi, f2[i] = e2[i].hi;
  }
  bool finite = true;
  int w[3];
  for (int k = 0; k < 3; ++k) {
    const int p = (k + 1) % 3, q = (k + 2) % 3;
    w[k] = ray_triangle::triple_sign(dd, a[p], a[q], finite);
    if (w[k] == 0) w[k] = triple_sign<Mul>(d, A[p], A[q]);
  }
  if (!finite) return unknown;
  const bool neg = w[0] < 0 || w[1] < 0 || w[2] < 0, pos = w[0] > 0 || w[1] > 0 || w[2] > 0;
  if (neg && pos) return 0;
  if (w[0] == 0 || w[1] == 0 || w[2] == 0) return unknown;
  const int sD = pos ? 1 : -1;
  int ns = ray_triangle::triple_sign(a[0], f1, f2, finite);
  if (ns == 0) ns = triple_sign<Mul>(A[0], e1, e2);
  if (!finite || ns == 0) return unknown;
  if (ns == -sD) return 0;  // lambda < 0
  if (t) {
    Pair<double> T0[3];
    double tt[3];
    for (int i = 0; i < 3; ++i) {
      T0[i] = robust::two_sum(tri.vertex[0][i], -(*t)[i]);
      tt[i] = T0[i].hi;
    }
    int nt = ray_triangle::triple_sign(tt, f1, f2, finite);
    if (nt == 0) nt = triple_sign<Mul>(T0, e1, e2);
    if (!finite || nt == 0) return unknown;
    if (nt == sD) return 0;  // lambda > 1
  }
  return 1;
}

}  // namespace words

// 1 a hit, 0 a miss, unknown (t: the segment's target, or nullptr for a ray along dir).
inline int orientation_on_words(const Vec3<double>& s0, const Vec3<double>* t0, const Vec3<double>& dir0,
                                const Triangle<double>& tri0) {
  double m = 0;
  robust::detail::largest(s0, m);
  robust::detail::largest(t0 ? *t0 : dir0, m);
  robust::detail::largest(tri0, m);
  robust::detail::Scale sc;
  if (!(m >= 0x1p-100 && m <= 0x1p100)) {
    sc = t0 ? robust::detail::scale_of(Segment<double>{s0, *t0}, tri0) : robust::detail::scale_of(Ray<double>{s0, dir0}, tri0);
  }
  const Vec3<double> s = sc.len(s0), dir = sc.len(dir0), tt = t0 ? sc.len(*t0) : dir;
  const Triangle<double> tri = robust::detail::scaled(tri0, sc);
  double big = 0;
  robust::detail::largest(s, big);
  robust::detail::largest(tt, big);
  robust::detail::largest(tri, big);
  if (!(big <= 0x1p100)) return unknown;  // NaN and infinities too
  const Vec3<double>* t = t0 ? &tt : nullptr;
  return robust::with_products([&](auto mul) { return words::decide<decltype(mul)>(s, t, dir, tri); });
}

}  // namespace cdref::oracle::ray_triangle
