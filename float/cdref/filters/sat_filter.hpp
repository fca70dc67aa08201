// cdref/filters/sat_filter.hpp - the first stage of the Section 3.3 classification oracle:
// every candidate separating axis of Theorem 3.1 evaluated in double against one static error
// bound for the whole query, and for a sphere and an oriented box two certificates from one
// point of the box; for a segment or a ray and an oriented box, Algorithm 3.3 in the box's
// face coordinates first (box_cast_filter.hpp), and for two oriented boxes Theorem 3.1 in A's
// face coordinates first (filter_face_coordinates below), these axes where those cannot
// decide. Plain double arithmetic on the query's inputs, so that both the oracle
// (exact/cdref/oracle/separating_axes.hpp: then the double words, then CGAL::Gmpq) and the
// robust tier's certified decisions (robust/separating_axes.hpp, at double) run it first:
// where it decides, its answer is the solid's at an exact type.
//
// ---- Stage 1 for separating axes: one static bound ----------------------------------------
// Coordinates are taken relative to the box B's centre: X = fl(p - c_B) for every point of A
// (one rounding, |X - X~| <= u |X~| / (1 - u)). Candidate axes L, in the book's order (A's
// faces, B's faces, A's edges x B's edges), are polynomials in exact inputs (box axes, e_i) and
// in such leaves: an oriented box's face normal a_j x a_k (2 roundings a component), a
// triangle's normal e_0 x (X_2 - X_0) and an edge cross e x g with e a difference of leaves
// (at most 4 roundings a component, counted along the evaluation tree as in the sphere and box
// queries' filters, oracle/sphere_sphere.hpp: K(leaf) <= 1, K(a +- b) = max + 1,
// K(a b) = K(a) + K(b) + 1). On each axis the test is
//   s = lo_A - r_B > 0  or  s' = -r_B - hi_A > 0   (B projects onto [-r_B, r_B]),
// with lo_A, hi_A the extremes of X . L (points), X_A . L -+ r_A (a box A), r = sum_k
// h_k |g_k . L|. Every s is then a sum of monomials each carrying at most K = 12 factors
// (1 + delta) (point term: 1 + 4 + 1 + 2 + 2; radius term: 4 + 1 + 2 + 1 + 2 + 2), so with
// s+ the sum of the monomials' absolute values |s~ - s| <= gamma_12 s+ (Higham 3.1, 3.3;
// min, max and |.| are 1-Lipschitz). And s+ <= (M_X + G_A + G_B) Lambda, where
//   Lambda >= max over candidate axes and components of L+_c (the component's own absolute
//            expansion): 1 for e_i; 2 m_A^2 for a_j x a_k (m_A = the largest |a_k,c|), and so
//            on for each kind below, with |e_c| <= 2 m_X for a difference of two points;
//   M_X    =  the largest |X|_1 over A's points (A's centre for a box A);
//   G      =  sum_k h_k |g_k|_1 over a box's generators (0 for points).
// The bound itself is computed in double from nonnegative terms (a few roundings each), so
// 13u (1 + 32u) (M_X + G_A + G_B) Lambda >= gamma_12 s+. Underflow: each of the at most 96
// operations of one s that underflows is off by at most 2^-1075: 96 * 2^-1074 more. No
// intermediate exceeds s+ (up to a factor 1 + 32u), so (M_X + G_A + G_B) Lambda <= 2^1000
// rules out overflow (a NaN or infinite input, or a magnitude beyond it, leaves the query to
// stage 2); a non-finite projection is never dropped by a min or a max.
// An axis that is exactly zero has s = 0: never certain to separate, as it should be (the
// book skips it); stage 1 proves an edge cross exactly zero when the edge and the box axis are
// exact inputs (or exact differences: their Two-Sum errors vanish) and both products of each
// component agree exactly (Two-Product by fma), and then skips it as certain.
// The ray's projection is half-infinite on the side where d . L > 0; d . L is exact 0 on the
// ray's own edge crosses (L = d x g); on a face of B its sign is certain when |d.L~| exceeds
// 7u |d|_1 Lambda (d exact, L with <= 2 roundings, dot product 3 more).
// A result is certain when an axis certainly separates and every earlier axis certainly does
// not (then its index is certain too), or when no axis can separate.
#pragma once

#include <algorithm>
#include <cdref/cdref.hpp>
#include <cmath>

#include "box_cast_filter.hpp"
#include "minmax.hpp"

namespace cdref::filters {

namespace sat {

inline constexpr int unknown = 2;
inline constexpr double u = 0x1p-53;

// A in coordinates relative to B's centre.
struct Shape {
  enum Kind { points, zonotope, ray };
  Kind kind = points;
  int n = 0;
  double X[3][3] = {};  // points, or the zonotope's centre, or the ray's source
  double g[3][3] = {};  // zonotope generators (exact inputs), or the ray's direction
  double h[3] = {};
  int faces = 0, edges = 0;
  double face[3][3] = {};
  double edge[3][3] = {};
  bool edge_exact[3] = {};  // the edge equals the exact difference of inputs (or is an input)
  double mx = 0;            // M_X
  double G = 0;
  double lambda_face = 0;   // bound on L+_c over A's faces
  double medge = 0;         // bound on |e_c| over A's edges (the leaves' expansion)
};
struct BoxB {
  bool aligned = false;  // g = the identity
  double g[3][3] = {};
  double h[3] = {};
  double face[3][3] = {};
  double G = 0, mb = 0, lambda_face = 0;
};

inline void cross(const double* a, const double* b, double* r) {
  r[0] = a[1] * b[2] - a[2] * b[1];
  r[1] = a[2] * b[0] - a[0] * b[2];
  r[2] = a[0] * b[1] - a[1] * b[0];
}
inline double dot(const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline double norm1(const double* a) { return std::fabs(a[0]) + std::fabs(a[1]) + std::fabs(a[2]); }
inline double maxabs(const double* a) { return std::max(std::fabs(a[0]), std::max(std::fabs(a[1]), std::fabs(a[2]))); }
// x - y, and whether it is exact (its Two-Sum error is zero)
inline double diff(double x, double y, bool& exact) {
  const double s = x - y, bv = s - x, av = s - bv;
  exact = exact && ((x - av) + (-y - bv)) == 0;
  return s;
}
// a x b is exactly zero (a, b exact values)
inline bool cross_exactly_zero(const double* a, const double* b) {
  for (int c = 0; c < 3; ++c) {
    const int i = (c + 1) % 3, j = (c + 2) % 3;
    const double p = a[i] * b[j], q = a[j] * b[i];
    if (p != q || std::fma(a[i], b[j], -p) != std::fma(a[j], b[i], -q)) return false;
  }
  return true;
}

inline BoxB box_b(const Box<double>& b) {
  BoxB r;
  r.aligned = true;
  for (int k = 0; k < 3; ++k) {
    r.g[k][k] = r.face[k][k] = 1;
    r.h[k] = b.extent[k];
    r.G += b.extent[k];
  }
  r.mb = 1;
  r.lambda_face = 1;
  return r;
}
inline BoxB box_b(const OrientedBox<double>& b) {
  BoxB r;
  for (int k = 0; k < 3; ++k) {
    for (int c = 0; c < 3; ++c) r.g[k][c] = b.axis[k][c];
    r.h[k] = b.extent[k];
    r.G += b.extent[k] * norm1(r.g[k]);
    r.mb = std::max(r.mb, maxabs(r.g[k]));
  }
  for (int k = 0; k < 3; ++k) cross(r.g[(k + 1) % 3], r.g[(k + 2) % 3], r.face[k]);
  r.lambda_face = 2 * r.mb * r.mb;
  return r;
}

inline void rel(const Vec3<double>& p, const Vec3<double>& c, double* X, bool& exact) {
  for (int i = 0; i < 3; ++i) X[i] = diff(p[i], c[i], exact);
}

inline Shape shape_a(const Segment<double>& s, const Vec3<double>& c) {
  Shape a;
  a.kind = Shape::points;
  a.n = 2;
  bool ex = true;
  rel(s.source, c, a.X[0], ex);
  rel(s.target, c, a.X[1], ex);
  a.edges = 1;
  for (int i = 0; i < 3; ++i) a.edge[0][i] = diff(a.X[1][i], a.X[0][i], ex);
  a.edge_exact[0] = ex;
  a.mx = std::max(norm1(a.X[0]), norm1(a.X[1]));
  a.medge = 2 * std::max(maxabs(a.X[0]), maxabs(a.X[1]));
  return a;
}
inline Shape shape_a(const Ray<double>& r, const Vec3<double>& c) {
  Shape a;
  a.kind = Shape::ray;
  a.n = 1;
  bool ex = true;
  rel(r.source, c, a.X[0], ex);
  for (int i = 0; i < 3; ++i) a.g[0][i] = a.edge[0][i] = r.direction[i];
  a.edges = 1;
  a.edge_exact[0] = true;
  a.mx = norm1(a.X[0]);
  a.medge = maxabs(a.g[0]);
  return a;
}
inline Shape shape_a(const Triangle<double>& t, const Vec3<double>& c) {
  Shape a;
  a.kind = Shape::points;
  a.n = 3;
  bool ex = true;
  for (int k = 0; k < 3; ++k) rel(t.vertex[k], c, a.X[k], ex);
  a.edges = 3;
  for (int k = 0; k < 3; ++k) {
    bool e = ex;
    for (int i = 0; i < 3; ++i) a.edge[k][i] = diff(a.X[(k + 1) % 3][i], a.X[k][i], e);
    a.edge_exact[k] = e;
  }
  double e2[3];
  for (int i = 0; i < 3; ++i) e2[i] = a.X[2][i] - a.X[0][i];
  a.faces = 1;
  cross(a.edge[0], e2, a.face[0]);
  double m = 0;
  for (int k = 0; k < 3; ++k) {
    a.mx = std::max(a.mx, norm1(a.X[k]));
    m = std::max(m, maxabs(a.X[k]));
  }
  a.medge = 2 * m;
  a.lambda_face = 2 * a.medge * a.medge;
  return a;
}
inline Shape shape_a(const OrientedBox<double>& b, const Vec3<double>& c) {
  Shape a;
  a.kind = Shape::zonotope;
  a.n = 3;
  bool ex = true;
  rel(b.center, c, a.X[0], ex);
  double m = 0;
  for (int k = 0; k < 3; ++k) {
    for (int i = 0; i < 3; ++i) a.g[k][i] = a.edge[k][i] = b.axis[k][i];
    a.h[k] = b.extent[k];
    a.G += b.extent[k] * norm1(a.g[k]);
    a.edge_exact[k] = true;
    m = std::max(m, maxabs(a.g[k]));
  }
  a.faces = a.edges = 3;
  for (int k = 0; k < 3; ++k) cross(a.g[(k + 1) % 3], a.g[(k + 2) % 3], a.face[k]);
  a.mx = norm1(a.X[0]);
  a.medge = m;
  a.lambda_face = 2 * m * m;
  return a;
}

// What the exact axis L makes zero or equal, left out of its test (the same identities as the
// double words', sat_words.hpp): the generators orthogonal to L (bit k of skip_a, skip_b: a
// face normal g_j x g_k is orthogonal to g_j and g_k, an edge cross e x g_j to g_j), and of A's
// points those whose exact projection another one repeats (a triangle's vertices on its own
// normal, an edge's two ends on its crosses): `count` points from `first` (cyclically). The
// static bound covers each value left, and the exact extremes are unchanged.
struct Exact {
  unsigned skip_a = 0, skip_b = 0;
  int first = 0, count = 0;  // count 0: every point
};

// 1: separated on L, 0: not, unknown. dir_bound: the bound on the ray's d . L (negative on
// the ray's own edge crosses, where d . L = 0 exactly).
inline int axis_test(const Shape& a, const BoxB& b, const double* L, double bound, double dir_bound, Exact ex = {}) {
  double rb = 0;
  if (b.aligned) {  // g_k = e_k: g_k . L = L_k (as the dot product gives it for finite L)
    rb = b.h[0] * std::fabs(L[0]) + b.h[1] * std::fabs(L[1]) + b.h[2] * std::fabs(L[2]);
  } else {
    for (int k = 0; k < 3; ++k)
      if (!((ex.skip_b >> k) & 1u)) rb += b.h[k] * std::fabs(dot(b.g[k], L));
  }
  double lo, hi;
  bool lo_inf = false, hi_inf = false;
  switch (a.kind) {
    case Shape::points: {
      const int count = ex.count ? ex.count : a.n;
      lo = hi = dot(a.X[ex.first % a.n], L);
      for (int k = 1; k < count; ++k) {
        const double x = dot(a.X[(ex.first + k) % a.n], L);
        if (!std::isfinite(x)) return unknown;  // std::min and std::max would drop a NaN
        lo = std::min(lo, x);
        hi = std::max(hi, x);
      }
      break;
    }
    case Shape::zonotope: {
      double ra = 0;
      for (int k = 0; k < 3; ++k)
        if (!((ex.skip_a >> k) & 1u)) ra += a.h[k] * std::fabs(dot(a.g[k], L));
      const double c = dot(a.X[0], L);
      lo = c - ra;
      hi = c + ra;
      break;
    }
    default: {  // ray: half-infinite where d . L > 0
      lo = hi = dot(a.X[0], L);
      if (dir_bound >= 0) {
        const double d = dot(a.g[0], L);
        if (d != 0 && !(std::fabs(d) > dir_bound)) return unknown;  // d . L = 0 is exact only for d~ = 0 and exact L
        if (d > 0) hi_inf = true;
        if (d < 0) lo_inf = true;
      }
      break;
    }
  }
  if (!std::isfinite(rb) || !std::isfinite(lo) || !std::isfinite(hi)) return unknown;
  if ((!lo_inf && lo - rb > bound) || (!hi_inf && -rb - hi > bound)) return 1;
  if ((lo_inf || lo - rb < -bound) && (hi_inf || -rb - hi < -bound)) return 0;
  return unknown;
}

// A triangle and an axis-aligned box, the classification alone: B's face axes first, as the
// book's own triangle-box test does, by the outcode signs of box_cast_filter.hpp (a point
// certainly beyond one plane of the box: |fl(fl(v_i - c_i) -+ h_i)| > 2u |fl(v_i - c_i)|), for the
// triangle's lowest and highest vertex on each axis (exact comparisons of inputs: the others
// lie between them). All three vertices beyond the same plane make that face's axis separate,
// so the exact test is disjoint too; only the index of the first separating axis could differ
// (A's face comes first in the book's order), so this runs where no index is asked for. Six
// such signs where the axes below set up one bound for all 13: most of a polygon's fan
// triangles that miss a box miss it so.
// (outcode_sign's certain 1 and -1 as values, the three axes combined with no branch: minima and
// maxima by value, as in triangle_filter.hpp)
inline bool apart_on_box_faces(const Triangle<double>& t, const Box<double>& b) {
  bool apart = false;
  for (int i = 0; i < 3; ++i) {
    const double x0 = t.vertex[0][i], x1 = t.vertex[1][i], x2 = t.vertex[2][i];
    const double lo = min_value(min_value(x0, x1), x2), hi = max_value(max_value(x0, x1), x2);
    const double c = b.center[i], h = b.extent[i];
    const double ql = lo - c, qh = hi - c, l = ql - h, m = qh + h;
    const bool above = (std::fabs(l) <= 0x1p1000) & (l > 0x1p-52 * std::fabs(ql));   // all above
    const bool below = (std::fabs(m) <= 0x1p1000) & (m < -0x1p-52 * std::fabs(qh));  // all below
    apart |= above | below;
  }
  return apart;
}

// Stage 1: 1 intersect, 0 disjoint, or unknown; *axis the first separating axis when it is
// certain too (else -2), -1 when they intersect. *open (when given) is 0 except where the answer
// is unknown after every axis was tested: then bit i is set for each axis i (in the book's order)
// left undecided, every other axis certainly does not separate, and the double words need look
// at these alone (sat_words.hpp).
template <class A, class B>
int filter(const A& a0, const B& b0, int* axis = nullptr, unsigned* open = nullptr) {
  if (open) *open = 0;
  const BoxB b = box_b(b0);
  const Shape a = shape_a(a0, b0.center);
  const double lambda = std::max({a.lambda_face, b.lambda_face, 2 * a.medge * b.mb});
  const double mag = (a.mx + a.G + b.G) * lambda;  // >= s+ for every axis, up to (1 + 32u)
  const double bound = 13 * u * (1 + 32 * u) * mag + 96 * 0x1p-1074;
  if (axis) *axis = -2;
  if (!(mag <= 0x1p1000)) return unknown;  // every intermediate is below s+: no overflow
  // the ray's d . L on B's faces: d exact, L with at most 2 roundings, the dot product 3 more
  const double dir_bound =
      a.kind == Shape::ray ? 6 * u * (1 + 32 * u) * (norm1(a.g[0]) * b.lambda_face) + 16 * 0x1p-1074 : -1;
  int index = 0;
  bool known_so_far = true, any_unknown = false;
  unsigned open_bits = 0;
  auto visit = [&](int t) {
    const int at = index++;
    if (t == 1) {
      if (axis && known_so_far) *axis = at;
      return true;
    }
    if (t == unknown) {
      known_so_far = false, any_unknown = true;
      open_bits |= 1u << at;
    }
    return false;
  };
  const bool zono = a.kind == Shape::zonotope;
  for (int k = 0; k < a.faces; ++k) {
    const Exact ex = zono ? Exact{7u & ~(1u << k), 0, 0, 0} : Exact{0, 0, 0, 1};  // a triangle: v_0 alone
    if (visit(axis_test(a, b, a.face[k], bound, dir_bound, ex))) return 0;
  }
  for (int k = 0; k < 3; ++k)
    if (visit(axis_test(a, b, b.face[k], bound, dir_bound, Exact{0, 7u & ~(1u << k), 0, 0}))) return 0;
  for (int i = 0; i < a.edges; ++i)
    for (int j = 0; j < 3; ++j) {
      double L[3];
      cross(a.edge[i], b.g[j], L);
      if (L[0] == 0 && L[1] == 0 && L[2] == 0 && a.edge_exact[i] && cross_exactly_zero(a.edge[i], b.g[j])) {
        visit(0);  // exactly zero: never separates
        continue;
      }
      // edge i of a triangle is (v_i, v_i+1): v_i+1 and v_i+2; of a segment, one end
      const Exact ex = zono ? Exact{1u << i, 1u << j, 0, 0}
                            : Exact{0, 1u << j, a.n == 3 ? i + 1 : 0, a.n == 3 ? 2 : 1};
      if (visit(axis_test(a, b, L, bound, a.kind == Shape::ray ? -1 : dir_bound, ex))) return 0;
    }
  if (any_unknown) {
    if (open) *open = open_bits;
    return unknown;
  }
  if (axis) *axis = -1;
  return 1;
}

// A segment or a ray and an oriented box: Algorithm 3.3 in the box's face coordinates first
// (box_cast_filter.hpp: a segment or a ray meets the box exactly when that cast hits), a few
// dozen operations where the axes above take six axis tests; the axes where it cannot decide
// (they recognise exact zeros: a shot along an edge or in a face plane of an axis-aligned frame,
// a box of zero extent, which no bound on the face coordinates decides).
template <class Shot>
int filter_shot_obb(const Shot& s, const OrientedBox<double>& b, int* axis, unsigned* open) {
  if (open) *open = 0;
  if (const int r = staged::filter(s, b); r != unknown) {
    if (axis) *axis = r == 1 ? -1 : -2;  // the first separating axis is not known here
    return r;
  }
  return filter<Shot, OrientedBox<double>>(s, b, axis, open);
}
inline int filter(const Segment<double>& s, const OrientedBox<double>& b, int* axis = nullptr, unsigned* open = nullptr) {
  return filter_shot_obb(s, b, axis, open);
}
inline int filter(const Ray<double>& ray, const OrientedBox<double>& b, int* axis = nullptr, unsigned* open = nullptr) {
  return filter_shot_obb(ray, b, axis, open);
}

// An oriented box's face normals n_i = a_{i+1} x a_{i+2} in double (2 roundings a component),
// and |a_0 . n_0| (|delta|: 5), for the face coordinates Y_i = n_i . (p - c) below.
template <class Axes>
double face_normals(const Axes& a, double (&n)[3][3]) {
  for (int i = 0; i < 3; ++i)
    for (int c = 0; c < 3; ++c) {
      const int c1 = (c + 1) % 3, c2 = (c + 2) % 3;
      n[i][c] = a[(i + 1) % 3][c1] * a[(i + 2) % 3][c2] - a[(i + 1) % 3][c2] * a[(i + 2) % 3][c1];
    }
  return std::fabs(a[0][0] * n[0][0] + a[0][1] * n[0][1] + a[0][2] * n[0][2]);
}

// ---- Stage 1 for two oriented boxes: Theorem 3.1 in A's face coordinates ----
// The map p -> Y = N_A (p - c_A) (rows n_i = a_{i+1} x a_{i+2}, as in box_cast_filter.hpp) is
// linear and invertible, so two boxes meet exactly when their images do, and Theorem 3.1 on
// the images (the faces and edges of each) decides that. There A is the axis-aligned box
// [-H, H] (H_i = h_i |delta_A|), and B is the parallelepiped about t = N_A (c_B - c_A) with
// generators G_k = h_k N_A b_k (the columns of G: G_ik = h_k n_i . b_k). The 15 axes and the
// test on each (separated iff s > 0, s = |t . L| - r_A - r_B; the exact identities
// G_j . (G_{j+1} x G_{j+2}) = 0 for the other columns give r_B in closed form):
//   e_i                 s = |t_i| - H_i - sum_k |G_ik|
//   L_j = G_{j+1} x G_{j+2}   s = |t . L_j| - sum_i H_i |L_ji| - |G_j . L_j|
//   e_i x G_k           s = |(G_k x t)_i| - H_{i+1} |G_{i+2,k}| - H_{i+2} |G_{i+1,k}|
//                             - |L_{k+1,i}| - |L_{k+2,i}|   (G_k x G_{k+1} = L_{k+2}, ...)
// Error bounds, counted as in box_cast_filter.hpp: n_i 2 roundings, delta 5, H 6, X = fl(c_B -
// c_A) 1, t 6, G 6, L 14; then s carries at most K = 10 (faces of A), 25 (faces of B) and 17
// (edges) on each monomial. With m_a, m_b the largest |a_kc|, |b_kc|, A2 = 2 m_a^2 and the
// static sums T = A2 |X|_1 (t), Hy = 6 m_a^3 max h_A (H), Gb = 3 A2 m_b max h_B (G; L: 2 Gb^2),
// the monomials' absolute values sum to at most S1 = T + Hy + 3 Gb, S2 = 6 Gb^2 (T + Hy + Gb)
// and S3 = 2 Gb (T + Hy + 2 Gb); the bounds (K + 1) u S cover gamma_K S with the roundings of
// S itself and |X| <= |X~| / (1 - u). Range: every static sum and m_a, m_b at most 2^100 (no
// value exceeds 2^310); a rounding that underflows is off by at most 2^-1075 and is carried
// through factors below 2^310, so 2^-600 added to every bound covers them all.
// An axis that is exactly zero (parallel edges) has s = 0 and leaves the filter undecided;
// sat::filter then runs the axes in world coordinates, which recognise exact zeros.
// *open (when given): where the answer is unknown, bit i set for each axis left undecided, in
// the book's order (A's faces e_i, B's faces L_j, then e_i x G_k for a_i x b_k): the same planes
// as the world axes (a linear map takes a plane spanned by two edge directions to the one
// spanned by their images, and scales each projection gap by one positive factor), so every
// other axis certainly does not separate in world coordinates either.
inline int filter_face_coordinates(const OrientedBox<double>& A, const OrientedBox<double>& B, unsigned* open = nullptr) {
  const auto& a = A.axis;
  const auto& b = B.axis;
  double n[3][3];
  const double D = face_normals(a, n);
  double ma = 0, mb = 0, ha = 0, hb = 0, X[3];
  for (int k = 0; k < 3; ++k) {
    ma = std::max(ma, maxabs(&a[k][0]));
    mb = std::max(mb, maxabs(&b[k][0]));
    ha = std::max(ha, A.extent[k]);
    hb = std::max(hb, B.extent[k]);
    X[k] = B.center[k] - A.center[k];
  }
  const double A2 = 2 * ma * ma, T = A2 * norm1(X), Hy = 3 * A2 * ma * ha, Gb = 3 * A2 * mb * hb;
  if (!(ma <= 0x1p100 && mb <= 0x1p100 && T <= 0x1p100 && Hy <= 0x1p100 && Gb <= 0x1p100)) return unknown;
  constexpr double floor = 0x1p-600;
  const double e1 = 11 * u * (T + Hy + 3 * Gb) + floor;
  const double e2 = 156 * u * (Gb * Gb) * (T + Hy + Gb) + floor;
  const double e3 = 36 * u * Gb * (T + Hy + 2 * Gb) + floor;
  double t[3], H[3], G[3][3];
  for (int i = 0; i < 3; ++i) {
    t[i] = dot(n[i], X);
    H[i] = A.extent[i] * D;
    for (int k = 0; k < 3; ++k) G[i][k] = (n[i][0] * b[k][0] + n[i][1] * b[k][1] + n[i][2] * b[k][2]) * B.extent[k];
  }
  bool undecided = false;
  unsigned bits = 0;
  int index = 0;
  auto separates = [&](double s, double e) {  // certainly separated; else notes an undecided axis
    const int at = index++;
    if (s > e) return true;
    if (!(s < -e)) undecided = true, bits |= 1u << at;
    return false;
  };
  for (int i = 0; i < 3; ++i)
    if (separates(std::fabs(t[i]) - (H[i] + (std::fabs(G[i][0]) + std::fabs(G[i][1]) + std::fabs(G[i][2]))), e1))
      return 0;
  double L[3][3];
  for (int j = 0; j < 3; ++j) {
    const int p = (j + 1) % 3, q = (j + 2) % 3;
    for (int c = 0; c < 3; ++c) {
      const int c1 = (c + 1) % 3, c2 = (c + 2) % 3;
      L[j][c] = G[c1][p] * G[c2][q] - G[c2][p] * G[c1][q];
    }
    const double tl = t[0] * L[j][0] + t[1] * L[j][1] + t[2] * L[j][2];
    const double ra = H[0] * std::fabs(L[j][0]) + H[1] * std::fabs(L[j][1]) + H[2] * std::fabs(L[j][2]);
    const double rb = std::fabs(G[0][j] * L[j][0] + G[1][j] * L[j][1] + G[2][j] * L[j][2]);
    if (separates(std::fabs(tl) - (ra + rb), e2)) return 0;
  }
  for (int i = 0; i < 3; ++i) {
    const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
    for (int k = 0; k < 3; ++k) {
      const double tt = G[i1][k] * t[i2] - G[i2][k] * t[i1];
      const double ra = H[i1] * std::fabs(G[i2][k]) + H[i2] * std::fabs(G[i1][k]);
      const double rb = std::fabs(L[(k + 1) % 3][i]) + std::fabs(L[(k + 2) % 3][i]);
      if (separates(std::fabs(tt) - (ra + rb), e3)) return 0;
    }
  }
  if (open && undecided) *open = bits;
  return undecided ? unknown : 1;
}
inline int filter(const OrientedBox<double>& A, const OrientedBox<double>& B, int* axis = nullptr,
                  unsigned* open = nullptr) {
  if (open) *open = 0;
  if (const int r = filter_face_coordinates(A, B); r != unknown) {
    if (axis) *axis = r == 1 ? -1 : -2;  // the first separating axis is not known here
    return r;
  }
  return filter<OrientedBox<double>, OrientedBox<double>>(A, B, axis, open);
}

// ---- Stage 1 for a triangle and a box: Theorem 3.1 in the box's face coordinates ----
// As for two oriented boxes above: the map p -> Y = N (p - c) (rows n_i = a_{i+1} x a_{i+2};
// for an axis-aligned box N = I) is linear and invertible (the axes are independent, decided
// exactly on input), takes the box to the axis-aligned [-H, H] (H_i = h_i |delta|, delta =
// det[a_0 a_1 a_2], since n_i . a_k = delta [i = k]) and the triangle to the one with vertices
// Y_k = N (v_k - c). Each of the 13 planes of Theorem 3.1 goes to the plane spanned by the
// images of the same two directions (the triangle's normal to f_0 x (Y_2 - Y_0), B's face
// a_{j+1} x a_{j+2} to e_j, the cross of edge e and a_j to f_e x e_j, f_e = Y_{e+1} - Y_e), and
// each projection gap s is multiplied by one positive factor, so an axis separates here exactly
// when it does in world coordinates, and the open axes are reported in the book's order (the
// triangle's normal, B's faces, then edge e x a_j at 4 + 3e + j). On [-H, H] the tests are:
//   e_i        s = max(min_k Y_ki - H_i, -H_i - max_k Y_ki)
//   normal m   s = |m . Y_0| - sum_i H_i |m_i|   (m = f_0 x (Y_2 - Y_0); m . Y_k is one value)
//   f_e x e_j  with q(Y) = Y_{j+1} f_{j+2} - Y_{j+2} f_{j+1} (Y_e and Y_{e+1} project alike):
//              s = max(min(q_{e+1}, q_{e+2}) - r, -r - max(q_{e+1}, q_{e+2})),
//              r = H_{j+1} |f_{j+2}| + H_{j+2} |f_{j+1}|
// Error bounds, counted as in the header (K roundings on every monomial, |s~ - s| <= gamma_K
// s+): Y carries dY roundings (X = fl(v - c) 1, n_i 2, the product 1, the sum of three 2: dY = 6;
// an axis-aligned box: dY = 1) and H dH (delta 5, the product 1: dH = 6; axis-aligned: H = h,
// dH = 0); then f has dY + 1, m dY + 3 and
//   e_i        K = max(dY, dH) + 1,     s+ <= Ty + Hy
//   normal     K = max(dY + 7, dH + 4), s+ <= 24 Ty^2 (Ty + Hy)
//   f_e x e_j  K = max(dY + 4, dH + 3), s+ <= 4 Ty (Ty + Hy)
// with the static sums Ty >= every Y_ki's monomials (2 m_a^2 max_k |X~_k|_1 / (1 - u) for an
// oriented box, m_a its largest |a_kc|; max_k |X~_k|_inf / (1 - u) for an axis-aligned one),
// Hy >= every H_i's (6 m_a^3 max h; max h). The bound (K + 1) u s+~ covers gamma_K s+ with the
// roundings of s+~ itself. Range and underflow as above: Ty, Hy at most 2^100 (no value exceeds
// 2^310), and 2^-600 added to every bound covers every rounding that underflows. An axis that is
// exactly zero (an edge parallel to a box axis: f_{j+1} = f_{j+2} = 0) has s = 0 and is left
// open, as is every axis of a zero-area triangle's normal; the double words and the world axes
// see exact zeros. 66 multiplications on [-H, H] and 51 for the map of an oriented box, where the
// world axes take several dot products an axis and a setup (a few hundred nanoseconds on cases near
// touching, where no test returns early).
inline int triangle_in_box_frame(const double (&Y)[3][3], const double (&H)[3], double Ty, double Hy, int dY, int dH,
                                 unsigned* open) {
  if (!(Ty <= 0x1p100 && Hy <= 0x1p100)) return unknown;
  constexpr double floor = 0x1p-600;
  const int kf = std::max(dY, dH) + 1, kn = std::max(dY + 7, dH + 4), ke = std::max(dY + 4, dH + 3);
  const double ef = (kf + 1) * u * (Ty + Hy) + floor;
  const double en = (kn + 1) * u * (24 * Ty * Ty * (Ty + Hy)) + floor;
  const double ee = (ke + 1) * u * (4 * Ty * (Ty + Hy)) + floor;
  bool undecided = false;
  unsigned bits = 0;
  auto separates = [&](double s, double e, int at) {  // certainly separated; else notes an undecided axis
    if (s > e) return true;
    if (!(s < -e)) undecided = true, bits |= 1u << at;
    return false;
  };
  // B's faces first (the cheapest; the order of the tests does not change the answer)
  for (int i = 0; i < 3; ++i) {
    const double lo = min_value(min_value(Y[0][i], Y[1][i]), Y[2][i]);
    const double hi = max_value(max_value(Y[0][i], Y[1][i]), Y[2][i]);
    if (separates(std::max(lo - H[i], -H[i] - hi), ef, 1 + i)) return 0;
  }
  double f[3][3];
  for (int e = 0; e < 3; ++e)
    for (int c = 0; c < 3; ++c) f[e][c] = Y[(e + 1) % 3][c] - Y[e][c];
  {
    double g[3], m[3];
    for (int c = 0; c < 3; ++c) g[c] = Y[2][c] - Y[0][c];
    cross(f[0], g, m);
    const double r = H[0] * std::fabs(m[0]) + H[1] * std::fabs(m[1]) + H[2] * std::fabs(m[2]);
    if (separates(std::fabs(dot(m, Y[0])) - r, en, 0)) return 0;
  }
  for (int e = 0; e < 3; ++e) {
    const double* y1 = Y[(e + 1) % 3];
    const double* y2 = Y[(e + 2) % 3];
    for (int j = 0; j < 3; ++j) {
      const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      const double q1 = y1[j1] * f[e][j2] - y1[j2] * f[e][j1];
      const double q2 = y2[j1] * f[e][j2] - y2[j2] * f[e][j1];
      const double r = H[j1] * std::fabs(f[e][j2]) + H[j2] * std::fabs(f[e][j1]);
      if (separates(std::max(min_value(q1, q2) - r, -r - max_value(q1, q2)), ee, 4 + 3 * e + j)) return 0;
    }
  }
  if (open && undecided) *open = bits;
  return undecided ? unknown : 1;
}
inline int filter_face_coordinates(const Triangle<double>& t, const Box<double>& b, unsigned* open = nullptr) {
  if (open) *open = 0;
  double Y[3][3], H[3], m = 0, hb = 0;
  for (int k = 0; k < 3; ++k) {
    for (int c = 0; c < 3; ++c) Y[k][c] = t.vertex[k][c] - b.center[c];
    m = std::max(m, maxabs(Y[k]));
    H[k] = b.extent[k];
    hb = std::max(hb, b.extent[k]);
  }
  return triangle_in_box_frame(Y, H, m * (1 + 2 * u), hb, 1, 0, open);
}
inline int filter_face_coordinates(const Triangle<double>& t, const OrientedBox<double>& b, unsigned* open = nullptr) {
  if (open) *open = 0;
  const auto& a = b.axis;
  double n[3][3];
  const double D = face_normals(a, n);
  double X[3][3], Y[3][3], H[3], ma = 0, mx = 0, hb = 0;
  for (int k = 0; k < 3; ++k) {
    for (int c = 0; c < 3; ++c) X[k][c] = t.vertex[k][c] - b.center[c];
    ma = std::max(ma, maxabs(&a[k][0]));
    mx = std::max(mx, norm1(X[k]));
    hb = std::max(hb, b.extent[k]);
    H[k] = b.extent[k] * D;
  }
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 3; ++i) Y[k][i] = dot(n[i], X[k]);
  if (!(ma <= 0x1p100)) return unknown;
  const double A2 = 2 * ma * ma;
  return triangle_in_box_frame(Y, H, A2 * mx * (1 + 2 * u), 3 * A2 * ma * hb, 6, 6, open);
}
// The whole first stage for a triangle and a box: the face coordinates, then the world axes where
// those cannot decide (they recognise exact zeros); the world axes alone where the first separating
// axis is asked for.
template <class B>
int filter_triangle_box(const Triangle<double>& t, const B& b, int* axis, unsigned* open) {
  if (open) *open = 0;
  if (!axis) {
    if constexpr (std::is_same_v<B, Box<double>>)
      if (apart_on_box_faces(t, b)) return 0;
    if (const int r = filter_face_coordinates(t, b); r != unknown) return r;
  }
  return filter<Triangle<double>, B>(t, b, axis, open);
}
inline int filter(const Triangle<double>& t, const Box<double>& b, int* axis = nullptr, unsigned* open = nullptr) {
  return filter_triangle_box(t, b, axis, open);
}
inline int filter(const Triangle<double>& t, const OrientedBox<double>& b, int* axis = nullptr, unsigned* open = nullptr) {
  return filter_triangle_box(t, b, axis, open);
}

}  // namespace sat

namespace sphere_obb {
inline constexpr int unknown = sat::unknown;
// Stage 1: two certificates from one candidate point of the box, with static error bounds.
// With d = fl(q - c) (one rounding), p_i = a_i . d~ and g_i = clamp(p_i, -h_i, h_i) (exact
// doubles with |g_i| <= h_i), the point x = c + sum_i g_i a_i lies in the box exactly (its
// coordinates are g_i / h_i in [-1, 1]); for a box orthonormal to rounding it is the book's
// closest point. Let w = q - x = d - sum_i g_i a_i, computed as w~ (K = 4 roundings a
// component against W+_c = |d_c| + sum_i |g_i a_ic|: |w~_c - w_c| <= gamma_4 W+_c <= e_c =
// 5u W+~_c (1 + 16u), W+~ its computed value).
//   intersect  |w|^2 <= rho^2 certainly: |w|^2 <= |w~|^2 + sum_c e_c (2 |w~_c| + e_c), and
//              fl(|w~|^2) carries gamma_3 of its nonnegative sum; rho^2 >= fl(rho rho)(1 - u).
//   disjoint   v = w~ (any vector is an axis): the sphere lies beyond the box along v when
//              G = v . d - sum_i h_i |v . a_i| > rho |v| (v . p <= v . c + sum_i h_i |v . a_i|
//              for every p of the box, v . (q + rho s) >= v . q - rho |v| for |s| <= 1).
//              G~ carries at most 7 roundings on each monomial (v exact, d a leaf), so
//              |G~ - G| <= gamma_7 G+ with G+ = |v| . |d| + sum_i h_i |v| . |a_i|; then
//              G >= G_lo = G~ - 8u G+ > 0 and G_lo^2 > rho^2 |v|^2 decide it (the squares
//              compared with 8u of margin on each side).
// Every bound is grown by (1 + 16u) for its own rounding, and 64 * 2^-1074 covers roundings
// that underflow; a non-finite value anywhere leaves the case to stage 2.
inline int filter(const Sphere<double>& s, const OrientedBox<double>& b) {
  constexpr double u = sat::u, grow = 1 + 16 * sat::u, eta = 64 * 0x1p-1074;
  double d[3], w[3], e2 = 0, ww = 0, Wd = 0;
  for (int c = 0; c < 3; ++c) d[c] = s.center[c] - b.center[c];
  double g[3];
  for (int i = 0; i < 3; ++i) {
    const double p = b.axis[i][0] * d[0] + b.axis[i][1] * d[1] + b.axis[i][2] * d[2];
    const double h = b.extent[i];
    g[i] = max_value(-h, min_value(h, p));  // (by value: no branch on which bound clamps)
    if (!std::isfinite(p)) return unknown;
  }
  for (int c = 0; c < 3; ++c) {
    w[c] = d[c] - (g[0] * b.axis[0][c] + g[1] * b.axis[1][c] + g[2] * b.axis[2][c]);
    const double Wp = std::fabs(d[c]) + std::fabs(g[0] * b.axis[0][c]) + std::fabs(g[1] * b.axis[1][c]) +
                      std::fabs(g[2] * b.axis[2][c]);
    const double e = 5 * u * grow * Wp;  // gamma_4 W+ with room for its own rounding
    e2 += e * (2 * std::fabs(w[c]) + e);
    ww += w[c] * w[c];
    Wd = std::max(Wd, Wp);
  }
  const double rr = s.radius * s.radius;
  if (!std::isfinite(ww) || !std::isfinite(e2) || !std::isfinite(rr)) return unknown;
  if ((ww * (1 + 4 * u) + e2 * grow + eta) * grow < rr * (1 - 2 * u)) return 1;
  // disjoint along v = w~
  double G = w[0] * d[0] + w[1] * d[1] + w[2] * d[2];
  double Gp = std::fabs(w[0] * d[0]) + std::fabs(w[1] * d[1]) + std::fabs(w[2] * d[2]);
  for (int i = 0; i < 3; ++i) {
    const double va = w[0] * b.axis[i][0] + w[1] * b.axis[i][1] + w[2] * b.axis[i][2];
    G -= b.extent[i] * std::fabs(va);
    Gp += b.extent[i] * (std::fabs(w[0] * b.axis[i][0]) + std::fabs(w[1] * b.axis[i][1]) + std::fabs(w[2] * b.axis[i][2]));
  }
  const double Glo = G - (8 * u * Gp * grow + eta);  // gamma_7 G+ with room
  if (!std::isfinite(Glo)) return unknown;
  if (Glo > 0 && Glo * Glo * (1 - 8 * u) > (rr * ww) * (1 + 8 * u) + eta) return 0;
  return unknown;
}
// An oriented box whose axes are the coordinate axes up to order and sign (the identity
// rotation and the 47 others of the cube's symmetry group) is an axis-aligned box: with a_i =
// s_i e_p(i) (s_i = +-1, p a permutation), {c + sum_i u_i a_i : |u_i| <= h_i} is {x : |x_j -
// c_j| <= h_i for j = p(i)}, the box with the same centre and the extents permuted. No
// rounding: the centre and the extents are copied. A unit vector with double components has
// a single nonzero one (a sum of three squares of dyadic rationals equal to 1 has one nonzero
// term, by descent mod 4), so these are the only boxes whose axes are exactly unit. On them a
// sphere touching a face, an edge or a corner exactly is easy to build in doubles, and the
// campaigns' families build it (their rotations include signed permutations). The
// certificates leave an exact touch undecided; before this step it took the rational stage
// (about 275 us a case), as an exact touch of any other box still does. The oracle's
// second stage and the robust tier's certified decision (robust/separating_axes.hpp) both take
// sphere-box's own stages on such a box.
inline bool as_axis_aligned(const OrientedBox<double>& b, Box<double>& out) {
  unsigned seen = 0;
  for (int i = 0; i < 3; ++i) {
    int j = -1;
    for (int c = 0; c < 3; ++c) {
      const double x = b.axis[i][c];
      if (x == 0) continue;
      if (std::fabs(x) != 1 || j >= 0) return false;  // (a NaN fails here)
      j = c;
    }
    if (j < 0 || ((seen >> j) & 1u)) return false;
    seen |= 1u << j;
    out.extent[j] = b.extent[i];
  }
  out.center = b.center;
  return true;
}
}  // namespace sphere_obb

}  // namespace cdref::filters
