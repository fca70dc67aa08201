// src/costreport.cpp - `cdref report`: what accuracy costs in time, measured side by side in
// one run, for every query the campaign engine runs.
//
// Rows (each query's descriptor makes them: fuzz/cdref/fuzz/describe.hpp; each answers the
// same prepared inputs in one loop, no call per case; a row that computes a query's outputs
// asks for all of them):
//   bare: the book's classification at double without its input checks (book::unchecked),
//   the loop a tight engine runs over bodies it checked once: the baseline; book at float,
//   double (all outputs, and the classification alone: book::hit or book::intersect), long
//   double, MPFR-128 and MPFR-256; the stable tier at float and double (and its
//   classification, with and without input checks) where the query has one; robust at float,
//   double and long double; the oracle (the classification alone, and every output correctly
//   rounded, with its hand-written filters); the generic staged path (the truth's own code on
//   a bounded double, a bounded double word, then rationals: cdref/exact/staged.hpp), the
//   classification and every output, uniform and near the boundary, beside the oracle's
//   rows: what the hand filters save; the book at CGAL::Gmpq, CGAL::Epeck::FT and CORE::Expr (the query and its first
//   output rounded correctly to double); CGAL's own do_intersect in its filtered (Epick) and
//   exact (Epeck) kernels, classification only, translated to closed solids as the
//   cross-check test does (tests/test_cgal_crosscheck.cpp: CGAL's sphere pairs test
//   surfaces). Where the book assumes what the inputs do not give (oriented boxes), the exact
//   rows run the truth's formulation instead. Then the query's own variants (the patches
//   engines ship, the book at an exact type), timed through the campaign's interface (the
//   columns' conversion included in their time).
// Columns: nanoseconds per query (median of interleaved repetitions over the same inputs, one
// thread; a row under 2 us a query runs untimed eight times (or for 5 ms) before each timed
// run, a slower one is timed on the first 2,000 cases), ratio to bare and to
// the book at double (all outputs), and for the rows the campaign engine runs: the share
// misclassified on the uniform family and on the query's hard families (every other family),
// and the p99 and max error in ulps of the row's type of every output group (lambda_enter,
// lambda_exit, point, normal; distance, depth, witnesses; ...) over all families, graded where
// the row and the truth classify alike. Exact rows and the oracle have no error by
// construction (the oracle's equality with the exact path is tested); MPFR's error is not
// measured here.
// Output: the table, and on request CSV, JSON and an SVG of cost against error (log-log, one
// point per row, one panel per query; gnuplot).
#include <algorithm>
#include <cdref/fuzz/campaign.hpp>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "campaign_cli.hpp"
#include "casefiles.hpp"
#include "options.hpp"
#include "output.hpp"
#include "plotting.hpp"

namespace cdref::cli {

using namespace cdref::fuzz;

namespace {

// Rows slower than 2 us a query are timed on this many of the cases (measure(), below; the
// exact types' rows have prepared no more, campaign.hpp).
constexpr std::size_t slow_cases = slow_row_cases;

struct Row : TimedRow {
  double ns = 0;
  // errors, from the campaign
  bool measured = false;
  double miss_uniform = 0, miss_hard = 0;
  std::uint64_t p99 = 0, max = 0;  // the first output group
  // every output group measured in ulps (labels, such as a separating axis's index, left out):
  // p99 and max over all families, in ulps of the row's type
  std::vector<std::uint64_t> p99s, maxs;
};

struct QueryReport {
  Query q;
  std::vector<Row> rows;
  double base = 0;  // book at double, all outputs
  double bare = 0;  // the book's classification at double without input checks
  std::size_t sink = 0;  // results of the near-boundary rows, kept so no row is optimized away
};

std::string pct(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g%%", 100 * x);
  return b;
}
std::string gnum(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", x);
  return b;
}

const Row* find_row(const QueryReport& r, const std::string& name) {
  for (const Row& row : r.rows)
    if (row.name == name) return &row;
  return nullptr;
}

// Untimed passes of a fast row over its cases from `first` on: eight, or as many as 5 ms allow.
void warm_up(const TimedRow::Batch& run, std::size_t first, std::size_t count, char* out) {
  const auto t0 = std::chrono::steady_clock::now();
  for (int pass = 0; pass < 8; ++pass) {
    run(first, count, out);
    if (std::chrono::steady_clock::now() - t0 > std::chrono::milliseconds(5)) return;
  }
}

QueryReport measure(Query q, std::uint64_t n, int reps, std::uint64_t err_n, int threads) {
  const Family& uni = family_by_name(q, "uniform");
  // timing_windows sets of n cases (campaign.hpp), one after another: a fast row's timed pass
  // r runs on set r (mod timing_windows), never on the set its warm-up ran on
  std::vector<Inputs> cases;
  for (std::uint64_t i = 0; i < n * timing_windows; ++i) cases.push_back(make_case(1, q, uni, uni.scales.front(), i));

  // the oracle where its filters fail by nature: the query's near-boundary family at its
  // hardest scale (2^-52 from tangency or touching, grazing edges and corners, or shots through
  // the shared vertices and edges of a mesh 10^6 from the origin)
  const Family* hp = nullptr;
  for (const char* name : {"near-tangent", "near-touching", "grazing", "watertight", "near-edge"})
    for (const Family& f : families(q))
      if (!hp && f.name == name) hp = &f;
  if (!hp) throw std::logic_error(std::string("no near-boundary family for ") + info(q).name);
  const Family& hard = *hp;
  const std::uint64_t n_hard = std::max<std::uint64_t>(1, n / 4);
  std::vector<Inputs> hard_cases;
  for (std::uint64_t i = 0; i < n_hard * timing_windows; ++i)
    hard_cases.push_back(make_case(1, q, hard, hard.scales.back(), i));
  const std::string hard_name = " (" + hard.name + " " + std::to_string(hard.scales.back()) + ")";
  QueryReport rep{q, {}, 0, 0};
  auto& rows = rep.rows;
  for (TimedRow& t : info(q).timed_rows(cases, hard_cases, hard_name)) {
    rows.emplace_back();
    static_cast<TimedRow&>(rows.back()) = std::move(t);
  }
  // the query's own variants (the patches engines ship, the book at an exact type), timed
  // through the campaign's interface: the conversion of the case's columns is in their time
  for (const Implementation& v : info(q).variants) {
    rows.emplace_back();
    rows.back().name = v.name + " (campaign interface)";
    rows.back().campaign_impl = v.name;
    rows.back().run = [run = v.run, q, &cases](std::size_t first, std::size_t n, char* out) {
      if (!out) return touch(cases.data() + first, n);
      for (std::size_t k = 0; k < n; ++k) out[k] = run(q, cases[first + k]).cls;
    };
    rows.back().cases = cases.size();
  }

  // timing: every row over the same inputs, `reps` times, interleaved; the median per row.
  // Every row must agree with the oracle's classification on every input it times (the
  // uniform family keeps clear of the boundaries), so no row is timed doing less work.
  std::vector<char> want(cases.size());
  for (std::size_t k = 0; k < cases.size(); ++k) want[k] = oracle_classify(q, cases[k]).cls;
  std::vector<std::vector<double>> times(rows.size());
  std::vector<char> got(std::max<std::size_t>(n, n_hard));
  std::size_t sink = 0;
  // A row slower than 2 us a query (the exact types, the oracle's outputs; one untimed pass
  // over 64 cases tells) is timed on the first `slow_cases` of them: its time goes to
  // arithmetic on long numbers, and a mispredicted branch (what the many cases are for, in the
  // fast rows) costs it a few nanoseconds of its microseconds; on all of them it would take
  // most of the run. A fast row is timed on a fresh set each pass (`windowed`).
  std::vector<std::size_t> counts(rows.size()), set_size(rows.size());
  std::vector<char> windowed(rows.size());
  for (std::size_t j = 0; j < rows.size(); ++j) {
    const std::size_t set = rows[j].hard ? n_hard : n;
    const std::size_t probe = std::min<std::size_t>({set, 64, rows[j].cases});
    const auto t0 = std::chrono::steady_clock::now();
    rows[j].run(0, probe, got.data());
    const auto t1 = std::chrono::steady_clock::now();
    const bool slow = std::chrono::duration<double, std::nano>(t1 - t0).count() > 2000.0 * double(probe);
    counts[j] = std::min({set, rows[j].cases, slow ? slow_cases : set});
    set_size[j] = set;
    windowed[j] = !slow && rows[j].cases >= set * timing_windows;
  }
  for (int r = 0; r < reps; ++r)
    for (std::size_t j = 0; j < rows.size(); ++j) {
      std::size_t disagree = 0;
      const std::size_t count = counts[j];
      // A fast row is timed warm but on cases it has not just run: its warm-up (eight passes,
      // or 5 ms of them: one pass left the code and the caches cold whichever heavy row ran
      // before it) runs on another set, then the timed set's inputs are read into cache
      // (run(first, n, nullptr)) and the timed pass answers them. Warmed up on the cases it was
      // then timed on, as until 37ecae8, a row whose branches depend on the data was timed
      // after the branch predictor had learned their outcomes: the ray cast's `bare` in 2.0 ns
      // a query where on fresh cases it takes 4.1 (README, "Fresh cases for every timed pass").
      const std::size_t w = windowed[j] ? std::size_t(r) % timing_windows : 0, first = w * set_size[j];
      const std::size_t warm = windowed[j] ? ((w + timing_windows / 2) % timing_windows) * set_size[j] : 0;
      if (r == 0 || times[j].back() < 2000) warm_up(rows[j].run, warm, count, got.data());
      if (windowed[j]) rows[j].run(first, count, nullptr);
      const auto t0 = std::chrono::steady_clock::now();
      rows[j].run(first, count, got.data());
      const auto t1 = std::chrono::steady_clock::now();
      if (rows[j].hard)
        for (std::size_t k = 0; k < count; ++k) disagree += got[k];  // (a count, not checked)
      else
        for (std::size_t k = 0; k < count; ++k) disagree += bool(got[k]) != bool(want[first + k]);
      if (disagree && !rows[j].hard && rows[j].campaign_impl.empty() && rows[j].error_note == "exact")
        throw std::logic_error(rows[j].name + " disagrees with the oracle on " + std::to_string(disagree) + " of " +
                               std::to_string(count) + " " + info(q).name + " cases");
      times[j].push_back(std::chrono::duration<double, std::nano>(t1 - t0).count() / double(count));
      if (rows[j].hard) sink += disagree;
    }
  // the prepared inputs go now (every row holds its own copy): one query's at a time in memory
  for (Row& row : rows) row.run = nullptr;
  for (std::size_t j = 0; j < rows.size(); ++j) {
    std::sort(times[j].begin(), times[j].end());
    rows[j].ns = times[j][times[j].size() / 2];
  }
  rep.bare = find_row(rep, "bare (book at double, unchecked)")->ns;
  rep.base = find_row(rep, "book double")->ns;
  rep.sink = sink;

  // accuracy: a campaign over every family of the query
  Spec spec;
  spec.queries = {q};
  spec.impls = {"book-float", "book-double", "book-long-double"};
  if (info(q).stable) spec.impls.insert(spec.impls.end(), {"stable-float", "stable-double"});
  spec.impls.insert(spec.impls.end(), {"robust-float", "robust-double", "robust-long-double"});
  for (const Implementation& v : info(q).variants) spec.impls.push_back(v.name);
  spec.n = err_n;
  spec.threads = threads;
  const Results res = run(spec);
  const std::size_t groups = info(q).outputs.size();
  struct Acc {
    std::uint64_t nu = 0, wu = 0, nh = 0, wh = 0;
    std::vector<std::uint64_t> max;
    std::vector<Histogram> h;
  };
  std::map<std::string, Acc> acc;
  for (const auto& [key, st] : res.cells) {
    Acc& a = acc[key.impl];
    a.max.resize(groups);
    a.h.resize(groups);
    const std::uint64_t m = st.n - st.refused - st.set_apart, w = st.cls_fp + st.cls_fn;
    if (key.family == "uniform") a.nu += m, a.wu += w;
    else a.nh += m, a.wh += w;
    for (std::size_t g = 0; g < groups; ++g) {
      for (int b = 0; b < Histogram::bins; ++b) a.h[g].count[b] += st.out[g].hist.count[b];
      if (st.out[g].worst.set) a.max[g] = std::max(a.max[g], st.out[g].worst.metric);
    }
  }
  for (Row& r : rows) {
    if (r.campaign_impl.empty()) continue;
    const Acc& a = acc.at(r.campaign_impl);
    r.measured = true;
    r.miss_uniform = double(a.wu) / double(std::max<std::uint64_t>(1, a.nu));
    r.miss_hard = double(a.wh) / double(std::max<std::uint64_t>(1, a.nh));
    for (std::size_t g = 0; g < groups; ++g) {
      if (info(q).outputs[g].label) continue;
      r.p99s.push_back(a.h[g].quantile(0.99));
      r.maxs.push_back(a.max[g]);
    }
    if (!r.p99s.empty()) r.p99 = r.p99s.front(), r.max = r.maxs.front();
  }
  return rep;
}

// The first output is a value measured in ulps (not a label such as a separating axis's index).
bool first_output_in_ulps(Query q) { return !info(q).outputs.empty() && !info(q).outputs[0].label; }

// The names of the output groups measured in ulps.
std::vector<std::string> value_outputs(Query q) {
  std::vector<std::string> names;
  for (const Output& out : info(q).outputs)
    if (!out.label) names.push_back(out.name);
  return names;
}

void print(std::ostream& o, const QueryReport& r) {
  const bool ulps = first_output_in_ulps(r.q);
  const std::vector<std::string> outs = value_outputs(r.q);
  o << info(r.q).name << " (" << info(r.q).describe << ")\n";
  char line[320];
  std::snprintf(line, sizeof line, "  %-34s %9s %8s %9s %13s %13s", "implementation", "ns/query", "x bare", "x double",
                "miss uniform", "miss hard");
  o << line;
  for (const std::string& name : outs) {
    std::snprintf(line, sizeof line, " %15s", name.c_str());
    o << line;
  }
  o << "\n";
  if (!outs.empty()) {
    std::snprintf(line, sizeof line, "  %-34s %9s %8s %9s %13s %13s", "", "", "", "", "", "");
    o << line;
    for (std::size_t g = 0; g < outs.size(); ++g) o << "   ulps p99/max";
    o << "\n";
  }
  for (const Row& row : r.rows) {
    std::string mu = row.error_note, mh = row.error_note;
    if (row.measured) {
      mu = pct(row.miss_uniform);
      mh = pct(row.miss_hard);
    }
    std::snprintf(line, sizeof line, "  %-34s %9.1f %8.2f %9.2f %13s %13s", row.name.c_str(), row.ns, row.ns / r.bare,
                  row.ns / r.base, mu.c_str(), mh.c_str());
    o << line;
    for (std::size_t g = 0; g < outs.size(); ++g) {
      const std::string cell =
          row.measured && g < row.p99s.size() ? gnum(double(row.p99s[g])) + "/" + gnum(double(row.maxs[g])) : row.error_note;
      std::snprintf(line, sizeof line, " %15s", cell.c_str());
      o << line;
    }
    o << "\n";
  }
  // the two targets the report exists to watch
  const Row* oc = find_row(r, "oracle, classification");
  // the book's classification alone (for a separating-axis query its full query)
  const Row* bc = find_row(r, ulps ? "book double, classification" : "book double");
  const Row* oa = find_row(r, "oracle, every output rounded");
  const Row* rd = find_row(r, "robust double");
  std::snprintf(line, sizeof line, "  oracle classification / bare = %.2f, / book double%s = %.2f", oc->ns / r.bare,
                ulps ? " classification" : "", oc->ns / bc->ns);
  o << line;
  if (oa) {
    std::snprintf(line, sizeof line, "; oracle every output rounded / robust double = %.2f", oa->ns / rd->ns);
    o << line;
  }
  // what the hand-written filters save over the generic staged path
  if (const Row* sc = find_row(r, "staged, classification")) {
    std::snprintf(line, sizeof line, "\n  staged classification / oracle classification = %.2f", sc->ns / oc->ns);
    o << line;
    const Row* sa = find_row(r, "staged, every output rounded");
    if (sa && oa) {
      std::snprintf(line, sizeof line, "; staged every output / oracle every output = %.2f", sa->ns / oa->ns);
      o << line;
    }
  }
  o << "\n\n";
}

void write_json(std::ostream& o, const std::vector<QueryReport>& reps, std::uint64_t n, int reps_n, std::uint64_t err_n) {
  using J = nlohmann::ordered_json;
  J queries = J::array();
  for (const QueryReport& r : reps) {
    J rows = J::array();
    for (const Row& row : r.rows) {
      J x = {{"implementation", row.name},
             {"ns_per_query", row.ns},
             {"ratio_to_bare", row.ns / r.bare},
             {"ratio_to_book_double", row.ns / r.base}};
      if (row.measured) {
        x["misclassified_uniform"] = row.miss_uniform;
        x["misclassified_hard"] = row.miss_hard;
        if (first_output_in_ulps(r.q)) x["p99_ulps"] = row.p99, x["max_ulps"] = row.max;
        const std::vector<std::string> outs = value_outputs(r.q);
        J og = J::array();
        for (std::size_t g = 0; g < outs.size() && g < row.p99s.size(); ++g)
          og.push_back({{"output", outs[g]}, {"p99_ulps", row.p99s[g]}, {"max_ulps", row.maxs[g]}});
        x["outputs"] = og;
      } else {
        x["error"] = row.error_note;
      }
      rows.push_back(x);
    }
    queries.push_back({{"query", info(r.q).name}, {"rows", rows}});
  }
  o << J{{"cdref_report", 1},
         {"cases_timed", n},
         {"repetitions", reps_n},
         {"error_cases_per_cell", err_n},
         {"queries", queries}}
           .dump(1)
    << "\n";
}

void write_csv(std::ostream& o, const std::vector<QueryReport>& reps) {
  o << "query,implementation,ns_per_query,ratio_to_bare,ratio_to_book_double,misclassified_uniform,misclassified_hard,p99_ulps,max_"
       "ulps,outputs_p99_max_ulps\n";
  for (const QueryReport& r : reps)
    for (const Row& row : r.rows) {
      // (implementation names contain commas: quoted, as CSV wants)
      o << info(r.q).name << ",\"" << row.name << "\"," << row.ns << "," << row.ns / r.bare << "," << row.ns / r.base << ",";
      if (row.measured) {
        o << row.miss_uniform << "," << row.miss_hard << ","
          << (first_output_in_ulps(r.q) ? std::to_string(row.p99) + "," + std::to_string(row.max) : ",") << ",";
        const std::vector<std::string> outs = value_outputs(r.q);
        for (std::size_t g = 0; g < outs.size() && g < row.p99s.size(); ++g)
          o << (g ? " " : "") << outs[g] << "=" << row.p99s[g] << "/" << row.maxs[g];
        o << "\n";
      } else {
        o << row.error_note << "," << row.error_note << "," << row.error_note << "," << row.error_note << ","
          << row.error_note << "\n";
      }
    }
}

// Cost against error, log-log, one panel per query and one point per row: x the time, y the
// max error of the first output in ulps (box-box: the share misclassified on the hard
// families). Exact rows (open circles, slanted labels) sit on the bottom line; MPFR's error
// is not measured and is left out.
std::string draw_svg(const std::vector<QueryReport>& reps) {
  std::ostringstream gp;
  const int cols = 2, nrows = int((reps.size() + cols - 1) / cols);
  gp << "set terminal svg size 1200," << 420 * nrows << " dynamic font 'sans,10' background rgb 'white'\n";
  // the data, inline: one block per query, rows "name ns error exact"
  for (std::size_t i = 0; i < reps.size(); ++i) {
    const bool values = first_output_in_ulps(reps[i].q);
    gp << "$q" << i << " << EOD\n";
    for (const Row& row : reps[i].rows) {
      if (!row.measured && row.error_note != "exact") continue;
      const double err = !row.measured ? 0 : values ? double(row.max) : row.miss_hard;
      const double floor = values ? 0.5 : 1e-5;
      std::string name = row.name;
      for (char& c : name)
        if (c == '"' || static_cast<unsigned char>(c) < 0x20) c = ' ';
      gp << "\"" << name << "\" " << row.ns << " " << std::max(err, floor) << " " << (row.measured ? 0 : 1) << "\n";
    }
    gp << "EOD\n";
  }
  gp << "set multiplot layout " << nrows << "," << cols
     << " title 'cdref report: cost against error (one point per implementation)'\n"
        "set logscale xy\nset grid\nset xlabel 'ns per query'\nset format y '10^{%L}'\nunset key\n";
  for (std::size_t i = 0; i < reps.size(); ++i) {
    const bool values = first_output_in_ulps(reps[i].q);
    gp << "set title " << gp_string(info(reps[i].q).name) << " noenhanced\nset ylabel "
       << gp_string(values ? "max error of the first output, ulps (exact: 0.5)" : "misclassified, hard families (exact: 1e-5)")
       << "\nset yrange [" << (values ? "0.3" : "5e-6") << ":*]\n";
    const std::string d = "$q" + std::to_string(i);
    gp << "plot " << d << " u 2:($4 == 0 ? $3 : 1/0) w p pt 7 ps 0.8 lc 1, " << d
       << " u 2:($4 == 0 ? $3 : 1/0):1 w labels left offset 0.6,0 font ',7' noenhanced, " << d
       << " u 2:($4 == 1 ? $3 : 1/0) w p pt 6 ps 0.8 lc 2, " << d
       << " u 2:($4 == 1 ? $3 : 1/0):1 w labels rotate by 50 left offset 0.3,0.5 font ',6' noenhanced tc lt 2\n";
  }
  gp << "unset multiplot\n";
  return gnuplot_svg(gp.str());
}

}  // namespace

struct ReportOptions {
  // 16,384 cases a set: over 2,000 repeated, a branch predictor learns enough of their sequence
  // that the book's box tests ran in a third of their time (README, "How many cases"); and each
  // timed pass on a fresh set (measure())
  std::uint64_t n = 16384, err_n = 1000;
  int reps = 5;
  int threads = default_threads();
  std::string csv, json, svg;
  std::vector<std::string> query_names;
};

int report_run(const ReportOptions& o) {
  const std::uint64_t n = o.n, err_n = o.err_n;
  const int reps = o.reps, threads = o.threads;
  std::vector<Query> queries;
  for (const auto& name : o.query_names) {
    const Query q = query_by_name(name);
    if (std::find(queries.begin(), queries.end(), q) != queries.end())
      throw std::invalid_argument("--query " + name + " is given twice");
    queries.push_back(q);
  }
  // before the work: a path that cannot be written is refused now
  std::optional<io::Output> csv, json, svg;
  if (!o.csv.empty()) csv.emplace(o.csv, "--csv");
  if (!o.json.empty()) json.emplace(o.json, "--json");
  if (!o.svg.empty()) svg.emplace(o.svg, "--svg");
  if (queries.empty()) queries = all_queries();
  // (with --json - or --csv -, standard output is the data's: the table goes to standard error)
  std::ostream& human = o.json == "-" || o.csv == "-" || o.svg == "-" ? std::cerr : std::cout;
  human << "cdref report: " << n << " uniform cases a timed pass, each pass of a fast row on a fresh set of "
            << timing_windows << ", median of " << reps << " interleaved repetitions, one thread; errors from " << err_n
            << " cases per cell of every family (every output, ulps of the row's type).\n\n";
  std::vector<QueryReport> out;
  for (Query q : queries) {
    out.push_back(measure(q, n, reps, err_n, threads));
    print(human, out.back());
    human.flush();
  }
  io::Outputs all;
  auto write = [&](std::optional<io::Output>& f, auto&& body) {
    if (!f) return;
    all.attempt([&] {
      body(f->stream());
      f->commit();
      if (!f->is_stdout()) human << "wrote " << f->path() << "\n";
    });
  };
  write(csv, [&](std::ostream& f) { write_csv(f, out); });
  write(json, [&](std::ostream& f) { write_json(f, out, n, reps, err_n); });
  try {
    if (svg) write(svg, [&](std::ostream& f) { f << draw_svg(out); });
  } catch (const std::runtime_error& e) {  // gnuplot failed: the other outputs are written
    all.attempt([&] { throw io::write_error(std::string("cannot draw --svg: ") + e.what()); });
  }
  all.finish();
  std::size_t sink = 0;
  for (const QueryReport& r : out) sink += r.sink;
  return sink == std::size_t(-1) ? 1 : 0;
}

void add_report_command(Program& program) {
  auto o = std::make_shared<ReportOptions>();
  // every row keeps its own copy of the timed_windows sets of cases (one query's at a time):
  // polygon-polygon's rows took 2.2 GB at 16,384 (maximum resident size, 2026-11-30), so 65,536
  // keeps them near 9 GB
  program
      .add("report",
           "what accuracy costs in time: every implementation of every query (or of --query Q) timed side by side on "
           "the same uniform cases (median of interleaved repetitions), with misclassification and ulp errors from a "
           "campaign; the SVG plots cost against error",
           [o] { return report_run(*o); })
      .queries("--query", o->query_names, "a query (repeatable; default: all; see cdref describe)")
      .whole("--n", o->n, 1, 65536, "uniform cases in a timed pass (default 16384)")
      .whole("--reps", o->reps, 1, 1000, "interleaved repetitions, the median taken (default 5)")
      .whole("--error-n", o->err_n, 1, 100000000, "cases per cell of the error campaign (default 1000)")
      .whole("--threads", o->threads, 1, 4096, "threads of the error campaign (default: the hardware's)")
      .text("--csv", o->csv, "write the table as CSV to this file (- for standard output)")
      .text("--json", o->json, "write the table as JSON to this file (- for standard output)")
      .text("--svg", o->svg, "draw cost against error to this SVG");
}

}  // namespace cdref::cli
