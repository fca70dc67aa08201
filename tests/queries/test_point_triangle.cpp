// tests/queries/test_point_triangle.cpp - point-triangle (Section 3.4), the query on the generic path:
// its answers checked against CGAL's own exact squared distance from a point to a triangle
// (CGAL::Simple_cartesian<CGAL::Gmpq>: CGAL's code, exact arithmetic), on every family and
// scale. The truth API's classification is "the squared distance is 0"; its distance is the
// square root of CGAL's squared distance correctly rounded; its closest point is the exact
// closest point (the book at Gmpq, which CGAL confirms lies on the triangle at that squared
// distance) rounded. The robust tier's certificate is never wrong and is given on random
// placements; the on-lattice family's points are on their triangles; bad input is refused by
// name.
#include <catch2/catch.hpp>
#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>
#include <cdref/error.hpp>
#include <cdref/exact.hpp>
#include <cdref/fuzz/campaign.hpp>
#include <cdref/truth.hpp>
#include <bit>
#include <cmath>
#include <limits>
#include <string>

#include "queries/point_triangle.hpp"

namespace cdref_test_point_triangle {

using namespace cdref;
using namespace cdref::fuzz;
using K = CGAL::Simple_cartesian<CGAL::Gmpq>;
using Spec = queries::PointTriangle;

K::Point_3 point(const Vec3<CGAL::Gmpq>& v) { return {v[0], v[1], v[2]}; }

// Whether d is sqrt(D) rounded to nearest: D lies between the squares of the midpoints from d
// to its neighbours (for d = 0, D = 0).
bool rounds_root(double d, const CGAL::Gmpq& D) {
  if (D == 0) return d == 0;
  if (!(d > 0) || !std::isfinite(d)) return false;
  const CGAL::Gmpq lo = (CGAL::Gmpq(std::nextafter(d, 0.0)) + CGAL::Gmpq(d)) / 2;
  const CGAL::Gmpq hi = (CGAL::Gmpq(d) + CGAL::Gmpq(std::nextafter(d, std::numeric_limits<double>::infinity()))) / 2;
  return lo * lo <= D && D <= hi * hi;
}

TEST_CASE("point-triangle: the truth API equals CGAL's exact squared distance on every family", "[point-triangle]") {
  const Query q = query_by_name("point-triangle");
  std::size_t cases = 0, on = 0;
  for (const Family& f : families(q))
    for (int k : f.scales)
      for (std::uint64_t i = 0; i < 40; ++i) {
        const Inputs in = make_case(3, q, f, k, i);
        const auto [p, t] = Spec::make<double>(in);
        const auto [pq, tq] = Spec::make<CGAL::Gmpq>(in);
        const auto [P, T] = Spec::cgal_make<K>(in);
        INFO(f.name << " k=" << k << " case " << i);
        const CGAL::Gmpq D = Spec::cgal_squared_distance(P, T);
        const Proximity<double> r = truth::proximity(p, t);
        REQUIRE(r.intersect == (D == 0));
        REQUIRE(Spec::cgal(P, T) == r.intersect);  // CGAL's predicate (the cost report's CGAL rows)
        REQUIRE(rounds_root(r.distance, D));
        REQUIRE(r.depth == 0);
        // the exact closest point: on the triangle, at CGAL's squared distance
        const Vec3<CGAL::Gmpq> x = book::closest_point(pq, tq);
        REQUIRE(CGAL::squared_distance(P, point(x)) == D);
        REQUIRE(Spec::cgal_squared_distance(point(x), T) == 0);
        for (int c = 0; c < 3; ++c) {
          REQUIRE(r.on_a[c] == p[c]);
          REQUIRE(r.on_b[c] == round_to<double>(x[c]));
          REQUIRE(r.closest[c] == r.on_b[c]);
        }
        // the exact path gives the same answer, bit for bit
        const Proximity<double> e = truth::proximity(p, t, truth::Path::exact);
        REQUIRE(e.intersect == r.intersect);
        REQUIRE(std::bit_cast<std::uint64_t>(e.distance) == std::bit_cast<std::uint64_t>(r.distance));
        for (int c = 0; c < 3; ++c) REQUIRE(e.on_b[c] == r.on_b[c]);
        // the book's squared distance at Gmpq is CGAL's
        REQUIRE(book::squared_distance(pq, tq) == D);
        ++cases;
        on += r.intersect;
        if (f.name == "on-lattice") REQUIRE(r.intersect);
      }
  CHECK(cases > 2000);
  CHECK(on >= 400);  // the on-lattice family (13 scales x 40) and the degenerate family's points on it
}

TEST_CASE("point-triangle: the robust tier's certificate is never wrong, and is given on random placements",
          "[point-triangle]") {
  const Query q = query_by_name("point-triangle");
  for (const Family& f : families(q))
    for (int k : f.scales) {
      std::size_t n = 0, certain = 0;
      for (std::uint64_t i = 0; i < 40; ++i, ++n) {
        const Inputs in = make_case(5, q, f, k, i);
        const auto [p, t] = Spec::make<double>(in);
        const auto [P, T] = Spec::cgal_make<K>(in);
        const bool exact = Spec::cgal_squared_distance(P, T) == 0;
        const robust::Decision d = robust::decide(p, t);
        INFO(f.name << " k=" << k << " case " << i);
        if (d.certain) REQUIRE(d.value == exact);
        certain += d.certain;
        // at float, on the inputs rounded to float (refused where one overflows float)
        const Vec3<float> pf = rebind<float>(p);
        const Triangle<float> tf = rebind<float>(t);
        bool finite = pf.allFinite();
        for (const auto& v : tf.vertex) finite = finite && v.allFinite();
        if (!finite) {
          REQUIRE_THROWS_AS(robust::decide(pf, tf), invalid_input);
          continue;
        }
        const robust::Decision df = robust::decide(pf, tf);
        if (df.certain) REQUIRE(df.value == book::intersect(rebind<CGAL::Gmpq>(pf), rebind<CGAL::Gmpq>(tf)));
      }
      if (f.name == "uniform") CHECK(certain == n);
    }
}

TEST_CASE("point-triangle: bad input is refused by name", "[point-triangle][errors]") {
  const Triangle<double> t{{Vec3<double>(0, 0, 0), Vec3<double>(1, 0, 0), Vec3<double>(0, 1, 0)}};
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  REQUIRE_THROWS_WITH(truth::proximity(Vec3<double>(nan, 0, 0), t), Catch::Contains("point has a non-finite x coordinate"));
  REQUIRE_THROWS_WITH(truth::proximity(Vec3<double>(0, 0, inf), t), Catch::Contains("point has a non-finite z coordinate"));
  Triangle<double> bad = t;
  bad.vertex[2][1] = -inf;
  REQUIRE_THROWS_WITH(truth::proximity(Vec3<double>(0, 0, 0), bad), Catch::Contains("triangle vertex 2"));
  REQUIRE_THROWS_AS(robust::decide(Vec3<double>(nan, 0, 0), t), invalid_input);
  REQUIRE_THROWS_AS(robust::proximity(Vec3<double>(0, 0, 0), bad), invalid_input);
  // a zero-area triangle is the segment it spans: the point on it is on the triangle
  const Triangle<double> seg{{Vec3<double>(0, 0, 0), Vec3<double>(2, 0, 0), Vec3<double>(1, 0, 0)}};
  REQUIRE(truth::proximity(Vec3<double>(0.5, 0, 0), seg).intersect);
  REQUIRE(truth::proximity(Vec3<double>(0.5, 1, 0), seg).distance == 1);
}

}  // namespace cdref_test_point_triangle
