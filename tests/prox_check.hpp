// tests/prox_check.hpp - one checker for every proximity case (sphere-sphere,
// segment-sphere, sphere-box) at every number type. Same rules as cast_check.hpp:
// exact types reproduce the expected answer exactly; a float type is compared with the
// book at Gmpq on its own rounding of the inputs, within stated bounds or with the
// stated drift.
#pragma once

#include "cast_check.hpp"

namespace cdref::test {

using X3 = std::array<X, 3>;

struct ProxExpect {
  std::optional<bool> intersect;  // proximity().intersect at this type, when it differs from the truth
  std::optional<bool> predicate;  // intersect() at this type, when it differs from the truth
  double min_ulps = 0;            // distance or depth error at least this (a proven drift)
  double max_ulps = 4;            // distance and depth errors at most this
  double max_witness_ulps = 8;    // witness coordinates at most this (ulps of the case's scale at 0)
};

struct ProxCase {
  std::string name;
  bool intersect = false;
  X distance, depth;
  X3 on_a, on_b;
  std::optional<X3> closest{};
  std::map<std::string, ProxExpect> floats{};
  double scale = 1;  // magnitude of the inputs, the unit for errors of values that are 0
};

// run(inputs-of-T) -> pair(Proximity, bool predicate); the inputs are made by make<T>().
template <class T, class Make, class Run>
void check_prox_case(const ProxCase& c, Make make, Run run) {
  INFO("case: " << c.name << "  type: " << tag<T>());
  if (!make.template finite<T>()) {
    REQUIRE_THROWS_AS(run(make.template at<T>()), invalid_input);
    return;
  }
  const auto in = make.template at<T>();
  const auto [res, pred] = run(in);
  if constexpr (is_exact_v<T>) {
    REQUIRE(res.intersect == c.intersect);
    REQUIRE(pred == c.intersect);
    REQUIRE(exact_equal(res.distance, c.distance.expr()));
    REQUIRE(exact_equal(res.depth, c.depth.expr()));
    for (int i = 0; i < 3; ++i) {
      REQUIRE(exact_equal(res.on_a[i], c.on_a[i].expr()));
      REQUIRE(exact_equal(res.on_b[i], c.on_b[i].expr()));
      if (c.closest) REQUIRE(exact_equal(res.closest[i], (*c.closest)[i].expr()));
    }
    // the witnesses realise the reported distance or depth
    Expr dd = 0;
    for (int i = 0; i < 3; ++i) {
      const Expr d = to_expr(res.on_a[i]) - to_expr(res.on_b[i]);
      dd = dd + d * d;
    }
    const Expr gap = c.intersect ? c.depth.expr() : c.distance.expr();
    REQUIRE(dd == gap * gap);
  } else {
    const auto ref_pair = run(make.exact(in));
    const auto& ref = ref_pair.first;
    const auto it = c.floats.find(tag<T>());
    const ProxExpect fe = it != c.floats.end() ? it->second : ProxExpect{};
    const double e_dist = ulps<T>(res.distance, to_expr(ref.distance), c.scale);
    const double e_depth = ulps<T>(res.depth, to_expr(ref.depth), c.scale);
    double e_wit = 0;
    for (int i = 0; i < 3; ++i) {
      e_wit = std::max(e_wit, ulps<T>(res.on_a[i], to_expr(ref.on_a[i]), c.scale));
      e_wit = std::max(e_wit, ulps<T>(res.on_b[i], to_expr(ref.on_b[i]), c.scale));
    }
    if (report_drift())
      std::cout << "[drift] " << c.name << " | " << tag<T>() << " | intersect " << res.intersect << " pred "
                << pred << " (truth " << ref.intersect << ") | distance " << e_dist << " ulps | depth " << e_depth
                << " ulps | witnesses " << e_wit << " ulps\n";
    REQUIRE(res.intersect == fe.intersect.value_or(ref.intersect));
    REQUIRE(pred == fe.predicate.value_or(fe.intersect.value_or(ref.intersect)));
    REQUIRE(std::max(e_dist, e_depth) >= fe.min_ulps);
    if (fe.min_ulps == 0) {
      REQUIRE(e_dist <= fe.max_ulps);
      REQUIRE(e_depth <= fe.max_ulps);
      REQUIRE(e_wit <= fe.max_witness_ulps);
    }
  }
}

}  // namespace cdref::test
