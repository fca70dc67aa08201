// tests/cast_check.hpp - one checker for every ray-cast case (spheres and boxes, segment
// and infinite ray), at every number type.
//
// Exact types must reproduce the expected answer exactly: hit, enters, lambda_enter,
// lambda_exit, the entry point (source + lambda_enter r) and the normal.
// A float type runs on its own rounding of the inputs; its reference is the book at
// Gmpq on exactly those inputs. Unless the case states otherwise for that type, it must
// classify like the reference and give both lambdas within `max_ulps` of its own
// precision. Where the case states a drift (the chapter's long-range warning, overflow),
// the test asserts that drift: the classification the float type gets, and the least
// error it shows.
#pragma once

#include <array>
#include <cstdlib>
#include <iostream>
#include <map>

#include "support.hpp"

namespace cdref::test {

using D3 = std::array<double, 3>;

struct FloatExpect {
  std::optional<bool> hit;  // the classification this type gets (when it differs from the truth)
  double min_ulps = 0;      // lambda_enter error at least this (a drift the test proves)
  double max_ulps = 4;      // lambda errors at most this
  std::optional<bool> predicate;  // hit() at this type, when it differs from cast().hit
};

struct CastCase {
  std::string name;
  D3 s, t;  // source, target (segment) or source, direction (infinite ray)
  bool infinite = false;
  bool hit = false;
  bool enters = false;
  X enter, exit;
  std::optional<D3> normal;  // expected normal; for spheres it is (point - c) / rho when absent
  std::map<std::string, FloatExpect> floats{};
};

template <class T>
std::string tag() {
  if constexpr (std::is_same_v<T, float>) return "float";
  if constexpr (std::is_same_v<T, double>) return "double";
  if constexpr (std::is_same_v<T, long double>) return "long double";
  if constexpr (std::is_same_v<T, mpreal>) return "mpfr";
  return number_traits<T>::name();
}

inline bool report_drift() { return std::getenv("CDREF_TEST_REPORT") != nullptr; }

template <class T>
bool all_finite(std::initializer_list<double> xs) {
  for (double x : xs)
    if (!number_traits<T>::is_finite(from_double<T>(x))) return false;
  return true;
}

template <class T, class Prim, class Cast, class Hit>
void check_cast_case(const CastCase& c, const Prim& prim_d, const Vec3<double>& center, double rho,
                     Cast cast_fn, Hit hit_fn) {
  INFO("case: " << c.name << "  type: " << tag<T>());
  auto to_t = [](const Prim& p) { return convert_prim<T>(p); };
  const Vec3<T> s = v3<T>(c.s[0], c.s[1], c.s[2]);
  const Vec3<T> t = v3<T>(c.t[0], c.t[1], c.t[2]);
  const bool finite = all_finite<T>({c.s[0], c.s[1], c.s[2], c.t[0], c.t[1], c.t[2]}) && prim_finite<T>(prim_d);
  if (!finite) {  // the inputs overflow this type: the query must refuse them by name
    REQUIRE_THROWS_AS(cast_fn(s, t, to_t(prim_d), c.infinite), invalid_input);
    return;
  }
  const auto res = cast_fn(s, t, to_t(prim_d), c.infinite);
  const bool h = hit_fn(s, t, to_t(prim_d), c.infinite);

  if constexpr (is_exact_v<T>) {
    REQUIRE(res.hit == c.hit);
    REQUIRE(h == c.hit);
    if (!c.hit) return;
    REQUIRE(res.enters == c.enters);
    REQUIRE(exact_equal(res.lambda_enter, c.enter.expr()));
    REQUIRE(exact_equal(res.lambda_exit, c.exit.expr()));
    const Expr lam = c.enter.expr();
    for (int i = 0; i < 3; ++i) {
      const Expr r = c.infinite ? to_expr(c.t[i]) : to_expr(c.t[i]) - to_expr(c.s[i]);
      REQUIRE(to_expr(res.point[i]) == to_expr(c.s[i]) + lam * r);
    }
    if (!c.enters) {
      for (int i = 0; i < 3; ++i) REQUIRE(to_expr(res.normal[i]) == 0);
    } else if (c.normal) {
      for (int i = 0; i < 3; ++i) REQUIRE(to_expr(res.normal[i]) == to_expr((*c.normal)[i]));
    } else if (rho != 0) {  // a sphere: the unit outward normal at the entry point
      Expr n2 = 0;
      for (int i = 0; i < 3; ++i) {
        REQUIRE(to_expr(res.normal[i]) == (to_expr(res.point[i]) - to_expr(center[i])) / to_expr(rho));
        n2 = n2 + to_expr(res.normal[i]) * to_expr(res.normal[i]);
      }
      REQUIRE(n2 == 1);
    }
  } else {
    // the truth for the inputs this type actually holds
    const Vec3<Q> sq(exact_q(s[0]), exact_q(s[1]), exact_q(s[2]));
    const Vec3<Q> tq(exact_q(t[0]), exact_q(t[1]), exact_q(t[2]));
    const auto ref = cast_fn(sq, tq, convert_prim_exact(to_t(prim_d)), c.infinite);
    const auto it = c.floats.find(tag<T>());
    const FloatExpect fe = it != c.floats.end() ? it->second : FloatExpect{};
    const bool expect_hit = fe.hit.value_or(ref.hit);
    if (report_drift())
      std::cout << "[drift] " << c.name << " | " << tag<T>() << " | hit " << res.hit << " (truth " << ref.hit
                << ")";
    REQUIRE(res.hit == expect_hit);
    REQUIRE(h == fe.predicate.value_or(expect_hit));
    if (res.hit && ref.hit) {
      const double e_enter = ulps<T>(res.lambda_enter, to_expr(ref.lambda_enter));
      const double e_exit = ulps<T>(res.lambda_exit, to_expr(ref.lambda_exit));
      if (report_drift()) std::cout << " | enter " << e_enter << " ulps | exit " << e_exit << " ulps";
      REQUIRE(e_enter >= fe.min_ulps);
      REQUIRE(e_enter <= fe.max_ulps);
      if (fe.min_ulps == 0) REQUIRE(e_exit <= fe.max_ulps);
    }
    if (report_drift()) std::cout << "\n";
  }
}

}  // namespace cdref::test
