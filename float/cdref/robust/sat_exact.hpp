// cdref/robust/sat_exact.hpp - Theorem 3.1 (book/separating_axes.hpp) on exact rationals, for
// the robust tier's separating-axis queries where nothing cheaper certifies the answer: the
// first look, the grids and the whole formulation on double words (separating_axes.hpp) all
// leave some decision open. That happens where a candidate axis's projections touch or nearly
// touch, as in a shape lying in a face's plane: the double words then cannot tell whether that
// axis separates, and the F formulation they fell back to could name a later axis as the first
// one (segment-obb planes/0, seed 1, case 193: axis 4 of a segment in the plane x = c - h of an
// axis-aligned box's face, where the touching intervals make axis 5 the first).
//
// The inputs are rationals exactly (GMP's mpq, rational.hpp), and so is every quantity of the
// book's Theorem 3.1: the polytopes' face normals (a triangle's (v1 - v0) x (v2 - v0), an
// oriented box's a_{k+1} x a_{k+2}, an axis-aligned box's e_k), edge directions (t - s, a ray's
// d, a triangle's v_{k+1} - v_k, a box's axes), the candidate axes L in the book's order (the
// faces of A, of B, then e_A[i] x e_B[j]; an exactly zero L skipped), and the projections (a
// vertex list's min and max of v . L; a zonotope's c . L -+ sum_k h_k |g_k . L|; a ray's s . L,
// open towards the side d . L points to: where L is a cross product with d itself, d . L is 0
// exactly here and the ray projects onto one point, as the book's own_edge flag has it in F).
// Closed intervals: touching ones overlap. So the classification, the first separating
// axis and its direction are the book's at an exact type, the direction rounded once to F
// (rational.hpp, rounded).
// Cost: a few tens of microseconds (tens of GMP products per axis, up to 15 axes); it runs only
// where every faster stage left the answer open.
#pragma once

#include <cdref/primitives.hpp>
#include <cdref/results.hpp>

#include "rational.hpp"

namespace cdref::robust::detail {

struct ExactPolytope {
  enum Kind { vertices, zonotope, ray };
  Kind kind = vertices;
  int n = 0;
  RVec point[3];  // the vertices; a zonotope's centre; a ray's source
  RVec gen[3];    // a zonotope's generators; a ray's direction
  Rational half[3];
  int faces = 0, edges = 0;
  RVec face[3], edge[3];
};

template <class F>
void exact_polytope(ExactPolytope& p, const Segment<F>& s) {
  p.kind = ExactPolytope::vertices;
  p.n = 2;
  set_vec(p.point[0], s.source);
  set_vec(p.point[1], s.target);
  p.edges = 1;
  sub_vec(p.edge[0], p.point[1], p.point[0]);
}
template <class F>
void exact_polytope(ExactPolytope& p, const Ray<F>& r) {
  p.kind = ExactPolytope::ray;
  p.n = 1;
  set_vec(p.point[0], r.source);
  set_vec(p.gen[0], r.direction);
  p.edges = 1;
  set_vec(p.edge[0], r.direction);
}
template <class F>
void exact_polytope(ExactPolytope& p, const Triangle<F>& t) {
  p.kind = ExactPolytope::vertices;
  p.n = 3;
  for (int k = 0; k < 3; ++k) set_vec(p.point[k], t.vertex[k]);
  p.edges = 3;
  for (int k = 0; k < 3; ++k) sub_vec(p.edge[k], p.point[(k + 1) % 3], p.point[k]);
  p.faces = 1;
  RVec e2;
  sub_vec(e2, p.point[2], p.point[0]);
  cross_vec(p.face[0], p.edge[0], e2);
}
template <class F>
void exact_polytope(ExactPolytope& p, const Box<F>& b) {
  p.kind = ExactPolytope::zonotope;
  p.n = 3;
  set_vec(p.point[0], b.center);
  p.faces = p.edges = 3;
  for (int k = 0; k < 3; ++k) {
    for (int i = 0; i < 3; ++i) {
      mpq_set_si(p.gen[k][i].q, i == k, 1);
      mpq_set_si(p.face[k][i].q, i == k, 1);
      mpq_set_si(p.edge[k][i].q, i == k, 1);
    }
    set_rational(p.half[k], b.extent[k]);
  }
}
template <class F>
void exact_polytope(ExactPolytope& p, const OrientedBox<F>& b) {
  p.kind = ExactPolytope::zonotope;
  p.n = 3;
  set_vec(p.point[0], b.center);
  p.faces = p.edges = 3;
  for (int k = 0; k < 3; ++k) {
    set_vec(p.gen[k], b.axis[k]);
    set_vec(p.edge[k], b.axis[k]);
    set_rational(p.half[k], b.extent[k]);
  }
  for (int k = 0; k < 3; ++k) cross_vec(p.face[k], p.gen[(k + 1) % 3], p.gen[(k + 2) % 3]);
}

struct ExactProjection {
  Rational lo, hi;
  bool lo_inf = false, hi_inf = false;
};

// L . P (book/separating_axes.hpp, project).
inline void exact_project(ExactProjection& r, const ExactPolytope& p, const RVec& L) {
  Rational x, t;
  switch (p.kind) {
    case ExactPolytope::vertices:
      dot_vec(r.lo, p.point[0], L);
      mpq_set(r.hi.q, r.lo.q);
      for (int k = 1; k < p.n; ++k) {
        dot_vec(x, p.point[k], L);
        if (mpq_cmp(x.q, r.lo.q) < 0) mpq_set(r.lo.q, x.q);
        if (mpq_cmp(x.q, r.hi.q) > 0) mpq_set(r.hi.q, x.q);
      }
      return;
    case ExactPolytope::zonotope: {
      Rational rad;
      for (int k = 0; k < p.n; ++k) {
        dot_vec(x, p.gen[k], L);
        mpq_abs(x.q, x.q);
        mpq_mul(t.q, p.half[k].q, x.q);
        mpq_add(rad.q, rad.q, t.q);
      }
      dot_vec(x, p.point[0], L);
      mpq_sub(r.lo.q, x.q, rad.q);
      mpq_add(r.hi.q, x.q, rad.q);
      return;
    }
    case ExactPolytope::ray:
      dot_vec(r.lo, p.point[0], L);
      mpq_set(r.hi.q, r.lo.q);
      dot_vec(x, p.gen[0], L);
      r.hi_inf = mpq_sgn(x.q) > 0;
      r.lo_inf = mpq_sgn(x.q) < 0;
      return;
  }
}

inline bool exact_apart(const ExactProjection& a, const ExactProjection& b) {
  return (!a.hi_inf && !b.lo_inf && mpq_cmp(a.hi.q, b.lo.q) < 0) || (!b.hi_inf && !a.lo_inf && mpq_cmp(b.hi.q, a.lo.q) < 0);
}

// Theorem 3.1 on the exact polytopes of a and b: the book's answer at an exact type, the
// direction rounded once to F.
template <class F, class A, class B>
Separation<F> separation_exact(const A& a, const B& b) {
  ExactPolytope pa, pb;
  exact_polytope(pa, a);
  exact_polytope(pb, b);
  Separation<F> res;
  int index = 0;
  const auto try_axis = [&](const RVec& L) {
    const int at = index++;
    if (mpq_sgn(L[0].q) == 0 && mpq_sgn(L[1].q) == 0 && mpq_sgn(L[2].q) == 0) return false;
    ExactProjection ja, jb;
    exact_project(ja, pa, L);
    exact_project(jb, pb, L);
    if (!exact_apart(ja, jb)) return false;
    res.axis = at;
    for (int k = 0; k < 3; ++k) res.direction[k] = rounded<F>(L[k]);
    return true;
  };
  for (int i = 0; i < pa.faces; ++i)
    if (try_axis(pa.face[i])) return res;
  for (int j = 0; j < pb.faces; ++j)
    if (try_axis(pb.face[j])) return res;
  RVec L;
  for (int i = 0; i < pa.edges; ++i)
    for (int j = 0; j < pb.edges; ++j) {
      cross_vec(L, pa.edge[i], pb.edge[j]);
      if (try_axis(L)) return res;
    }
  res.intersect = true;
  return res;
}

}  // namespace cdref::robust::detail
