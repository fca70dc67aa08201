// tests/test_triangles.cpp - Section 3.4 at float, double, long double, Gmpq and Epeck::FT:
// a sphere and a triangle (the closest point in every region: face, edges, vertices; zero-area
// triangles; the centre on the triangle; long range and magnitudes near 1e150 and 1e-150), with
// exact expected answers written as rationals or a + b sqrt(d); the robust version's
// certificate on the same cases.
#include <cdref/robust/sphere_triangle.hpp>

#include "prox_check.hpp"

using namespace cdref;
using namespace cdref::test;

namespace {

Sphere<double> sph(double x, double y, double z, double r) { return {Vec3<double>(x, y, z), r}; }
Triangle<double> tri(Vec3<double> a, Vec3<double> b, Vec3<double> c) { return {{a, b, c}}; }
Vec3<double> P(double x, double y, double z) { return Vec3<double>(x, y, z); }
X3 x3(X a, X b, X c) { return {a, b, c}; }

struct SphTri {
  PairOf<Sphere<double>, Triangle<double>> in;
  ProxCase c;
};

std::vector<SphTri> sphere_triangle_cases() {
  const Triangle<double> t = tri(P(0, 0, 0), P(4, 0, 0), P(0, 4, 0));  // in the plane z = 0
  const double big = std::ldexp(1.0, 500), tiny = std::ldexp(1.0, -500);
  std::vector<SphTri> v;
  auto add = [&](Sphere<double> s, Triangle<double> tr, ProxCase c) { v.push_back({{s, tr}, std::move(c)}); };
  add(sph(1, 1, 3, 3), t, {"touching the face", true, Q(0), Q(0), x3(1, 1, 0), x3(1, 1, 0), x3(1, 1, 0)});
  add(sph(1, 1, 3, 3), tri(P(0, 0, 0), P(0, 4, 0), P(4, 0, 0)), {"the same, the other orientation", true, Q(0), Q(0),
                                                               x3(1, 1, 0), x3(1, 1, 0), x3(1, 1, 0)});
  add(sph(1, 1, 3, 2), t, {"above the face", false, Q(1), Q(0), x3(1, 1, 1), x3(1, 1, 0), x3(1, 1, 0)});
  add(sph(1, 1, 3, 4), t, {"through the face", true, Q(0), Q(1), x3(1, 1, -1), x3(1, 1, 0), x3(1, 1, 0)});
  add(sph(-3, -4, 0, 4), t, {"near vertex 0", false, Q(1), Q(0), x3("-3/5", "-4/5", 0), x3(0, 0, 0), x3(0, 0, 0)});
  add(sph(2, -3, 4, 5), t, {"touching edge 01", true, Q(0), Q(0), x3(2, 0, 0), x3(2, 0, 0), x3(2, 0, 0)});
  // beyond the hypotenuse x + y = 4: the foot is (2, 2, 0), sqrt(2) away
  add(sph(3, 3, 0, 1), t,
      {"beyond the hypotenuse", false, X(Q(-1), Q(1), Q(2)), Q(0),
       x3(X(Q(3), Q(-1, 2), Q(2)), X(Q(3), Q(-1, 2), Q(2)), Q(0)), x3(2, 2, 0), x3(2, 2, 0)});
  // past vertex 1: the foot on the hypotenuse's line, (4.5, -0.5), lies beyond it
  add(sph(6, 1, 0, 1), t, {"near vertex 1", false, X(Q(-1), Q(1), Q(5)), Q(0),
                           x3(X(Q(6), Q(-2, 5), Q(5)), X(Q(1), Q(-1, 5), Q(5)), Q(0)), x3(4, 0, 0), x3(4, 0, 0)});
  add(sph(1, 1, 0, 2), t, {"centre on the face", true, Q(0), Q(2), x3(1, 1, 2), x3(1, 1, 0), x3(1, 1, 0)});
  add(sph(0, 0, 0, 0), t, {"a point at a vertex", true, Q(0), Q(0), x3(0, 0, 0), x3(0, 0, 0), x3(0, 0, 0)});
  // zero-area triangles: the segment [0, 4] on the x-axis, and a point
  const Triangle<double> seg = tri(P(0, 0, 0), P(2, 0, 0), P(4, 0, 0));
  add(sph(2, 3, 0, 3), seg, {"a segment triangle, touching", true, Q(0), Q(0), x3(2, 0, 0), x3(2, 0, 0), x3(2, 0, 0)});
  add(sph(6, 3, 0, 3), seg, {"a segment triangle, past its end", false, X(Q(-3), Q(1), Q(13)), Q(0),
                             x3(X(Q(6), Q(-6, 13), Q(13)), X(Q(3), Q(-9, 13), Q(13)), Q(0)), x3(4, 0, 0),
                             x3(4, 0, 0)});
  add(sph(1, 0, 0, 1), seg, {"the centre on a segment triangle", true, Q(0), Q(1), x3(1, 0, 1), x3(1, 0, 0),
                             x3(1, 0, 0)});
  const Triangle<double> pt = tri(P(1, 1, 1), P(1, 1, 1), P(1, 1, 1));
  add(sph(1, 1, 4, 3), pt, {"a point triangle, touching", true, Q(0), Q(0), x3(1, 1, 1), x3(1, 1, 1), x3(1, 1, 1)});
  add(sph(1, 1, 1, 2), pt, {"the centre on a point triangle", true, Q(0), Q(2), x3(3, 1, 1), x3(1, 1, 1),
                            x3(1, 1, 1)});
  // magnitudes: the hypotenuse case scaled by 2^500 and 2^-500 (exact in double)
  // The region tests multiply two dot products (degree 4 in the coordinates). At 2^500 they
  // overflow double (about 2^2008): the book's distance, depth and witnesses are not finite. At
  // 2^-500 they underflow to 0, vc = 0 passes the test of edge 01 and the book answers with
  // the wrong edge, some 10^16 ulps of the scale off. Both are proven drifts; long double's
  // range covers both and it stays within 4 ulps.
  for (const double sc : {big, tiny}) {
    const Q k(sc);
    std::map<std::string, ProxExpect> overflow;
    ProxExpect drift;
    drift.min_ulps = sc > 1 ? std::numeric_limits<double>::infinity() : 1e15;
    overflow["double"] = drift;
    add(sph(3 * sc, 3 * sc, 0, sc), tri(P(0, 0, 0), P(4 * sc, 0, 0), P(0, 4 * sc, 0)),
        {sc > 1 ? "beyond the hypotenuse at 2^500" : "beyond the hypotenuse at 2^-500", false,
         X(Q(-k), k, Q(2)), Q(0), x3(X(Q(3) * k, Q(-k / 2), Q(2)), X(Q(3) * k, Q(-k / 2), Q(2)), Q(0)),
         x3(X(Q(2) * k), X(Q(2) * k), Q(0)), x3(X(Q(2) * k), X(Q(2) * k), Q(0)), overflow, sc});
  }
  return v;
}

}  // namespace

TEMPLATE_TEST_CASE("sphere-triangle (3.4) on hard cases", "[sphere-triangle]", float, double, long double, CGAL::Gmpq,
                   CGAL::Epeck::FT) {
  for (const auto& sc : sphere_triangle_cases())
    check_prox_case<TestType>(sc.c, sc.in, [](const auto& in) {
      return std::pair{book::proximity(in.first, in.second, want_all), book::intersect(in.first, in.second)};
    });
}

TEMPLATE_TEST_CASE("robust sphere-triangle: certain, exact classification and accurate values on the hard cases",
                   "[sphere-triangle][robust]", float, double, long double) {
  using F = TestType;
  for (const auto& sc : sphere_triangle_cases()) {
    if (!sc.in.template finite<F>()) continue;
    INFO(sc.c.name);
    const auto in = sc.in.template at<F>();
    const auto ex = sc.in.exact(in);
    const auto truth = book::proximity(ex.first, ex.second, want_all);
    const robust::Decision d = robust::decide(in.first, in.second);
    const auto p = robust::proximity(in.first, in.second, want_all);
    REQUIRE(p.intersect == d.value);
    if (d.certain) REQUIRE(d.value == truth.intersect);
    // dyadic inputs of moderate size: the double words decide every one of these
    if (sc.c.scale == 1) REQUIRE(d.certain);
    CHECK(ulps<F>(p.distance, to_expr(truth.distance), sc.c.scale) <= 1);
    CHECK(ulps<F>(p.depth, to_expr(truth.depth), sc.c.scale) <= 1);
  }
}
