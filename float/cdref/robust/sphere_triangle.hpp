// cdref/robust/sphere_triangle.hpp - the robust sphere-triangle query (Section 3.4) at float,
// double and long double: proximity, intersect and decide.
//
// At double the oracle's first stage runs first (oracle/triangle_filter.hpp: two certificates
// from one point of the triangle, static error bounds): where it decides, the classification
// is exact and certain, and decide() returns at once.
//
// Formulation: the book's (book/sphere_triangle.hpp: the closest point region by region, a
// zero-area triangle as its segment) evaluated on double words (robust/words.hpp: exact inputs,
// every length scaled by a power of two, a rigorous running error bound), relative to the
// sphere's centre (words.hpp, about_centre: the vertices' differences from it are exact double
// words, so the closest point carries u^2 of its distance from the centre, not of its
// coordinates). The region tests compare dot products of exact differences (degree 2) and va,
// vb, vc (degree 4), each held to about u^2 of its size, and the classification compares
// |x - c|^2 with rho^2; each is certain when its double word's sign is. The scaling keeps the
// degree-4 terms in range where the book in double overflows or underflows (coordinates near
// 2^500 or 2^-500). decide() is certain when the double-word evaluation of intersect
// completed: then the classification equals the book's at an exact type. Otherwise the book
// runs in F and the answer is uncertain (a centre on a region boundary, a tangent sphere, a
// triangle whose area is too small to call). proximity() takes its values from the double
// words rounded to F when its own evaluation completes, else from the double words with
// lenient signs (a region test too close to call takes the double word's sign: the closest
// point is continuous across region boundaries; F's value kept where it lies within the double
// word's enclosure), else from F, and always classifies as decide() does. The values are not
// claimed correctly rounded (that is the oracle's job); `cdref campaign --query sphere-triangle
// --impl robust-double` measures them: the distance sqrt|x - c|^2 - rho cancels when it is far
// below the radius (the double words' error is about u^2 of the triangle's size: 40 ulps at
// worst at 2^-52 of the radius from touching), so where its enclosure is wider than u/16 of it
// the distance or depth comes from |x - c|^2 exactly (sphere_triangle_eval, triangle_xx and
// rational.hpp's sharpen_gap: within an ulp on every family). In the face region
// the outputs come from the triangle's normal (proximity_by_face below): the sphere's witness
// c + rho (x - c) / |x - c| took its direction from x - c, which cancels when the centre lies
// near the plane (2.3e4 ulps on the degenerate family; now every output within 1 ulp there).
#pragma once

#include <cdref/book/sphere_triangle.hpp>
#include <cdref/oracle/triangle_filter.hpp>
#include <cdref/oracle/triangle_words.hpp>

#include "rational.hpp"
#include "words.hpp"

namespace cdref::robust {

namespace detail {

// At double, the oracle's first stage (oracle/triangle_filter.hpp: two certificates from one
// point of the triangle) before the double words: 1 (they meet), 0 (disjoint) or 2 (undecided;
// always at float and long double). Where it decides, its answer is the book's at an exact
// type, so every entry point takes it (decide(), the predicate and proximity's classification).
template <class F>
int sphere_triangle_first_stage(const Sphere<F>& s, const Triangle<F>& t) {
  if constexpr (std::is_same_v<F, double>) {
    // (where the static bounds cannot tell, the same two certificates on double words:
    // oracle/triangle_words.hpp)
    const int f = oracle::sphere_triangle::filter(s, t);
    return f != oracle::sphere_triangle::unknown ? f : oracle::sphere_triangle::certificates_on_words(s, t);
  } else {
    return oracle::sphere_triangle::unknown;
  }
}

// The book's proximity, its outputs in the face region from the triangle's normal. There the
// closest point is the centre's projection on the plane: with n = ab x ac and
// side = (a - c) . n, x - c = n side / |n|^2 exactly, so |x - c| = |side| / |n|, the sphere's
// witness is c + rho sign(side) n / |n| (n when side = 0: the book's x == c case), and the
// classification |x - c|^2 <= rho^2 reads side^2 <= rho^2 |n|^2: the same values as the
// book's in exact arithmetic. On the double words n carries u^2 of its size wherever the
// centre lies, and side is exact where the inputs make it so, while the book's x - c is the
// difference of two nearly equal points when the centre lies near the plane: a centre an ulp
// off the triangle gave the witness direction u relative error (thousands of ulps of a
// coordinate that cancels), and a centre exactly on it a closest point an ulp off, from F,
// where x == c was too close to call (the degenerate families).
template <class T>
Proximity<sqrt_t<T>> proximity_by_face(const Sphere<T>& sp, const Triangle<T>& tri, unsigned w) {
  using S = sqrt_t<T>;
  Vec3<T> dir = zero_vec<T>();
  bool face = false;
  const Vec3<T> x = book::detail::closest_on_triangle(tri, sp.center, &dir, &face);
  if (!face) return book::detail::sphere_triangle_outputs(sp, tri, x, dir, w);
  const Vec3<T> n = Vec3<T>(tri.vertex[1] - tri.vertex[0]).cross(Vec3<T>(tri.vertex[2] - tri.vertex[0]));
  const T nn = n.squaredNorm();
  const T side = Vec3<T>(tri.vertex[0] - sp.center).dot(n);
  const T& rho = sp.radius;
  Proximity<S> res;
  res.intersect = side * side <= rho * rho * nn;
  const bool on = side == T(0);  // the centre lies on the triangle
  const Vec3<T> v = on ? zero_vec<T>() : Vec3<T>(n * T(side / nn));
  if (w & (want_closest | want_witnesses)) {
    const Vec3<S> at = on ? lift<S>(sp.center) : lift<S>(Vec3<T>(sp.center + v));
    if (w & want_closest) res.closest = at;
    if (w & want_witnesses) res.on_b = at;
  }
  if (!(w & (want_distance | want_depth | want_witnesses))) return res;
  const S nl = root(nn);
  const S len = on ? S(0) : S(S(side < T(0) ? T(-side) : side) / nl);
  if (w & want_distance) res.distance = book::detail::max_of(S(len - S(rho)), S(0));
  if (w & want_depth) res.depth = book::detail::max_of(S(S(rho) - len), S(0));
  if (w & want_witnesses) res.on_a = offset(sp.center, S(side < T(0) ? T(-rho) : rho), book::detail::divided(n, nl));
  return res;
}

// |x - c|^2 exactly, x the point of the closed triangle closest to c: the projection of c on
// the plane where it lies in the triangle (n = e1 x e2 != 0 and every edge's
// ((v_k+1 - v_k) x (c - v_k)) . n >= 0: then |x - c|^2 = ((c - v_0) . n)^2 / n.n), else the
// nearest of the three edges' closest points (segment_xx; a zero-area triangle is its edges).
template <class F>
void triangle_xx(Rational& xx, const Vec3<F>& c, const Triangle<F>& t) {
  RVec p, v[3], e1, e2, n;
  set_vec(p, c);
  for (int k = 0; k < 3; ++k) set_vec(v[k], t.vertex[k]);
  sub_vec(e1, v[1], v[0]);
  sub_vec(e2, v[2], v[0]);
  cross_vec(n, e1, e2);
  Rational nn, side;
  dot_vec(nn, n, n);
  if (mpq_sgn(nn.q) != 0) {
    bool inside = true;
    for (int k = 0; k < 3 && inside; ++k) {
      RVec e, pk, m;
      sub_vec(e, v[(k + 1) % 3], v[k]);
      sub_vec(pk, p, v[k]);
      cross_vec(m, e, pk);
      dot_vec(side, m, n);
      inside = mpq_sgn(side.q) >= 0;
    }
    if (inside) {
      RVec pv;
      sub_vec(pv, p, v[0]);
      dot_vec(side, pv, n);
      mpq_mul(xx.q, side.q, side.q);
      mpq_div(xx.q, xx.q, nn.q);
      return;
    }
  }
  Rational d;
  for (int k = 0; k < 3; ++k) {
    segment_xx(k == 0 ? xx : d, p, v[k], v[(k + 1) % 3]);
    if (k > 0 && mpq_cmp(d.q, xx.q) < 0) mpq_set(xx.q, d.q);
  }
}

// The double words alone (the oracle's second stage).
template <class F>
std::pair<Proximity<F>, Decision> sphere_triangle_words(const Sphere<F>& s, const Triangle<F>& t, unsigned w,
                                                        WordValues* kept = nullptr) {
  // (on the double words relative to the centre: words.hpp, about_centre)
  return proximity_on_words(
      s, t,
      [w](const auto& x, const auto& y) {
        return about_centre(x, y, w, [w](const auto& a, const auto& b) { return proximity_by_face(a, b, w); },
                            [](auto tri, const auto& c) {
                              for (auto& v : tri.vertex) v = std::decay_t<decltype(c)>(v - c);
                              return tri;
                            });
      },
      [](const auto& x, const auto& y) { return book::intersect(x, y); }, kept);
}
// Proximity's values from the double words, its classification from them where they are
// certain, else from the first stage where it decides.
// The distance and the depth then sharpened where the double words leave them loose
// (rational.hpp, sharpen_gap: |x - c|^2 exactly, triangle_xx).
template <class F>
std::pair<Proximity<F>, Decision> sphere_triangle_eval(const Sphere<F>& s, const Triangle<F>& t, unsigned w,
                                                       WordValues* kept = nullptr) {
  WordValues local;
  WordValues& kv = kept ? *kept : local;
  auto r = sphere_triangle_words(s, t, w, &kv);
  if (!r.second.certain)
    if (const int f = sphere_triangle_first_stage(s, t); f != oracle::sphere_triangle::unknown) {
      r.first.intersect = f != 0;
      r.second = {f != 0, true};
    }
  sharpen_gap(r.first, kv, s.radius, w, [&](Rational& xx) { return triangle_xx(xx, s.center, t), true; });
  return r;
}

}  // namespace detail

template <class F>
Proximity<F> proximity(const Sphere<F>& s, const Triangle<F>& t, unsigned w = want_proximity) {
  check(s, "sphere");
  check(t, "triangle");
  return with_fma([&] { return detail::sphere_triangle_eval(s, t, w).first; });
}
template <class F>
Decision decide(const Sphere<F>& s, const Triangle<F>& t) {
  check(s, "sphere");
  check(t, "triangle");
  if (const int f = detail::sphere_triangle_first_stage(s, t); f != oracle::sphere_triangle::unknown)
    return {f != 0, true};
  return detail::sphere_triangle_words(s, t, want_proximity).second;
}
template <class F>
bool intersect(const Sphere<F>& s, const Triangle<F>& t) {
  return decide(s, t).value;
}

}  // namespace cdref::robust
