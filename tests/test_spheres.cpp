// tests/test_spheres.cpp - Section 3.1 at every number type: sphere-sphere, the segment and
// infinite-ray casts of Algorithm 3.1, and the segment-sphere test of Algorithm 3.2.
// Expected answers are exact, written as rationals or a + b sqrt(d).
#include <cdref/robust/ray_sphere.hpp>

#include "prox_check.hpp"

// This file's names in a namespace of its own: the test files are compiled several to a unit
// (tests/CMakeLists.txt).
namespace cdref_test_spheres {

using namespace cdref;
using namespace cdref::test;

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();
const double y_in = 1.0 - std::ldexp(1.0, -40);   // 1 - 2^-40
const double y_out = 1.0 + std::ldexp(1.0, -40);  // 1 + 2^-40
const Q q_in = Q(1) - p2(-40);
const Q q_out = Q(1) + p2(-40);
// Near 1e160 and 1e-160, as powers of two so that 3 * big is exact: squares of these
// overflow (past ~1.3e154) or underflow (below ~1.5e-154) in double.
const double big = std::ldexp(1.0, 532);     // ~1.4e160
const double tiny = std::ldexp(1.0, -532);   // ~7.1e-161

Sphere<double> sph(double x, double y, double z, double r) { return {Vec3<double>(x, y, z), r}; }

struct SphereCast {
  Sphere<double> sphere;
  CastCase c;
};

// Sphere at the origin, radius 1, unless given.
const Sphere<double> unit = sph(0, 0, 0, 1);

std::vector<SphereCast> ray_sphere_cases() {
  std::vector<SphereCast> v;
  auto add = [&](Sphere<double> s, CastCase c) { v.push_back({s, std::move(c)}); };
  add(unit, {"through the centre", {-3, 0, 0}, {3, 0, 0}, false, true, true, "1/3", "2/3"});
  add(unit, {"chord with irrational lambdas", {-2, 0.5, 0}, {2, 0.5, 0}, false, true, true,
             X(q("1/2"), q("-1/16"), Q(12)), X(q("1/2"), q("1/16"), Q(12))});
  add(sph(10, -20, 30, 5), {"sphere off the origin", {0, -20, 30}, {20, -20, 30}, false, true, true, "1/4", "3/4"});
  add(unit, {"exact tangency", {-2, 1, 0}, {2, 1, 0}, false, true, true, "1/2", "1/2", D3{0, 1, 0}});
  add(unit, {"near tangency inside by 2^-40", {-2, y_in, 0}, {2, y_in, 0}, false, true, true,
             X(q("1/2"), q("-1/4"), Q(1) - q_in * q_in), X(q("1/2"), q("1/4"), Q(1) - q_in * q_in)});
  add(unit, {"near tangency outside by 2^-40", {-2, y_out, 0}, {2, y_out, 0}, false, false});
  // The chapter's long-range warning: sigma = (s.r)^2 - |r|^2 (|s|^2 - rho^2) cancels.
  // At 1e8 radii |s|^2 - 1 = 1e16 - 1 rounds to 1e16 in double, sigma comes out 0 and
  // lambda_enter = 1/2 instead of 1/2 - 5e-9: 5e-9 / 2^-54 = 9e7 ulps off. long double
  // keeps 11 more bits and still misses by ~1e7 ulps. float's own ulp at 1/2 (6e-8) is
  // larger than the whole error, so float is within an ulp here.
  add(unit, {"long range 1e8 radii, through the centre",
             {-1e8, 0, 0},
             {1e8, 0, 0},
             false,
             true,
             true,
             Q(1e8 - 1) / Q(2e8),
             Q(1e8 + 1) / Q(2e8),
             std::nullopt,
             {{"double", {true, 1e7, inf}}, {"long double", {true, 1e6, inf}}}});
  // At 1e4 radii, passing 2^-40 radii outside the sphere: the truth is a miss, but in
  // double |s|^2 = 1e8 + 1 + 2^-39 loses its last term, sigma = 0 and the book reports a
  // (tangent) hit. long double's ulp at 1e8 is 2^-37: the same loss.
  add(unit, {"long range 1e4 radii, miss by 2^-40",
             {-1e4, y_out, 0},
             {1e4, y_out, 0},
             false,
             false,
             false,
             {},
             {},
             std::nullopt,
             {{"double", {true, 0, inf}}, {"long double", {true, 0, inf}}}});
  add(unit, {"source inside", {0, 0, 0}, {2, 0, 0}, false, true, false, Q(0), "1/2"});
  add(unit, {"source on the sphere, inward", {-1, 0, 0}, {1, 0, 0}, false, true, true, Q(0), Q(1), D3{-1, 0, 0}});
  add(unit, {"source on the sphere, outward", {1, 0, 0}, {2, 0, 0}, false, true, false, Q(0), Q(0)});
  add(unit, {"target on the sphere", {-3, 0, 0}, {-1, 0, 0}, false, true, true, Q(1), Q(1), D3{-1, 0, 0}});
  add(unit, {"segment too short", {-3, 0, 0}, {-2, 0, 0}, false, false});
  add(unit, {"segment pointing away", {2, 0, 0}, {3, 0, 0}, false, false});
  add(unit, {"zero-length segment inside", {0.5, 0, 0}, {0.5, 0, 0}, false, true, false, Q(0), Q(1)});
  add(unit, {"zero-length segment on the sphere", {0, 1, 0}, {0, 1, 0}, false, true, false, Q(0), Q(1)});
  add(unit, {"zero-length segment outside", {0, 1, 1}, {0, 1, 1}, false, false});
  add(sph(0, 0, 0, 0), {"point sphere on the line", {-1, 0, 0}, {1, 0, 0}, false, true, true, "1/2", "1/2",
                        D3{0, 0, 0}});
  // 1e160: |r|^2 = 3.6e321 overflows double, sigma = inf - inf = NaN, and the book's
  // "if sigma >= 0" reports a miss. long double and MPFR have the range.
  add(sph(0, 0, 0, big), {"coordinates near 1e160",
                            {-3 * big, 0, 0},
                            {3 * big, 0, 0},
                            false,
                            true,
                            true,
                            "1/3",
                            "2/3",
                            std::nullopt,
                            {{"double", {false, 0, inf}}}});
  // 1e-160: the squares are subnormal or zero in double; sigma and s.r lose their digits.
  add(sph(0, 0, 0, tiny), {"coordinates near 1e-160",
                             {-3 * tiny, 0, 0},
                             {3 * tiny, 0, 0},
                             false,
                             true,
                             true,
                             "1/3",
                             "2/3",
                             std::nullopt,
                             {{"double", {true, 1e12, inf}}}});
  // infinite rays
  add(unit, {"ray through the centre", {-3, 0, 0}, {1, 0, 0}, true, true, true, Q(2), Q(4)});
  add(unit, {"ray with a non-unit direction", {-3, 0, 0}, {2, 0, 0}, true, true, true, Q(1), Q(2)});
  add(unit, {"ray from inside", {0, 0, 0}, {0, 0, 1}, true, true, false, Q(0), Q(1)});
  add(unit, {"ray pointing away", {2, 0, 0}, {1, 0, 0}, true, false});
  add(unit, {"ray tangent", {-5, 0, 1}, {1, 0, 0}, true, true, true, Q(5), Q(5), D3{0, 0, 1}});
  // 1e12 radii: |s|^2 - 1 = 1e24 - 1 needs 80 bits and rounds to 1e24 in double and in
  // long double, sigma = 0, lambda_enter = 1e12 instead of 1e12 - 1: an error of 1, which
  // is 2^13 ulps of double and 2^24 ulps of long double at 1e12.
  add(unit, {"ray at 1e12 radii",
             {-1e12, 0, 0},
             {1, 0, 0},
             true,
             true,
             true,
             Q(1e12 - 1),
             Q(1e12 + 1),
             std::nullopt,
             {{"double", {true, 8192, 8192}}, {"long double", {true, 16777216, 16777216}}}});
  return v;
}

template <class T>
void run_ray_sphere() {
  for (const auto& sc : ray_sphere_cases()) {
    const Vec3<double> center = sc.sphere.center;
    check_cast_case<T>(
        sc.c, sc.sphere, center, sc.sphere.radius,
        [](const auto& s, const auto& t, const auto& sp, bool infinite) {
          using U = typename std::decay_t<decltype(s)>::Scalar;
          return infinite ? book::cast(Ray<U>{s, t}, sp) : book::cast(Segment<U>{s, t}, sp);
        },
        [](const auto& s, const auto& t, const auto& sp, bool infinite) {
          using U = typename std::decay_t<decltype(s)>::Scalar;
          return infinite ? book::hit(Ray<U>{s, t}, sp) : book::hit(Segment<U>{s, t}, sp);
        });
  }
}

}  // namespace

TEMPLATE_TEST_CASE("ray-sphere casts (Algorithm 3.1) on hard cases", "[ray-sphere]", CDREF_ALL_TYPES) {
  run_ray_sphere<TestType>();
}

TEMPLATE_TEST_CASE("robust ray-sphere casts keep their accuracy on the same hard cases", "[ray-sphere][robust]",
                   float, double, long double) {
  // No drift is allowed here: every case must classify as the truth (on the type's own
  // rounding of the inputs) and give both lambdas within 4 ulps, where the book loses up
  // to 9e7 ulps, misclassifies near tangency at 1e4 radii, and overflows at 1e160.
  for (auto sc : ray_sphere_cases()) {
    sc.c.floats.clear();
    const Vec3<double> center = sc.sphere.center;
    check_cast_case<TestType>(
        sc.c, sc.sphere, center, sc.sphere.radius,
        [](const auto& s, const auto& t, const auto& sp, bool infinite) {
          using U = typename std::decay_t<decltype(s)>::Scalar;
          if constexpr (is_exact_v<U>)  // the reference: the book, exactly
            return infinite ? book::cast(Ray<U>{s, t}, sp) : book::cast(Segment<U>{s, t}, sp);
          else
            return infinite ? robust::cast(Ray<U>{s, t}, sp) : robust::cast(Segment<U>{s, t}, sp);
        },
        [](const auto& s, const auto& t, const auto& sp, bool infinite) {
          using U = typename std::decay_t<decltype(s)>::Scalar;
          return infinite ? robust::hit(Ray<U>{s, t}, sp) : robust::hit(Segment<U>{s, t}, sp);
        });
  }
}

// ---------------------------------------------------------------------------
namespace {

X3 x3(X a, X b, X c) { return {a, b, c}; }

struct SphereSphereCase {
  PairOf<Sphere<double>, Sphere<double>> in;
  ProxCase c;
};

std::vector<SphereSphereCase> sphere_sphere_cases() {
  std::vector<SphereSphereCase> v;
  v.push_back({{sph(0, 0, 0, 1), sph(3, 0, 0, 1)},
               {"disjoint", false, Q(1), Q(0), x3(Q(1), Q(0), Q(0)), x3(Q(2), Q(0), Q(0))}});
  v.push_back({{sph(0, 0, 0, 1), sph(2, 0, 0, 1)},
               {"touching", true, Q(0), Q(0), x3(Q(1), Q(0), Q(0)), x3(Q(1), Q(0), Q(0))}});
  // v = (-1, -1, 0), |v| = sqrt 2, depth 3 - sqrt 2, u = -(sqrt 2 / 2)(1, 1, 0)
  v.push_back({{sph(0, 0, 0, 2), sph(1, 1, 0, 1)},
               {"overlapping, irrational depth", true, Q(0), X(Q(3), Q(-1), Q(2)),
                x3(X(Q(0), Q(1), Q(2)), X(Q(0), Q(1), Q(2)), Q(0)),
                x3(X(Q(1), q("-1/2"), Q(2)), X(Q(1), q("-1/2"), Q(2)), Q(0))}});
  v.push_back({{sph(1, 2, 3, 1), sph(1, 2, 3, 2)},
               {"concentric", true, Q(0), Q(3), x3(Q(0), Q(2), Q(3)), x3(Q(3), Q(2), Q(3))}});
  // v = (-2e8, -1, 0), |v|^2 = 4e16 + 1 rounds to 4e16 in double and float: the spheres
  // are disjoint by 2.5e-9, both say touching and report distance 0. The book's distance
  // |v| - (rhoA + rhoB) cancels at every precision: long double and MPFR-128 classify
  // right but their distance is still off by more than 1e15 of their own ulps.
  const Q vv = Q(4e16) + Q(1);
  v.push_back({{sph(0, 0, 0, 1e8), sph(2e8, 1, 0, 1e8)},
               {"near-touching at 1e8",
                false,
                X(Q(-2e8), Q(1), vv),
                Q(0),
                x3(X(Q(0), Q(2e16) / vv, vv), X(Q(0), Q(1e8) / vv, vv), Q(0)),
                x3(X(Q(2e8), Q(-2e16) / vv, vv), X(Q(1), Q(-1e8) / vv, vv), Q(0)),
                std::nullopt,
                {{"float", {true, true, 1e6, inf, inf}},
                 {"double", {true, true, 1e15, inf, inf}},
                 {"long double", {std::nullopt, std::nullopt, 1e15, inf, inf}},
                 {"mpfr", {std::nullopt, std::nullopt, 1e15, inf, inf}}},
                1e8}});
  // 1e160: |v|^2 and (rhoA + rhoB)^2 both overflow to infinity in double, and inf <= inf
  // reports an intersection 1e160 away.
  v.push_back({{sph(0, 0, 0, big), sph(3 * big, 0, 0, big)},
               {"coordinates near 1e160",
                false,
                Q(big),
                Q(0),
                x3(Q(big), Q(0), Q(0)),
                x3(Q(2 * big), Q(0), Q(0)),
                std::nullopt,
                {{"double", {true, true, 0, inf, inf}}},
                big}});
  v.push_back({{sph(0, 0, 0, tiny), sph(3 * tiny, 0, 0, tiny)},
               {"coordinates near 1e-160", false, Q(tiny), Q(0), x3(Q(tiny), Q(0), Q(0)),
                x3(Q(2 * tiny), Q(0), Q(0)), std::nullopt, {}, tiny}});
  return v;
}

}  // namespace

TEMPLATE_TEST_CASE("sphere-sphere (3.1.1) on hard cases", "[sphere-sphere]", CDREF_ALL_TYPES) {
  for (const auto& sc : sphere_sphere_cases())
    check_prox_case<TestType>(sc.c, sc.in, [](const auto& in) {
      return std::pair{book::proximity(in.first, in.second), book::intersect(in.first, in.second)};
    });
}

// ---------------------------------------------------------------------------
namespace {

Segment<double> seg(double sx, double sy, double sz, double tx, double ty, double tz) {
  return {Vec3<double>(sx, sy, sz), Vec3<double>(tx, ty, tz)};
}

struct SegmentSphereCase {
  PairOf<Segment<double>, Sphere<double>> in;
  ProxCase c;
};

std::vector<SegmentSphereCase> segment_sphere_cases() {
  std::vector<SegmentSphereCase> v;
  auto add = [&](Segment<double> s, Sphere<double> sp, ProxCase c) { v.push_back({{s, sp}, std::move(c)}); };
  add(seg(-1, 2, 0, 1, 2, 0), unit,
      {"closest point inside the segment", false, Q(1), Q(0), x3(Q(0), Q(2), Q(0)), x3(Q(0), Q(1), Q(0)),
       x3(Q(0), Q(2), Q(0))});
  add(seg(2, 0, 0, 3, 0, 0), unit,
      {"closest point is the source", false, Q(1), Q(0), x3(Q(2), Q(0), Q(0)), x3(Q(1), Q(0), Q(0)),
       x3(Q(2), Q(0), Q(0))});
  add(seg(-3, 0, 0, -2, 0, 0), unit,
      {"closest point is the target", false, Q(1), Q(0), x3(Q(-2), Q(0), Q(0)), x3(Q(-1), Q(0), Q(0)),
       x3(Q(-2), Q(0), Q(0))});
  // x = 0: witness rho (r x e_y)/|r x e_y| with r = (2,0,0): r x e_y = (0,0,2).
  add(seg(-1, 0, 0, 1, 0, 0), unit,
      {"segment through the centre", true, Q(0), Q(1), x3(Q(0), Q(0), Q(0)), x3(Q(0), Q(0), Q(1)),
       x3(Q(0), Q(0), Q(0))});
  // r = (1,2,3): smallest |r_i| on x, r x e_x = (0, 3, -2), witness (0, 3, -2)/sqrt(13).
  add(seg(-1, -2, -3, 0, 0, 0), unit,
      {"segment ending at the centre", true, Q(0), Q(1), x3(Q(0), Q(0), Q(0)),
       x3(Q(0), X(Q(0), q("3/13"), Q(13)), X(Q(0), q("-2/13"), Q(13))), x3(Q(0), Q(0), Q(0))});
  add(seg(-1, 1, 1, 1, 1, 1), sph(0, 0, 0, 2),
      {"irrational depth", true, Q(0), X(Q(2), Q(-1), Q(2)), x3(Q(0), Q(1), Q(1)),
       x3(Q(0), X(Q(0), Q(1), Q(2)), X(Q(0), Q(1), Q(2))), x3(Q(0), Q(1), Q(1))});
  add(seg(0, 0, 0, 0, 0, 0), unit,
      {"zero-length segment at the centre", true, Q(0), Q(1), x3(Q(0), Q(0), Q(0)), x3(Q(1), Q(0), Q(0)),
       x3(Q(0), Q(0), Q(0))});
  add(seg(0, 0, 3, 0, 0, 3), unit,
      {"zero-length segment outside", false, Q(2), Q(0), x3(Q(0), Q(0), Q(3)), x3(Q(0), Q(0), Q(1)),
       x3(Q(0), Q(0), Q(3))});
  add(seg(5, 5, 5, 5, 5, 7), sph(5, 5, 6, 1),
      {"segment through an off-origin centre", true, Q(0), Q(1), x3(Q(5), Q(5), Q(6)), x3(Q(5), Q(6), Q(6)),
       x3(Q(5), Q(5), Q(6))});
  // Touching at long range: the closest point is (0,1,0) exactly, on the unit sphere.
  // The division-free predicate |s|^2 |r|^2 - delta^2 <= rho^2 |r|^2 cancels at 4e32:
  // The truth sits exactly on the boundary (the two sides are equal), so a rounding error
  // of the wrong sign flips it: in long double the products lose ~1e13 each and
  // intersect() says no, while proximity(), which divides first as the listing does,
  // still finds the touch. (In double the errors happen to cancel here.)
  add(seg(-1e8, 1, 0, 1e8 + 1, 1, 0), unit,
      {"touching at 1e8 radii",
       true,
       Q(0),
       Q(0),
       x3(Q(0), Q(1), Q(0)),
       x3(Q(0), Q(1), Q(0)),
       x3(Q(0), Q(1), Q(0)),
       {{"long double", {std::nullopt, false, 0, inf, inf}}},
       1e8});
  add(seg(-3 * big, 0, 2 * big, 3 * big, 0, 2 * big), sph(0, 0, 0, big),
      {"coordinates near 1e160",
       false,
       Q(big),
       Q(0),
       x3(Q(0), Q(0), Q(2 * big)),
       x3(Q(0), Q(0), Q(big)),
       x3(Q(0), Q(0), Q(2 * big)),
       {{"double", {true, true, 0, inf, inf}}},
       big});
  return v;
}

}  // namespace

TEMPLATE_TEST_CASE("segment-sphere (Algorithm 3.2) on hard cases", "[segment-sphere]", CDREF_ALL_TYPES) {
  for (const auto& sc : segment_sphere_cases())
    check_prox_case<TestType>(sc.c, sc.in, [](const auto& in) {
      return std::pair{book::proximity(in.first, in.second), book::intersect(in.first, in.second)};
    });
}

TEMPLATE_TEST_CASE("Algorithms 3.1 and 3.2 agree at exact types", "[segment-sphere][ray-sphere]",
                   CDREF_EXACT_TYPES) {
  // Two different algorithms for one predicate: hit() (3.1, root-free) and intersect()
  // (3.2, closest point). On a grid of segments, including tangent and touching ones,
  // they must agree exactly.
  using T = TestType;
  const Sphere<T> sp{Vec3<T>(T(0), T(0), T(0)), T(2)};
  int n = 0;
  for (int a = -3; a <= 3; ++a)
    for (int b = -3; b <= 3; ++b)
      for (int c = -2; c <= 2; ++c)
        for (int d = -3; d <= 3; d += 2) {
          const Segment<T> s{Vec3<T>(T(a), T(b), T(c)), Vec3<T>(T(d), T(a - b), T(c + 1))};
          REQUIRE(book::hit(s, sp) == book::intersect(s, sp));
          REQUIRE(book::cast(s, sp).hit == book::proximity(s, sp).intersect);
          ++n;
        }
  REQUIRE(n == 7 * 7 * 5 * 4);
}

}  // namespace cdref_test_spheres
