/// \file
/// cdref/book/separating_axes.hpp - Section 3.3, Theorem 3.1: separating axes of polytopes,
/// as one reusable piece.
///
/// A vector L is a separating axis of A and B when the projections L . A and L . B (closed
/// intervals) do not overlap; then A and B are disjoint. For convex polytopes the converse
/// holds with a finite list of candidates (Theorem 3.1): if A and B are disjoint, one of
///   - the face normals of A,
///   - the face normals of B,
///   - the cross products e_A x e_B of an edge direction of A and one of B
/// separates them. (A - B, the Minkowski difference, is a convex polytope; A and B are
/// disjoint iff the origin lies outside it, and then one of its facets separates the origin.
/// Each facet of A - B is a facet of A plus a vertex of B, a vertex of A plus a facet of B,
/// or an edge of A plus an edge of B, whose normal is then e_A x e_B.)
///
/// The polytopes here are given by their face normals, their edge directions and their
/// projection: a list of vertices (segment, triangle), a zonotope c + sum_k t_k h_k g_k,
/// |t_k| <= 1 (an axis-aligned or oriented box: projection radius sum_k h_k |g_k . L|), or a
/// ray s + lambda d, lambda >= 0 (projection [s . L, +inf) when d . L > 0). A flat polytope
/// (a triangle) has its normal as its one face; with a box as the other polytope the box's
/// three edge directions keep the candidates complete even when the triangle is coplanar
/// with a flat box, and a triangle of zero area is the segment or point it spans (its zero
/// normal and zero edges drop out, and what remains is the candidate list of that segment or
/// point). Boxes of zero extent keep their edge directions. Two flat polytopes in one plane
/// (two triangles) are not covered by these candidates: their separating axes lie in the plane,
/// the side normals n x e of their edges, which such a polytope must then list among its faces.
///
/// The axes are tried in the documented order: the faces of A (index 0, 1, ...), then the
/// faces of B, then e_A[i] x e_B[j] for i, then j (index faces_A + faces_B + i * edges_B + j),
/// and the first that separates is reported. An axis that is exactly zero (parallel edges,
/// a zero-area triangle's normal) is skipped: it never separates; one that is merely tiny is a
/// valid axis like any other. Sets are closed: projections that touch overlap.
///
/// At an exact number type this decides exactly; at a float type every projection is rounded
/// (and a rounded cross product may be zero, or not, where the exact one is not, or is).
#pragma once

#include <array>

#include "common.hpp"

namespace cdref::book {

/// A convex polytope as Theorem 3.1 sees it: its points (vertices, or a zonotope's centre and
/// generators, or a ray's source and direction), its face normals and its edge directions.
template <class T>
struct Polytope {
  /// How `point`, `gen` and `half` describe the set.
  enum Kind { vertices, zonotope, ray };
  Kind kind = vertices;  ///< how the set is described
  int n = 0;                       ///< vertices, or generators of a zonotope
  std::array<Vec3<T>, 3> point{};  ///< the vertices; a zonotope's centre; a ray's source
  std::array<Vec3<T>, 3> gen{};    ///< a zonotope's generator directions; a ray's direction
  std::array<T, 3> half{};         ///< a zonotope's half-lengths h_k along gen[k]
  ///@{
  /// How many face normals and edge directions are in use.
  int faces = 0, edges = 0;
  ///@}
  std::array<Vec3<T>, 3> face{};   ///< face normals (unnormalised, either sign)
  std::array<Vec3<T>, 3> edge{};   ///< edge directions
};

/// The projection L . P as a closed interval; lo_inf / hi_inf for a ray's open end.
template <class T>
struct Projection {
  ///@{
  /// The interval's ends.
  T lo, hi;
  ///@}
  ///@{
  /// Whether the interval is unbounded below, above.
  bool lo_inf = false, hi_inf = false;
  ///@}
};

namespace detail {

/// `own_edge`: L is a cross product with the polytope's own edge direction, so a ray's
/// direction is orthogonal to it (d . L = 0 identically: the ray projects onto one point).
template <class T>
Projection<T> project(const Polytope<T>& p, const Vec3<T>& L, bool own_edge = false) {
  Projection<T> r{T(0), T(0)};
  switch (p.kind) {
    case Polytope<T>::vertices: {
      r.lo = r.hi = p.point[0].dot(L);
      for (int k = 1; k < p.n; ++k) {
        const T x = p.point[k].dot(L);
        r.lo = min_of(r.lo, x);
        r.hi = max_of(r.hi, x);
      }
      return r;
    }
    case Polytope<T>::zonotope: {
      const T c = p.point[0].dot(L);
      T rad(0);
      for (int k = 0; k < p.n; ++k) {
        rad += p.half[k] * abs_of(T(p.gen[k].dot(L)));
      }
      r.lo = c - rad;
      r.hi = c + rad;
      return r;
    }
    case Polytope<T>::ray: {
      r.lo = r.hi = p.point[0].dot(L);
      if (own_edge) return r;
      const T d = p.gen[0].dot(L);
      if (d > T(0)) r.hi_inf = true;
      if (d < T(0)) r.lo_inf = true;
      return r;
    }
  }
  return r;
}

/// The closed intervals are disjoint.
template <class T>
bool apart(const Projection<T>& a, const Projection<T>& b) {
  return (!a.hi_inf && !b.lo_inf && a.hi < b.lo) || (!b.hi_inf && !a.lo_inf && b.hi < a.lo);
}

}  // namespace detail

/// Theorem 3.1 on two polytopes: intersect, or the first separating axis in the order above.
template <class T>
Separation<T> separate(const Polytope<T>& a, const Polytope<T>& b) {
  Separation<T> res;
  int index = 0;
  auto try_axis = [&](const Vec3<T>& L, bool edge_cross = false) {
    const int at = index++;
    if (detail::is_zero(L)) return false;
    if (!detail::apart(detail::project(a, L, edge_cross), detail::project(b, L, edge_cross))) return false;
    res.axis = at;
    res.direction = L;
    return true;
  };
  for (int i = 0; i < a.faces; ++i)
    if (try_axis(a.face[i])) return res;
  for (int j = 0; j < b.faces; ++j)
    if (try_axis(b.face[j])) return res;
  for (int i = 0; i < a.edges; ++i)
    for (int j = 0; j < b.edges; ++j)
      if (try_axis(Vec3<T>(a.edge[i].cross(b.edge[j])), true)) return res;
  res.intersect = true;
  return res;
}

/// ---- the chapter's primitives as polytopes ----
template <class T>
Polytope<T> polytope(const Segment<T>& s) {
  Polytope<T> p;
  p.kind = Polytope<T>::vertices;
  p.n = 2;
  p.point[0] = s.source;
  p.point[1] = s.target;
  p.edges = 1;
  p.edge[0] = s.target - s.source;
  return p;
}

/// The ray as a polytope: its source and direction (an unbounded zonotope).
template <class T>
Polytope<T> polytope(const Ray<T>& r) {
  Polytope<T> p;
  p.kind = Polytope<T>::ray;
  p.n = 1;
  p.point[0] = r.source;
  p.gen[0] = r.direction;
  p.edges = 1;
  p.edge[0] = r.direction;
  return p;
}

/// The triangle as a polytope: three vertices, its normal as face, its edges.
template <class T>
Polytope<T> polytope(const Triangle<T>& t) {
  Polytope<T> p;
  p.kind = Polytope<T>::vertices;
  p.n = 3;
  p.point = t.vertex;
  p.edges = 3;
  for (int k = 0; k < 3; ++k) p.edge[k] = t.vertex[(k + 1) % 3] - t.vertex[k];
  p.faces = 1;
  p.face[0] = p.edge[0].cross(Vec3<T>(t.vertex[2] - t.vertex[0]));
  return p;
}

/// The axis-aligned box as a polytope: a zonotope of the coordinate axes, faces and edges e_x, e_y, e_z.
template <class T>
Polytope<T> polytope(const Box<T>& b) {
  Polytope<T> p;
  p.kind = Polytope<T>::zonotope;
  p.n = 3;
  p.point[0] = b.center;
  p.faces = p.edges = 3;
  for (int k = 0; k < 3; ++k) {
    p.gen[k] = p.face[k] = p.edge[k] = unit_vec<T>(k);
    p.half[k] = b.extent[k];
  }
  return p;
}

/// The oriented box as the solid its inputs define: face normals a_1 x a_2, a_2 x a_0,
/// a_0 x a_1 (the true normals of the parallelepiped), edge directions a_0, a_1, a_2.
template <class T>
Polytope<T> polytope(const OrientedBox<T>& b) {
  Polytope<T> p;
  p.kind = Polytope<T>::zonotope;
  p.n = 3;
  p.point[0] = b.center;
  p.faces = p.edges = 3;
  for (int k = 0; k < 3; ++k) {
    p.gen[k] = p.edge[k] = b.axis[k];
    p.half[k] = b.extent[k];
    p.face[k] = b.axis[(k + 1) % 3].cross(b.axis[(k + 2) % 3]);
  }
  return p;
}

/// Theorem 3.1 on any two of the chapter's polytopes, after the input checks.
template <class A, class B>
auto separate_polytopes(const A& a, const B& b, const char* name_a, const char* name_b) {
  check(a, name_a);
  check(b, name_b);
  return separate(polytope(a), polytope(b));
}

}  // namespace cdref::book
