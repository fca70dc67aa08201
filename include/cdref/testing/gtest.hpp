/// \file
/// cdref/testing/gtest.hpp - GoogleTest / GoogleMock matchers against the exact answer.
///
///   #include <cdref/testing/gtest.hpp>
///   using cdref::testing::WithinUlpsOfTruth;
///   EXPECT_THAT(my_lambda, WithinUlpsOfTruth(ray, sphere, &cdref::Cast<double>::lambda_enter, 4));
///   EXPECT_THAT(my_u, cdref::testing::WithinScaleOfTruth(ray, tri, &cdref::TriangleCast<double>::u, 1e-12));
///
/// The truth is <cdref/truth.hpp>'s (cdref::truth::answer(a, b)), correctly rounded to the
/// field's type; a failure prints the truth and how far the value is from it in ulps, absolutely
/// and relative to the scale.
#pragma once

#include <gmock/gmock.h>
#include <cdref/testing/tolerance.hpp>
#include <cdref/truth.hpp>
#include <ostream>

namespace cdref::testing {

/// A value (float or double) against a truth of its type, within a Tolerance.
template <class F>
class GTestTruthMatcher : public ::testing::MatcherInterface<F> {
 public:
  /// truth: the exact answer rounded to F; t: how close a value must be.
  GTestTruthMatcher(F truth, Tolerance t) : truth_(truth), tol_(t) {}
  /// Whether x is within the tolerance, explaining how far it is.
  bool MatchAndExplain(F x, ::testing::MatchResultListener* listener) const override {
    const truth::Deviation d = truth::deviation(x, truth_, tol_.scale);
    *listener << describe(d).substr(2);
    return accepts(tol_, d);
  }
  /// What the matcher asks.
  void DescribeTo(std::ostream* os) const override { *os << describe(tol_, double(truth_)); }
  /// What its negation asks.
  void DescribeNegationTo(std::ostream* os) const override { *os << "not: " << describe(tol_, double(truth_)); }

 private:
  F truth_;
  Tolerance tol_;
};

/// Within `ulps` of a truth already computed.
template <class F>
::testing::Matcher<F> WithinUlpsOfTruth(F truth, std::uint64_t ulps) {
  return ::testing::MakeMatcher(new GTestTruthMatcher<F>(truth, {ulps, 0, 1}));
}
/// Within `ulps` of the field `field` of the exact answer on (a, b).
template <class A, class B, class R, class F>
::testing::Matcher<F> WithinUlpsOfTruth(const A& a, const B& b, F R::*field, std::uint64_t ulps) {
  return ::testing::MakeMatcher(new GTestTruthMatcher<F>(truth::answer(a, b).*field, {ulps, 0, truth::scale_of(a, b)}));
}
/// Within rel * (the inputs' scale) of the field `field` of the exact answer on (a, b).
template <class A, class B, class R, class F>
::testing::Matcher<F> WithinScaleOfTruth(const A& a, const B& b, F R::*field, double rel) {
  return ::testing::MakeMatcher(new GTestTruthMatcher<F>(truth::answer(a, b).*field, {0, rel, truth::scale_of(a, b)}));
}

}  // namespace cdref::testing
