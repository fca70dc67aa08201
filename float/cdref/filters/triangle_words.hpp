// cdref/filters/triangle_words.hpp - the orientation form of a ray or segment cast on a triangle
// on double words: the second stage of the Section 3.4 cast oracles (exact/cdref/oracle/
// ray_triangle.hpp, and through it the polygon casts), and of the robust tier's certified
// decision on those casts (robust/ray_triangle.hpp), before the book's whole test on double words.
// Below it, a sphere and a triangle: the first stage's two certificates on double words; and
// two triangles: the first stage's plane and edge tests with these signs.
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

#include <cdref/filters/triangle_filter.hpp>
#include <cdref/bounded/word_bounds.hpp>
#include <cmath>

namespace cdref::filters::ray_triangle {

namespace words {

using eft::Pair;
using word_bounds::Word;

// The sign of a . (b x c) on exact pairs: 1, -1, or 0 when the bound does not decide it.
template <class Mul>
int triple_sign(const Pair<double> (&a)[3], const Pair<double> (&b)[3], const Pair<double> (&c)[3]) {
  static constexpr double zero[3] = {0, 0, 0};
  Word x[3];
  word_bounds::cross_words<Mul>(b, c, x);
  const int s = word_bounds::sign_of(word_bounds::dot_words<Mul>(a, zero, x));
  return s == word_bounds::unknown ? 0 : s;
}

template <class Mul>
int decide(const Vec3<double>& s, const Vec3<double>* t, const Vec3<double>& dir, const Triangle<double>& tri) {
  Pair<double> A[3][3], d[3], e1[3], e2[3];
  double a[3][3], dd[3], f1[3], f2[3];  // the same in double, for the static signs
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 3; ++k) {
      A[k][i] = eft::two_sum(tri.vertex[k][i], -s[i]);
      a[k][i] = A[k][i].hi;
    }
    d[i] = t ? eft::two_sum((*t)[i], -s[i]) : Pair<double>{dir[i], 0.0};
    e1[i] = eft::two_sum(tri.vertex[1][i], -tri.vertex[0][i]);
    e2[i] = eft::two_sum(tri.vertex[2][i], -tri.vertex[0][i]);
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
      T0[i] = eft::two_sum(tri.vertex[0][i], -(*t)[i]);
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
  Triangle<double> tri;
  if (t0) {
    Segment<double> seg;
    if (!word_bounds::in_word_range(Segment<double>{s0, *t0}, tri0, seg, tri)) return unknown;
    return eft::with_products([&](auto mul) { return words::decide<decltype(mul)>(seg.source, &seg.target, seg.target, tri); });
  }
  Ray<double> ray;
  if (!word_bounds::in_word_range(Ray<double>{s0, dir0}, tri0, ray, tri)) return unknown;
  return eft::with_products([&](auto mul) { return words::decide<decltype(mul)>(ray.source, nullptr, ray.direction, tri); });
}

}  // namespace cdref::filters::ray_triangle

namespace cdref::filters::sphere_triangle {

// ---- A sphere and a triangle: the first stage's two certificates on double words ----------
// The first stage (triangle_filter.hpp) takes the book's closest point x = v0 + u e1 + v e2 in
// double, (u, v) clamped so that x lies in the triangle exactly, and w = x - c. They meet when
// |w| <= rho; they are disjoint along a direction g when min_k g . (v_k - c) > rho |g| (a linear
// function's minimum over the triangle is at a vertex). Near tangency its static bounds cannot
// tell, and here the same tests are taken on double words (word_bounds.hpp's bounds):
//   - they meet: the same x (its (u, v) are exact doubles), w_i = X0_i + u E1_i + v E2_i with
//     X0 = v0 - c, E1 = v1 - v0, E2 = v2 - v0 exact pairs and u E1_i, v E2_i two exact products
//     each; rho^2 - |w|^2 certainly > 0. x is the closest point up to the rounding of (u, v),
//     which moves |w| by the square of that (along the face or an edge): u^2 of it;
//   - disjoint: the direction must be the normal of the closest feature to about u^2, since the
//     test loses the tilt of g times the triangle's size, first order (with g = w the sphere-obb
//     case failed 13% of the time at 2^-52, sat_words.hpp). So g = w + du E1 + dv E2 with (du, dv)
//     one Gauss-Newton step for the free parameters of the closest feature (from the clamped
//     (u, v): the face when u, v > 0 and u + v < 1; an edge when one constraint holds: v0v1
//     (v = 0), v0v2 (u = 0), v1v2 (u + v = 1, along E2 - E1); a vertex has none), the gradient
//     E . w on double words and the 1x1 or 2x2 system in double (g needs no exactness: any
//     direction is a certificate); G = min_k g . X_k by dot_words (the minimum of words as in
//     sat_words.hpp), G certainly > 0 and G^2 - rho^2 |g|^2 certainly > 0.
// Range and scaling as for the casts (|w|^2, rho^2 and G are homogeneous of degree 2 in the
// lengths; every input at most 2^100 after it).
namespace words {

using eft::Pair;
using word_bounds::Word;

template <class Mul>
int certificates(const Sphere<double>& sp, const Triangle<double>& t) {
  using namespace word_bounds;
  static constexpr double zero[3] = {0, 0, 0};
  Pair<double> X[3][3], E1[3], E2[3];
  double Xd[3][3];
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 3; ++i) {
      X[k][i] = eft::two_sum(t.vertex[k][i], -sp.center[i]);
      Xd[k][i] = X[k][i].hi;
    }
  for (int i = 0; i < 3; ++i) {
    E1[i] = eft::two_sum(t.vertex[1][i], -t.vertex[0][i]);
    E2[i] = eft::two_sum(t.vertex[2][i], -t.vertex[0][i]);
  }
  double u, v;
  closest_barycentric(Xd, u, v);
  if (!(u >= 0)) u = 0;  // clamped as the first stage clamps them (triangle_filter.hpp)
  if (!(u <= 1)) u = 1;
  const double r0 = 1 - u, r0_err = -u - (r0 - 1);
  const double room = std::bit_cast<double>(std::bit_cast<std::uint64_t>(r0) - std::uint64_t(r0_err < 0));
  if (!(v >= 0)) v = 0;
  if (!(v <= room)) v = room;
  // w = X0 + u E1 + v E2
  const auto along = [](Word acc, double f, const Pair<double>& e) {
    if (f == 0) return acc;
    acc = add_words(acc, {Mul::prod(f, e.hi), 0}, 1);
    return e.lo == 0 ? acc : add_words(acc, {Mul::prod(f, e.lo), 0}, 1);
  };
  Word w[3], ww{{0, 0}, 0};
  for (int i = 0; i < 3; ++i) {
    w[i] = along(along(Word{X[0][i], 0}, u, E1[i]), v, E2[i]);
    ww = add_words(ww, mul_words<Mul>(w[i], w[i]), 1);
  }
  const Word rr{Mul::prod(sp.radius, sp.radius), 0};
  if (sign_of(add_words(rr, ww, -1)) == 1) return 1;
  // disjoint along g: one step for the closest feature's free parameters
  const bool on_u0 = u == 0, on_v0 = v == 0, on_sum = v == room && u + v == 1;
  const int constraints = int(on_u0) + int(on_v0) + int(on_sum);
  double a1[3], a2[3];
  for (int i = 0; i < 3; ++i) a1[i] = E1[i].hi, a2[i] = E2[i].hi;
  const auto dotd = [](const double (&p)[3], const double (&q)[3]) { return p[0] * q[0] + p[1] * q[1] + p[2] * q[2]; };
  double du = 0, dv = 0;
  if (constraints == 0) {  // the face: the 2x2 normal equations
    const double g1 = dot_words<Mul>(E1, zero, w).v.hi, g2 = dot_words<Mul>(E2, zero, w).v.hi;
    const double h11 = dotd(a1, a1), h12 = dotd(a1, a2), h22 = dotd(a2, a2), det = h11 * h22 - h12 * h12;
    if (det > 0) {
      du = (-g1 * h22 + g2 * h12) / det;
      dv = (-g2 * h11 + g1 * h12) / det;
    }
  } else if (constraints == 1) {  // an edge: one parameter along it
    if (on_v0) {
      const double h = dotd(a1, a1);
      if (h > 0) du = -dot_words<Mul>(E1, zero, w).v.hi / h;
    } else if (on_u0) {
      const double h = dotd(a2, a2);
      if (h > 0) dv = -dot_words<Mul>(E2, zero, w).v.hi / h;
    } else {  // v1v2: u = 1 - s, v = s, direction E2 - E1
      double e[3];
      for (int i = 0; i < 3; ++i) e[i] = a2[i] - a1[i];
      const double h = dotd(e, e);
      if (h > 0) {
        const double gs = dot_words<Mul>(E2, zero, w).v.hi - dot_words<Mul>(E1, zero, w).v.hi;
        dv = -gs / h;
        du = -dv;
      }
    }
  }
  if (!std::isfinite(du) || !std::isfinite(dv)) return unknown;
  Word g[3], gg{{0, 0}, 0};
  for (int i = 0; i < 3; ++i) {
    g[i] = along(along(w[i], du, E1[i]), dv, E2[i]);
    g[i].e = 0;  // g is a direction of our choosing: its value hi + lo is exact
  }
  for (int i = 0; i < 3; ++i) gg = add_words(gg, mul_words<Mul>(g[i], g[i]), 1);
  Word G = dot_words<Mul>(X[0], zero, g);
  for (int k = 1; k < 3; ++k) {
    const Word x = dot_words<Mul>(X[k], zero, g);
    G = min_word(G, x);
  }
  if (sign_of(G) == 1 && sign_of(add_words(mul_words<Mul>(G, G), mul_words<Mul>(rr, gg), -1)) == 1) return 0;
  return unknown;
}

}  // namespace words

// 1 they meet, 0 disjoint, unknown.
inline int certificates_on_words(const Sphere<double>& sp, const Triangle<double>& t0) {
  Sphere<double> s;
  Triangle<double> t;
  if (!word_bounds::in_word_range(sp, t0, s, t)) return unknown;
  return eft::with_products<true>([&](auto mul) { return words::certificates<decltype(mul)>(s, t); });
}

}  // namespace cdref::filters::sphere_triangle

namespace cdref::filters::triangle_triangle {

// ---- Two triangles: the first stage's tests with the signs on double words ----------------
// The first stage (triangle_filter.hpp) proves two triangles disjoint when one's vertices lie
// strictly on one side of the other's plane, met when an edge of one meets the other (a segment
// cast), and disjoint when none of the six edges does (two closed triangles that meet, coplanar or
// not, have a common point on an edge of one of them: their intersection is convex and compact,
// and an extreme point of it lies on a boundary). Here the same tests, each sign the static bounds
// leave taken on double words: a vertex's side of a plane as the triple product (x - v0) . (e1 x
// e2) on exact pairs (words::triple_sign above), and each edge cast by the orientation form on
// double words (ray_triangle::orientation_on_words). An exact zero is left to the next stages (a
// vertex on the other's plane, an edge through an edge or a vertex, coplanar triangles).
namespace words {

// The sides of q's vertices against p's plane, certain (1 or -1) or 0 (static bound, then words).
template <class Mul>
bool plane_separates(const Triangle<double>& p, const Triangle<double>& q, bool& finite) {
  using eft::Pair;
  Pair<double> e1[3], e2[3];
  double f1[3], f2[3];
  for (int i = 0; i < 3; ++i) {
    e1[i] = eft::two_sum(p.vertex[1][i], -p.vertex[0][i]);
    e2[i] = eft::two_sum(p.vertex[2][i], -p.vertex[0][i]);
    f1[i] = e1[i].hi, f2[i] = e2[i].hi;
  }
  int first = 0;
  for (int k = 0; k < 3; ++k) {
    Pair<double> x[3];
    double xd[3];
    for (int i = 0; i < 3; ++i) {
      x[i] = eft::two_sum(q.vertex[k][i], -p.vertex[0][i]);
      xd[i] = x[i].hi;
    }
    int sg = ray_triangle::triple_sign(xd, f1, f2, finite);
    if (sg == 0) sg = ray_triangle::words::triple_sign<Mul>(x, e1, e2);
    if (sg == 0 || (k > 0 && sg != first)) return false;
    first = sg;
  }
  return true;
}

// The first stage's segment cast from s to t on `other` (out of line: inlined into the fused-product
// copy, g++ 12 warns of an out-of-bounds read on the ray's path, which a segment never takes).
[[gnu::noinline]] inline int edge_filter(const Vec3<double>& s, const Vec3<double>& t, const Triangle<double>& other) {
  return ray_triangle::filter(s, &t, t, other);
}

template <class Mul>
int decide(const Triangle<double>& a, const Triangle<double>& b) {
  bool finite = true;
  if (plane_separates<Mul>(a, b, finite) || plane_separates<Mul>(b, a, finite)) return finite ? 0 : unknown;
  if (!finite) return unknown;
  bool open = false;
  for (const Triangle<double>* from : {&a, &b}) {
    const Triangle<double>& other = from == &a ? b : a;
    for (int k = 0; k < 3; ++k) {
      const Vec3<double>& s = from->vertex[k];
      const Vec3<double>& t = from->vertex[(k + 1) % 3];
      int r = edge_filter(s, t, other);
      if (r == unknown) r = ray_triangle::orientation_on_words(s, &t, t, other);
      if (r == 1) return 1;
      open = open || r != 0;
    }
  }
  return open ? unknown : 0;
}

}  // namespace words

// 1 they meet, 0 disjoint, unknown.
inline int tests_on_words(const Triangle<double>& a0, const Triangle<double>& b0) {
  Triangle<double> a, b;
  if (!word_bounds::in_word_range(a0, b0, a, b)) return unknown;
  return eft::with_products<true>([&](auto mul) { return words::decide<decltype(mul)>(a, b); });
}

// Two polygons: the pairs' first stage at once (triangle_filter.hpp, polygon_pairs) with each
// plane sign its static bound cannot tell taken on double words (words::triple_sign on exact
// pairs of the same differences). A polygon whose vertex lies 2^-52 of its size from the other's
// plane leaves that vertex's sign open against every fan triangle of the other, so no plane
// separates any pair and every pair's six edge casts run (about 70 at up to 8 vertices); with
// the sign on words, the planes separate every pair at once where the polygons are apart. The
// edge casts the static bound cannot tell are left, as in polygon_filter, to the pairs one by one.
// 1 they meet, 0 disjoint, unknown; *words (when given) set where a sign came from double words.
inline int polygon_on_words(const Polygon<double>& a, const Polygon<double>& b, bool* words = nullptr) {
  if (words) *words = false;
  Polygon<double> as, bs;  // far from 1 in magnitude, scaled by one power of two: no sign changes
  if (!word_bounds::in_word_range(a, b, as, bs)) return polygon_filter(a, b);
  return eft::with_products<true>([&](auto mul) {
    using Mul = decltype(mul);
    return polygon_pairs(a, b, [&](int w, int i, int k) {
      const Polygon<double>& p = w == 0 ? as : bs;
      const Polygon<double>& q = w == 0 ? bs : as;
      eft::Pair<double> e1[3], e2[3], x[3];
      for (int c = 0; c < 3; ++c) {
        e1[c] = eft::two_sum(p.vertex[i + 1][c], -p.vertex[0][c]);
        e2[c] = eft::two_sum(p.vertex[i + 2][c], -p.vertex[0][c]);
        x[c] = eft::two_sum(q.vertex[k][c], -p.vertex[0][c]);
      }
      const int sg = ray_triangle::words::triple_sign<Mul>(x, e1, e2);
      if (words && sg != 0) *words = true;
      return sg;
    });
  });
}

}  // namespace cdref::filters::triangle_triangle
