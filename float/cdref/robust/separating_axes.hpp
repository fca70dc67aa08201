// cdref/robust/separating_axes.hpp - robust versions of the Section 3.3 queries: segment,
// ray and triangle against axis-aligned and oriented boxes, oriented box against oriented
// box (separate / intersect / decide), and the casts and the sphere query on an oriented box
// (cast / hit / proximity / intersect / decide), at float, double and long double.
//
// Formulation: the solid's own answer (cdref::solid and Theorem 3.1 on the true face normals,
// book/separating_axes.hpp), evaluated on oracle::Bounded2: double words (hi + lo) with a
// rigorous running bound on their error (its header derives every operation's bound). The
// inputs enter exactly (a float or a double is one double; a long double is hi + lo with
// hi = fl(x), lo = x - hi, exact while x lies within double's range; otherwise, and for
// inputs whose scaled products would leave it, the double-word path is not taken). Every
// length is first scaled by a power of two so that the largest lies in [1, 2) (decisions,
// parameters and unit normals do not change; points and distances are scaled back). Products
// of two inputs are exact in a double word, so a cross product of parallel axes is exactly
// zero and drops out; every other quantity carries an error of order u^2 times its operands.
// Each decisive comparison (a separating axis's intervals, an outcode, the order of two
// crossing parameters, a squared distance against rho^2) is certain when the double word's
// sign is certain; |x|, min and max need no decision (they are 1-Lipschitz).
//
// Certificate: decide_separation() (decide(), where the pair has no other; decide_cast() for
// the casts, which classify as cast() does) is certain when the double-word evaluation completed, every
// decision certain: then the classification (and the first separating axis, the entering
// face) equals the solid's at an exact type. When a comparison is too close to call, the same
// formulation runs in F and the answer is marked uncertain. Values come from the double word
// rounded to F (for a certain answer each is within about one ulp of F; they are not claimed
// correctly rounded: that is the oracle's job). The full query and decide() always classify
// alike: when the classification is certain but a later step of the double-word evaluation is
// not (two faces entered at nearly the same parameter, a closest point on a face's border),
// the full query's values come from F and its classification is the certain one.
#pragma once

#include <cdref/oracle/bounded2.hpp>
#include <cdref/primitives.hpp>
#include <cdref/solid/obb.hpp>
#include <cmath>
#include <optional>
#include <type_traits>

#include "decision.hpp"

namespace cdref::robust {

namespace detail {

using W = oracle::Bounded2;

// x as an exact double word, or nothing.
template <class F>
std::optional<W> word(F x) {
  if constexpr (std::is_same_v<F, long double>) {
    const double hi = static_cast<double>(x);
    if (!std::isfinite(hi)) return std::nullopt;
    const double lo = static_cast<double>(x - static_cast<long double>(hi));
    if (static_cast<long double>(hi) + static_cast<long double>(lo) != x) return std::nullopt;
    return W::exact_pair(hi, lo);
  } else {
    return W(static_cast<double>(x));
  }
}
template <class F>
std::optional<Vec3<W>> word(const Vec3<F>& v) {
  Vec3<W> r;
  for (int i = 0; i < 3; ++i) {
    const auto w = word(v[i]);
    if (!w) return std::nullopt;
    r[i] = *w;
  }
  return r;
}

// Every primitive's fields as exact double words (all or nothing).
struct Words {
  bool ok = true;
  template <class F>
  Vec3<W> operator()(const Vec3<F>& v) {
    const auto w = word(v);
    if (!w) ok = false;
    return w ? *w : zero_vec<W>();
  }
  template <class F>
  W operator()(F x) {
    const auto w = word(x);
    if (!w) ok = false;
    return w ? *w : W(0.0);
  }
};
template <class F>
Segment<W> lift_words(const Segment<F>& s, Words& w) { return {w(s.source), w(s.target)}; }
template <class F>
Ray<W> lift_words(const Ray<F>& r, Words& w) { return {w(r.source), w(r.direction)}; }
template <class F>
Triangle<W> lift_words(const Triangle<F>& t, Words& w) { return {{w(t.vertex[0]), w(t.vertex[1]), w(t.vertex[2])}}; }
template <class F>
Box<W> lift_words(const Box<F>& b, Words& w) { return {w(b.center), w(b.extent)}; }
template <class F>
OrientedBox<W> lift_words(const OrientedBox<F>& b, Words& w) {
  return {w(b.center), w(b.extent), {w(b.axis[0]), w(b.axis[1]), w(b.axis[2])}};
}
template <class F>
Sphere<W> lift_words(const Sphere<F>& s, Words& w) { return {w(s.center), w(s.radius)}; }

// A double word's value in F (hi + lo rounded to F).
template <class F>
F value(const W& x) {
  if constexpr (std::is_same_v<F, long double>)
    return static_cast<long double>(x.hi()) + static_cast<long double>(x.lo());
  else
    return static_cast<F>(x.hi() + x.lo());
}
template <class F>
Vec3<F> value(const Vec3<W>& v) {
  return Vec3<F>(value<F>(v[0]), value<F>(v[1]), value<F>(v[2]));
}

// Every length of a case (coordinates, extents, radii, a ray's direction) scaled by 2^k, the
// oriented boxes' axes left as they are: every decision is unchanged (the solids are scaled by
// 2^k; a ray's set does not depend on its direction's length), and so are parameters and
// unit normals, while points and distances scale by 2^k. Scaling the largest length to
// [1, 2) keeps products of small inputs out of the underflow range, where the double word's
// bound loses its exactness. Exact unless a scaled value leaves the normal range: then k = 0.
struct Scale {
  int k = 0;
  template <class F>
  F len(F x) const { return std::ldexp(x, k); }
  template <class F>
  Vec3<F> len(const Vec3<F>& v) const { return Vec3<F>(len(v[0]), len(v[1]), len(v[2])); }
};
template <class F>
void largest(F x, F& m) { m = std::max(m, F(std::fabs(x))); }
template <class F>
void largest(const Vec3<F>& v, F& m) { for (int i = 0; i < 3; ++i) largest(v[i], m); }
template <class F> void largest(const Segment<F>& s, F& m) { largest(s.source, m), largest(s.target, m); }
template <class F> void largest(const Ray<F>& r, F& m) { largest(r.source, m), largest(r.direction, m); }
template <class F> void largest(const Triangle<F>& t, F& m) { for (const auto& v : t.vertex) largest(v, m); }
template <class F> void largest(const Box<F>& b, F& m) { largest(b.center, m), largest(b.extent, m); }
template <class F> void largest(const OrientedBox<F>& b, F& m) { largest(b.center, m), largest(b.extent, m); }
template <class F> void largest(const Sphere<F>& s, F& m) { largest(s.center, m), largest(s.radius, m); }
template <class F> Segment<F> scaled(const Segment<F>& s, const Scale& c) { return {c.len(s.source), c.len(s.target)}; }
template <class F> Ray<F> scaled(const Ray<F>& r, const Scale& c) { return {c.len(r.source), c.len(r.direction)}; }
template <class F>
Triangle<F> scaled(const Triangle<F>& t, const Scale& c) {
  return {{c.len(t.vertex[0]), c.len(t.vertex[1]), c.len(t.vertex[2])}};
}
template <class F> Box<F> scaled(const Box<F>& b, const Scale& c) { return {c.len(b.center), c.len(b.extent)}; }
template <class F>
OrientedBox<F> scaled(const OrientedBox<F>& b, const Scale& c) {
  return {c.len(b.center), c.len(b.extent), b.axis};
}
template <class F> Sphere<F> scaled(const Sphere<F>& s, const Scale& c) { return {c.len(s.center), c.len(s.radius)}; }
template <class F> bool same(F x, F y) { return x == y; }
template <class F> bool same(const Vec3<F>& x, const Vec3<F>& y) { return x == y; }
template <class F> bool same(const Segment<F>& x, const Segment<F>& y) { return same(x.source, y.source) && same(x.target, y.target); }
template <class F> bool same(const Ray<F>& x, const Ray<F>& y) { return same(x.source, y.source) && same(x.direction, y.direction); }
template <class F>
bool same(const Triangle<F>& x, const Triangle<F>& y) {
  return same(x.vertex[0], y.vertex[0]) && same(x.vertex[1], y.vertex[1]) && same(x.vertex[2], y.vertex[2]);
}
template <class F> bool same(const Box<F>& x, const Box<F>& y) { return same(x.center, y.center) && same(x.extent, y.extent); }
template <class F>
bool same(const OrientedBox<F>& x, const OrientedBox<F>& y) { return same(x.center, y.center) && same(x.extent, y.extent); }
template <class F> bool same(const Sphere<F>& x, const Sphere<F>& y) { return same(x.center, y.center) && same(x.radius, y.radius); }
template <class F> F scalar_of(const Triangle<F>&);
template <class F> F scalar_of(const OrientedBox<F>&);

template <class A, class B>
Scale scale_of(const A& a, const B& b) {
  using F = std::decay_t<decltype(scalar_of(a))>;
  F m = F(0);
  largest(a, m);
  largest(b, m);
  Scale sc;
  if (m > F(0) && std::isfinite(m)) {
    sc.k = -std::ilogb(m);
    const Scale back{-sc.k};
    if (!same(scaled(scaled(a, sc), back), a) || !same(scaled(scaled(b, sc), back), b)) sc.k = 0;
  }
  return sc;
}

// Runs f on the primitives as double words (scaled as above); nothing when they are not
// representable or a decision is uncertain.
template <class A, class B, class Fn>
auto on_words(const A& a, const B& b, Fn f, Scale* used = nullptr)
    -> std::optional<decltype(f(lift_words(a, std::declval<Words&>()), lift_words(b, std::declval<Words&>())))> {
  const Scale sc = scale_of(a, b);
  if (used) *used = sc;
  Words w;
  const auto aw = lift_words(scaled(a, sc), w);
  const auto bw = lift_words(scaled(b, sc), w);
  if (!w.ok) return std::nullopt;
  try {
    return f(aw, bw);
  } catch (const oracle::uncertain&) {
    return std::nullopt;
  }
}

template <class F, class A, class B>
std::pair<Separation<F>, bool> separation(const A& a, const B& b) {
  const auto r = on_words(a, b, [](const auto& x, const auto& y) { return book::separate(book::polytope(x), book::polytope(y)); });
  if (r) {
    Separation<F> s;
    s.intersect = r->intersect;
    s.axis = r->axis;
    s.direction = value<F>(r->direction);
    return {s, true};
  }
  return {book::separate(book::polytope(a), book::polytope(b)), false};
}

template <class F>
Cast<F> cast_value(const Cast<W>& c) {
  Cast<F> r;
  r.hit = c.hit;
  r.enters = c.enters;
  r.unbounded_exit = c.unbounded_exit;
  r.lambda_enter = value<F>(c.lambda_enter);
  r.lambda_exit = value<F>(c.lambda_exit);
  r.point = value<F>(c.point);
  r.normal = value<F>(c.normal);
  return r;
}
template <class F>
Proximity<F> proximity_value(const Proximity<W>& p) {
  Proximity<F> r;
  r.intersect = p.intersect;
  r.distance = value<F>(p.distance);
  r.depth = value<F>(p.depth);
  r.on_a = value<F>(p.on_a);
  r.on_b = value<F>(p.on_b);
  r.closest = value<F>(p.closest);
  return r;
}

}  // namespace detail

// ---- separating axes ----
#define CDREF_ROBUST_SEPARATE(A, B, NA, NB)                                                 \
  template <class F>                                                                        \
  Separation<F> separate(const A<F>& a, const B<F>& b) {                                    \
    check(a, NA);                                                                           \
    check(b, NB);                                                                           \
    return detail::separation<F>(a, b).first;                                               \
  }                                                                                         \
  template <class F>                                                                        \
  bool intersect(const A<F>& a, const B<F>& b) {                                            \
    return separate(a, b).intersect;                                                        \
  }                                                                                         \
  template <class F>                                                                        \
  Decision decide_separation(const A<F>& a, const B<F>& b) {                                \
    check(a, NA);                                                                           \
    check(b, NB);                                                                           \
    const auto [s, certain] = detail::separation<F>(a, b);                                  \
    return {s.intersect, certain};                                                          \
  }
CDREF_ROBUST_SEPARATE(Segment, Box, "segment", "box")
CDREF_ROBUST_SEPARATE(Ray, Box, "ray", "box")
CDREF_ROBUST_SEPARATE(Triangle, Box, "triangle", "box")
CDREF_ROBUST_SEPARATE(Segment, OrientedBox, "segment", "oriented box")
CDREF_ROBUST_SEPARATE(Ray, OrientedBox, "ray", "oriented box")
CDREF_ROBUST_SEPARATE(Triangle, OrientedBox, "triangle", "oriented box")
CDREF_ROBUST_SEPARATE(OrientedBox, OrientedBox, "oriented box A", "oriented box B")
#undef CDREF_ROBUST_SEPARATE
// decide() where no other robust query on the same pair has one (a segment or a ray and an
// axis-aligned box: ray_box.hpp's certificate of Algorithm 3.3 decides the same thing).
template <class F> Decision decide(const Triangle<F>& a, const Box<F>& b) { return decide_separation(a, b); }
template <class F> Decision decide(const Segment<F>& a, const OrientedBox<F>& b) { return decide_separation(a, b); }
template <class F> Decision decide(const Ray<F>& a, const OrientedBox<F>& b) { return decide_separation(a, b); }
template <class F> Decision decide(const Triangle<F>& a, const OrientedBox<F>& b) { return decide_separation(a, b); }
template <class F> Decision decide(const OrientedBox<F>& a, const OrientedBox<F>& b) { return decide_separation(a, b); }

// ---- casts on an oriented box, a sphere and an oriented box ----
namespace detail {

// The full query and its certificate from one evaluation, so that they always classify alike:
// the double-word query; else the double-word classification with the query's values in F;
// else both in F, uncertain.
template <class F, class A>
std::pair<Cast<F>, Decision> cast_eval(const A& a, const OrientedBox<F>& b, unsigned w) {
  Scale sc;
  if (const auto r = on_words(a, b, [w](const auto& x, const auto& y) { return solid::cast(x, y, w); }, &sc)) {
    Cast<F> c = cast_value<F>(*r);
    c.point = Scale{-sc.k}.len(c.point);  // parameters and unit normals do not scale
    return {c, {r->hit, true}};
  }
  Cast<F> c = solid::cast(a, b, w);
  const auto h = on_words(a, b, [](const auto& x, const auto& y) { return solid::hit(x, y); });
  const Decision d = h ? Decision{*h, true} : Decision{solid::hit(a, b), false};
  c.hit = d.value;
  return {c, d};
}

template <class F>
std::pair<Proximity<F>, Decision> proximity_eval(const Sphere<F>& s, const OrientedBox<F>& b, unsigned w) {
  Scale sc;
  if (const auto r = on_words(s, b, [w](const auto& x, const auto& y) { return solid::proximity(x, y, w); }, &sc)) {
    Proximity<F> p = proximity_value<F>(*r);
    const Scale back{-sc.k};
    p.distance = back.len(p.distance), p.depth = back.len(p.depth);
    p.on_a = back.len(p.on_a), p.on_b = back.len(p.on_b), p.closest = back.len(p.closest);
    return {p, {r->intersect, true}};
  }
  Proximity<F> p = solid::proximity(s, b, w);
  const auto h = on_words(s, b, [](const auto& x, const auto& y) { return solid::intersect(x, y); });
  const Decision d = h ? Decision{*h, true} : Decision{solid::intersect(s, b), false};
  p.intersect = d.value;
  return {p, d};
}

}  // namespace detail

#define CDREF_ROBUST_OBB_CAST(A, NA)                                          \
  template <class F>                                                          \
  Cast<F> cast(const A<F>& a, const OrientedBox<F>& b, unsigned w = want_cast) { \
    check(a, NA);                                                             \
    check(b, "oriented box");                                                 \
    return detail::cast_eval(a, b, w).first;                                  \
  }                                                                           \
  template <class F>                                                          \
  Decision decide_cast(const A<F>& a, const OrientedBox<F>& b) {              \
    check(a, NA);                                                             \
    check(b, "oriented box");                                                 \
    return detail::cast_eval(a, b, want_cast).second;                         \
  }                                                                           \
  template <class F>                                                          \
  bool hit(const A<F>& a, const OrientedBox<F>& b) {                          \
    return decide_cast(a, b).value;                                           \
  }
CDREF_ROBUST_OBB_CAST(Segment, "segment")
CDREF_ROBUST_OBB_CAST(Ray, "ray")
#undef CDREF_ROBUST_OBB_CAST

template <class F>
Proximity<F> proximity(const Sphere<F>& s, const OrientedBox<F>& b, unsigned w = want_proximity) {
  check(s, "sphere");
  check(b, "oriented box");
  return detail::proximity_eval(s, b, w).first;
}
template <class F>
Decision decide(const Sphere<F>& s, const OrientedBox<F>& b) {
  check(s, "sphere");
  check(b, "oriented box");
  return detail::proximity_eval(s, b, want_proximity).second;
}
template <class F>
bool intersect(const Sphere<F>& s, const OrientedBox<F>& b) {
  return decide(s, b).value;
}

}  // namespace cdref::robust
