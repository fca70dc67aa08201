/// \file
/// cdref/fields.hpp - the members of every primitive and every result, for code that treats
/// them all alike: converting a primitive to another number type, scaling it, rounding a result,
/// comparing two results field by field. A primitive is described here once (members, lengths,
/// directions); every generic operation below and in the robust tier derives from that.
///
///   members(p)             the primitive's members as a tuple of references (std::tie), in
///                          declaration order;
///   lengths(p)             the members that scale with the primitive (its coordinates, extents,
///                          radii, a ray's direction; a polygon's and a fan's first n vertices as
///                          a span), as a tuple of references;
///   directions(p)          the members that do not (an oriented box's unit axes; empty for the
///                          others);
///   for_each_length(p, f), for_each_value(p, f)
///                          f(x) for every scalar and every point among the lengths (and the
///                          directions, for_each_value), arrays and spans element by element;
///   rebind<T>(p)           the same primitive over T, each coordinate converted by T(x) (exact
///                          from double to every exact type cdref uses, and to float with
///                          rounding); rebind_with<T>(p, conv) converts each by conv(x);
///   zip_fields(a, b, f)    for two results of one kind (Cast, TriangleCast, FanCast, Proximity,
///                          TriangleIntersection, Separation), possibly over different number
///                          types, calls f(name, a's field, b's field) for each field, named as the
///                          case files' answer columns name it ("lambda_enter", "witness_a", ...).
///                          A FanCast's fields are its first hit's, then "hits";
///   rounded_by<F>(r, round) a result over any number type with each field converted to F by
///                          round(x) (a bool or an int field is its own).
///
/// A new primitive gives its members() and lengths() here (and directions() if it has any): the
/// robust tier's scaling, its double-word lift, the input conversions and the tests' helpers
/// then handle it. The functions are found by argument-dependent lookup where they are used, so
/// a primitive declared in a query's own header (in namespace cdref) can give them there.
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <span>
#include <tuple>
#include <type_traits>

#include "fan.hpp"
#include "primitives.hpp"
#include "results.hpp"

namespace cdref {

/// ---- primitives ----
namespace detail {
template <template <class> class K, class T>
void kind_of(const K<T>&);
/// the vertices a polygon or a fan uses: n, kept within its array (a polygon not yet checked may
/// say anything: nothing outside the array is read)
constexpr std::size_t in_use(int n, int max) { return std::size_t(n < 0 ? 0 : n > max ? max : n); }
}  // namespace detail
/// P is a K<T> for some T, const or not (a primitive's description below takes either).
template <class P, template <class> class K>
concept is_a = requires(const P& p) { detail::kind_of<K>(p); };

/// A primitive's members as a tuple of references (std::tie), in declaration order; and its
/// lengths, the members that scale with it (see the file's comment): one pair of lines a
/// primitive.
template <is_a<Sphere> P> auto members(P& p) { return std::tie(p.center, p.radius); }
/// A primitive's lengths: the members that scale with it (one overload a primitive, beside members()).
template <is_a<Sphere> P> auto lengths(P& p) { return std::tie(p.center, p.radius); }
template <is_a<Box> P> auto members(P& p) { return std::tie(p.center, p.extent); }
template <is_a<Box> P> auto lengths(P& p) { return std::tie(p.center, p.extent); }
template <is_a<Segment> P> auto members(P& p) { return std::tie(p.source, p.target); }
template <is_a<Segment> P> auto lengths(P& p) { return std::tie(p.source, p.target); }
template <is_a<Ray> P> auto members(P& p) { return std::tie(p.source, p.direction); }
template <is_a<Ray> P> auto lengths(P& p) { return std::tie(p.source, p.direction); }
template <is_a<Triangle> P> auto members(P& p) { return std::tie(p.vertex); }
template <is_a<Triangle> P> auto lengths(P& p) { return std::tie(p.vertex); }
template <is_a<OrientedBox> P> auto members(P& p) { return std::tie(p.center, p.extent, p.axis); }
template <is_a<OrientedBox> P> auto lengths(P& p) { return std::tie(p.center, p.extent); }
template <is_a<Polygon> P> auto members(P& p) { return std::tie(p.vertex, p.n); }
template <is_a<Polygon> P> auto lengths(P& p) { return std::make_tuple(std::span(p.vertex.data(), detail::in_use(p.n, p.max_vertices))); }
template <is_a<Fan> P> auto members(P& p) { return std::tie(p.center, p.ring, p.n, p.closed); }
template <is_a<Fan> P> auto lengths(P& p) { return std::make_tuple(std::ref(p.center), std::span(p.ring.data(), detail::in_use(p.n, p.max_ring))); }

/// The members of a primitive that do not scale with it: an oriented box's unit axes.
template <class T> auto directions(OrientedBox<T>& p) { return std::tie(p.axis); }
/// The same, for a const oriented box.
template <class T> auto directions(const OrientedBox<T>& p) { return std::tie(p.axis); }
/// ... none for the other primitives.
template <class P> std::tuple<> directions(const P&) { return {}; }

namespace detail {
/// f(x) for a scalar or a point x, and for each element of an array or a span of them
template <class X, class Fn>
void each_value(X&& x, Fn& f) {
  using D = std::remove_cvref_t<X>;
  if constexpr (requires { x.rows(); } || std::is_arithmetic_v<D> || !requires { x.size(); x[0]; }) {
    f(x);
  } else {
    for (auto&& e : x) each_value(e, f);
  }
}
template <class Tuple, class Fn>
void each_in(Tuple&& t, Fn& f) {
  std::apply([&](auto&&... x) { (each_value(x, f), ...); }, std::forward<Tuple>(t));
}
}  // namespace detail

/// f(x) for every scalar and point among p's lengths, in declaration order.
template <class P, class Fn>
void for_each_length(P& p, Fn&& f) {
  detail::each_in(lengths(p), f);
}
/// f(x) for every scalar and point among p's lengths, then among its directions.
template <class P, class Fn>
void for_each_value(P& p, Fn&& f) {
  detail::each_in(lengths(p), f);
  detail::each_in(directions(p), f);
}

/// Whether a and b are equal member by member: a scalar by == (NaN equals nothing), a point
/// coordinate by coordinate, an array or a span element by element (two spans of different
/// lengths differ).
template <class X, class Y>
bool same_value(const X& a, const Y& b) {
  using D = std::remove_cvref_t<X>;
  if constexpr (requires { a.rows(); } || std::is_arithmetic_v<D> || !requires { a.size(); a[0]; }) {
    return a == b;
  } else {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
      if (!same_value(a[i], b[i])) return false;
    return true;
  }
}
namespace detail {
template <class TX, class TY>
bool same_in(const TX& x, const TY& y) {
  return [&]<std::size_t... I>(std::index_sequence<I...>) {
    return (same_value(std::get<I>(x), std::get<I>(y)) && ...);
  }(std::make_index_sequence<std::tuple_size_v<TX>>{});
}
}  // namespace detail
/// Whether two primitives of one kind have the same lengths (a scaling's round trip was exact).
template <class P>
bool same_lengths(const P& a, const P& b) {
  return detail::same_in(lengths(a), lengths(b));
}
/// Whether two primitives of one kind have the same members (a conversion's round trip was exact).
template <class P>
bool same_members(const P& a, const P& b) {
  return detail::same_in(members(a), members(b));
}

template <class T, template <class> class P, class U, class Conv>
P<T> rebind_with(const P<U>& p, Conv&& conv);

namespace detail {
/// one member converted: a coordinate by conv(x), a vector and an array element-wise, a nested
/// primitive by rebind_with, a count or a flag copied
template <class T, class D, class S, class Conv>
void convert_member(D& d, const S& s, Conv& conv) {
  if constexpr (std::is_same_v<S, int> || std::is_same_v<S, bool>) {
    d = s;
  } else if constexpr (requires { s.rows(); }) {
    for (int i = 0; i < 3; ++i) d[i] = conv(s[i]);
  } else if constexpr (requires { s.size(); s[0]; typename S::value_type; }) {
    for (std::size_t i = 0; i < s.size(); ++i) convert_member<T>(d[i], s[i], conv);
  } else if constexpr (requires { members(s); }) {
    d = rebind_with<T>(s, conv);
  } else {
    d = conv(s);
  }
}
}  // namespace detail

/// The primitive p over the number type T, each coordinate converted by conv(x) (a count or a
/// flag copied).
template <class T, template <class> class P, class U, class Conv>
P<T> rebind_with(const P<U>& p, Conv&& conv) {
  P<T> out{};
  auto dst = members(out);
  const auto src = members(p);
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    (detail::convert_member<T>(std::get<I>(dst), std::get<I>(src), conv), ...);
  }(std::make_index_sequence<std::tuple_size_v<decltype(src)>>{});
  return out;
}
/// A point over T, each coordinate converted by conv(x).
template <class T, class U, class Conv>
Vec3<T> rebind_with(const Vec3<U>& p, Conv&& conv) {
  return Vec3<T>(conv(p[0]), conv(p[1]), conv(p[2]));
}
/// A polygon over T: its n vertices converted, the unused ones zero (they may hold anything).
template <class T, class U, class Conv>
Polygon<T> rebind_with(const Polygon<U>& p, Conv&& conv) {
  Polygon<T> out;
  out.n = p.n;
  for (int k = 0; k < Polygon<T>::max_vertices; ++k)
    out.vertex[k] = k < p.n ? rebind_with<T>(p.vertex[k], conv) : zero_vec<T>();
  return out;
}
/// A fan over T: its n ring vertices converted, the unused ones zero.
template <class T, class U, class Conv>
Fan<T> rebind_with(const Fan<U>& f, Conv&& conv) {
  Fan<T> out;
  out.n = f.n;
  out.closed = f.closed;
  out.center = rebind_with<T>(f.center, conv);
  for (int k = 0; k < Fan<T>::max_ring; ++k) out.ring[k] = k < f.n ? rebind_with<T>(f.ring[k], conv) : zero_vec<T>();
  return out;
}

/// The primitive (or the point) p over the number type T, each coordinate converted by T(x).
template <class T, class P>
auto rebind(const P& p) {
  return rebind_with<T>(p, [](const auto& x) { return T(x); });
}

/// ---- results ----
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
template <class S> bool classification_of(const FanCast<S>& r) { return r.first.hit; }  ///< as above
template <class S> bool classification_of(const Proximity<S>& r) { return r.intersect; }  ///< as above
template <class S> bool classification_of(const TriangleIntersection<S>& r) { return r.intersect; }  ///< as above
template <class S> bool classification_of(const Separation<S>& r) { return r.intersect; }  ///< as above
inline bool classification_of(bool r) { return r; }  ///< as above

/// A result over any number type S, each field converted to F by round(x) (a value of S to F);
/// a bool or an int field is its own. One field-wise conversion for every result type: the
/// robust tier's rounding of its bounded and its double results, and the truth API's.
template <class F, template <class> class R, class S, class Round>
R<F> rounded_by(const R<S>& r, Round round) {
  R<F> out;
  zip_fields(r, out, [&](const char*, const auto& x, auto& y) {
    using X = std::remove_cvref_t<decltype(x)>;
    if constexpr (std::is_same_v<X, bool> || std::is_same_v<X, int>)
      y = x;
    else if constexpr (requires { x.rows(); })
      for (int i = 0; i < 3; ++i) y[i] = round(x[i]);
    else
      y = round(x);
  });
  return out;
}

}  // namespace cdref
