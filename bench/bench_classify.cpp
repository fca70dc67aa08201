// bench/bench_classify.cpp - the fast exact classification oracle against the book at double,
// for every query (from its descriptor's cost-report rows). Per query: the book's
// classification at double and oracle::classify on 1024 pre-generated cases of the uniform
// family (cycled), the same on the query's near-boundary family at its hardest scale, where
// the filter cannot decide, and there the oracle's expansion stage alone (queries that have
// one). Quote ratios taken in one run (medians of --benchmark_repetitions=3); Debian's
// libbenchmark is a debug build (its own per-iteration overhead is in every figure).
#include <benchmark/benchmark.h>

#include <cdref/fuzz/campaign.hpp>
#include <memory>
#include <string>
#include <vector>

using namespace cdref::fuzz;

namespace {

std::vector<Inputs> cases_of(Query q, const Family& f, int scale) {
  std::vector<Inputs> c;
  for (std::uint64_t i = 0; i < 1024; ++i) c.push_back(make_case(1, q, f, scale, i));
  return c;
}

const Family* hard_family(Query q) {
  for (const char* name : {"near-tangent", "near-touching", "grazing"})
    for (const Family& f : families(q))
      if (f.name == name) return &f;
  return nullptr;
}

void run_row(benchmark::State& st, std::shared_ptr<TimedRow> row) {
  std::size_t k = 0;
  for (auto _ : st) benchmark::DoNotOptimize(row->run(k++ & 1023));
  st.SetItemsProcessed(st.iterations());
}

void expansion(benchmark::State& st, Query q, std::shared_ptr<std::vector<Inputs>> cases) {
  std::size_t k = 0;
  for (auto _ : st) benchmark::DoNotOptimize(info(q).oracle_stage(1, (*cases)[k++ & 1023]));
  st.SetItemsProcessed(st.iterations());
}

void reg(Query q) {
  const QueryInfo& qi = info(q);
  const Family* hard = hard_family(q);
  if (!hard) return;
  const auto uni = cases_of(q, family_by_name(q, "uniform"), 0);
  const auto hc = std::make_shared<std::vector<Inputs>>(cases_of(q, *hard, hard->scales.back()));
  const std::string h = hard->name + "-" + std::to_string(hard->scales.back());
  const std::string book = qi.outputs.empty() ? "book double" : "book double, classification";
  for (auto [cases, tag] : {std::pair<const std::vector<Inputs>*, std::string>{&uni, "uniform"}, {hc.get(), h}})
    for (TimedRow& row : qi.timed_rows(*cases, *hc, "")) {
      const char* what = row.name == book ? "book" : row.name == "oracle, classification" ? "oracle" : nullptr;
      if (!what || row.hard) continue;
      benchmark::RegisterBenchmark((std::string(qi.name) + "/" + what + "/" + tag).c_str(), run_row,
                                   std::make_shared<TimedRow>(std::move(row)));
    }
  if (qi.oracle_stage)
    benchmark::RegisterBenchmark((std::string(qi.name) + "/expansion/" + h).c_str(), expansion, q, hc);
}

}  // namespace

int main(int argc, char** argv) {
  for (Query q : all_queries()) reg(q);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
