// tests/test_errors.cpp - bad input gets a clear error naming the argument, the field and
// the value: NaN and infinite coordinates, negative radius and extent, inverted min-max
// boxes, a zero direction for an infinite ray. Case by case, for every query.
#include "support.hpp"

// This file's names in a namespace of its own: the test files are compiled several to a unit
// (tests/CMakeLists.txt).
namespace cdref_test_errors {

using namespace cdref;
using namespace cdref::test;
using Catch::Matchers::Contains;

namespace {
template <class T>
T nan_of() {
  if constexpr (std::is_same_v<T, mpreal>)
    return mpreal().setNan();
  else
    return std::numeric_limits<T>::quiet_NaN();
}
template <class T>
T inf_of() {
  if constexpr (std::is_same_v<T, mpreal>)
    return mpreal().setInf(1);
  else
    return std::numeric_limits<T>::infinity();
}
}  // namespace

TEMPLATE_TEST_CASE("non-finite input is refused by name", "[errors]", float, double, long double, mpfr::mpreal) {
  using T = TestType;
  const Vec3<T> o(T(0), T(0), T(0)), e(T(1), T(0), T(0));
  const Sphere<T> good{o, T(1)};
  const Box<T> box{o, Vec3<T>(T(1), T(1), T(1))};
  const Sphere<T> nan_centre{Vec3<T>(T(0), nan_of<T>(), T(0)), T(1)};
  const Sphere<T> inf_radius{o, inf_of<T>()};
  const Segment<T> nan_target{o, Vec3<T>(T(0), T(0), nan_of<T>())};
  const Ray<T> inf_source{Vec3<T>(-inf_of<T>(), T(0), T(0)), e};
  const Box<T> nan_extent{o, Vec3<T>(T(1), nan_of<T>(), T(1))};

  REQUIRE_THROWS_WITH(book::intersect(nan_centre, good), Contains("sphere A centre has a non-finite y coordinate (nan)"));
  REQUIRE_THROWS_WITH(book::proximity(good, nan_centre), Contains("sphere B centre has a non-finite y coordinate"));
  REQUIRE_THROWS_WITH(book::intersect(good, inf_radius), Contains("sphere B radius is not finite (inf)"));
  REQUIRE_THROWS_WITH(book::cast(nan_target, good), Contains("segment target has a non-finite z coordinate (nan)"));
  REQUIRE_THROWS_WITH(book::hit(nan_target, good), Contains("segment target"));
  REQUIRE_THROWS_WITH(book::intersect(nan_target, good), Contains("segment target"));
  REQUIRE_THROWS_WITH(book::proximity(nan_target, good), Contains("segment target"));
  REQUIRE_THROWS_WITH(book::cast(inf_source, good), Contains("ray source has a non-finite x coordinate (-inf)"));
  REQUIRE_THROWS_WITH(book::hit(inf_source, box), Contains("ray source has a non-finite x coordinate"));
  REQUIRE_THROWS_WITH(book::cast(Segment<T>{o, e}, nan_extent), Contains("box extent has a non-finite y coordinate"));
  REQUIRE_THROWS_WITH(book::hit(Segment<T>{o, e}, nan_extent), Contains("box extent"));
  REQUIRE_THROWS_WITH(book::intersect(inf_radius, box), Contains("sphere radius is not finite"));
  REQUIRE_THROWS_WITH(book::proximity(good, nan_extent), Contains("box extent"));
  REQUIRE_THROWS_WITH(book::intersect(box, nan_extent), Contains("box B extent"));
  const MinMaxBox<T> nan_corner{o, Vec3<T>(nan_of<T>(), T(1), T(1))};
  REQUIRE_THROWS_WITH(book::intersect(nan_corner, to_min_max(box)), Contains("box A max corner has a non-finite x"));
  REQUIRE_THROWS_AS(book::intersect(nan_corner, to_min_max(box)), invalid_input);
}

TEMPLATE_TEST_CASE("domain errors are refused by name", "[errors]", double, float, CGAL::Gmpq, CGAL::Epeck::FT) {
  using T = TestType;
  const Vec3<T> o(T(0), T(0), T(0)), e(T(1), T(0), T(0));
  const Sphere<T> good{o, T(1)};
  const Sphere<T> negative{o, T(-1)};
  const Box<T> box{o, Vec3<T>(T(1), T(1), T(1))};
  const Box<T> neg_extent{o, Vec3<T>(T(1), T(-2), T(1))};
  const Ray<T> zero_dir{o, o};

  REQUIRE_THROWS_WITH(book::intersect(good, negative), Contains("sphere B radius is negative (-1)"));
  REQUIRE_THROWS_WITH(book::proximity(negative, good), Contains("sphere A radius is negative (-1)"));
  REQUIRE_THROWS_WITH(book::cast(Segment<T>{o, e}, negative), Contains("sphere radius is negative"));
  REQUIRE_THROWS_WITH(book::hit(Segment<T>{o, e}, negative), Contains("sphere radius is negative"));
  REQUIRE_THROWS_WITH(book::cast(Ray<T>{o, e}, negative), Contains("sphere radius is negative"));
  REQUIRE_THROWS_WITH(book::intersect(Segment<T>{o, e}, negative), Contains("sphere radius is negative"));
  REQUIRE_THROWS_WITH(book::proximity(Segment<T>{o, e}, negative), Contains("sphere radius is negative"));
  REQUIRE_THROWS_WITH(book::intersect(negative, box), Contains("sphere radius is negative"));
  REQUIRE_THROWS_WITH(book::proximity(good, neg_extent), Contains("box extent is negative along y (-2)"));
  REQUIRE_THROWS_WITH(book::intersect(neg_extent, box), Contains("box A extent is negative along y (-2)"));
  REQUIRE_THROWS_WITH(book::cast(Segment<T>{o, e}, neg_extent), Contains("box extent is negative along y"));
  REQUIRE_THROWS_WITH(book::hit(Ray<T>{o, e}, neg_extent), Contains("box extent is negative along y"));
  REQUIRE_THROWS_WITH(book::cast(zero_dir, good), Contains("ray direction is the zero vector"));
  REQUIRE_THROWS_WITH(book::hit(zero_dir, good), Contains("ray direction is the zero vector"));
  REQUIRE_THROWS_WITH(book::cast(zero_dir, box), Contains("ray direction is the zero vector"));
  REQUIRE_THROWS_WITH(book::hit(zero_dir, box), Contains("ray direction is the zero vector"));
  const MinMaxBox<T> inverted{Vec3<T>(T(0), T(0), T(1)), Vec3<T>(T(1), T(1), T(0))};
  REQUIRE_THROWS_WITH(book::intersect(to_min_max(box), inverted), Contains("box B is inverted along z (min 1 > max 0)"));
  // the degenerate but valid inputs are accepted
  REQUIRE_NOTHROW(book::cast(Segment<T>{o, o}, good));
  REQUIRE_NOTHROW(book::intersect(Sphere<T>{o, T(0)}, box));
  REQUIRE_NOTHROW(book::hit(Segment<T>{o, e}, Box<T>{o, o}));
}

}  // namespace cdref_test_errors
