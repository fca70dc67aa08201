// cdref/oracle/triangle_triangle.hpp - the fast exact classification oracle for two triangles
// (Section 3.4) at double inputs: what book::intersect (book/triangle_triangle.hpp) returns at
// CGAL::Gmpq, in three stages.
//
//   1. filter    (a) a plane: the signs of dB_k = (b_k - a0) . ((a1 - a0) x (a2 - a0)), and of
//                dA_k the other way, each a triple product of rounded differences with the
//                static bound of oracle/ray_triangle.hpp; three certain signs alike separate.
//                (b) the edges: two closed triangles meet iff an edge of one meets the other
//                (non-coplanar: an end of their common segment lies on an edge of one of them;
//                coplanar: edges cross, or one triangle holds the other and with it its edges;
//                a zero-area triangle's edges cover its span). Each of the six edge-triangle
//                pairs is the segment-triangle filter of oracle/ray_triangle.hpp: one certain
//                hit proves the triangles meet, six certain misses that they do not.
//   2. double word  the robust version's evaluation (robust/triangle_triangle.hpp), certain
//                when every comparison is (Stage::expansion names this stage here);
//   3. rational  book::intersect at CGAL::Gmpq.
#pragma once

#include <cdref/cdref.hpp>
#include <cdref/exact.hpp>
#include <cdref/oracle/ray_triangle.hpp>
#include <cdref/oracle/rational.hpp>
#include <cdref/oracle/stage.hpp>
#include <cdref/robust/triangle_triangle.hpp>

namespace cdref::oracle {

namespace triangle_triangle {

inline constexpr int unknown = 2;

// The signs of t's vertices against the plane of p, certain or 0.
inline bool plane_separates(const Triangle<double>& p, const Triangle<double>& t, bool& finite) {
  double e1[3], e2[3], x[3];
  for (int i = 0; i < 3; ++i) {
    e1[i] = p.vertex[1][i] - p.vertex[0][i];
    e2[i] = p.vertex[2][i] - p.vertex[0][i];
  }
  int s[3];
  for (int k = 0; k < 3; ++k) {
    for (int i = 0; i < 3; ++i) x[i] = t.vertex[k][i] - p.vertex[0][i];
    s[k] = ray_triangle::triple_sign(x, e1, e2, finite);
  }
  return s[0] != 0 && s[0] == s[1] && s[0] == s[2];
}

inline int filter(const Triangle<double>& a, const Triangle<double>& b) {
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
inline int double_word(const Triangle<double>& a, const Triangle<double>& b) {
  const robust::Decision d = robust::decide(a, b);
  return d.certain ? int(d.value) : unknown;
}
inline bool rational(const Triangle<double>& a, const Triangle<double>& b) {
  return book::intersect(rational_inputs::toq(a), rational_inputs::toq(b)).intersect;
}
inline int at_stage(Stage st, const Triangle<double>& a, const Triangle<double>& b) {
  return st == Stage::filter ? filter(a, b) : st == Stage::expansion ? double_word(a, b) : int(rational(a, b));
}

}  // namespace triangle_triangle

inline bool classify(const Triangle<double>& a, const Triangle<double>& b, Stage* used = nullptr) {
  check(a, "triangle A");
  check(b, "triangle B");
  for (Stage st : {Stage::filter, Stage::expansion}) {
    const int r = triangle_triangle::at_stage(st, a, b);
    if (r != triangle_triangle::unknown) {
      if (used) *used = st;
      return r != 0;
    }
  }
  if (used) *used = Stage::rational;
  return triangle_triangle::rational(a, b);
}

}  // namespace cdref::oracle
