/// \file
/// cdref/testing/catch2.hpp - Catch2 (v2, Debian's catch2) matchers against the exact answer.
///
///   #include <cdref/testing/catch2.hpp>
///   using namespace cdref::testing;
///   REQUIRE_THAT(my_lambda, WithinUlpsOfTruth(ray, sphere, &cdref::Cast<double>::lambda_enter, 4));
///   REQUIRE_THAT(my_u, WithinScaleOfTruth(ray, tri, &cdref::TriangleCast<double>::u, 1e-12));
///   REQUIRE_THAT(my_result, MatchesTruth(ray, sphere, {.ulps = 4}));   // a cdref result struct
///
/// The truth is <cdref/truth.hpp>'s (cdref::truth::answer(a, b)), correctly rounded to the
/// field's type; a failure prints the truth and how far the value is from it in ulps, absolutely
/// and relative to the scale.
#pragma once

#include <catch2/catch.hpp>
#include <cdref/testing/tolerance.hpp>
#include <cdref/truth.hpp>
#include <string>

namespace cdref::testing {

/// A value (float or double) against a truth of its type, within a Tolerance.
template <class F>
class TruthMatcher : public Catch::MatcherBase<F> {
 public:
  /// truth: the exact answer rounded to F; t: how close a value must be.
  TruthMatcher(F truth, Tolerance t) : truth_(truth), tol_(t) {}
  /// Whether x is within the tolerance of the truth.
  bool match(const F& x) const override {
    dev_ = truth::deviation(x, truth_, tol_.scale);
    return accepts(tol_, dev_);
  }
  /// What the matcher asks, and after a match how far the value was.
  std::string describe() const override { return testing::describe(tol_, double(truth_)) + testing::describe(dev_); }

 private:
  F truth_;
  Tolerance tol_;
  mutable truth::Deviation dev_;
};

/// Within `ulps` of a truth already computed.
template <class F>
TruthMatcher<F> WithinUlpsOfTruth(F truth, std::uint64_t ulps) {
  return TruthMatcher<F>(truth, {ulps, 0, 1});
}
/// Within `ulps` of the field `field` of the exact answer on (a, b).
template <class A, class B, class R, class F>
TruthMatcher<F> WithinUlpsOfTruth(const A& a, const B& b, F R::*field, std::uint64_t ulps) {
  return TruthMatcher<F>(truth::answer(a, b).*field, {ulps, 0, truth::scale_of(a, b)});
}
/// Within rel * (the inputs' scale) of the field `field` of the exact answer on (a, b): for
/// values near 0, where ulps of the value mean little.
template <class A, class B, class R, class F>
TruthMatcher<F> WithinScaleOfTruth(const A& a, const B& b, F R::*field, double rel) {
  return TruthMatcher<F>(truth::answer(a, b).*field, {0, rel, truth::scale_of(a, b)});
}

/// A whole cdref result (Cast, Proximity, ...) against the exact answer on (a, b): the
/// classification equal, every field truth::compare lists within the tolerance (each at its own
/// scale: the tolerance's `scale` is not used).
template <class R, class A, class B>
class ResultMatcher : public Catch::MatcherBase<R> {
 public:
  /// The exact answer on (a, b) and the tolerance of its fields.
  ResultMatcher(const A& a, const B& b, Tolerance t) : a_(a), b_(b), truth_(truth::answer(a, b)), tol_(t) {}
  /// Whether every field of r is within the tolerance.
  bool match(const R& r) const override {
    failed_.clear();
    for (const truth::FieldDeviation& d : truth::compare(r, truth_, a_, b_)) {
      const bool label = d.field == "hit" || d.field == "intersect" || d.field == "enters" ||
                         d.field == "unbounded_exit" || d.field == "axis" || d.field == "coplanar" || d.field == "hits";
      if (label ? d.error.abs != 0 : !accepts({tol_.ulps, tol_.rel, 1}, d.error)) {
        char b[240];
        std::snprintf(b, sizeof b, "%s%s%s: %.17g, the truth %.17g (%llu ulps, abs %.3g, %.3g of its scale)",
                      failed_.empty() ? "" : "; ", d.field.c_str(),
                      d.field == "point" || d.field == "normal" || d.field.rfind("witness", 0) == 0 ||
                              d.field == "closest" || d.field == "p" || d.field == "q" || d.field == "direction"
                          ? (d.component == 0 ? "_x" : d.component == 1 ? "_y" : "_z")
                          : "",
                      d.value, d.truth, (unsigned long long)d.error.ulps, d.error.abs, d.error.rel);
        failed_ += b;
      }
    }
    return failed_.empty();
  }
  /// What the matcher asks, and the fields that failed.
  std::string describe() const override {
    return "matches the exact answer within " + std::to_string(tol_.ulps) + " ulps" +
           (tol_.rel > 0 ? " or " + std::to_string(tol_.rel) + " of each field's scale" : std::string()) +
           (failed_.empty() ? std::string() : "; " + failed_);
  }

 private:
  A a_;
  B b_;
  R truth_;
  Tolerance tol_;
  mutable std::string failed_;
};
/// A whole result against the exact answer on (a, b), within `t` (default: equal).
template <class A, class B>
auto MatchesTruth(const A& a, const B& b, Tolerance t = {}) {
  return ResultMatcher<decltype(truth::answer(a, b)), A, B>(a, b, t);
}

}  // namespace cdref::testing
