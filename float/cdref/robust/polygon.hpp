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

// (the inputs checked once, in the book's order; the fan triangles' vertices are the polygon's)
template <class F>
Decision decide(const Segment<F>& s, const Polygon<F>& p) {
  check(s, "segment");
  check(p);
  return detail::union_of(p.triangles(), [&](int k) { return detail::triangle_decide_checked(s, p.triangle(k), true); });
}
template <class F>
Decision decide(const Ray<F>& r, const Polygon<F>& p) {
  check(r, "ray");
  check(p);
  return detail::union_of(p.triangles(), [&](int k) { return detail::triangle_decide_checked(r, p.triangle(k), false); });
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

namespace detail {
// The power of two proximity(sphere, polygon) scales its query by (below): words.hpp's
// scale_of where the largest length lies below 2^(2(p - 1)) times the smallest normal number,
// so that distances down to 2^-p of it could be subnormal; none otherwise (the scaling would
// change no comparison, and its exact round trip costs more than the query's first stage).
template <class F>
Scale tiny_scale(const Sphere<F>& s, const Polygon<F>& p) {
  constexpr F eps = std::numeric_limits<F>::epsilon(), tiny = std::numeric_limits<F>::min() / (eps * eps);
  F m = F(0);
  largest(s, m);
  largest(p, m);
  return m < tiny ? scale_of(s, p) : Scale{};
}
}  // namespace detail

// (on the query scaled as proximity() scales it, so that the two classify alike)
template <class F>
Decision decide(const Sphere<F>& s, const Polygon<F>& p) {
  check(p);  // (the sphere by each triangle's decide)
  const auto run = [](const Sphere<F>& a, const Polygon<F>& b) {
    return detail::union_of(b.triangles(), [&](int k) { return decide(a, b.triangle(k)); });
  };
  const detail::Scale sc = detail::tiny_scale(s, p);
  return sc.k == 0 ? run(s, p) : run(detail::scaled(s, sc), detail::scaled(p, sc));
}
namespace detail {
// At double, first: every fan triangle's first look (sphere_triangle.hpp, item F) with every
// value, and its classification. The nearest is the least key |x - c| - rho; it is taken where its key's
// interval lies below every other's, or where each triangle it cannot be told from gives the
// same values bit for bit (each within 3/4 of an ulp of its own truth, so of the nearest's).
// The union's classification is exact, every triangle's being certain. false: the loop below.
inline bool same_values(const Proximity<double>& a, const Proximity<double>& b) {
  return a.distance == b.distance && a.depth == b.depth && a.on_a == b.on_a && a.on_b == b.on_b && a.closest == b.closest;
}
// Correct: each value the truth correctly rounded (sphere_triangle_fast's), for the oracle.
template <class Mul, bool Correct = false>
bool polygon_sphere_first_look(const Sphere<double>& s, const Polygon<double>& p, Proximity<double>& best) {
  constexpr unsigned all = want_distance | want_depth | want_witnesses | want_closest;
  constexpr double u = first_look_u;
  Proximity<double> r[Polygon<double>::max_vertices];
  double key[Polygon<double>::max_vertices][3];
  bool meet = false;
  int b = 0;
  const int n = p.triangles();
  for (int k = 0; k < n; ++k) {
    int f = filters::sphere_triangle::unknown;
    if ((sphere_triangle_fast<Mul, Correct>(s, p.triangle(k), f, all, r[k], key[k]) & all) != all) return false;
    meet = meet || f != 0;
    if (key[k][0] < key[b][0] || (key[k][0] == key[b][0] && key[k][1] < key[b][1])) b = k;
  }
  // g_k - g_b from the double words: (h_k - h_b) exactly by two_sum, the lows' difference and
  // the sums rounded three times (u of each); it exceeds e_b + e_k where the rounded difference
  // less those roundings does (margins 4u and 8u for the test's own roundings)
  const auto apart = [&](int k) {
    const Pair<double> d = two_sum(key[k][0], -key[b][0]);
    const double r = d.lo + (key[k][1] - key[b][1]), total = d.hi + r;
    const double slack = u * ((std::fabs(key[k][1]) + std::fabs(key[b][1])) + std::fabs(r));
    return total * (1 - 4 * u) > ((key[b][2] + key[k][2]) + slack) * (1 + 8 * u);
  };
  for (int k = 0; k < n; ++k)
    if (k != b && !apart(k) && !same_values(r[b], r[k])) return false;
  best = r[b];
  best.intersect = meet;
  return true;
}
}  // namespace detail

// The nearest fan triangle (the book's choice: the least |x - c|, the first on ties) is chosen
// by the triangles' robust distances and depths: key |x - c| - rho, i.e. the distance, or minus
// the depth. Every triangle's robust query runs anyway for the union's certificate; the book's
// choice in F went wrong where its squared distances lose their digits (at 10^+-300 they
// overflow or underflow and it took the first triangle: 1.7e19 ulps of witness on the
// magnitude family; near touching and at range 10^13 ulps of distance). A query of tiny lengths
// is first scaled by the power of two that brings its largest into [1, 2) (tiny_scale; exact,
// or not at all), and its lengths scaled back at the end: the keys are then compared with F's
// full precision even where the inputs are subnormal (at 10^-320 two triangles' distances that
// differ in their eleventh bit rounded to one subnormal, and the first triangle's witnesses
// were taken for the nearest's: 73 ulps of witness). Two keys are compared on the double
// words' values where both triangles' double words completed (hi, then lo): on a fan bent by
// the rounding of its vertices, two triangles' distances near a diagonal agree to F's last bit
// while their closest points lie sqrt(u) apart (at float 873 ulps of witness).
template <class F>
Proximity<F> proximity(const Sphere<F>& s0, const Polygon<F>& p0, unsigned w = want_proximity) {
  check(s0, "sphere");
  check(p0);
  const detail::Scale sc = detail::tiny_scale(s0, p0), back{-sc.k};
  const Sphere<F> s = detail::scaled(s0, sc);
  const Polygon<F> p = detail::scaled(p0, sc);
  Proximity<F> best;
  bool first_look = false;  // (at double, above)
  if constexpr (std::is_same_v<F, double>)
    first_look = with_products([&](auto mul) { return detail::polygon_sphere_first_look<decltype(mul)>(s, p, best); });
  // the key |x - c| - rho as hi + lo: the double words' where they completed, else F's value
  std::pair<long double, double> best_key{0, 0};
  Decision u{best.intersect, true};
  bool yes = false;  // a triangle certainly met
  for (int k = 0; k < p.triangles() && !first_look; ++k) {
    // (every output, as decide() asks: the same evaluation, so the same certificate)
    detail::WordValues kept;
    const auto e = detail::sphere_triangle_eval(s, p.triangle(k), want_proximity, &kept);
    const Proximity<F>& r = e.first;
    const Decision& d = e.second;
    yes = yes || (d.value && d.certain);
    u.value = u.value || d.value;
    u.certain = u.certain && d.certain;
    std::pair<long double, double> key{r.intersect ? -(long double)r.depth : (long double)r.distance, 0.0};
    if (kept.words) key = r.intersect ? std::pair<long double, double>{-kept.depth_hi, -kept.depth_lo}
                                      : std::pair<long double, double>{kept.distance_hi, kept.distance_lo};
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
// The oracle's every-output path at double first, as sphere_triangle.hpp's: every value the
// truth correctly rounded where every fan triangle's first look proves it and orders them.
inline bool proximity_rounded(const Sphere<double>& s, const Polygon<double>& p, Proximity<double>& res) {
  check(s, "sphere");
  check(p);
  return with_products([&](auto mul) { return detail::polygon_sphere_first_look<decltype(mul), true>(s, p, res); });
}

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
  // at double the pairs' first stage at once, the plane signs its static bound cannot tell on
  // double words (filters/triangle_words.hpp, polygon_on_words): where it decides, its answer is
  // the union's exact one
  if constexpr (std::is_same_v<F, double>)
    if (const int f = filters::triangle_triangle::polygon_on_words(a, b); f != filters::triangle_triangle::unknown)
      return {f != 0, true};
  const int nb = b.triangles();
  return detail::union_of(a.triangles() * nb, [&](int k) { return decide(a.triangle(k / nb), b.triangle(k % nb)); });
}
template <class F>
bool intersect(const Polygon<F>& a, const Polygon<F>& b) { return decide(a, b).value; }

}  // namespace cdref::robust
