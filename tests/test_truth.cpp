// tests/test_truth.cpp - <cdref/truth.hpp>: the exact answer for one input, in one call.
//
// 1. On every family and scale of every query, the public call's oracle answer equals its exact
//    path's (the book at CGAL::Gmpq, rounded) in every field, bit for bit, at double and float.
// 2. Hand cases whose exact answers are known, each value checked to be the correctly rounded
//    one by exact comparisons with the midpoints on either side of it.
// 3. Bad input refused by name, degenerate input answered, the other argument order, and the
//    comparison helpers.
#include <catch2/catch.hpp>
#include <cdref/exact.hpp>
#include <cdref/fuzz/campaign.hpp>
#include <cdref/truth.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "queries/group_boxes.hpp"
#include "queries/group_obb_casts.hpp"
#include "queries/group_polygons.hpp"
#include "queries/group_sat_boxes.hpp"
#include "queries/group_sat_obbs.hpp"
#include "queries/group_sphere_obb.hpp"
#include "queries/group_spheres.hpp"
#include "queries/group_triangle_casts.hpp"
#include "queries/group_triangles.hpp"
#include "queries/groups.hpp"

// Every X(spec, Result, fn, A, B) line of the groups, as the public declaration of <cdref/truth.hpp>
// it defines: a line without its declaration (or with another signature) does not compile here,
// a declaration without its definition does not link. (The units that define the functions
// include cdref/truth/basics.hpp, not truth.hpp, so that a new query's declarations recompile
// only what calls them.)
namespace cdref::truth::declared {
#define CDREF_DECLARED(S, Result, fn, A, B)                                                              \
  out.push_back(reinterpret_cast<void (*)()>(                                                          \
      static_cast<Result<double> (*)(const A<double>&, const B<double>&, Path)>(&truth::fn)));         \
  out.push_back(reinterpret_cast<void (*)()>(static_cast<Result<float> (*)(const A<float>&, const B<float>&, Path)>(&truth::fn)));
#define CDREF_DECLARED_GROUP(fn, list) list(CDREF_DECLARED)
inline std::vector<void (*)()> functions() {
  std::vector<void (*)()> out;
  CDREF_QUERY_GROUPS(CDREF_DECLARED_GROUP)
  return out;
}
#undef CDREF_DECLARED_GROUP
#undef CDREF_DECLARED
}  // namespace cdref::truth::declared

namespace cdref_test_truth {

using namespace cdref;
using Q = CGAL::Gmpq;

// Whether the double (float) x is the correctly rounded value of the number whose square is
// `square` and which lies on the given side of `offset`: value = offset + sign * sqrt(square).
// Decided exactly: the midpoints m- and m+ between x and its neighbours bracket the value.
template <class F>
bool rounds_to(F x, const Q& offset, int sign, const Q& square) {
  const Q lo = (Q(double(x)) + Q(double(std::nextafter(x, F(-INFINITY))))) / 2;
  const Q hi = (Q(double(x)) + Q(double(std::nextafter(x, F(INFINITY))))) / 2;
  // value in [lo, hi]  <=>  sign * (m - offset) brackets sqrt(square) for m = lo, hi
  const Q a = sign > 0 ? lo - offset : offset - hi;  // sqrt(square) >= a
  const Q b = sign > 0 ? hi - offset : offset - lo;  // sqrt(square) <= b
  const bool above_a = a <= 0 || a * a <= square;
  const bool below_b = b >= 0 && b * b >= square;
  return above_a && below_b;
}

TEST_CASE("truth: every query's two functions are declared in <cdref/truth.hpp> and defined", "[truth]") {
  const std::vector<void (*)()> fns = truth::declared::functions();
  CHECK(fns.size() == 2 * fuzz::all_queries().size());
  for (void (*f)() : fns) CHECK(f != nullptr);
}

TEST_CASE("truth: every field of the oracle's answer equals the exact path's, on every family", "[truth]") {
  using namespace cdref::fuzz;
  for (const Query q : all_queries()) {
    const QueryInfo& qi = info(q);
    REQUIRE(qi.truth_api_check);
    for (const Family& f : qi.families) {
      for (const int scale : f.scales) {
        for (std::uint64_t i = 0; i < 40; ++i) {
          const Inputs in = make_case(7, q, f, scale, i);
          for (const int precision : {53, 24}) {
            const std::string d = qi.truth_api_check(in, precision);
            INFO(qi.name << " " << f.name << "/" << scale << " case " << i << " precision " << precision);
            CHECK(d == "");
          }
        }
      }
    }
  }
}

TEST_CASE("truth: first_difference names the field that differs", "[truth]") {
  // the comparison the test above relies on
  const Cast<double> c = truth::cast(Ray<double>{{0, 0, -5}, {0, 0, 1}}, Sphere<double>{{0.5, 0, 0}, 1});
  CHECK(truth::first_difference(c, c) == "");
  Cast<double> d = c;
  d.normal[1] = -0.0;  // 0 and -0: equal numbers, different bits
  CHECK(truth::first_difference(c, d) == "normal_y: 0x0p+0, -0x0p+0");
  d = c;
  d.enters = false;
  CHECK(truth::first_difference(c, d) == "enters: 1, 0");
  CHECK(truth::first_difference(true, false) == "intersect: 1, 0");
}

TEST_CASE("truth: ray-sphere-cast, hand cases correctly rounded", "[truth]") {
  // from (0, 0, -5) along z onto the unit ball at (0.5, 0, 0): lambda = 5 -+ sqrt(0.75)
  const Ray<double> ray{{0, 0, -5}, {0, 0, 1}};
  const Sphere<double> ball{{0.5, 0, 0}, 1};
  const Cast<double> c = truth::cast(ray, ball);
  REQUIRE(c.hit);
  CHECK(c.enters);
  CHECK(rounds_to(c.lambda_enter, Q(5), -1, Q(3, 4)));
  CHECK(rounds_to(c.lambda_exit, Q(5), 1, Q(3, 4)));
  CHECK(c.point[0] == 0);
  CHECK(c.point[1] == 0);
  CHECK(rounds_to(c.point[2], Q(0), -1, Q(3, 4)));  // -5 + lambda_enter = -sqrt(0.75)
  CHECK(c.normal[0] == -0.5);                        // (point - centre) / 1
  CHECK(rounds_to(c.normal[2], Q(0), -1, Q(3, 4)));
  // at float: every value rounded once, from the exact value, to float
  const Cast<float> cf = truth::cast(Ray<float>{{0, 0, -5}, {0, 0, 1}}, Sphere<float>{{0.5f, 0, 0}, 1});
  REQUIRE(cf.hit);
  CHECK(rounds_to(cf.lambda_enter, Q(5), -1, Q(3, 4)));
  CHECK(rounds_to(cf.lambda_exit, Q(5), 1, Q(3, 4)));
  // the direction's length is the unit of lambda
  const Cast<double> c2 = truth::cast(Ray<double>{{0, 0, -5}, {0, 0, 2}}, ball);
  CHECK(rounds_to(c2.lambda_enter, Q(5, 2), -1, Q(3, 16)));
  // a miss: nothing but hit = false
  const Cast<double> m = truth::cast(Ray<double>{{0, 0, -5}, {0, 0, -1}}, ball);
  CHECK_FALSE(m.hit);
  CHECK(m.lambda_enter == 0);
  CHECK(m.point == Vec3<double>(0, 0, 0));
  // from inside: lambda_enter = 0, the source, no normal
  const Cast<double> in = truth::cast(Ray<double>{{0.5, 0, 0}, {0, 0, 1}}, ball);
  CHECK(in.hit);
  CHECK_FALSE(in.enters);
  CHECK(in.lambda_enter == 0);
  CHECK(in.lambda_exit == 1);
  CHECK(in.normal == Vec3<double>(0, 0, 0));
}

TEST_CASE("truth: a segment and a triangle, with barycentric coordinates", "[truth]") {
  const Triangle<double> tri{{Vec3<double>(0, 0, 0), Vec3<double>(1, 0, 0), Vec3<double>(0, 1, 0)}};
  const TriangleCast<double> c = truth::cast(Segment<double>{{0.25, 0.5, 1}, {0.25, 0.5, -1}}, tri);
  REQUIRE(c.hit);
  CHECK(c.lambda_enter == 0.5);
  CHECK(c.point == Vec3<double>(0.25, 0.5, 0));
  CHECK(c.u == 0.25);
  CHECK(c.v == 0.5);
  CHECK(c.normal == Vec3<double>(0, 0, 1));  // the triangle's normal, facing the source
  // through the edge v1-v2 exactly (closed): a hit
  CHECK(truth::cast(Segment<double>{{0.5, 0.5, 1}, {0.5, 0.5, -1}}, tri).hit);
  // a hair outside it: no hit
  const double off = std::nextafter(0.5, 1.0);
  CHECK_FALSE(truth::cast(Segment<double>{{0.5, off, 1}, {0.5, off, -1}}, tri).hit);
}

TEST_CASE("truth: proximity, separation and intersection, hand cases", "[truth]") {
  const Sphere<double> s{{3, 0, 0}, 1};
  const Box<double> box{{0, 0, 0}, {1, 1, 1}};
  const Proximity<double> p = truth::proximity(s, box);
  CHECK_FALSE(p.intersect);
  CHECK(p.distance == 1);
  CHECK(p.depth == 0);
  CHECK(p.on_a == Vec3<double>(2, 0, 0));
  CHECK(p.on_b == Vec3<double>(1, 0, 0));
  CHECK(p.closest == Vec3<double>(1, 0, 0));
  // the other order: the witnesses follow the arguments
  const Proximity<double> r = truth::proximity(box, s);
  CHECK(r.on_a == Vec3<double>(1, 0, 0));
  CHECK(r.on_b == Vec3<double>(2, 0, 0));
  // touching boxes intersect (closed sets); a gap of one ulp does not
  CHECK(truth::intersect(Box<double>{{0, 0, 0}, {1, 1, 1}}, Box<double>{{2, 0, 0}, {1, 1, 1}}));
  CHECK_FALSE(truth::intersect(Box<double>{{0, 0, 0}, {1, 1, 1}}, Box<double>{{std::nextafter(2.0, 3.0), 0, 0}, {1, 1, 1}}));
  // a triangle above a box: separated by the triangle's own normal, (v1 - v0) x (v2 - v0) =
  // (0, -2, 4), axis 0 in triangle-box's order (the box projects to [-6, 6] on it, the triangle to 10)
  const Triangle<double> tri{{Vec3<double>(-1, -1, 2), Vec3<double>(1, -1, 2), Vec3<double>(0, 1, 3)}};
  const Separation<double> sep = truth::separate(tri, box);
  CHECK_FALSE(sep.intersect);
  CHECK(sep.axis == 0);
  CHECK(sep.direction == Vec3<double>(0, -2, 4));
  CHECK(truth::separate(box, tri).axis == 0);
  // lowered under the box's top face's plane z = 1 plus a little, the normal no longer
  // separates; the box's z axis (axis 3) does
  const Triangle<double> low{{Vec3<double>(-1, -1, 1.5), Vec3<double>(1, -1, 1.5), Vec3<double>(0, 1, 1.5)}};
  const Separation<double> sep2 = truth::separate(low, box);
  CHECK(sep2.axis == 0);  // a flat triangle: its normal (0, 0, 4) is the z axis itself
  CHECK(sep2.direction == Vec3<double>(0, 0, 4));
  // two triangles crossing: the segment they share
  const Triangle<double> t1{{Vec3<double>(-1, -1, 0), Vec3<double>(3, -1, 0), Vec3<double>(-1, 3, 0)}};
  const Triangle<double> t2{{Vec3<double>(0, 0, -1), Vec3<double>(0, 0, 1), Vec3<double>(1, 0, 0)}};
  const TriangleIntersection<double> x = truth::intersect(t1, t2);
  CHECK(x.intersect);
  CHECK_FALSE(x.coplanar);
  CHECK(x.p == Vec3<double>(0, 0, 0));
  CHECK(x.q == Vec3<double>(1, 0, 0));
}

TEST_CASE("truth: sphere-sphere depth correctly rounded", "[truth]") {
  // centres 1 apart, radii 1 and 0.5: depth = 0.5; at distance sqrt(2): depth 1.5 - sqrt(2)
  const Proximity<double> p = truth::proximity(Sphere<double>{{0, 0, 0}, 1}, Sphere<double>{{1, 1, 0}, 0.5});
  CHECK(p.intersect);
  CHECK(rounds_to(p.depth, Q(3, 2), -1, Q(2)));
  CHECK(p.distance == 0);
}

TEST_CASE("truth: bad input is refused by name", "[truth]") {
  const Sphere<double> ok{{0, 0, 0}, 1};
  const auto message = [](auto f) {
    try {
      f();
    } catch (const invalid_input& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  CHECK(message([&] { truth::cast(Ray<double>{{0, 0, 0}, {0, 0, 0}}, ok); }) == "ray direction is the zero vector");
  CHECK(message([&] { truth::cast(Ray<double>{{0, NAN, 0}, {0, 0, 1}}, ok); }) ==
        "ray source has a non-finite y coordinate (nan)");
  CHECK(message([&] { truth::proximity(ok, Sphere<double>{{0, 0, 0}, -1}); }) == "sphere b radius is negative (-1)");
  CHECK(message([&] { truth::proximity(Sphere<double>{{INFINITY, 0, 0}, 1}, ok); }) ==
        "sphere a centre has a non-finite x coordinate (inf)");
  CHECK(message([&] { truth::intersect(Box<double>{{0, 0, 0}, {1, -2, 1}}, Box<double>{{0, 0, 0}, {1, 1, 1}}); }) ==
        "box a extent is negative along y (-2)");
  Polygon<double> nine;
  nine.n = 9;
  CHECK(message([&] { truth::cast(Ray<double>{{0, 0, 0}, {0, 0, 1}}, nine); }) ==
        "polygon has 9 vertices (3 to 8 are allowed)");
  const OrientedBox<double> flat_axes{{0, 0, 0}, {1, 1, 1}, {Vec3<double>(1, 0, 0), Vec3<double>(0, 1, 0), Vec3<double>(1, 1, 0)}};
  CHECK(message([&] { truth::proximity(ok, flat_axes); }) ==
        "oriented box axes are linearly dependent (det[a0 a1 a2] = 0 exactly)");
  Fan<double> fan;
  fan.n = 2;
  fan.closed = true;
  CHECK(message([&] { truth::cast(Ray<double>{{0, 0, 0}, {0, 0, 1}}, fan); }) ==
        "fan is closed with 2 ring vertices (3 are needed)");
  // float inputs are checked as floats
  CHECK(message([&] { truth::cast(Ray<float>{{0, 0, 0}, {0, 0, 1}}, Sphere<float>{{0, 0, 0}, -0.5f}); }) ==
        "sphere radius is negative (-0.5)");
}

TEST_CASE("truth: degenerate inputs have their documented meaning", "[truth]") {
  // a zero radius is a point: the ray through it hits it at lambda 5, with enter = exit
  const Cast<double> c = truth::cast(Ray<double>{{0, 0, -5}, {0, 0, 1}}, Sphere<double>{{0, 0, 0}, 0});
  CHECK(c.hit);
  CHECK(c.lambda_enter == 5);
  CHECK(c.lambda_exit == 5);
  // a zero-area triangle is the segment it spans
  const Triangle<double> sliver{{Vec3<double>(0, 0, 0), Vec3<double>(2, 0, 0), Vec3<double>(1, 0, 0)}};
  const Proximity<double> p = truth::proximity(Sphere<double>{{1, 2, 0}, 1}, sliver);
  CHECK(p.distance == 1);
  CHECK(p.closest == Vec3<double>(1, 0, 0));
  // a flat box (zero extent along z) is the square it spans
  CHECK(truth::cast(Ray<double>{{0, 0, -1}, {0, 0, 1}}, Box<double>{{0, 0, 0}, {1, 1, 0}}).lambda_enter == 1);
}

TEST_CASE("truth: deviations in ulps, absolute and relative to the inputs' scale", "[truth]") {
  CHECK(truth::ulp_distance(1.0, std::nextafter(1.0, 2.0)) == 1);
  CHECK(truth::ulp_distance(-0.0, 0.0) == 0);
  CHECK(truth::ulp_distance(-std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::denorm_min()) == 2);
  CHECK(truth::ulp_distance(1.0f, 2.0f) == (1u << 23));
  // 1e-15 against an exact 0: a huge ulp count, a tiny error against the scene's size
  const Triangle<double> tri{{Vec3<double>(0, 0, 0), Vec3<double>(4, 0, 0), Vec3<double>(0, 4, 0)}};
  const Ray<double> ray{{0, 0, 1}, {0, 0, -1}};
  const TriangleCast<double> t = truth::cast(ray, tri);
  REQUIRE(t.u == 0);
  TriangleCast<double> mine = t;
  mine.u = 1e-15;
  bool seen = false;
  for (const truth::FieldDeviation& d : truth::compare(mine, t, ray, tri)) {
    if (d.field != "u") {
      CHECK(d.error.ulps == 0);
      continue;
    }
    seen = true;
    CHECK(d.error.ulps > (std::uint64_t(1) << 60));
    CHECK(d.error.abs == 1e-15);
    CHECK(d.error.rel == 1e-15);  // u is a weight: its scale is 1
  }
  CHECK(seen);
  // a point one ulp of the scene's size off
  const Sphere<double> s{{3, 0, 0}, 1};
  const Box<double> box{{0, 0, 0}, {1, 1, 1}};
  Proximity<double> p = truth::proximity(s, box);
  Proximity<double> q = p;
  q.on_b[0] = std::nextafter(1.0, 2.0);
  for (const truth::FieldDeviation& d : truth::compare(q, p, s, box))
    if (d.field == "witness_b" && d.component == 0) {
      CHECK(d.error.ulps == 1);
      CHECK(d.error.rel == 0x1p-52 / 3);  // against the scale 3 (the sphere's centre)
    }
}

TEST_CASE("truth: the exact path answers alike", "[truth]") {
  const Ray<double> ray{{0, 0, -5}, {0, 0, 1}};
  const Sphere<double> ball{{0.5, 0, 0}, 1};
  const Cast<double> a = truth::cast(ray, ball), b = truth::cast(ray, ball, truth::Path::exact);
  CHECK(a.lambda_enter == b.lambda_enter);
  CHECK(a.point == b.point);
  CHECK(a.normal == b.normal);
}

}  // namespace cdref_test_truth
