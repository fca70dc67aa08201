// bench/bench_tiers.cpp - `cdref_bench`: every query's tiers timed with Google Benchmark, one
// benchmark per query, family and row of the cost report (the rows come from the query's
// descriptor, fuzz/cdref/fuzz/describe.hpp, as `cdref report` takes them), on 16,384 prepared
// cases per family (--cases=N): the uniform family, the long-range family at its farthest scale and the
// query's near-boundary family at 2^-32 (where it has that scale) and at its hardest scale
// (where they exist). Each benchmark runs the
// row's loop over those cases per iteration and reports ns per query; a row prepares
// timing_windows such sets (campaign.hpp; --sets=N fewer) and each iteration runs the next, so that no pass
// runs on cases the branch predictor has just seen (README, "Fresh cases for every timed
// pass"); the exact types' rows run on the first slow_row_cases of the first set. After the run, one
// table per query and family gives every row's time as a ratio to `bare` (the book's
// classification at double without input checks) taken in the same run.
//
//   cdref_bench --benchmark_filter='ray-sphere-cast/'      one query
//   cdref_bench --benchmark_filter='/uniform-0/(bare|stable|robust-double)'   (names end in /min_time:0.050)
//   cdref_bench --benchmark_repetitions=3                  medians of three
//   cdref_bench --sets=1                                   the same cases every iteration (the branch predictor learns them)
// Each benchmark runs at least 0.05 s by default (--benchmark_min_time changes it). Debian's
// libbenchmark is a debug build: its own overhead is per iteration (16,384 queries), small here.
#include <benchmark/benchmark.h>

#include <cdref/fuzz/campaign.hpp>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <string>
#include <vector>

using namespace cdref::fuzz;

namespace {

// Cases per family and set (--cases=N): over the same 1024 cases repeated, the book's box and
// slab tests ran in a third of the time they take on 16,384 (README, "How many cases"), and
// over the same 16,384 repeated this machine's predictor still learned the ray cast's (hence
// the sets).
std::size_t cases_per_family = 16384;
// Sets of those cases each row prepares and runs in turn (--sets=N, 1 to timing_windows; 1: the
// same cases every iteration, as before the sets, for comparison).
std::size_t sets = timing_windows;

// "book double, classification" -> "book-double-classification"
std::string slug(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == ' ' || c == ',' || c == '(' || c == ')') {
      if (!out.empty() && out.back() != '-') out += '-';
    } else {
      out += c;
    }
  }
  while (!out.empty() && out.back() == '-') out.pop_back();
  return out;
}

struct Timed {
  std::string query, family, row;
};
std::map<std::string, Timed>& registered() {
  static std::map<std::string, Timed> r;
  return r;
}

// One query's family at one scale: its rows are prepared when the first of its benchmarks runs
// and dropped when another set's are (Google Benchmark runs one benchmark's repetitions, then
// the next, in registration order), so that only one set's prepared inputs are alive at a time
// (every row holds its own copy of the cases, in its own types).
struct CaseSet {
  Query q;
  const Family* f;
  int scale;
  std::vector<TimedRow> rows;
};
CaseSet* alive = nullptr;
std::vector<TimedRow>& rows_of(CaseSet& s) {
  if (alive != &s) {
    if (alive) std::vector<TimedRow>().swap(alive->rows);
    std::vector<Inputs> cases;
    for (std::uint64_t i = 0; i < cases_per_family * sets; ++i)
      cases.push_back(make_case(1, s.q, *s.f, s.scale, i));
    s.rows = info(s.q).timed_rows(cases, cases, "");
    alive = &s;
  }
  return s.rows;
}

void run_row(benchmark::State& st, CaseSet* set, std::size_t row) {
  const TimedRow& r = rows_of(*set)[row];
  const std::size_t n = std::min(cases_per_family, r.cases);
  const bool windowed = r.cases >= cases_per_family * sets;
  std::vector<char> out(n);
  std::size_t w = 0;
  for (auto _ : st) {
    r.run(w * n, n, out.data());
    if (windowed) w = (w + 1) % sets;
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  st.SetItemsProcessed(st.iterations() * std::int64_t(n));
  st.counters["cases"] = double(n);  // queries per iteration (the Reporter's divisor)
}

const Family* family_named(Query q, std::initializer_list<const char*> names) {
  for (const char* name : names)
    for (const Family& f : families(q))
      if (f.name == name) return &f;
  return nullptr;
}

void reg(Query q) {
  const QueryInfo& qi = info(q);
  struct Set {
    const Family* f;
    int scale;
  };
  std::vector<Set> sets{{&family_by_name(q, "uniform"), family_by_name(q, "uniform").scales.front()}};
  if (const Family* lr = family_named(q, {"long-range"})) sets.push_back({lr, lr->scales.back()});
  if (const Family* h = family_named(q, {"near-tangent", "near-touching", "grazing", "watertight", "near-edge"})) {
    // 2^-32 from the boundary, where the filters are to decide (near-tangent, near-touching),
    // then the hardest scale, where they cannot
    if (h->scales.back() != 32 && std::find(h->scales.begin(), h->scales.end(), 32) != h->scales.end())
      sets.push_back({h, 32});
    sets.push_back({h, h->scales.back()});
  }
  for (const Set& set : sets) {
    auto* cs = new CaseSet{q, set.f, set.scale, {}};  // lives as long as the benchmarks
    // the rows' names from one case (the rows themselves are prepared when first run)
    const std::vector<Inputs> one{make_case(1, q, *set.f, set.scale, 0)};
    const std::string fam = set.f->name + "-" + std::to_string(set.scale);
    const std::vector<TimedRow> named = qi.timed_rows(one, one, "");
    for (std::size_t j = 0; j < named.size(); ++j) {
      if (named[j].hard) continue;  // the same rows on these cases
      const std::string row_name = slug(named[j].name);
      const std::string name = std::string(qi.name) + "/" + fam + "/" + row_name;
      registered()[name] = {qi.name, fam, row_name};
      benchmark::RegisterBenchmark(name.c_str(), run_row, cs, j)->MinTime(0.05);
    }
  }
}

// The console output, and every run's ns per query kept for the ratio tables.
class Reporter : public benchmark::ConsoleReporter {
 public:
  std::map<std::string, double> ns;  // by benchmark name
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs) {
      if (r.error_occurred || r.iterations == 0) continue;
      const std::string base = r.run_name.function_name;  // as registered (no /min_time: suffix)
      // seconds per iteration (iterations and aggregates alike), over the row's queries per iteration
      const auto c = r.counters.find("cases");
      const double per_iteration = c != r.counters.end() && c->second.value > 0 ? double(c->second.value)
                                                                                 : double(cases_per_family);
      const double per_query =
          1e9 * r.GetAdjustedRealTime() / benchmark::GetTimeUnitMultiplier(r.time_unit) / per_iteration;
      if (r.run_type == Run::RT_Aggregate) {
        if (r.aggregate_name == "median") ns[base] = per_query;
      } else if (!ns.count(base) || r.repetitions <= 1) {
        ns[base] = per_query;
      }
    }
  }
};

void ratio_tables(const std::map<std::string, double>& ns) {
  std::map<std::pair<std::string, std::string>, std::vector<std::pair<std::string, double>>> tables;
  for (const auto& [name, t] : registered()) {
    const auto it = ns.find(name);
    if (it != ns.end()) tables[{t.query, t.family}].push_back({t.row, it->second});
  }
  if (tables.empty()) return;
  std::printf("\nns per query and ratio to bare (the book's classification at double, unchecked), this run:\n");
  for (const auto& [key, rows] : tables) {
    double bare = 0;
    for (const auto& [row, t] : rows)
      if (row.rfind("bare", 0) == 0) bare = t;
    std::printf("%s, %s\n", key.first.c_str(), key.second.c_str());
    for (const auto& [row, t] : rows) {
      if (bare > 0)
        std::printf("  %-48s %12.1f %10.2f\n", row.c_str(), t, t / bare);
      else
        std::printf("  %-48s %12.1f %10s\n", row.c_str(), t, "(no bare)");
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  // --cases=N and --sets=N (ours; Google Benchmark refuses flags it does not know, so they are
  // taken out first)
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.rfind("--cases=", 0) == 0) {
      char* end = nullptr;
      const unsigned long long n = std::strtoull(a.c_str() + 8, &end, 10);
      // (every row prepares timing_windows sets of N: as `cdref report --n`, at most 65,536)
      if (a.size() == 8 || *end != '\0' || n == 0 || n > 65536) {
        std::fprintf(stderr, "cdref_bench: --cases needs a whole number from 1 to 65536, got '%s'\n", a.c_str() + 8);
        return 2;
      }
      cases_per_family = std::size_t(n);
    } else if (a.rfind("--sets=", 0) == 0) {
      char* end = nullptr;
      const unsigned long long n = std::strtoull(a.c_str() + 7, &end, 10);
      if (a.size() == 7 || *end != '\0' || n == 0 || n > timing_windows) {
        std::fprintf(stderr, "cdref_bench: --sets needs a whole number from 1 to %zu, got '%s'\n", timing_windows,
                     a.c_str() + 7);
        return 2;
      }
      sets = std::size_t(n);
    } else {
      argv[kept++] = argv[i];
    }
  }
  argc = kept;
  for (Query q : all_queries()) reg(q);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  Reporter rep;
  benchmark::RunSpecifiedBenchmarks(&rep);
  ratio_tables(rep.ns);
  benchmark::Shutdown();
  return 0;
}
