// examples/validate/test_my_raycast.cpp - your float code checked by cdref, in your own tests.
// A textbook ray-sphere cast in float (as a game would ship it) and a careful one in double,
// each validated against the exact answer with cdref::validate. (Catch2's runner comes from the
// library target Catch2::Catch2WithMain, CMakeLists.txt.)
#include <catch2/catch.hpp>
#include <cdref/validate.hpp>
#include <cmath>
#include <cstdio>

namespace {

struct Hit {
  bool hit;
  double t;
};

// the quadratic |s + t d - c|^2 = r^2, smallest root; a source inside hits at t = 0
template <class F>
Hit my_raycast(const F s[3], const F d[3], const F c[3], F r) {
  F m[3], a = 0, b = 0, k = -r * r;
  for (int i = 0; i < 3; ++i) {
    m[i] = s[i] - c[i];
    a += d[i] * d[i];
    b += d[i] * m[i];
    k += m[i] * m[i];
  }
  if (k <= 0) return {true, 0};
  if (b >= 0) return {false, 0};
  const F disc = b * b - a * k;
  if (disc < 0) return {false, 0};
  return {true, double((-b - std::sqrt(disc)) / a)};
}

template <class F>
cdref::validate::Answer answer(const cdref::validate::Case& c) {
  const auto s = c.vec("source"), d = c.vec("direction"), ctr = c.vec("center");
  const F S[3] = {F(s[0]), F(s[1]), F(s[2])}, D[3] = {F(d[0]), F(d[1]), F(d[2])}, C[3] = {F(ctr[0]), F(ctr[1]), F(ctr[2])};
  const Hit h = my_raycast<F>(S, D, C, F(c("radius")));
  return cdref::validate::Answer(h.hit).value("lambda_enter", h.t);
}

}  // namespace

TEST_CASE("my double ray cast classifies exactly on uniform cases") {
  const auto report = cdref::validate::run({.query = "ray-sphere-cast", .families = {"uniform"}, .n = 2000},
                                           answer<double>);
  INFO(report.table());
  REQUIRE(report.cases() == 2000);
  REQUIRE(report.misclassified() == 0);
  // the entry parameter's error, pinned at what this implementation does (measured with this
  // seed: p99 and max in ulps of double), so that a change for the worse fails
  std::printf("double, uniform: lambda_enter p99 %llu, max %llu ulps\n", (unsigned long long)report.p99_ulps("lambda_enter"),
              (unsigned long long)report.max_ulps("lambda_enter"));
  CHECK(report.max_ulps("lambda_enter") <= 88);
  // the same error relative to the inputs' scale (absolute errors say what an ulp count near 0
  // hides): pinned the same way
  std::printf("double, uniform: lambda_enter max abs %.3g, max rel %.3g\n", report.max_abs("lambda_enter"),
              report.max_rel("lambda_enter"));
  CHECK(report.max_rel("lambda_enter") <= 2e-14);  // (1.94e-14 with this seed)
}

TEST_CASE("my float ray cast: exact on uniform cases, wrong near tangency") {
  const auto uniform = cdref::validate::run(
      {.query = "ray-sphere-cast", .families = {"uniform"}, .n = 2000, .precision = 24}, answer<float>);
  INFO(uniform.table());
  CHECK(uniform.misclassified() == 0);
  // near tangency the float discriminant cancels: the report counts the shots it gets wrong
  // and lists the worst with their inputs
  const auto tangent = cdref::validate::run(
      {.query = "ray-sphere-cast", .families = {"near-tangent"}, .n = 2000, .precision = 24}, answer<float>);
  std::printf("float, near-tangent: %llu of %llu misclassified (%llu false hits, %llu misses)\n",
              (unsigned long long)tangent.misclassified(), (unsigned long long)tangent.cases(),
              (unsigned long long)tangent.false_positives(), (unsigned long long)tangent.false_negatives());
  CHECK(tangent.misclassified() > 0);
}

TEST_CASE("a cast with another convention: a source inside reports the exit point") {
  // like several libraries, this cast reports where the ray leaves a sphere it starts in;
  // those cases mean something else than cdref's (a hit at lambda 0) and are set apart
  auto exit_convention = [](const cdref::validate::Case& c) {
    const auto s = c.vec("source"), d = c.vec("direction"), ctr = c.vec("center");
    const Hit h = my_raycast<double>(s.data(), d.data(), ctr.data(), c("radius"));
    if (!h.hit || h.t != 0) return cdref::validate::Answer(h.hit).value("lambda_enter", h.t);
    double m[3], a = 0, b = 0, k = -c("radius") * c("radius");  // inside: the far root
    for (int i = 0; i < 3; ++i) {
      m[i] = s[i] - ctr[i];
      a += d[i] * d[i];
      b += d[i] * m[i];
      k += m[i] * m[i];
    }
    return cdref::validate::Answer(true).value("lambda_enter", (-b + std::sqrt(b * b - a * k)) / a);
  };
  cdref::validate::Options o{.query = "ray-sphere-cast", .families = {"uniform"}, .n = 2000};
  o.convention = [](const cdref::validate::Case& c) {
    return c.exact_classification() && c.exact_value("lambda_enter") == 0;  // the source inside or on
  };
  const auto report = cdref::validate::run(o, exit_convention);
  INFO(report.table());
  std::printf("exit convention, uniform: %llu cases set apart, %llu misclassified among the rest\n",
              (unsigned long long)report.convention_cases, (unsigned long long)report.misclassified());
  CHECK(report.convention_cases > 0);
  CHECK(report.misclassified() == 0);
  CHECK(report.max_ulps("lambda_enter") <= 88);  // the other cases are the plain cast's
  // without the convention the 42 exits would be graded as errors against lambda 0
  o.convention = nullptr;
  CHECK(cdref::validate::run(o, exit_convention).max_ulps("lambda_enter") > 1000000);
}
