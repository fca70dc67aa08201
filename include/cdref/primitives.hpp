/// \file
/// cdref/primitives.hpp - the chapter's primitives as plain structs over a number type T,
/// and the checks that reject input outside a query's domain.
///
///   Sphere<T>      centre c, radius rho >= 0 (rho = 0 is a point).
///   Box<T>         axis-aligned, centre-extent: [c - h, c + h], h >= 0 (a zero extent is a
///                  flat box).
///   MinMaxBox<T>   axis-aligned, min-max: [p, q], p <= q. to_min_max / to_center_extent
///                  convert (exactly at exact types; with rounding at float types).
///   Segment<T>     the chapter's "ray" s->t: points s + lambda (t - s), lambda in [0, 1].
///                  s = t is allowed (a point).
///   Ray<T>         the infinite ray: points s + lambda d, lambda >= 0, d != 0. The chapter
///                  takes d of unit length; cdref accepts any nonzero d, and lambda is then
///                  measured in units of |d|.
///   Triangle<T>    vertices v0, v1, v2: the closed, two-sided triangle (edges and vertices
///                  belong to it). A triangle of zero area is the segment or the point its
///                  vertices span, and every query treats it as that set; it is not an error.
///   Polygon<T>     3 to 8 vertices: the union of the fan triangles (v0, v_i, v_i+1), which for a
///                  convex planar polygon is the polygon (closed, two-sided); see the struct.
///   OrientedBox<T> centre c, extents h >= 0 and three axes a_0, a_1, a_2: the solid
///                  {c + sum_i t_i h_i a_i : |t_i| <= 1}. Axes given as floats are orthonormal
///                  only to rounding (the only exactly orthonormal matrices with dyadic entries
///                  are the signed permutations), so the solid is in general a
///                  parallelepiped, and that set is what the box means: its face normals are
///                  a_1 x a_2, a_2 x a_0, a_0 x a_1 and its edge directions the axes. The axes
///                  must be linearly independent (decided exactly: det[a_0 a_1 a_2] != 0);
///                  they need not be unit or orthogonal. A zero extent is a flat box.
///
/// The algorithms follow the chapter in working in the local coordinates of the sphere
/// or box (its centre at the origin); the structs place it anywhere in space, and a
/// query subtracts the centre first.
#pragma once

#include <cstdio>
#include <string>
#include <type_traits>

#include <array>

#include "det_sign.hpp"
#include "error.hpp"
#include "number_traits.hpp"
#include "vec.hpp"

namespace cdref {

/// A sphere (a solid ball): centre c and radius rho >= 0; rho = 0 is a point.
template <class T>
struct Sphere {
  Vec3<T> center;  ///< the centre c
  T radius;        ///< the radius rho >= 0
};

/// An axis-aligned box in centre-extent form: [c - h, c + h], h >= 0 (a zero extent is a flat box).
template <class T>
struct Box {
  Vec3<T> center;  ///< the centre c
  Vec3<T> extent;  ///< the half-widths h >= 0 along x, y and z
};

/// An axis-aligned box in min-max form: [p, q], p <= q component by component.
template <class T>
struct MinMaxBox {
  Vec3<T> min;  ///< the lower corner p
  Vec3<T> max;  ///< the upper corner q
};

/// The chapter's "ray" s->t: the points s + lambda (t - s), lambda in [0, 1]; s = t is a point.
template <class T>
struct Segment {
  Vec3<T> source;  ///< s, where lambda = 0
  Vec3<T> target;  ///< t, where lambda = 1
};

/// The infinite ray: the points s + lambda d, lambda >= 0, d != 0; lambda is in units of |d|.
template <class T>
struct Ray {
  Vec3<T> source;     ///< s, where lambda = 0
  Vec3<T> direction;  ///< d, any nonzero vector
};

/// A closed, two-sided triangle; a triangle of zero area is the segment or point it spans.
template <class T>
struct Triangle {
  std::array<Vec3<T>, 3> vertex;  ///< v0, v1, v2
};

/// A polygon of 3 to 8 vertices (Section 3.4): the union of the fan triangles
/// (v0, v_i, v_i+1), i = 1 .. n - 2. For a convex planar polygon (the chapter's) that is the
/// polygon, closed and two-sided. Any other vertex list (not planar, not convex, with repeated or
/// collinear vertices) is that fan: a well-defined set, the same at every number type, so no
/// vertex list is refused for its shape; only n outside 3..8 and non-finite coordinates are.
template <class T>
struct Polygon {
  static constexpr int max_vertices = 8;       ///< at most this many vertices
  std::array<Vec3<T>, max_vertices> vertex{};  ///< v0 .. v(n-1); those from n on are unused
  int n = 0;                                   ///< vertices in use, 3 to 8
  /// The number of fan triangles, n - 2.
  int triangles() const { return n - 2; }
  /// Fan triangle k: (v0, v(k+1), v(k+2)), k = 0 .. n - 3.
  Triangle<T> triangle(int k) const { return {{vertex[0], vertex[k + 1], vertex[k + 2]}}; }
};

/// An oriented box: the solid {c + sum_i t_i h_i a_i : |t_i| <= 1}, a parallelepiped when the axes
/// are not exactly orthonormal. The axes must be linearly independent; they need not be unit or
/// orthogonal (see the file's comment).
template <class T>
struct OrientedBox {
  Vec3<T> center;               ///< the centre c
  Vec3<T> extent;               ///< the extents h >= 0 along the three axes
  std::array<Vec3<T>, 3> axis;  ///< the axes a_0, a_1, a_2
};

/// The same box in min-max form, [c - h, c + h] (rounded at float types).
template <class T>
MinMaxBox<T> to_min_max(const Box<T>& b) {
  return {Vec3<T>(b.center - b.extent), Vec3<T>(b.center + b.extent)};
}

/// The same box in centre-extent form, c = (p + q) / 2, h = (q - p) / 2 (rounded at float types).
template <class T>
Box<T> to_center_extent(const MinMaxBox<T>& b) {
  Vec3<T> c, h;
  for (int i = 0; i < 3; ++i) {
    c[i] = (b.min[i] + b.max[i]) / T(2);
    h[i] = (b.max[i] - b.min[i]) / T(2);
  }
  return {c, h};
}

/// ---------------------------------------------------------------------------
/// Input checks. Each throws cdref::invalid_input naming the argument, the field
/// and the offending value.
namespace detail {

template <class T>
std::string show(const T& x) {
  const double d = number_traits<T>::to_double(x);
  if (d != d) return "nan";  // whatever the sign bit of the NaN
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", d);
  return buf;
}

inline const char* axis_name(int i) { return i == 0 ? "x" : (i == 1 ? "y" : "z"); }

/// The message is built only when a check fails, out of line: a valid input costs a few
/// subtractions and one branch. For IEEE types x - x is 0 exactly when x is finite (NaN for an
/// infinity or a NaN), so the sum of the three differences is 0 exactly when a vector is finite.
template <class T>
[[noreturn, gnu::cold, gnu::noinline]] void not_finite(const T& x, const char* name, const char* field) {
  throw invalid_input(std::string(name) + " " + field + " is not finite (" + show(x) + ")");
}
template <class T>
[[noreturn, gnu::cold, gnu::noinline]] void not_finite(const Vec3<T>& v, const char* name, const char* field) {
  int i = 0;
  while (i < 2 && number_traits<T>::is_finite(v[i])) ++i;
  throw invalid_input(std::string(name) + (*field ? " " : "") + field + " has a non-finite " + axis_name(i) +
                      " coordinate (" + show(v[i]) + ")");
}
template <class T>
[[noreturn, gnu::cold, gnu::noinline]] void negative(const T& x, const char* name, const char* what) {
  throw invalid_input(std::string(name) + " " + what + " (" + show(x) + ")");
}
/// "<name> <what> <where> (<x>)", e.g. "box extent is negative along y (-1)"
template <class T>
[[noreturn, gnu::cold, gnu::noinline]] void negative_along(const T& x, const char* name, const char* what,
                                                          const std::string& where) {
  throw invalid_input(std::string(name) + " " + what + " " + where + " (" + show(x) + ")");
}
template <class T>
[[noreturn, gnu::cold, gnu::noinline]] void inverted(const T& lo, const T& hi, const char* name, int i) {
  throw invalid_input(std::string(name) + " is inverted along " + axis_name(i) + " (min " + show(lo) + " > max " +
                      show(hi) + ")");
}
[[noreturn, gnu::cold, gnu::noinline]] inline void fail(const char* name, const char* what) {
  throw invalid_input(std::string(name) + " " + what);
}

template <class T>
void check_finite(const T& x, const char* name, const char* field) {
  if (!number_traits<T>::is_finite(x)) [[unlikely]]
    not_finite(x, name, field);
}

template <class T>
void check_finite(const Vec3<T>& v, const char* name, const char* field) {
  if constexpr (std::is_floating_point_v<T>) {
    if (!(T(T(v[0] - v[0]) + T(v[1] - v[1])) + T(v[2] - v[2]) == T(0))) [[unlikely]]
      not_finite(v, name, field);
  } else {
    for (int i = 0; i < 3; ++i)
      if (!number_traits<T>::is_finite(v[i])) [[unlikely]]
        not_finite(v, name, field);
  }
}

}  // namespace detail

/// Checks a primitive before a query: A sphere: finite centre and radius, radius >= 0.
/// Throws cdref::invalid_input naming the argument (`name`), the field and the value.
template <class T>
void check(const Sphere<T>& s, const char* name = "sphere") {
  detail::check_finite(s.center, name, "centre");
  detail::check_finite(s.radius, name, "radius");
  if (s.radius < T(0)) [[unlikely]]
    detail::negative(s.radius, name, "radius is negative");
}

/// Checks a primitive before a query: An axis-aligned box: finite centre and extents, extents >= 0.
/// Throws cdref::invalid_input naming the argument (`name`), the field and the value.
template <class T>
void check(const Box<T>& b, const char* name = "box") {
  detail::check_finite(b.center, name, "centre");
  detail::check_finite(b.extent, name, "extent");
  for (int i = 0; i < 3; ++i)
    if (b.extent[i] < T(0)) [[unlikely]]
      detail::negative_along(b.extent[i], name, "extent is negative along", detail::axis_name(i));
}

/// Checks a primitive before a query: A min-max box: finite corners, min <= max on every axis.
/// Throws cdref::invalid_input naming the argument (`name`), the field and the value.
template <class T>
void check(const MinMaxBox<T>& b, const char* name = "box") {
  detail::check_finite(b.min, name, "min corner");
  detail::check_finite(b.max, name, "max corner");
  for (int i = 0; i < 3; ++i)
    if (b.max[i] < b.min[i]) [[unlikely]]
      detail::inverted(b.min[i], b.max[i], name, i);
}

/// Checks a primitive before a query: A segment: finite source and target (source = target is allowed).
/// Throws cdref::invalid_input naming the argument (`name`), the field and the value.
template <class T>
void check(const Segment<T>& s, const char* name = "segment") {
  detail::check_finite(s.source, name, "source");
  detail::check_finite(s.target, name, "target");
}

/// Checks a primitive before a query: A ray: finite source and direction, the direction not the
/// zero vector. Throws cdref::invalid_input naming the argument (`name`), the field and the value.
template <class T>
void check(const Ray<T>& r, const char* name = "ray") {
  detail::check_finite(r.source, name, "source");
  detail::check_finite(r.direction, name, "direction");
  if (r.direction[0] == T(0) && r.direction[1] == T(0) && r.direction[2] == T(0)) [[unlikely]]
    detail::fail(name, "direction is the zero vector");
}

/// A point (a Vec3 as a query's argument): finite.
template <class T>
void check(const Vec3<T>& p, const char* name = "point") {
  detail::check_finite(p, name, "");  // "point has a non-finite x coordinate (nan)"
}

/// Checks a primitive before a query: A triangle: finite vertices (zero area is allowed).
/// Throws cdref::invalid_input naming the argument (`name`), the field and the value.
template <class T>
void check(const Triangle<T>& t, const char* name = "triangle") {
  static const char* const field[3] = {"vertex 0", "vertex 1", "vertex 2"};
  for (int k = 0; k < 3; ++k) detail::check_finite(t.vertex[k], name, field[k]);
}

/// Checks a primitive before a query: A polygon: 3 to 8 vertices, each finite.
/// Throws cdref::invalid_input naming the argument (`name`), the field and the value.
template <class T>
void check(const Polygon<T>& p, const char* name = "polygon") {
  if (p.n < 3 || p.n > Polygon<T>::max_vertices)
    throw invalid_input(std::string(name) + " has " + std::to_string(p.n) + " vertices (3 to 8 are allowed)");
  static const char* const field[8] = {"vertex 0", "vertex 1", "vertex 2", "vertex 3",
                                       "vertex 4", "vertex 5", "vertex 6", "vertex 7"};
  for (int k = 0; k < p.n; ++k) detail::check_finite(p.vertex[k], name, field[k]);
}

/// check(OrientedBox) that also returns the sign of det[a0 a1 a2] (1 or -1), which it decides
/// anyway (the oracle's oriented-box entry takes it: oracle/enter_obb.hpp).
template <class T>
int checked_orientation(const OrientedBox<T>& b, const char* name = "oriented box") {
  static const char* const field[3] = {"axis 0", "axis 1", "axis 2"};
  detail::check_finite(b.center, name, "centre");
  detail::check_finite(b.extent, name, "extent");
  for (int k = 0; k < 3; ++k) detail::check_finite(b.axis[k], name, field[k]);
  for (int i = 0; i < 3; ++i)
    if (b.extent[i] < T(0)) [[unlikely]]
      detail::negative_along(b.extent[i], name, "extent is negative along", "axis " + std::to_string(i));
  const int det = det3_sign(b.axis[0], b.axis[1], b.axis[2]);
  if (det == 0) [[unlikely]]
    detail::fail(name, "axes are linearly dependent (det[a0 a1 a2] = 0 exactly)");
  return det;
}
/// Checks a primitive before a query: An oriented box: finite centre, extents >= 0, finite and
/// linearly independent axes (decided exactly). Throws cdref::invalid_input naming the argument
/// (`name`), the field and the value.
template <class T>
void check(const OrientedBox<T>& b, const char* name = "oriented box") {
  checked_orientation(b, name);
}

}  // namespace cdref
