/// \file
/// cdref/truth.hpp - the exact answer for one input, in one call.
///
/// For every query of Sections 3.1-3.4, a function over the primitives in double (or float) that
/// returns the query's result (Cast, TriangleCast, FanCast, Proximity, TriangleIntersection,
/// Separation, or a bool) with the classification decided exactly and every value correctly
/// rounded to the caller's type (round to nearest, ties to even): lambda_enter, lambda_exit, point,
/// normal, u, v, distance, depth, both witnesses, the closest point, the ends of a
/// triangle-triangle intersection, the separating axis and its direction. The inputs are taken as
/// the exact numbers their doubles (floats) denote.
///
///   #include <cdref/truth.hpp>           // link cdref::cdref (find_package(cdref))
///   const cdref::Ray<double> ray{{0, 0, -5}, {0, 0, 1}};
///   const cdref::Sphere<double> ball{{0.1, 0, 0}, 1};
///   const cdref::Cast<double> c = cdref::truth::cast(ray, ball);
///   // c.hit, c.lambda_enter (the double nearest 5 - sqrt(0.99)), c.point, c.normal, ...
///
/// The names are the book tier's (cdref::book::cast, proximity, separate, intersect), and so are
/// the meanings: each function's result is the book's algorithm evaluated on exact numbers, then
/// rounded. The conventions of each query (closed solids, lambda in units of |direction| for a
/// ray and of target - source for a segment, which witness is which) are documented at the
/// result structs (results.hpp, fan.hpp) and the book's headers (book/*.hpp). Where the chapter's
/// pair is symmetric both argument orders are offered (a proximity's witnesses follow the
/// arguments: witness_a is on the first).
///
/// How: the fast exact oracle (a float filter with a proven error bound, then double words with
/// rigorous bounds, then exact rationals only where those cannot decide or round), so a call
/// costs about what `cdref report`'s "oracle, every output" row says, typically a few hundred
/// nanoseconds, not the microseconds of the book at an exact type. Path::exact skips the filters
/// and evaluates the book at CGAL::Gmpq for every input: the same answer, for cross-checking.
///
/// Errors: an input outside the query's domain throws cdref::invalid_input naming the argument
/// and what is wrong ("sphere radius is negative (-1)", "ray direction is the zero vector",
/// "oriented box axes are linearly dependent ...", "polygon has 9 vertices ..."; two arguments of
/// one kind are named "... a" and "... b"). A degenerate but meaningful input is answered with
/// its documented meaning: a zero radius is a point, a zero extent a flat box, a zero-area
/// triangle the segment or point it spans, a segment with source = target a point.
///
/// This header includes only cdref's core (Eigen, no CGAL): the exact machinery is in the
/// library. The exact value itself, beyond its rounding, is the book at an exact type
/// (<cdref/cdref.hpp> with <cdref/exact.hpp>): examples/truth_exact.cpp shows it.
#pragma once

#include "truth/basics.hpp"

namespace cdref::truth {

// Path (oracle or exact), detail::Bool and the comparison tools: cdref/truth/basics.hpp.

/// ---- Section 3.1: spheres ----
/// sphere-sphere: distance, penetration depth and witnesses of two closed balls.
Proximity<double> proximity(const Sphere<double>& a, const Sphere<double>& b, Path path = Path::oracle);
/// sphere-sphere at float's rounding.
Proximity<float> proximity(const Sphere<float>& a, const Sphere<float>& b, Path path = Path::oracle);
/// segment-sphere-cast (Algorithm 3.1): the segment source->target cast on the closed ball, lambda in [0, 1].
Cast<double> cast(const Segment<double>& a, const Sphere<double>& b, Path path = Path::oracle);
/// segment-sphere-cast at float's rounding.
Cast<float> cast(const Segment<float>& a, const Sphere<float>& b, Path path = Path::oracle);
/// ray-sphere-cast (Algorithm 3.1): the ray source + lambda direction, lambda >= 0 in units of |direction|.
Cast<double> cast(const Ray<double>& a, const Sphere<double>& b, Path path = Path::oracle);
/// ray-sphere-cast at float's rounding.
Cast<float> cast(const Ray<float>& a, const Sphere<float>& b, Path path = Path::oracle);
/// segment-sphere (Algorithm 3.2): the segment against the ball; `closest` is the segment's point nearest the centre.
Proximity<double> proximity(const Segment<double>& a, const Sphere<double>& b, Path path = Path::oracle);
/// segment-sphere at float's rounding.
Proximity<float> proximity(const Segment<float>& a, const Sphere<float>& b, Path path = Path::oracle);

/// ---- Section 3.2: axis-aligned boxes ----
/// box-box: whether two closed axis-aligned boxes share a point.
bool intersect(const Box<double>& a, const Box<double>& b, Path path = Path::oracle);
/// box-box on float inputs (a classification: the same as at double).
bool intersect(const Box<float>& a, const Box<float>& b, Path path = Path::oracle);
/// segment-box-cast (Algorithm 3.3, the slabs): the segment cast on the closed box.
Cast<double> cast(const Segment<double>& a, const Box<double>& b, Path path = Path::oracle);
/// segment-box-cast at float's rounding.
Cast<float> cast(const Segment<float>& a, const Box<float>& b, Path path = Path::oracle);
/// ray-box-cast (Algorithm 3.3): the ray cast on the closed box (`unbounded_exit` when it never leaves).
Cast<double> cast(const Ray<double>& a, const Box<double>& b, Path path = Path::oracle);
/// ray-box-cast at float's rounding.
Cast<float> cast(const Ray<float>& a, const Box<float>& b, Path path = Path::oracle);
/// sphere-box: the ball against the box; `closest` is the box's point nearest the centre.
Proximity<double> proximity(const Sphere<double>& a, const Box<double>& b, Path path = Path::oracle);
/// sphere-box at float's rounding.
Proximity<float> proximity(const Sphere<float>& a, const Box<float>& b, Path path = Path::oracle);

/// ---- Section 3.3: separating axes ----
/// segment-box (Theorem 3.1): whether they meet, else the first separating axis and its direction.
Separation<double> separate(const Segment<double>& a, const Box<double>& b, Path path = Path::oracle);
/// segment-box at float's rounding.
Separation<float> separate(const Segment<float>& a, const Box<float>& b, Path path = Path::oracle);
/// ray-box (Theorem 3.1).
Separation<double> separate(const Ray<double>& a, const Box<double>& b, Path path = Path::oracle);
/// ray-box at float's rounding.
Separation<float> separate(const Ray<float>& a, const Box<float>& b, Path path = Path::oracle);
/// triangle-box (Theorem 3.1, 13 axes).
Separation<double> separate(const Triangle<double>& a, const Box<double>& b, Path path = Path::oracle);
/// triangle-box at float's rounding.
Separation<float> separate(const Triangle<float>& a, const Box<float>& b, Path path = Path::oracle);
/// obb-obb (Theorem 3.1, 15 axes) on the solids the boxes' axes span (primitives.hpp: OrientedBox).
Separation<double> separate(const OrientedBox<double>& a, const OrientedBox<double>& b, Path path = Path::oracle);
/// obb-obb at float's rounding.
Separation<float> separate(const OrientedBox<float>& a, const OrientedBox<float>& b, Path path = Path::oracle);
/// segment-obb (Theorem 3.1).
Separation<double> separate(const Segment<double>& a, const OrientedBox<double>& b, Path path = Path::oracle);
/// segment-obb at float's rounding.
Separation<float> separate(const Segment<float>& a, const OrientedBox<float>& b, Path path = Path::oracle);
/// triangle-obb (Theorem 3.1).
Separation<double> separate(const Triangle<double>& a, const OrientedBox<double>& b, Path path = Path::oracle);
/// triangle-obb at float's rounding.
Separation<float> separate(const Triangle<float>& a, const OrientedBox<float>& b, Path path = Path::oracle);
/// segment-obb-cast: the segment cast on the oriented box's solid.
Cast<double> cast(const Segment<double>& a, const OrientedBox<double>& b, Path path = Path::oracle);
/// segment-obb-cast at float's rounding.
Cast<float> cast(const Segment<float>& a, const OrientedBox<float>& b, Path path = Path::oracle);
/// ray-obb-cast: the ray cast on the oriented box's solid.
Cast<double> cast(const Ray<double>& a, const OrientedBox<double>& b, Path path = Path::oracle);
/// ray-obb-cast at float's rounding.
Cast<float> cast(const Ray<float>& a, const OrientedBox<float>& b, Path path = Path::oracle);
/// sphere-obb: the ball against the oriented box's solid; `closest` is the box's point nearest the centre.
Proximity<double> proximity(const Sphere<double>& a, const OrientedBox<double>& b, Path path = Path::oracle);
/// sphere-obb at float's rounding.
Proximity<float> proximity(const Sphere<float>& a, const OrientedBox<float>& b, Path path = Path::oracle);

/// ---- Section 3.4: triangles and polygons ----
/// sphere-triangle: the ball against the closed triangle; `closest` is the triangle's point nearest the centre.
Proximity<double> proximity(const Sphere<double>& a, const Triangle<double>& b, Path path = Path::oracle);
/// sphere-triangle at float's rounding.
Proximity<float> proximity(const Sphere<float>& a, const Triangle<float>& b, Path path = Path::oracle);
/// point-triangle: the triangle's point closest to p (witness_b and `closest`), its distance, and
/// `intersect`: p lies on the closed triangle (witness_a is p, depth 0).
Proximity<double> proximity(const Vec3<double>& p, const Triangle<double>& b, Path path = Path::oracle);
/// point-triangle at float's rounding.
Proximity<float> proximity(const Vec3<float>& p, const Triangle<float>& b, Path path = Path::oracle);
/// ray-triangle-cast: the ray on the closed two-sided triangle, with the barycentric u, v of the entry point.
TriangleCast<double> cast(const Ray<double>& a, const Triangle<double>& b, Path path = Path::oracle);
/// ray-triangle-cast at float's rounding.
TriangleCast<float> cast(const Ray<float>& a, const Triangle<float>& b, Path path = Path::oracle);
/// segment-triangle-cast: the segment on the closed two-sided triangle.
TriangleCast<double> cast(const Segment<double>& a, const Triangle<double>& b, Path path = Path::oracle);
/// segment-triangle-cast at float's rounding.
TriangleCast<float> cast(const Segment<float>& a, const Triangle<float>& b, Path path = Path::oracle);
/// ray-fan-cast: the ray on a fan of triangles (mesh level): the first hit and the number of triangles hit.
FanCast<double> cast(const Ray<double>& a, const Fan<double>& b, Path path = Path::oracle);
/// ray-fan-cast at float's rounding.
FanCast<float> cast(const Ray<float>& a, const Fan<float>& b, Path path = Path::oracle);
/// segment-fan-cast: the segment on a fan of triangles.
FanCast<double> cast(const Segment<double>& a, const Fan<double>& b, Path path = Path::oracle);
/// segment-fan-cast at float's rounding.
FanCast<float> cast(const Segment<float>& a, const Fan<float>& b, Path path = Path::oracle);
/// triangle-triangle: whether they meet, whether coplanar, and the ends p, q of their intersection segment.
TriangleIntersection<double> intersect(const Triangle<double>& a, const Triangle<double>& b, Path path = Path::oracle);
/// triangle-triangle at float's rounding.
TriangleIntersection<float> intersect(const Triangle<float>& a, const Triangle<float>& b, Path path = Path::oracle);
/// ray-polygon-cast: the ray on the polygon (the union of its fan triangles, primitives.hpp).
Cast<double> cast(const Ray<double>& a, const Polygon<double>& b, Path path = Path::oracle);
/// ray-polygon-cast at float's rounding.
Cast<float> cast(const Ray<float>& a, const Polygon<float>& b, Path path = Path::oracle);
/// segment-polygon-cast: the segment on the polygon.
Cast<double> cast(const Segment<double>& a, const Polygon<double>& b, Path path = Path::oracle);
/// segment-polygon-cast at float's rounding.
Cast<float> cast(const Segment<float>& a, const Polygon<float>& b, Path path = Path::oracle);
/// polygon-polygon: whether two polygons share a point.
bool intersect(const Polygon<double>& a, const Polygon<double>& b, Path path = Path::oracle);
/// polygon-polygon on float inputs.
bool intersect(const Polygon<float>& a, const Polygon<float>& b, Path path = Path::oracle);
/// polygon-box: whether the polygon meets the closed box.
bool intersect(const Polygon<double>& a, const Box<double>& b, Path path = Path::oracle);
/// polygon-box on float inputs.
bool intersect(const Polygon<float>& a, const Box<float>& b, Path path = Path::oracle);
/// polygon-obb: whether the polygon meets the parallelepiped the oriented box's inputs define
/// (its axes need not be orthonormal; the exact answer for the solid they span).
bool intersect(const Polygon<double>& a, const OrientedBox<double>& b, Path path = Path::oracle);
/// polygon-obb on float inputs.
bool intersect(const Polygon<float>& a, const OrientedBox<float>& b, Path path = Path::oracle);
/// polygon-sphere: the ball against the polygon (witness_a on the ball, witness_b on the polygon).
Proximity<double> proximity(const Sphere<double>& a, const Polygon<double>& b, Path path = Path::oracle);
/// polygon-sphere at float's rounding.
Proximity<float> proximity(const Sphere<float>& a, const Polygon<float>& b, Path path = Path::oracle);

/// ---- the other argument order of the symmetric pairs ----
/// box-sphere: sphere-box with the witnesses swapped (witness_a on the box).
template <class F> Proximity<F> proximity(const Box<F>& a, const Sphere<F>& b, Path path = Path::oracle) { return detail::swapped(proximity(b, a, path)); }
/// obb-sphere: sphere-obb with the witnesses swapped.
template <class F> Proximity<F> proximity(const OrientedBox<F>& a, const Sphere<F>& b, Path path = Path::oracle) { return detail::swapped(proximity(b, a, path)); }
/// triangle-sphere: sphere-triangle with the witnesses swapped.
template <class F> Proximity<F> proximity(const Triangle<F>& a, const Sphere<F>& b, Path path = Path::oracle) { return detail::swapped(proximity(b, a, path)); }
/// polygon-sphere in the query's own order: sphere-polygon with the witnesses swapped.
template <class F> Proximity<F> proximity(const Polygon<F>& a, const Sphere<F>& b, Path path = Path::oracle) { return detail::swapped(proximity(b, a, path)); }
/// sphere-segment: segment-sphere with the witnesses swapped.
template <class F> Proximity<F> proximity(const Sphere<F>& a, const Segment<F>& b, Path path = Path::oracle) { return detail::swapped(proximity(b, a, path)); }
/// box-segment: segment-box (the axes keep the query's order and numbering).
template <class F> Separation<F> separate(const Box<F>& a, const Segment<F>& b, Path path = Path::oracle) { return separate(b, a, path); }
/// box-ray: ray-box.
template <class F> Separation<F> separate(const Box<F>& a, const Ray<F>& b, Path path = Path::oracle) { return separate(b, a, path); }
/// box-triangle: triangle-box.
template <class F> Separation<F> separate(const Box<F>& a, const Triangle<F>& b, Path path = Path::oracle) { return separate(b, a, path); }
/// obb-segment: segment-obb.
template <class F> Separation<F> separate(const OrientedBox<F>& a, const Segment<F>& b, Path path = Path::oracle) { return separate(b, a, path); }
/// obb-triangle: triangle-obb.
template <class F> Separation<F> separate(const OrientedBox<F>& a, const Triangle<F>& b, Path path = Path::oracle) { return separate(b, a, path); }
/// box-polygon: polygon-box.
template <class F> bool intersect(const Box<F>& a, const Polygon<F>& b, Path path = Path::oracle) { return intersect(b, a, path); }
/// obb-polygon: polygon-obb.
template <class F> bool intersect(const OrientedBox<F>& a, const Polygon<F>& b, Path path = Path::oracle) { return intersect(b, a, path); }
/// triangle-point: point-triangle with the witnesses swapped (witness_a the closest point).
template <class F> Proximity<F> proximity(const Triangle<F>& a, const Vec3<F>& b, Path path = Path::oracle) { return detail::swapped(proximity(b, a, path)); }

/// ---- any pair, by its primitives ----
/// The query on (a, b) whatever its kind: cast, proximity, separate or intersect, as declared
/// above for that pair of primitives (the generic entry of the test matchers).
template <class A, class B>
auto answer(const A& a, const B& b, Path path = Path::oracle) {
  if constexpr (requires { cast(a, b, path); })
    return cast(a, b, path);
  else if constexpr (requires { proximity(a, b, path); })
    return proximity(a, b, path);
  else if constexpr (requires { separate(a, b, path); })
    return separate(a, b, path);
  else
    return intersect(a, b, path);
}

}  // namespace cdref::truth
