// cdref/robust/sat_first_look.hpp - the first look of the separating-axis queries at double
// (segment-box, ray-box, triangle-box, segment-obb, ray-obb, triangle-obb, obb-obb): the whole
// answer of robust::separate (whether they meet; when apart, the first separating axis of
// Theorem 3.1 in the book's order and its direction L) from the oracle's first stage, where it
// certifies them, in place of the whole formulation on double words (separating_axes.hpp,
// detail::separation), which took 1.5-5.5 us a case on the oriented boxes.
//
//  0. Where steps 1-2 on the inputs as they are decline and the inputs lie far from 1 (a length
//     beyond 2^+-100: the magnitude families), they run again on the inputs scaled by a
//     power of two 2^-k, exactly (length_scale.hpp: every point, a box's centre and extents; a
//     ray's direction by its own 2^-j): the classification and the axis do not change (a ray is the same set
//     whatever its direction's length), and the direction comes back multiplied by 2^(k deg),
//     deg its degree in lengths (a triangle's normal 2, an edge of a segment or a triangle 1, a
//     ray's direction j/k, a box's axes 0). Where a value scaled back leaves the normal range,
//     or a scaled input would: the slower path.
//  1. The classification and the axis: filters/sat_filter.hpp's filter, every candidate axis in
//     the book's order (A's faces, B's faces, A's edges x B's edges, an exactly zero axis
//     counted and skipped as the book does) against one static bound. Where it decides, the
//     classification is the book's (the solid's) at an exact type; where they are apart and
//     every axis before the first that certainly separates certainly does not, that axis's
//     index is the book's at an exact type too. Otherwise: the slower path.
//  2. The direction L, as the book computes it (book/separating_axes.hpp, polytope()): an
//     axis-aligned box's face e_k, exactly; otherwise a cross product x X y of two vectors
//     whose components are exact pairs: an oriented box's axes a_k as they are (its faces a_{k+1}
//     x a_{k+2}, its edges a_k), a box's edges e_k, a ray's direction, a segment's edge t - s
//     and a triangle's edges v_{k+1} - v_k and v_2 - v_0 by two_sum (its face (v_1 - v_0) x (v_2
//     - v_0)). Each component x_j y_k - x_k y_j by word_bounds::cross_term (the products of the
//     high parts exact, the cross terms and the lows in double: within 8u of their magnitudes
//     plus 2u^2 of the products plus 16 eta), kept where its bound proves it within 3/4 of an
//     ulp of the exact value (first_look.hpp, first_look_kept; the oracle's every-output path,
//     Correct: where it is the exact value rounded). A component whose two products each have a
//     zero factor is exactly 0. Any component not kept: the slower path.
// Range: every factor's high part at most 2^500 (no product overflows); the filter's own range
// (it refuses NaN and infinities, which the input checks name first).
#pragma once

#include <cdref/filters/sat_filter.hpp>
#include <cdref/bounded/word_bounds.hpp>
#include <cdref/primitives.hpp>
#include <cdref/results.hpp>
#include <cmath>

#include "first_look.hpp"
#include "length_scale.hpp"

namespace cdref::robust::detail {

// A vector of exact pairs (step 2).
struct PairVec {
  Pair<double> c[3];
};
inline PairVec pair_vec(const Vec3<double>& v) { return {{{v[0], 0.0}, {v[1], 0.0}, {v[2], 0.0}}}; }
inline PairVec pair_diff(const Vec3<double>& a, const Vec3<double>& b) {
  return {{two_sum(a[0], -b[0]), two_sum(a[1], -b[1]), two_sum(a[2], -b[2])}};
}
inline PairVec pair_unit(int k) {
  PairVec p{};
  p.c[k] = {1.0, 0.0};
  return p;
}

// The polytopes' faces (as the two factors of a cross product, or an exact unit vector) and
// edges, as book/separating_axes.hpp's polytope() defines them.
struct SatFace {
  bool unit = false;  // an axis-aligned box's e_k
  int k = 0;
  PairVec x, y;
};
inline constexpr int sat_faces(const Segment<double>*) { return 0; }
inline constexpr int sat_faces(const Ray<double>*) { return 0; }
inline constexpr int sat_faces(const Triangle<double>*) { return 1; }
inline constexpr int sat_faces(const Box<double>*) { return 3; }
inline constexpr int sat_faces(const OrientedBox<double>*) { return 3; }
inline constexpr int sat_edges(const Segment<double>*) { return 1; }
inline constexpr int sat_edges(const Ray<double>*) { return 1; }
inline constexpr int sat_edges(const Triangle<double>*) { return 3; }
inline constexpr int sat_edges(const Box<double>*) { return 3; }
inline constexpr int sat_edges(const OrientedBox<double>*) { return 3; }

inline SatFace sat_face(const Triangle<double>& t, int) {
  return {false, 0, pair_diff(t.vertex[1], t.vertex[0]), pair_diff(t.vertex[2], t.vertex[0])};
}
inline SatFace sat_face(const Box<double>&, int k) { return {true, k, {}, {}}; }
inline SatFace sat_face(const OrientedBox<double>& b, int k) {
  return {false, 0, pair_vec(b.axis[(k + 1) % 3]), pair_vec(b.axis[(k + 2) % 3])};
}
inline SatFace sat_face(const Segment<double>&, int) { return {}; }  // (none: not reached)
inline SatFace sat_face(const Ray<double>&, int) { return {}; }      // (none: not reached)
inline PairVec sat_edge(const Segment<double>& s, int) { return pair_diff(s.target, s.source); }
inline PairVec sat_edge(const Ray<double>& r, int) { return pair_vec(r.direction); }
inline PairVec sat_edge(const Triangle<double>& t, int k) { return pair_diff(t.vertex[(k + 1) % 3], t.vertex[k]); }
inline PairVec sat_edge(const Box<double>&, int k) { return pair_unit(k); }
inline PairVec sat_edge(const OrientedBox<double>& b, int k) { return pair_vec(b.axis[k]); }

// x X y, each component kept (step 2); false where one is not, or a factor is out of range.
template <class Mul, bool Correct>
bool cross_kept(const PairVec& x, const PairVec& y, Vec3<double>& out) {
  namespace wb = word_bounds;
  for (int c = 0; c < 3; ++c)
    if (!(std::fabs(x.c[c].hi) <= 0x1p500 && std::fabs(y.c[c].hi) <= 0x1p500)) return false;
  for (int c = 0; c < 3; ++c) {
    const int j = (c + 1) % 3, k = (c + 2) % 3;
    if ((x.c[j].hi == 0 || y.c[k].hi == 0) && (x.c[k].hi == 0 || y.c[j].hi == 0)) {
      out[c] = 0.0;  // (a pair whose high part is 0 is 0)
      continue;
    }
    const wb::Word w = wb::cross_term<Mul>(x.c[j], y.c[k], x.c[k], y.c[j]);
    if (!first_look_kept<Correct>(w.v, w.e)) return false;
    out[c] = w.v.hi;
  }
  return true;
}

// Steps 1-2 (header) on inputs in range: true where `out` is the whole answer.
template <class Mul, bool Correct, class A, class B>
bool sat_first_look_in_range(const A& a, const B& b, Separation<double>& out) {
  int axis = -2;
  const int r = filters::sat::filter<A, B>(a, b, &axis);
  if (r == filters::sat::unknown) return false;
  out = Separation<double>{};
  if (r == 1) {
    out.intersect = true;  // (axis -1, direction 0, as the book leaves them)
    return true;
  }
  if (axis < 0) return false;
  out.axis = axis;
  constexpr int fa = sat_faces(static_cast<const A*>(nullptr)), fb = sat_faces(static_cast<const B*>(nullptr));
  constexpr int eb = sat_edges(static_cast<const B*>(nullptr));
  SatFace f;
  if (axis < fa) {
    f = sat_face(a, axis);
  } else if (axis < fa + fb) {
    f = sat_face(b, axis - fa);
  } else {
    const int e = axis - fa - fb;
    return cross_kept<Mul, Correct>(sat_edge(a, e / eb), sat_edge(b, e % eb), out.direction);
  }
  if (f.unit) {
    out.direction[f.k] = 1.0;
    return true;
  }
  return cross_kept<Mul, Correct>(f.x, f.y, out.direction);
}

// The power of two the direction of axis `axis` scales by when the lengths scale by 2^-k (a
// ray's direction by 2^-j): a triangle's normal 2k, an edge of a segment or a triangle k, of a
// ray j, of a box 0; a cross of two edges the sum.
template <class A, class B>
int sat_axis_degree(int axis, int k, int j) {
  constexpr int fa = sat_faces(static_cast<const A*>(nullptr)), fb = sat_faces(static_cast<const B*>(nullptr));
  const int edge_a = std::is_same_v<A, Ray<double>> ? j : (std::is_same_v<A, Segment<double>> || std::is_same_v<A, Triangle<double>>) ? k : 0;
  if (axis < fa) return std::is_same_v<A, Triangle<double>> ? 2 * k : 0;
  if (axis < fa + fb) return 0;
  return edge_a;  // (B's edges are a box's axes)
}

// Steps 0-2 (header): true where `out` is the whole answer.
template <class Mul, bool Correct, class A, class B>
bool sat_first_look(const A& a, const B& b, Separation<double>& out) {
  // (the inputs as they are first, as obb_cast.hpp's first look)
  if (sat_first_look_in_range<Mul, Correct>(a, b, out)) return true;
  LengthScale s;
  A as;
  B bs;
  if (scale_lengths(a, b, s, as, bs) != Scaling::scaled || !sat_first_look_in_range<Mul, Correct>(as, bs, out)) return false;
  if (out.intersect) return true;
  // the direction back, exactly where it stays a normal number (else a second rounding)
  const int e = sat_axis_degree<A, B>(out.axis, s.k, s.j);
  for (int c = 0; c < 3; ++c) {
    out.direction[c] = std::ldexp(out.direction[c], e);
    const double v = out.direction[c];
    if (!std::isfinite(v) || (v != 0 && std::fabs(v) < 0x1p-1022)) return false;
  }
  return true;
}

}  // namespace cdref::robust::detail
