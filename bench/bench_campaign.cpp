// bench/bench_campaign.cpp - throughput of a campaign of the segment cast on a sphere (the book
// at double against the truth from the oracle), in cases per second on one core, with every
// output graded and with the classification alone (--outputs cls), and what it is made of:
// case generation, the book at double, the exact truth, the oracle (all outputs, and the
// classification alone); the same campaigns of the ray cast (campaign_ray).
// Ratios from one run are the figures to quote; Debian's libbenchmark is a debug build (its
// own overhead is per iteration, small next to these bodies).
#include <benchmark/benchmark.h>

#include <cdref/fuzz/campaign.hpp>

using namespace cdref::fuzz;

namespace {

const Query cast = query_by_name("segment-sphere-cast");
const Family& fam(const char* name) { return family_by_name(cast, name); }
// prepared cases for the parts below, more than a branch predictor learns (README, "How many
// cases")
constexpr std::size_t kCases = 16384;

void campaign_of(benchmark::State& st, Query q, const char* family, bool classification_only) {
  const std::uint64_t n = 4096;
  Spec s;
  s.classification_only = classification_only;
  s.queries = {q};
  s.impls = {"book-double"};
  s.families = {family};
  s.scales = {family_by_name(q, family).scales.front()};
  s.n = n;
  s.threads = 1;
  // a new seed each iteration: no case repeats, as in a campaign (a branch predictor learns a
  // few thousand cases repeated; README, "How many cases")
  for (auto _ : st) {
    benchmark::DoNotOptimize(run(s));
    ++s.seed;
  }
  st.SetItemsProcessed(st.iterations() * std::int64_t(n));
}
void campaign(benchmark::State& st, const char* family, bool classification_only) {
  campaign_of(st, cast, family, classification_only);
}
void campaign_ray(benchmark::State& st, const char* family, bool classification_only) {
  campaign_of(st, query_by_name("ray-sphere-cast"), family, classification_only);
}

void generate(benchmark::State& st) {
  std::uint64_t i = 0;
  const Family& f = fam("uniform");
  const std::uint64_t key = cell_key(1, cast, f, 0);  // once per cell, as in a campaign
  for (auto _ : st) benchmark::DoNotOptimize(make_case_of(key, f, 0, i++));
  st.SetItemsProcessed(st.iterations());
}

void book_double(benchmark::State& st) {
  const Implementation& im = implementation_by_name("book-double");
  std::vector<Inputs> cases;
  for (std::uint64_t i = 0; i < kCases; ++i) cases.push_back(make_case(1, cast, fam("uniform"), 0, i));
  std::size_t k = 0;
  for (auto _ : st) benchmark::DoNotOptimize(im.run(cast, cases[k++ % kCases]));
  st.SetItemsProcessed(st.iterations());
}

void exact_truth(benchmark::State& st) {
  std::vector<Inputs> cases;
  for (std::uint64_t i = 0; i < kCases; ++i) cases.push_back(make_case(1, cast, fam("uniform"), 0, i));
  std::size_t k = 0;
  for (auto _ : st) benchmark::DoNotOptimize(truth(cast, cases[k++ % kCases], 53));
  st.SetItemsProcessed(st.iterations());
}

void oracle_all(benchmark::State& st, const char* family) {
  std::vector<Inputs> cases;
  for (std::uint64_t i = 0; i < kCases; ++i) cases.push_back(make_case(1, cast, fam(family), fam(family).scales.back(), i));
  std::size_t k = 0;
  for (auto _ : st) benchmark::DoNotOptimize(oracle_truth(cast, cases[k++ % kCases], 53));
  st.SetItemsProcessed(st.iterations());
}

void oracle_classification(benchmark::State& st, const char* family) {
  std::vector<Inputs> cases;
  for (std::uint64_t i = 0; i < kCases; ++i) cases.push_back(make_case(1, cast, fam(family), fam(family).scales.back(), i));
  std::size_t k = 0;
  for (auto _ : st) benchmark::DoNotOptimize(oracle_classify(cast, cases[k++ % kCases]));
  st.SetItemsProcessed(st.iterations());
}

void book_double_classification(benchmark::State& st) {
  std::vector<Inputs> cases;
  for (std::uint64_t i = 0; i < kCases; ++i) cases.push_back(make_case(1, cast, fam("uniform"), 0, i));
  TimedRow row;
  for (TimedRow& r : info(cast).timed_rows(cases, cases, ""))
    if (r.name == "book double, classification") row = std::move(r);
  std::vector<char> out(cases.size());
  for (auto _ : st) {
    row.run(0, out.size(), out.data());
    benchmark::DoNotOptimize(out.data());
  }
  st.SetItemsProcessed(st.iterations() * std::int64_t(out.size()));
}

}  // namespace

BENCHMARK(book_double_classification);
BENCHMARK_CAPTURE(oracle_all, uniform, "uniform");
BENCHMARK_CAPTURE(oracle_classification, uniform, "uniform");
BENCHMARK_CAPTURE(oracle_classification, near_tangent_2m52, "near-tangent");
BENCHMARK_CAPTURE(campaign, uniform, "uniform", false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(campaign, long_range, "long-range", false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(campaign, uniform_classification_only, "uniform", true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(campaign, long_range_classification_only, "long-range", true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(campaign_ray, uniform, "uniform", false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(campaign_ray, long_range, "long-range", false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(campaign_ray, uniform_classification_only, "uniform", true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(campaign_ray, long_range_classification_only, "long-range", true)->Unit(benchmark::kMillisecond);
BENCHMARK(generate);
BENCHMARK(book_double);
BENCHMARK(exact_truth);
BENCHMARK_MAIN();
