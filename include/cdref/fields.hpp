// cdref/fields.hpp - the members of every primitive and every result, for code that treats
// them all alike: converting a primitive to another number type, rounding a result, comparing
// two results field by field.
//
//   members(p)             the primitive's members as a tuple of references (std::tie), in
//                          declaration order;
//   rebind<T>(p)           the same primitive over T, each coordinate converted by T(x) (exact
//                          from double to every exact type cdref uses, and to float with
//                          rounding);
//   zip_fields(a, b, f)    for two results of one kind (Cast, TriangleCast, FanCast, Proximity,
//                          TriangleIntersection, Separation), possibly over different number
//                          types, calls f(name, a's field, b's field) for each field, named as the
//                          case files' answer columns name it ("lambda_enter", "witness_a", ...).
//                          A FanCast's fields are its first hit's, then "hits".
#pragma once

#include <array>
#include <tuple>
#include <type_traits>

#include "fan.hpp"
#include "primitives.hpp"
#include "results.hpp"

namespace cdref {

// ---- primitives ----
/// A primitive's members as a tuple of references (std::tie), in declaration order.
template <class T> auto members(Sphere<T>& p) { return std::tie(p.center, p.radius); }
template <class T> auto members(const Sphere<T>& p) { return std::tie(p.center, p.radius); }
template <class T> auto members(Box<T>& p) { return std::tie(p.center, p.extent); }
template <class T> auto members(const Box<T>& p) { return std::tie(p.center, p.extent); }
template <class T> auto members(Segment<T>& p) { return std::tie(p.source, p.target); }
template <class T> auto members(const Segment<T>& p) { return std::tie(p.source, p.target); }
template <class T> auto members(Ray<T>& p) { return std::tie(p.source, p.direction); }
template <class T> auto members(const Ray<T>& p) { return std::tie(p.source, p.direction); }
template <class T> auto members(Triangle<T>& p) { return std::tie(p.vertex); }
template <class T> auto members(const Triangle<T>& p) { return std::tie(p.vertex); }
template <class T> auto members(Polygon<T>& p) { return std::tie(p.vertex, p.n); }
template <class T> auto members(const Polygon<T>& p) { return std::tie(p.vertex, p.n); }
template <class T> auto members(OrientedBox<T>& p) { return std::tie(p.center, p.extent, p.axis); }
template <class T> auto members(const OrientedBox<T>& p) { return std::tie(p.center, p.extent, p.axis); }
template <class T> auto members(Fan<T>& p) { return std::tie(p.center, p.ring, p.n, p.closed); }
template <class T> auto members(const Fan<T>& p) { return std::tie(p.center, p.ring, p.n, p.closed); }

namespace detail {
// one member converted: a coordinate by T(x), a vector and an array element-wise, a count or a
// flag copied
template <class D, class S>
void convert_member(D& d, const S& s) {
  if constexpr (std::is_same_v<S, int> || std::is_same_v<S, bool>) {
    d = s;
  } else if constexpr (requires { s.size(); s[0]; typename S::value_type; } && !requires { s.rows(); }) {
    for (std::size_t i = 0; i < s.size(); ++i) convert_member(d[i], s[i]);
  } else if constexpr (requires { s.rows(); }) {
    for (int i = 0; i < 3; ++i) d[i] = typename D::Scalar(s[i]);
  } else {
    d = D(s);
  }
}
}  // namespace detail

/// The primitive p over the number type T (each coordinate converted by T(x)).
template <class T, template <class> class P, class U>
P<T> rebind(const P<U>& p) {
  P<T> out{};
  auto dst = members(out);
  const auto src = members(p);
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    (detail::convert_member(std::get<I>(dst), std::get<I>(src)), ...);
  }(std::make_index_sequence<std::tuple_size_v<decltype(src)>>{});
  return out;
}

/// A point over T (a Vec3 as a query's argument), each coordinate converted by T(x).
template <class T, class U>
Vec3<T> rebind(const Vec3<U>& p) {
  return Vec3<T>(T(p[0]), T(p[1]), T(p[2]));
}
/// A polygon over T: its n vertices converted, the unused ones zero (they may hold anything).
template <class T, class U>
Polygon<T> rebind(const Polygon<U>& p) {
  Polygon<T> out;
  out.n = p.n;
  for (int k = 0; k < Polygon<T>::max_vertices; ++k)
    out.vertex[k] = k < p.n ? Vec3<T>(T(p.vertex[k][0]), T(p.vertex[k][1]), T(p.vertex[k][2])) : zero_vec<T>();
  return out;
}
/// A fan over T: its n ring vertices converted, the unused ones zero.
template <class T, class U>
Fan<T> rebind(const Fan<U>& f) {
  Fan<T> out;
  out.n = f.n;
  out.closed = f.closed;
  out.center = Vec3<T>(T(f.center[0]), T(f.center[1]), T(f.center[2]));
  for (int k = 0; k < Fan<T>::max_ring; ++k)
    out.ring[k] = k < f.n ? Vec3<T>(T(f.ring[k][0]), T(f.ring[k][1]), T(f.ring[k][2])) : zero_vec<T>();
  return out;
}

// ---- results ----
/// Calls f(name, a.field, b.field) for each field of two casts (see the file's comment).
template <class S, class B, class Fn>
void zip_fields(const Cast<S>& a, B&& b, Fn&& f) {
  f("hit", a.hit, b.hit);
  f("enters", a.enters, b.enters);
  f("unbounded_exit", a.unbounded_exit, b.unbounded_exit);
  f("lambda_enter", a.lambda_enter, b.lambda_enter);
  f("lambda_exit", a.lambda_exit, b.lambda_exit);
  f("point", a.point, b.point);
  f("normal", a.normal, b.normal);
}
/// ... of two triangle casts: a cast's fields, then u and v.
template <class S, class B, class Fn>
void zip_fields(const TriangleCast<S>& a, B&& b, Fn&& f) {
  zip_fields(static_cast<const Cast<S>&>(a), b, f);
  f("u", a.u, b.u);
  f("v", a.v, b.v);
}
/// ... of two casts on a fan: the first hit's fields, then the number of triangles hit.
template <class S, class B, class Fn>
void zip_fields(const FanCast<S>& a, B&& b, Fn&& f) {
  zip_fields(a.first, b.first, f);
  f("hits", a.hits, b.hits);
}
/// ... of two proximity results.
template <class S, class B, class Fn>
void zip_fields(const Proximity<S>& a, B&& b, Fn&& f) {
  f("intersect", a.intersect, b.intersect);
  f("distance", a.distance, b.distance);
  f("depth", a.depth, b.depth);
  f("witness_a", a.on_a, b.on_a);
  f("witness_b", a.on_b, b.on_b);
  f("closest", a.closest, b.closest);
}
/// ... of two triangle-triangle results.
template <class S, class B, class Fn>
void zip_fields(const TriangleIntersection<S>& a, B&& b, Fn&& f) {
  f("intersect", a.intersect, b.intersect);
  f("coplanar", a.coplanar, b.coplanar);
  f("p", a.p, b.p);
  f("q", a.q, b.q);
}
/// ... of two separating-axis results.
template <class S, class B, class Fn>
void zip_fields(const Separation<S>& a, B&& b, Fn&& f) {
  f("intersect", a.intersect, b.intersect);
  f("axis", a.axis, b.axis);
  f("direction", a.direction, b.direction);
}

/// The classification of any result: hit for a cast, intersect otherwise (a bool is its own).
template <class S> bool classification_of(const Cast<S>& r) { return r.hit; }
template <class S> bool classification_of(const FanCast<S>& r) { return r.first.hit; }
template <class S> bool classification_of(const Proximity<S>& r) { return r.intersect; }
template <class S> bool classification_of(const TriangleIntersection<S>& r) { return r.intersect; }
template <class S> bool classification_of(const Separation<S>& r) { return r.intersect; }
inline bool classification_of(bool r) { return r; }

}  // namespace cdref
