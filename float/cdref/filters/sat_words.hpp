// cdref/filters/sat_words.hpp - Theorem 3.1 on double words, on the axes the first stage left
// open: the second stage of the Section 3.3 classification oracle for a segment, a triangle or an
// oriented box against an axis-aligned or an oriented box (exact/cdref/oracle/separating_axes.hpp),
// and of the robust tier's certified decision on those pairs (robust/separating_axes.hpp).
//
// The first stage (sat_filter.hpp) tests every candidate axis in double against one static bound
// and, where it cannot decide, says which axes it left open: each other axis certainly does not
// separate. Near touching that is one axis of the 13 or 15 (a vertex near a face leaves that
// face's axis, an edge grazing an edge their cross; counted over 400 cases a query at 2^-52 on the
// near-touching and grazing families of triangle-box, triangle-obb and obb-obb: one open axis in
// every case the first stage did not decide). The pair is disjoint exactly when some axis
// separates, so the open axes decide it: one of them certainly separating makes it disjoint, all of
// them certainly not separating makes the shapes meet, and anything else is left to the double
// words of the whole formulation (robust/separating_axes.hpp), then to CGAL::Gmpq. Before this
// stage those ran on every case the first stage left open, a microsecond or more where one axis
// takes a tenth of it.
//
// On one axis the test is the first stage's (sat_filter.hpp): with coordinates relative to B's
// centre, B projects onto [-r_B, r_B], r_B = sum_k h_k |g_k . L|, and A onto [lo, hi] (the extremes
// of X . L over A's points; X_0 . L -+ sum_k h_k |a_k . L| for a box A), and L separates exactly
// when s = lo - r_B > 0 or s' = -r_B - hi > 0. The sign of each is invariant under a positive
// scaling of L, and a negative one swaps s and s', so L may be any nonzero multiple of the book's
// axis; it is the same polynomial in the inputs here: A's face normal (v_1 - v_0) x (v_2 - v_0) or
// a_j x a_k, B's face normal e_k or b_j x b_k, an edge cross e x g with e = v_{k+1} - v_k or a_k.
// Every quantity is then a double word with a rigorous bound on its distance from the exact value
// (word_bounds.hpp, which derives each operation's bound):
//   X = p - c_B and e = v_{k+1} - v_k   exact pairs (Two-Sum of two inputs);
//   L                                   cross_words of exact pairs (an input is the pair (x, 0));
//   x . L, g . L                        dot_words (x, g exact pairs);
//   |w|                                 the word or its negation: 1-Lipschitz, the bound unchanged;
//   h w                                 scale_word; sums and differences add_words;
//   min and max of two words            the one with the smaller (larger) value hi + lo, with the
//                                       larger of the two bounds (both are 1-Lipschitz in the
//                                       maximum norm, so the exact extreme lies within it).
// A sign is certain when |hi| - |lo| exceeds the bound (word_bounds::sign_of); an exact zero is
// never certain there, so an axis that is exactly zero (parallel edges the first stage could not
// prove parallel), or a pair exactly touching, is left to the next stages, which see exact zeros.
// Range: every input at most 2^100 in magnitude (each quantity is of degree at most 4 in them: no
// value overflows; NaN and infinities fail the test); below, the bounds' allowance for underflow
// (2^-1022 an operation) only widens them. Where the largest input is beyond 2^100 or below
// 2^-100, every length (points, centres, extents; not an oriented box's axes) is first scaled by
// the power of two that brings it to [1, 2) (robust/words.hpp, scale_of: kept only where scaling
// back gives the inputs again, so the scaling is exact). On every axis s and s' are then
// multiplied by a positive power of two (each is homogeneous in the lengths: of degree 1 on an
// oriented box's face axes, 2 on an edge cross, 3 on a triangle's normal), and their signs stay. A ray's half-infinite projection (the sign of d . L,
// exactly 0 on its own edge crosses) is not handled here: the casts on an oriented box have their
// own second stage first (box_cast_words.hpp, obb_cast_words), and a ray is left to the next stage.
#pragma once

#include <cdref/filters/sat_filter.hpp>
#include <cdref/bounded/word_bounds.hpp>
#include <cmath>

namespace cdref::filters::sat_words {

using eft::Pair;
using word_bounds::Word;
using word_bounds::abs_word;
using word_bounds::max_word;
using word_bounds::min_word;
using word_bounds::pair_less;

inline constexpr int unknown = sat::unknown;

// The shapes as exact pairs and inputs: A's points relative to B's centre (or a box A's centre),
// A's edges (differences of inputs, or a box's axes), the generators and half-extents of each.
struct Shapes {
  int n = 0;             // A's points (0 for a box A)
  int faces = 0, edges = 0;
  bool zonotope = false;  // A is a box
  bool b_aligned = true;  // B is axis-aligned
  Pair<double> X[3][3];   // A's points, or its centre
  Pair<double> edge[3][3];
  Pair<double> face_b[2][3];  // a triangle's two edges from v_0, for its normal
  Pair<double> ga[3][3], gb[3][3];
  double ha[3] = {}, hb[3] = {};
  bool ok = true;
};

inline Pair<double> input(double x) { return {x, 0.0}; }
inline void check_range(Shapes& s, double x) { s.ok = s.ok && std::fabs(x) <= 0x1p100; }
inline void relative(Shapes& s, Pair<double> (&X)[3], const Vec3<double>& p, const Vec3<double>& c) {
  for (int i = 0; i < 3; ++i) {
    check_range(s, p[i]);
    X[i] = eft::two_sum(p[i], -c[i]);
  }
}
inline void difference(Pair<double> (&e)[3], const Vec3<double>& p, const Vec3<double>& q) {
  for (int i = 0; i < 3; ++i) e[i] = eft::two_sum(p[i], -q[i]);
}

inline void set_b(Shapes& s, const Box<double>& b) {
  for (int k = 0; k < 3; ++k) {
    check_range(s, b.center[k]);
    check_range(s, b.extent[k]);
    s.hb[k] = b.extent[k];
    for (int i = 0; i < 3; ++i) s.gb[k][i] = input(i == k ? 1.0 : 0.0);
  }
}
inline void set_b(Shapes& s, const OrientedBox<double>& b) {
  s.b_aligned = false;
  for (int k = 0; k < 3; ++k) {
    check_range(s, b.center[k]);
    check_range(s, b.extent[k]);
    s.hb[k] = b.extent[k];
    for (int i = 0; i < 3; ++i) {
      check_range(s, b.axis[k][i]);
      s.gb[k][i] = input(b.axis[k][i]);
    }
  }
}
// (`edges` false: A's edges are left out, for a caller that looks at no edge axis)
inline void set_a(Shapes& s, const Segment<double>& seg, const Vec3<double>& c, bool edges) {
  s.n = 2;
  relative(s, s.X[0], seg.source, c);
  relative(s, s.X[1], seg.target, c);
  s.edges = 1;
  if (edges) difference(s.edge[0], seg.target, seg.source);
}
inline void set_a(Shapes& s, const Triangle<double>& t, const Vec3<double>& c, bool edges) {
  s.n = 3;
  for (int k = 0; k < 3; ++k) relative(s, s.X[k], t.vertex[k], c);
  s.faces = 1;
  s.edges = 3;
  if (edges) {
    for (int k = 0; k < 3; ++k) difference(s.edge[k], t.vertex[(k + 1) % 3], t.vertex[k]);
    for (int i = 0; i < 3; ++i) {  // v_1 - v_0 and v_2 - v_0 = -(v_0 - v_2): the same exact pairs
      s.face_b[0][i] = s.edge[0][i];
      s.face_b[1][i] = {-s.edge[2][i].hi, -s.edge[2][i].lo};
    }
  } else {
    difference(s.face_b[0], t.vertex[1], t.vertex[0]);
    difference(s.face_b[1], t.vertex[2], t.vertex[0]);
  }
}
inline void set_a(Shapes& s, const OrientedBox<double>& a, const Vec3<double>& c, bool) {
  s.zonotope = true;
  relative(s, s.X[0], a.center, c);
  s.faces = s.edges = 3;
  for (int k = 0; k < 3; ++k) {
    check_range(s, a.extent[k]);
    s.ha[k] = a.extent[k];
    for (int i = 0; i < 3; ++i) {
      check_range(s, a.axis[k][i]);
      s.ga[k][i] = s.edge[k][i] = input(a.axis[k][i]);
    }
  }
}

template <class A, class B>
Shapes shapes(const A& a, const B& b, bool edges = true) {
  Shapes s;
  set_b(s, b);
  set_a(s, a, b.center, edges);
  return s;
}

// sum_k h_k |g_k . L| over the generators k not in `skip` (bit k): a generator orthogonal to L
// by an identity of exact values (L = g_j x g_k is orthogonal to g_j and g_k, an edge cross e x
// g_j to g_j) adds exactly zero, so it is left out. The words bound the exact sum either way.
template <class Mul>
Word radius(const Pair<double> (&g)[3][3], const double (&h)[3], const Word (&L)[3], unsigned skip = 0) {
  static constexpr double zero[3] = {0, 0, 0};
  Word r{{0, 0}, 0};
  for (int k = 0; k < 3; ++k)
    if (!((skip >> k) & 1u))
      r = word_bounds::add_words(r, word_bounds::scale_word<Mul>(abs_word(word_bounds::dot_words<Mul>(g[k], zero, L)), h[k]), 1);
  return r;
}
// The same for the coordinate axes as generators (an axis-aligned box): g_k . L = L_k.
template <class Mul>
Word aligned_radius(const double (&h)[3], const Word (&L)[3]) {
  Word r = word_bounds::scale_word<Mul>(abs_word(L[0]), h[0]);
  for (int k = 1; k < 3; ++k) r = word_bounds::add_words(r, word_bounds::scale_word<Mul>(abs_word(L[k]), h[k]), 1);
  return r;
}

// On axis `index` in the book's order (A's faces, B's faces, A's edges x B's generators): s1 = lo -
// r_B and s2 = -r_B - hi as words, each within its bound of the exact value. Only what the exact
// axis makes nonzero is evaluated (each omission an identity of the exact values, so the bounds
// still hold for the exact s1, s2):
//   B's face k of an axis-aligned box   L = e_k: r_B = h_k, x . L = x_k (exact pairs);
//   B's face k of an oriented box       r_B = h_k |b_k . L| (b_k+1, b_k+2 orthogonal to L);
//   A's face (a triangle)               its three vertices project alike: v_0 alone;
//   A's face k (a box)                  r_A = h_k |a_k . L|;
//   an edge e x g_j                     g_j . L = 0 in r_B; a triangle's edge (v_e, v_e+1)
//                                       projects as one point, a segment as one, a box's edge
//                                       generator a_e leaves r_A.
template <class Mul>
void axis_words(const Shapes& s, int index, Word& s1, Word& s2) {
  static constexpr double zero[3] = {0, 0, 0};
  Word L[3];
  unsigned skip_b = 0, skip_a = 0;  // generators orthogonal to L
  int first = 0, count = s.n;       // the points of A that can differ along L
  if (index < s.faces) {
    if (s.zonotope) {
      word_bounds::cross_words<Mul>(s.ga[(index + 1) % 3], s.ga[(index + 2) % 3], L);
      skip_a = 7u & ~(1u << index);
    } else {
      word_bounds::cross_words<Mul>(s.face_b[0], s.face_b[1], L);
      count = 1;
    }
  } else if (index < s.faces + 3) {
    const int k = index - s.faces;
    if (s.b_aligned) {
      const Word rb{{s.hb[k], 0}, 0};
      Word lo, hi;
      if (s.zonotope) {
        Word ra{{0, 0}, 0};
        for (int i = 0; i < 3; ++i)
          ra = word_bounds::add_words(ra, word_bounds::scale_word<Mul>(abs_word({s.ga[i][k], 0}), s.ha[i]), 1);
        const Word c{s.X[0][k], 0};
        lo = word_bounds::add_words(c, ra, -1);
        hi = word_bounds::add_words(c, ra, 1);
      } else {
        lo = hi = {s.X[0][k], 0};
        for (int p = 1; p < s.n; ++p) {
          const Word x{s.X[p][k], 0};
          lo = min_word(lo, x);
          hi = max_word(hi, x);
        }
      }
      s1 = word_bounds::add_words(lo, rb, -1);
      s2 = word_bounds::add_words(word_bounds::negated(rb), hi, -1);
      return;
    }
    word_bounds::cross_words<Mul>(s.gb[(k + 1) % 3], s.gb[(k + 2) % 3], L);
    skip_b = 7u & ~(1u << k);
  } else {
    const int e = (index - s.faces - 3) / 3, j = (index - s.faces - 3) % 3;
    word_bounds::cross_words<Mul>(s.edge[e], s.gb[j], L);
    skip_b = 1u << j;
    if (s.zonotope) skip_a = 1u << e;
    else if (s.n == 3) first = e + 1, count = 2;  // v_e+1 stands for v_e, then v_e+2
    else count = 1;                               // a segment: its one edge
  }
  const Word rb = s.b_aligned ? aligned_radius<Mul>(s.hb, L) : radius<Mul>(s.gb, s.hb, L, skip_b);
  Word lo, hi;
  if (s.zonotope) {
    const Word c = word_bounds::dot_words<Mul>(s.X[0], zero, L), ra = radius<Mul>(s.ga, s.ha, L, skip_a);
    lo = word_bounds::add_words(c, ra, -1);
    hi = word_bounds::add_words(c, ra, 1);
  } else {
    lo = hi = word_bounds::dot_words<Mul>(s.X[first % s.n], zero, L);
    for (int p = 1; p < count; ++p) {
      const Word x = word_bounds::dot_words<Mul>(s.X[(first + p) % s.n], zero, L);
      lo = min_word(lo, x);
      hi = max_word(hi, x);
    }
  }
  s1 = word_bounds::add_words(lo, rb, -1);
  s2 = word_bounds::add_words(word_bounds::negated(rb), hi, -1);
}

// 1 axis `index` certainly separates, 0 it certainly does not, unknown.
template <class Mul>
int axis_on_words(const Shapes& s, int index) {
  Word w1, w2;
  axis_words<Mul>(s, index, w1, w2);
  const int s1 = word_bounds::sign_of(w1), s2 = word_bounds::sign_of(w2);
  if (s1 == 1 || s2 == 1) return 1;
  if (s1 == -1 && s2 == -1) return 0;
  return unknown;
}

template <class Mul>
int decide_open(const Shapes& s, unsigned open) {
  bool undecided = false;
  for (int i = 0; open >> i; ++i) {
    if (!((open >> i) & 1u)) continue;
    const int t = axis_on_words<Mul>(s, i);
    if (t == 1) return 0;
    undecided = undecided || t == unknown;
  }
  return undecided ? unknown : 1;
}

// 1 they meet, 0 disjoint, unknown; `open` as sat::filter leaves it (0: nothing to go on).
template <class A, class B>
int decide(const A& a, const B& b, unsigned open) {
  if constexpr (std::is_same_v<A, Ray<double>>) {
    return unknown;
  } else {
    if (open == 0) return unknown;
    A as;  // far from 1 in magnitude, both shapes scaled by one power of two (header)
    B bs;
    if (!word_bounds::in_word_range(a, b, as, bs)) return unknown;
    // A's edges only where an edge axis is open (they follow A's faces and B's three)
    constexpr int a_faces = std::is_same_v<A, Triangle<double>> ? 1 : std::is_same_v<A, OrientedBox<double>> ? 3 : 0;
    const Shapes s = shapes(as, bs, (open >> (a_faces + 3)) != 0);
    if (!s.ok) return unknown;
    return eft::with_products([&](auto mul) { return decide_open<decltype(mul)>(s, open); });
  }
}

// ---- A sphere and an oriented box: the first stage's two certificates on double words ----
// The first stage (sat_filter.hpp, sphere_obb::filter) takes a point x = c + sum_i g_i a_i of the
// box (|g_i| <= h_i exactly, so x lies in it) and the direction v = q - x. They meet when |q - x|
// <= rho; they are disjoint when G = v . (q - c) - sum_i h_i |v . a_i| > rho |v| (every point p of
// the box has v . (p - c) <= sum_i h_i |v . a_i|, every point y of the sphere v . (y - c) >= v .
// (q - c) - rho |v|). It checks both against static bounds, too wide near tangency. Here both are
// evaluated on double words, with x and v made accurate enough for cases 2^-52 from tangency:
//   - x: g_i = clamp(a_i . d~, -h_i, h_i) in double (d~ = fl(q - c)), then each free coordinate
//     (|g_i| < h_i) corrected once, g_i + a_i . w as a double word clamped again. The axes are
//     orthonormal to about u, so that step (Jacobi's for the Gram system of the free axes) leaves
//     x off the closest point by about u^2 along the face instead of u. |q - x| moves by the
//     square of that; but the disjoint test loses h_i |v . a_i| on each free axis, first order in
//     the tilt of v: with x off by u it failed on 13% of the near-touching cases at 2^-52;
//   - w_c = d_c - sum_i g_i a_ic    d = q - c an exact pair (Two-Sum), sum_i g_i a_ic by
//     dot_words (g_i exact pairs, the axes exact), then add_words;
//   - they meet: rho^2 - |w|^2 certainly > 0 (rho^2 an exact product; an exact touch is left to
//     the next stage);
//   - disjoint along v = w's values hi + lo (any vector is a direction: v is exact as a pair):
//     G = d . v - sum_i h_i |a_i . v| by dot_words, |.| and scale_word, G certainly > 0 and G^2 -
//     rho^2 |v|^2 certainly > 0.
// Every bound is word_bounds.hpp's. Range and scaling as above: |w|^2, rho^2 and G are homogeneous
// of degree 2 in the lengths (v is a length), and every input must be at most 2^100 after it.
template <class Mul>
void sphere_obb_offset(const Pair<double> (&d)[3], const Pair<double> (&g)[3], const OrientedBox<double>& b, Word (&w)[3]) {
  using namespace word_bounds;
  static constexpr double exact[3] = {0, 0, 0};
  for (int c = 0; c < 3; ++c) {
    const Word column[3] = {{input(b.axis[0][c]), 0}, {input(b.axis[1][c]), 0}, {input(b.axis[2][c]), 0}};
    w[c] = add_words({d[c], 0}, dot_words<Mul>(g, exact, column), -1);
  }
}

// The point x's coordinates g_i (exact pairs, |g_i| <= h_i) and w = q - x on double words.
template <class Mul>
void sphere_obb_point(const Sphere<double>& sp, const OrientedBox<double>& b, Pair<double> (&d)[3], Pair<double> (&g)[3],
                      Word (&w)[3]) {
  using namespace word_bounds;
  static constexpr double zero[3] = {0, 0, 0};
  Pair<double> a[3][3];
  bool free_axis[3];
  for (int c = 0; c < 3; ++c) {
    d[c] = eft::two_sum(sp.center[c], -b.center[c]);
    for (int i = 0; i < 3; ++i) a[i][c] = input(b.axis[i][c]);
  }
  for (int i = 0; i < 3; ++i) {
    const double p = b.axis[i][0] * d[0].hi + b.axis[i][1] * d[1].hi + b.axis[i][2] * d[2].hi;
    const double h = b.extent[i];
    g[i] = {p < -h ? -h : (p > h ? h : p), 0.0};  // (no NaN: the range test has passed)
    free_axis[i] = std::fabs(g[i].hi) < h;
  }
  sphere_obb_offset<Mul>(d, g, b, w);
  if (free_axis[0] || free_axis[1] || free_axis[2]) {
    Pair<double> g1[3];
    for (int i = 0; i < 3; ++i) {
      g1[i] = g[i];
      if (!free_axis[i]) continue;
      const Word step = dot_words<Mul>(a[i], zero, w);
      const Pair<double> t = eft::two_sum(g[i].hi, step.v.hi), h{b.extent[i], 0}, mh{-b.extent[i], 0};
      g1[i] = pair_less(h, t) ? h : (pair_less(t, mh) ? mh : t);
    }
    sphere_obb_offset<Mul>(d, g1, b, w);
    for (int i = 0; i < 3; ++i) g[i] = g1[i];
  }
}

template <class Mul>
int sphere_obb_certificates(const Sphere<double>& sp, const OrientedBox<double>& b) {
  using namespace word_bounds;
  static constexpr double zero[3] = {0, 0, 0};
  Pair<double> d[3], g[3], a[3][3];
  Word w[3];
  sphere_obb_point<Mul>(sp, b, d, g, w);
  for (int i = 0; i < 3; ++i)
    for (int c = 0; c < 3; ++c) a[i][c] = input(b.axis[i][c]);
  Word ww{{0, 0}, 0};
  for (int c = 0; c < 3; ++c) ww = add_words(ww, mul_words<Mul>(w[c], w[c]), 1);
  const Word rr{Mul::prod(sp.radius, sp.radius), 0};
  if (sign_of(add_words(rr, ww, -1)) == 1) return 1;
  // disjoint along v
  Word v[3], vv{{0, 0}, 0};
  for (int c = 0; c < 3; ++c) v[c] = {w[c].v, 0};
  for (int c = 0; c < 3; ++c) vv = add_words(vv, mul_words<Mul>(v[c], v[c]), 1);
  Word G = dot_words<Mul>(d, zero, v);
  for (int i = 0; i < 3; ++i) G = add_words(G, scale_word<Mul>(abs_word(dot_words<Mul>(a[i], zero, v)), b.extent[i]), -1);
  if (sign_of(G) == 1 && sign_of(add_words(mul_words<Mul>(G, G), mul_words<Mul>(rr, vv), -1)) == 1) return 0;
  return unknown;
}

// 1 they meet, 0 disjoint, unknown.
inline int decide(const Sphere<double>& sp, const OrientedBox<double>& b) {
  Sphere<double> s;
  OrientedBox<double> bs;
  if (!word_bounds::in_word_range(sp, b, s, bs)) return unknown;
  return eft::with_products([&](auto mul) { return sphere_obb_certificates<decltype(mul)>(s, bs); });
}

}  // namespace cdref::filters::sat_words
