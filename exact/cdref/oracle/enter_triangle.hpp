// cdref/oracle/enter_triangle.hpp - oracle::enter on a triangle (Section 3.4, Moller-Trumbore)
// and on a polygon (its fan, enter_first): a segment's or a ray's lambda_enter correctly rounded
// to double (what every cast shares, and the exact path: enter.hpp).
//
// ---- A triangle: the plane's parameter, corrected once, certified ---------------------------
// Where det = e1 . (d x e2) != 0 the book's lambda = e2 . q / det with q = (s - v0) x e1, that
// is lambda* = -(sv . n) / (d . n) with sv = s - v0, n = e1 x e2 (scalar triple products
// permuted), and the plane's signed offset g(l) = (sv + l d) . n is linear in l: for any l0,
//     lambda* = l0 - g(l0) / (d . n)   exactly.
// So l0 = -(sv . n) / (d . n) rounded needs no bound; the correction is where the accuracy is
// (plane_parameter, shared with the oriented box). e1, e2, sv and d are exact two_sum pairs;
// n_i = e1_j e2_k - e1_k e2_j as a double word (cross_term: the two products of high parts
// exact, the four cross terms and the lows summed in double, the lows' products dropped), off
// by en_i = 8u (the lows' and cross terms' magnitudes) + 2u^2 (|e1_j e2_k| + |e1_k e2_j|) +
// 16 eta; w = sv + l0 d as double words with ew_i as the sphere's (affine_words); each dot
// product with n (dot_words: the products of the high parts exact and summed by two_sum, the
// lows in double) is off by 12u (the lows' magnitudes) + 1.01 (sum |x_i| en_i + |n_i| ex_i +
// the dropped x.lo n.lo) + 64 eta. D = d . n must be certainly nonzero (|D| - eD > 0; else a
// shot parallel to the plane or in it: the exact path); g = w . n is rounded once more (2u of
// the two terms summed). Then delta = -g^ / D^ is off from -g / D by (eg + |g^| eD / |D^|) /
// D_lo + u |delta|; l0 + delta as a double word (two_sum), the bound doubled,
// Bounded2::try_rounded. The exact value's
// relative error is then of order u^2 |w| |n| / |d . n| / lambda*: away from grazing shots the
// rounding is decided on all but a few in 10^13 cases. Range: robust::in_certified_range, every
// difference at most 2^250, l0 at most 2^250 (no product overflows; underflow in the eta terms).
#pragma once

#include <cdref/oracle/enter.hpp>
#include <cdref/oracle/ray_triangle.hpp>

namespace cdref::oracle {

namespace enter_detail {

// The triangle's double path on a hit (header, "A triangle"): the value, or nothing.
template <class Mul, class Shot>
std::optional<double> triangle_double(const Shot& x, const Triangle<double>& tri) {
  if (!robust::in_certified_range(x, tri)) return std::nullopt;
  const Vec3<double>& v0 = tri.vertex[0];
  Pair<double> e1[3], e2[3], sv[3], d[3];
  shot_pairs(x, v0, sv, d);
  for (int i = 0; i < 3; ++i) {
    e1[i] = eft::two_sum(tri.vertex[1][i], -v0[i]);
    e2[i] = eft::two_sum(tri.vertex[2][i], -v0[i]);
  }
  if (!(std::max({largest(e1), largest(e2), largest(sv), largest(d)}) <= 0x1p250)) return std::nullopt;
  Word n[3];
  cross_words<Mul>(e1, e2, n);
  const double zero[3] = {0, 0, 0};
  return plane_parameter<Mul>(sv, d, n, dot_words<Mul>(sv, zero, n), Word{{0, 0}, 0});
}


template <class Shot>
Entry triangle_enter(const Shot& x, const Triangle<double>& tri, bool* exact_used) {
  return entry_of(classify_triangle_cast(x, tri, nullptr), x, tri, exact_used, [&] { return solid_double(x, tri); });
}

}  // namespace enter_detail

// A segment or a ray against a triangle, then against a polygon (its fan's triangles).
inline Entry enter(const Segment<double>& seg, const Triangle<double>& tri, bool* exact_used = nullptr) {
  check(seg, "segment");
  check(tri, "triangle");
  return enter_detail::triangle_enter(seg, tri, exact_used);
}
inline Entry enter(const Ray<double>& ray, const Triangle<double>& tri, bool* exact_used = nullptr) {
  check(ray, "ray");
  check(tri, "triangle");
  return enter_detail::triangle_enter(ray, tri, exact_used);
}
inline Entry enter(const Segment<double>& seg, const Polygon<double>& p, bool* exact_used = nullptr) {
  check(seg, "segment");
  check(p);
  return enter_first(
      p.triangles(), [&](int k, bool* e) { return enter_detail::triangle_enter(seg, p.triangle(k), e); }, exact_used);
}
inline Entry enter(const Ray<double>& ray, const Polygon<double>& p, bool* exact_used = nullptr) {
  check(ray, "ray");
  check(p);
  return enter_first(
      p.triangles(), [&](int k, bool* e) { return enter_detail::triangle_enter(ray, p.triangle(k), e); }, exact_used);
}

}  // namespace cdref::oracle
