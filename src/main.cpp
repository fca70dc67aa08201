// src/main.cpp - the cdref command line.
//
//   cdref                       the default campaign (every query, book at float and double)
//   cdref campaign [options]    a campaign; see `cdref help`
//   cdref merge FILE...         merge shard results into the unsharded result
//   cdref describe              queries, their columns, families and scales
//   cdref demo                  a few hard cases side by side with the exact answer
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <exception>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <cdref/exact/gmp_pool.hpp>
#include "campaign_cli.hpp"
#include "casefiles.hpp"
#include "report.hpp"
#include "scene/scene.hpp"

namespace cdref::peers {
int peers_command(const std::vector<std::string>& args);  // src/peers/peers.cpp
}

int run_demo();

namespace {

using namespace cdref;
using namespace cdref::fuzz;

const char* usage = R"(usage:
  cdref                          run the default campaign and print the findings
  cdref campaign [options]       run a campaign
      --query Q        a query (repeatable; default: all; see `cdref describe`)
      --family F       a family (repeatable; default: all of each query)
      --scale K        a scale of the family (repeatable; default: all)
      --impl I         book-float, book-double, book-long-double; stable-float, stable-double;
                       robust-float, robust-double, robust-long-double; a query's own variants
                       (book-exact, book-double-eps, ...: see `cdref describe`) (repeatable;
                       default: all)
      --n N            cases per (query, family, scale) cell (default 1000)
      --seed S         the campaign seed (default 1)
      --threads T      worker threads (default: hardware threads)
      --shard k/N      run only the cases with index % N == k
      --checkpoint F   write the results so far to F as the campaign goes
      --checkpoint-every S  seconds between checkpoints (default 10; 0: after every round)
      --resume         continue the campaign saved in --checkpoint F
      --out F          write the results (mergeable text form) to F
      --json F         write the results as JSON to F ("-" for standard output)
      --csv F          write the results as CSV to F ("-" for standard output)
      --outputs O      all (default): grade every output against the correctly rounded truth;
                       cls: grade the classification alone (the classification oracle: fast);
                       certain: every output, but an implementation with a certificate (robust-*)
                       only where it calls its classification certain (what it promises)
      --quiet          no table
                       (across the ranks of an MPI job: mpirun --bind-to none -np R cdref-mpi campaign
                       [options]; see cdref-mpi help)
  cdref merge [--out F] [--json F] [--csv F] FILE...
                                 merge complete shard files of one campaign
  cdref report [--query Q]... [--n N] [--reps R] [--error-n N] [--threads T]
               [--csv F] [--json F] [--svg F]
                                 what accuracy costs in time: every implementation of every
                                 query (or of --query Q) timed side by side on the same N
                                 uniform cases (median of R interleaved repetitions), with
                                 misclassification and ulp errors from a campaign of
                                 --error-n cases per cell; the SVG plots cost against error
  cdref describe                 list queries, input and output columns, families and scales
  cdref cases --query Q [--family F] [--scale K] [--n N] [--seed S] [--decimal] [--out F]
                                 write case inputs as CSV (hex-float; --decimal: 17 digits)
  cdref cases --describe Q       the case and answer columns of query Q
  cdref oracle --query Q [--cases F] [--precision 24|53|64] [--outputs all|cls] [--decimal] [--out F]
                                 the exact answers to a case file, correctly rounded
                                 (24: for the inputs rounded to float, as float; 64: as long double;
                                 --outputs cls: the classification columns alone)
  cdref score --query Q --cases F --answers A [--precision 24|53|64]
                                 grade an answer file (any subset of the answer columns)
  cdref plot --query Q --family F [--output O] [--n N] [--seed S] [--out F.svg]
                                 drift against scale as SVG (gnuplot): misclassified share
                                 and p99/max ulps of output O, book-float and book-double
  cdref demo                     the chapter's algorithms beside the exact answer on hard cases
  cdref scene [FILE] [--precision float|double|exact]... [--compare A,B]... [--json F] [--svg F]
              [--quiet]
                                 run a scene (JSON, see docs/scenes.md; no FILE: the built-in
                                 default, scenes/default.json) evaluating only the queries its
                                 effects name, and print its event log; --compare float,exact
                                 runs both and prints the events they disagree on and the
                                 differences of the continuous outputs (default: float,exact
                                 and double,exact); --svg draws the top view with the events
  cdref peers [--n N] [--seed S] [--threads T] [--json F] [--svg F]
                                 GLM's, Bullet's and Eigen's functions on cdref's families at
                                 float against the exact answer: cases where their convention
                                 gives another meaning set apart, misclassifications, p99/max ulps
)";

struct Args {
  std::vector<std::string> v;
  std::size_t i = 0;
  bool more() const { return i < v.size(); }
  std::string next(const std::string& opt) {
    if (i >= v.size()) throw std::invalid_argument(opt + " needs a value");
    return v[i++];
  }
};

// A progress bar with rate and ETA on a terminal; nothing otherwise.
struct Progress {
  bool tty = isatty(2);
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  void operator()(double done, double total) const {
    if (!tty) return;
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double frac = total > 0 ? done / total : 1;
    const int width = 30, filled = int(frac * width);
    const double eta = frac > 0 ? secs * (1 - frac) / frac : 0;
    std::fprintf(stderr, "\r[%.*s%*s] %3.0f%%  %.0f cases/s  ETA %.0fs ", filled,
                 "##############################", width - filled, "", 100 * frac, secs > 0 ? done / secs : 0,
                 eta);
    if (done >= total) std::fprintf(stderr, "\n");
  }
};

int campaign(Args& a, bool defaults) {
  cli::CampaignCommand c = cli::parse_campaign({a.v.begin() + long(a.i), a.v.end()}, defaults, false);
  Spec& spec = c.spec;
  Progress bar;
  spec.progress = [&bar](double d, double t) { bar(d, t); };
  if (defaults) std::cout << cli::default_campaign_banner(spec);
  const auto t0 = std::chrono::steady_clock::now();
  const Results r = run(spec);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  cli::emit_campaign(c, r);
  std::uint64_t cases = 0;
  for (const auto& [k, st] : r.cells) cases += st.n;
  if (!c.quiet)
    std::cout << "\n" << cases << " evaluations in " << secs << " s on " << spec.threads << " threads.\n";
  return 0;
}

int merge(Args& a) {
  std::string out, json, csv;
  std::vector<Saved> shards;
  while (a.more()) {
    const std::string opt = a.next("");
    if (opt == "--out")
      out = a.next(opt);
    else if (opt == "--json")
      json = a.next(opt);
    else if (opt == "--csv")
      csv = a.next(opt);
    else {
      std::ifstream f(opt, std::ios::binary);
      if (!f) throw std::runtime_error("cannot read " + opt);
      std::stringstream ss;
      ss << f.rdbuf();
      shards.push_back(deserialize(ss.str(), opt));
    }
  }
  const Results r = merge_shards(shards);
  // the merged result is the unsharded campaign's: shard 0 of 1, complete
  if (!out.empty())
    cli::write_to(out, serialize(Saved{shards.front().fingerprint, 0, 1, shards.front().items_total,
                                  shards.front().items_total, r, shards.front().seed}));
  cli::CampaignCommand c;
  c.spec.seed = shards.front().seed;
  c.json = json;
  c.csv = csv;
  cli::emit_campaign(c, r);
  return 0;
}

int describe() {
  for (Query q : all_queries()) {
    const QueryInfo& qi = info(q);
    std::cout << qi.name << ": " << qi.describe << "\n  inputs:";
    for (const auto& c : qi.inputs) std::cout << " " << c;
    std::cout << "\n  outputs: " << qi.cls_name << " (full query), " << qi.pred_name << " (predicate)";
    for (std::size_t g = 0; g < qi.outputs.size(); ++g)
      std::cout << ", " << qi.outputs[g].name << (qi.outputs[g].width == 3 ? "[xyz]" : "");
    if (!qi.variants.empty()) {
      std::cout << "\n  variants:";
      for (const Implementation& v : qi.variants) std::cout << " " << v.name;
    }
    std::cout << "\n  families:\n";
    for (const Family& f : families(q)) {
      std::cout << "    " << f.name << " (scales";
      for (int k : f.scales) std::cout << " " << k;
      std::cout << "): " << f.describe << "\n";
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char* argv[]) {
  cdref::exact::use_gmp_pool();  // GMP's small blocks cached per thread (gmp_pool.hpp)
  Args a;
  for (int i = 1; i < argc; ++i) a.v.push_back(argv[i]);
  try {
    if (!a.more()) return campaign(a, true);
    const std::string cmd = a.next("");
    if (cmd == "campaign") return campaign(a, false);
    if (cmd == "merge") return merge(a);
    if (cmd == "describe") return describe();
    if (cmd == "demo") return run_demo();
    if (cmd == "cases") return cli::cases_command({a.v.begin() + long(a.i), a.v.end()});
    if (cmd == "oracle") return cli::oracle_command({a.v.begin() + long(a.i), a.v.end()});
    if (cmd == "score") return cli::score_command({a.v.begin() + long(a.i), a.v.end()});
    if (cmd == "plot") return cli::plot_command({a.v.begin() + long(a.i), a.v.end()});
    if (cmd == "report") return cli::report_command({a.v.begin() + long(a.i), a.v.end()});
    if (cmd == "scene") return scene::scene_command({a.v.begin() + long(a.i), a.v.end()});
    if (cmd == "peers") return peers::peers_command({a.v.begin() + long(a.i), a.v.end()});
    if (cmd == "help" || cmd == "--help" || cmd == "-h") {
      std::cout << usage;
      return 0;
    }
    throw std::invalid_argument("unknown command '" + cmd + "'");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cdref: %s\n%s", e.what(), std::strstr(e.what(), "unknown command") ? usage : "");
    return 2;
  }
}
