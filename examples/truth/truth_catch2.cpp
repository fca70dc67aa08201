// examples/truth/truth_catch2.cpp - the exact answer for one input, in a Catch2 test (Catch2's
// runner comes from the library target Catch2::Catch2WithMain, CMakeLists.txt).
#include <catch2/catch.hpp>
#include <cdref/testing/catch2.hpp>
#include <cmath>

using cdref::Cast;
using namespace cdref::testing;

// Your float code: the textbook quadratic, smallest root.
double my_ray_sphere(const cdref::Ray<double>& r, const cdref::Sphere<double>& s) {
  const auto m = r.source - s.center;
  const double a = r.direction.dot(r.direction), b = m.dot(r.direction);
  const double c = m.dot(m) - s.radius * s.radius;
  return (-b - std::sqrt(b * b - a * c)) / a;
}

TEST_CASE("my ray cast against the exact answer") {
  const cdref::Ray<double> ray{{0, 0, -5}, {0, 0, 1}};
  const cdref::Sphere<double> ball{{0.5, 0, 0}, 1};
  const Cast<double> truth = cdref::truth::cast(ray, ball);  // every field correctly rounded
  REQUIRE(truth.hit);
  CHECK_THAT(my_ray_sphere(ray, ball), WithinUlpsOfTruth(ray, ball, &Cast<double>::lambda_enter, 2));

  // 10^8 radii away the quadratic cancels: b * b - a * c loses the ball entirely, and the
  // answer is 0.87 off, tens of millions of ulps ...
  const cdref::Ray<double> far{{0, 0, -1e8}, {0, 0, 1}};
  CHECK_THAT(my_ray_sphere(far, ball), !WithinUlpsOfTruth(far, ball, &Cast<double>::lambda_enter, 2));
  // ... yet within 1e-8 of the scene's size (1e8): how far off it is, in a game's terms
  CHECK_THAT(my_ray_sphere(far, ball), WithinScaleOfTruth(far, ball, &Cast<double>::lambda_enter, 1e-8));
}

TEST_CASE("a whole result, and bad input named") {
  const cdref::Triangle<double> tri{{cdref::Vec3<double>(0, 0, 0), {1, 0, 0}, {0, 1, 0}}};
  const cdref::Segment<double> seg{{0.25, 0.5, 1}, {0.25, 0.5, -1}};
  cdref::TriangleCast<double> mine = cdref::truth::cast(seg, tri);
  CHECK_THAT(mine, MatchesTruth(seg, tri));
  mine.u = std::nextafter(mine.u, 1.0);
  CHECK_THAT(mine, !MatchesTruth(seg, tri));
  CHECK_THAT(mine, MatchesTruth(seg, tri, {.ulps = 1}));
  CHECK_THROWS_WITH(cdref::truth::cast(cdref::Ray<double>{{0, 0, 0}, {0, 0, 0}}, tri),
                    "ray direction is the zero vector");
}
