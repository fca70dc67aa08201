// examples/truth/truth_gtest.cpp - the exact answer for one input, in a GoogleTest test.
#include <gtest/gtest.h>
#include <cdref/testing/gtest.hpp>
#include <cmath>

using cdref::Proximity;
using cdref::testing::WithinScaleOfTruth;
using cdref::testing::WithinUlpsOfTruth;

// Your float code: the distance between two balls.
double my_distance(const cdref::Sphere<double>& a, const cdref::Sphere<double>& b) {
  return std::fmax((a.center - b.center).norm() - a.radius - b.radius, 0.0);
}

TEST(Truth, SphereSphereDistance) {
  const cdref::Sphere<double> a{{0, 0, 0}, 1}, b{{3, 4, 0}, 0.5};
  EXPECT_EQ(cdref::truth::proximity(a, b).distance, 3.5);  // exactly: 5 - 1.5
  EXPECT_THAT(my_distance(a, b), WithinUlpsOfTruth(a, b, &Proximity<double>::distance, 1));
  // a near-miss along a diagonal: the distance is about 2^-20, and the rounding of the norm
  // (an ulp of 2) is hundreds of thousands of the distance's ulps ...
  const double x = (2 + 0x1p-20) / std::sqrt(2.0);
  const cdref::Sphere<double> c{{0, 0, 0}, 1}, d{{x, x, 0}, 1};
  EXPECT_THAT(my_distance(c, d), ::testing::Not(WithinUlpsOfTruth(c, d, &Proximity<double>::distance, 4)));
  // ... and under 1e-15 of the scene's size
  EXPECT_THAT(my_distance(c, d), WithinScaleOfTruth(c, d, &Proximity<double>::distance, 1e-15));
}
