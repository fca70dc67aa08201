// src/campaign_cli.cpp - the options of `cdref campaign` and its outputs.
#include "campaign_cli.hpp"

#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "casefiles.hpp"
#include "report.hpp"

namespace cdref::cli {

using namespace cdref::fuzz;

std::uint64_t to_u64(const std::string& s, const std::string& opt) {
  std::size_t pos = 0;
  unsigned long long x = 0;
  try {
    x = std::stoull(s, &pos);
  } catch (const std::exception&) {
    pos = 0;
  }
  if (pos != s.size() || s.empty() || s.find('-') != std::string::npos)
    throw std::invalid_argument(opt + " wants a nonnegative whole number, not '" + s + "'");
  return x;
}

int to_int(const std::string& s, const std::string& opt) {
  std::size_t pos = 0;
  int x = 0;
  try {
    x = std::stoi(s, &pos);
  } catch (const std::exception&) {
    pos = 0;
  }
  if (pos != s.size() || s.empty()) throw std::invalid_argument(opt + " wants a whole number, not '" + s + "'");
  return x;
}

void write_to(const std::string& path, const std::string& text) {
  if (path == "-") {
    std::cout << text;
    return;
  }
  std::ofstream f(path, std::ios::binary);
  f << text;
  if (!f) throw std::runtime_error("cannot write " + path);
}

CampaignCommand parse_campaign(const std::vector<std::string>& args, bool defaults, bool mpi) {
  CampaignCommand c;
  Spec& spec = c.spec;
  spec.threads = int(std::max(1u, std::thread::hardware_concurrency()));
  if (defaults) spec.n = 1000;  // a minute and a quarter on 2 cores
  std::size_t i = 0;
  auto next = [&](const std::string& opt) -> std::string {
    if (i >= args.size()) throw std::invalid_argument(opt + " needs a value");
    return args[i++];
  };
  while (i < args.size()) {
    const std::string opt = args[i++];
    if (opt == "--query")
      spec.queries.push_back(query_by_name(next(opt)));
    else if (opt == "--family")
      spec.families.push_back(next(opt));
    else if (opt == "--scale")
      spec.scales.push_back(to_int(next(opt), opt));
    else if (opt == "--impl") {
      spec.impls.push_back(next(opt));
      implementation_by_name(spec.impls.back());
    } else if (opt == "--n")
      spec.n = to_u64(next(opt), opt);
    else if (opt == "--seed")
      spec.seed = to_u64(next(opt), opt);
    else if (opt == "--threads") {
      const std::uint64_t t = to_u64(next(opt), opt);
      if (t < 1 || t > 4096) throw std::invalid_argument("--threads wants 1 to 4096, not " + std::to_string(t));
      spec.threads = int(t);
    } else if (opt == "--shard") {
      const std::string s = next(opt);
      const auto slash = s.find('/');
      if (slash == std::string::npos) throw std::invalid_argument("--shard wants k/N, not '" + s + "'");
      spec.shard = to_int(s.substr(0, slash), opt);
      spec.shards = to_int(s.substr(slash + 1), opt);
    } else if (opt == "--checkpoint")
      spec.checkpoint = next(opt);
    else if (opt == "--resume")
      spec.resume = true;
    else if (opt == "--out")
      c.out = next(opt);
    else if (opt == "--json")
      c.json = next(opt);
    else if (opt == "--csv")
      c.csv = next(opt);
    else if (opt == "--quiet")
      c.quiet = true;
    else if (opt == "--outputs") {
      const std::string o = next(opt);
      if (o != "all" && o != "cls" && o != "certain")
        throw std::invalid_argument(
            "--outputs is all (every output), cls (the classification alone) or certain (every output where "
            "a certificate says certain), not '" + o + "'");
      spec.classification_only = o == "cls";
      spec.certain_outputs = o == "certain";
    }
    else if (opt == "--mpi") {  // (cdref-mpi runs across the ranks whether or not it is given)
      if (!mpi)
        throw std::invalid_argument(
            "--mpi: campaigns across MPI ranks run as `mpirun --bind-to none -np R cdref-mpi campaign ...` (built "
            "beside cdref when OpenMPI is installed)");
    } else if (opt == "--checkpoint-every") {
      const std::string s = next(opt);
      char* end = nullptr;
      const double x = std::strtod(s.c_str(), &end);
      if (s.empty() || end != s.c_str() + s.size() || !std::isfinite(x) || x < 0 || x > 1e6)
        throw std::invalid_argument("--checkpoint-every wants seconds from 0 to 1e6, not '" + s + "'");
      spec.checkpoint_every = x;
    } else
      throw std::invalid_argument("unknown option '" + opt + "' (see `" + (mpi ? "cdref-mpi" : "cdref") + " help`)");
  }
  if (spec.resume && spec.checkpoint.empty()) throw std::invalid_argument("--resume needs --checkpoint FILE");
  // a name given twice would run its cells twice and count every case of them twice
  auto once = [](const auto& v, const std::string& opt, auto name) {
    for (std::size_t a = 0; a < v.size(); ++a)
      for (std::size_t b = a + 1; b < v.size(); ++b)
        if (v[a] == v[b]) throw std::invalid_argument(opt + " " + name(v[a]) + " is given twice");
  };
  once(spec.queries, "--query", [](Query q) { return std::string(info(q).name); });
  once(spec.families, "--family", [](const std::string& f) { return f; });
  once(spec.impls, "--impl", [](const std::string& i) { return i; });
  once(spec.scales, "--scale", [](int k) { return std::to_string(k); });
  if (spec.shards < 1 || spec.shard < 0 || spec.shard >= spec.shards)
    throw std::invalid_argument("--shard wants k/N with 0 <= k < N");
  if (spec.queries.empty()) spec.queries = all_queries();
  if (spec.impls.empty())  // every implementation of the chosen queries
    for (const Implementation& im : builtin_implementations())
      for (Query q : spec.queries)
        if (im.supports(q)) {
          spec.impls.push_back(im.name);
          break;
        }
  return c;
}

std::string default_campaign_banner(const Spec& spec) {
  return "cdref: the default campaign - every query of Sections 3.1-3.4, the book's algorithms and the\n"
         "robust versions at float, double and long double (and the queries' own variants) against the\n"
         "exact answer, " +
         std::to_string(spec.n) + " cases in each (query, family, scale) cell, seed " + std::to_string(spec.seed) +
         ".\n\n";
}

void emit_campaign(const CampaignCommand& c, const Results& r) {
  if (!c.out.empty()) write_to(c.out, serialize(c.spec, r, total_items(c.spec)));
  if (!c.json.empty()) {
    std::ostringstream s;
    write_json(s, r, c.spec.seed);
    write_to(c.json, s.str());
  }
  if (!c.csv.empty()) {
    std::ostringstream s;
    write_csv(s, r);
    write_to(c.csv, s.str());
  }
  if (!c.quiet) print_table(std::cout, r, c.spec.seed);
}

}  // namespace cdref::cli
