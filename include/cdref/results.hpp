/// \file
/// cdref/results.hpp - what the queries return, and how a caller asks for only part of it.
///
/// S is the type of a value that may contain a square root: sqrt_t<T> for the sphere
/// queries, T itself for the box queries (they need only divisions).
#pragma once

#include <cstdint>

#include "vec.hpp"

namespace cdref {

/// Which quantities a query computes. A field that is not asked for is left at zero;
/// `hit` / `intersect` is always computed.
enum want : std::uint32_t {
  want_lambda_enter = 1u << 0,
  want_lambda_exit = 1u << 1,
  want_point = 1u << 2,
  want_normal = 1u << 3,
  want_distance = 1u << 4,
  want_depth = 1u << 5,
  want_witnesses = 1u << 6,
  want_closest = 1u << 7,
  want_barycentric = 1u << 8,
  want_cast = want_lambda_enter | want_lambda_exit | want_point | want_normal,
  want_proximity = want_distance | want_depth | want_witnesses | want_closest,
  want_all = 0x1ffu,
};

/// A ray cast (segment s->t, lambda in [0,1]; or infinite ray, lambda >= 0).
///   hit          the cast meets the closed solid;
///   enters       the cast crosses the boundary into the solid at `point` (false when the
///                source already lies in the solid: then lambda_enter = 0, point = source
///                and normal = 0);
///   lambda_enter smallest lambda in the solid;
///   lambda_exit  largest lambda in the solid (for an infinite ray that leaves the box
///                nowhere it stays `unbounded_exit`);
///   point        source + lambda_enter * direction, in world coordinates;
///   normal       outward unit normal of the boundary at `point` when `enters`, else 0.
template <class S>
struct Cast {
  bool hit = false;               ///< the cast meets the closed solid
  bool enters = false;            ///< it crosses the boundary into the solid at `point`
  bool unbounded_exit = false;    ///< an infinite ray that never leaves the solid
  S lambda_enter = S(0);          ///< the smallest lambda in the solid
  S lambda_exit = S(0);           ///< the largest lambda in the solid
  Vec3<S> point = zero_vec<S>();   ///< source + lambda_enter * direction
  Vec3<S> normal = zero_vec<S>();  ///< the outward unit normal at `point` when `enters`, else 0
};

/// A ray cast on a triangle (Section 3.4) adds the barycentric weights of v1 and v2 at `point`
/// (point = (1 - u - v) v0 + u v1 + v v2). The normal is the triangle's, turned to face the
/// source; book/ray_triangle.hpp lists where it is 0.
template <class S>
struct TriangleCast : Cast<S> {
  S u = S(0);  ///< the barycentric weight of v1 at `point`
  S v = S(0);  ///< the barycentric weight of v2 at `point`
};

/// Two triangles (Section 3.4, book/triangle_triangle.hpp).
///   intersect    they share a point (closed sets);
///   coplanar     both lie in one plane (neither of zero area) and meet: the intersection is a
///                convex polygon, and p = q = 0;
///   p, q         otherwise, when they meet, the ends of the intersection segment (p = q at a
///                single point), p first in lexicographic order of (x, y, z).
template <class T>
struct TriangleIntersection {
  bool intersect = false;       ///< they share a point
  bool coplanar = false;        ///< both lie in one plane and meet in an area
  Vec3<T> p = zero_vec<T>();  ///< the first end of the intersection segment (lexicographic order)
  Vec3<T> q = zero_vec<T>();  ///< its other end
};

/// A proximity query on a pair (A, B).
///   intersect    A and B share a point (closed sets);
///   distance     max(min |a - b|, 0) over a in A, b in B;
///   depth        penetration depth: the length of the shortest translation that
///                separates them (0 when they do not intersect);
///   on_a, on_b   witness points: for a nonzero distance the closest pair, for a nonzero
///                depth the pair whose difference is the penetration vector;
///   closest      (segment-sphere, sphere-box) the point of the segment / box closest to
///                the sphere's centre, which the chapter's test is built on.
template <class S>
struct Proximity {
  bool intersect = false;           ///< A and B share a point
  S distance = S(0);                ///< max(min |a - b|, 0)
  S depth = S(0);                   ///< the penetration depth (0 when apart)
  Vec3<S> on_a = zero_vec<S>();     ///< the witness point on A
  Vec3<S> on_b = zero_vec<S>();     ///< the witness point on B
  Vec3<S> closest = zero_vec<S>();  ///< the point closest to the sphere's centre, where the query has it
};

/// A separating-axis test (Section 3.3, Theorem 3.1) on a pair (A, B) of convex polytopes.
///   intersect    A and B share a point (closed sets: touching intersects);
///   axis         when they do not, the index of the first separating axis in the query's
///                documented order (-1 when they intersect);
///   direction    that axis, unnormalised, in world coordinates (0 when they intersect).
template <class T>
struct Separation {
  bool intersect = false;              ///< A and B share a point
  int axis = -1;                       ///< the first separating axis's index, -1 when they intersect
  Vec3<T> direction = zero_vec<T>();  ///< that axis, unnormalised, in world coordinates
};

}  // namespace cdref
