// cdref/robust/polygon.hpp - the robust polygon queries (Section 3.4) at float, double and long
// double: the robust triangle queries over the polygon's fan (book/polygon.hpp says why the fan
// is the polygon).
//
// Certificate: the union's. A triangle certainly hit (met) makes the polygon's answer certainly
// yes; every triangle certainly missed makes it certainly no; otherwise the answer is the union
// of the triangles' answers, uncertain. The casts keep the triangle casts' guarantee: they never
// miss where the exact shot meets a triangle of the fan, so no ray leaks through a diagonal.
// Values come from the triangle that gives them (the first hit, the nearest triangle), as that
// triangle's robust query reports them; the nearest triangle is chosen by the robust values
// (proximity below).
#pragma once

#include <cdref/book/polygon.hpp>

#include "ray_triangle.hpp"
#include "separating_axes.hpp"
#include "sphere_triangle.hpp"
#include "triangle_triangle.hpp"

namespace cdref::robust {

namespace detail {

// The union of the decisions of the fan's triangles (or pairs), stopping at a certain yes.
template <class Each>
Decision union_of(int count, Each each) {
  Decision u{false, true};
  for (int k = 0; k < count; ++k) {
    const Decision d = each(k);
    if (d.value && d.certain) return d;
    u.value = u.value || d.value;
    u.certain = u.certain && d.certain;
  }
  return u;
}

}  // namespace detail

template <class F>
Decision decide(const Segment<F>& s, const Polygon<F>& p) {
  check(p);
  return detail::union_of(p.triangles(), [&](int k) { return decide(s, p.triangle(k)); });
}
template <class F>
Decision decide(const Ray<F>& r, const Polygon<F>& p) {
  check(p);
  return detail::union_of(p.triangles(), [&](int k) { return decide(r, p.triangle(k)); });
}
template <class F>
Cast<F> cast(const Segment<F>& s, const Polygon<F>& p) {
  check(p);
  // the book's fan cast, the first hit by enters_before (ray_triangle.hpp: exact where the
  // rounded parameters of two triangles are equal or adjacent)
  return book::detail::polygon_cast(p, [&](const Triangle<F>& t) { return cast(s, t); },
                                    [&](int k, int j, F lk, F lj) { return enters_before(s, p.triangle(k), lk, p.triangle(j), lj); });
}
template <class F>
Cast<F> cast(const Ray<F>& r, const Polygon<F>& p) {
  check(p);
  return book::detail::polygon_cast(p, [&](const Triangle<F>& t) { return cast(r, t); },
                                    [&](int k, int j, F lk, F lj) { return enters_before(r, p.triangle(k), lk, p.triangle(j), lj); });
}
template <class F>
bool hit(const Segment<F>& s, const Polygon<F>& p) { return decide(s, p).value; }
template <class F>
bool hit(const Ray<F>& r, const Polygon<F>& p) { return decide(r, p).value; }

// (on the query scaled as proximity() scales it, so that the two classify alike)
template <class F>
Decision decide(const Sphere<F>& s0, const Polygon<F>& p0) {
  check(s0, "sphere");
  check(p0);
  const detail::Scale sc = detail::scale_of(s0, p0);
  const Sphere<F> s = detail::scaled(s0, sc);
  const Polygon<F> p = detail::scaled(p0, sc);
  return detail::union_of(p.triangles(), [&](int k) { return decide(s, p.triangle(k)); });
}
// The nearest fan triangle (the book's choice: the least |x - c|, the first on ties) is chosen
// by the triangles' robust distances and depths: key |x - c| - rho, i.e. the distance, or minus
// the depth. Every triangle's robust query runs anyway for the union's certificate; the book's
// choice in F went wrong where its squared distances lose their digits (at 10^+-300 they
// overflow or underflow and it took the first triangle: 1.7e19 ulps of witness on the
// magnitude family; near touching and at range 10^13 ulps of distance). The query is first
// scaled by the power of two that brings its largest length into [1, 2) (words.hpp, scale_of:
// exact, or not at all), and its lengths scaled back at the end: the keys are then compared
// with F's full precision even where the inputs are subnormal (at 10^-320 two triangles'
// distances that differ in their eleventh bit rounded to one subnormal, and the first
// triangle's witnesses were taken for the nearest's: 73 ulps of witness).
template <class F>
Proximity<F> proximity(const Sphere<F>& s0, const Polygon<F>& p0, unsigned w = want_proximity) {
  check(s0, "sphere");
  check(p0);
  const detail::Scale sc = detail::scale_of(s0, p0), back{-sc.k};
  const Sphere<F> s = detail::scaled(s0, sc);
  const Polygon<F> p = detail::scaled(p0, sc);
  Proximity<F> best;
  F best_key = F(0);
  Decision u{false, true};
  bool yes = false;  // a triangle certainly met
  for (int k = 0; k < p.triangles(); ++k) {
    // (every output, as decide() asks: the same evaluation, so the same certificate)
    const auto e = detail::sphere_triangle_eval(s, p.triangle(k), want_proximity);
    const Proximity<F>& r = e.first;
    const Decision& d = e.second;
    yes = yes || (d.value && d.certain);
    u.value = u.value || d.value;
    u.certain = u.certain && d.certain;
    const F key = r.intersect ? F(-r.depth) : r.distance;
    if (k == 0 || key < best_key) best = r, best_key = key;
  }
  if (yes) u = {true, true};
  best.intersect = u.value;  // the union's classification, as decide() gives it
  best.distance = (w & want_distance) ? back.len(best.distance) : F(0);
  best.depth = (w & want_depth) ? back.len(best.depth) : F(0);
  if (w & want_witnesses)
    best.on_a = back.len(best.on_a), best.on_b = back.len(best.on_b);
  else
    best.on_a = best.on_b = Vec3<F>(F(0), F(0), F(0));
  best.closest = (w & want_closest) ? back.len(best.closest) : Vec3<F>(F(0), F(0), F(0));
  return best;
}
template <class F>
bool intersect(const Sphere<F>& s, const Polygon<F>& p) { return decide(s, p).value; }

template <class F>
Decision decide(const Polygon<F>& p, const Box<F>& b) {
  check(p);
  return detail::union_of(p.triangles(), [&](int k) { return decide(p.triangle(k), b); });
}
template <class F>
bool intersect(const Polygon<F>& p, const Box<F>& b) { return decide(p, b).value; }

template <class F>
Decision decide(const Polygon<F>& a, const Polygon<F>& b) {
  check(a, "polygon A");
  check(b, "polygon B");
  const int nb = b.triangles();
  return detail::union_of(a.triangles() * nb, [&](int k) { return decide(a.triangle(k / nb), b.triangle(k % nb)); });
}
template <class F>
bool intersect(const Polygon<F>& a, const Polygon<F>& b) { return decide(a, b).value; }

}  // namespace cdref::robust
