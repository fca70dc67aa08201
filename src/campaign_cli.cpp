// src/campaign_cli.cpp - the options of `cdref campaign` and its outputs.
#include "campaign_cli.hpp"

#include <algorithm>
#include <iostream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "report.hpp"

namespace cdref::cli {

using namespace cdref::fuzz;

namespace {

std::string family_names() {
  std::set<std::string> names;
  for (Query q : all_queries())
    for (const Family& f : families(q)) names.insert(f.name);
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

std::string query_names() {
  std::string s;
  for (Query q : all_queries()) s += (s.empty() ? "" : ", ") + std::string(info(q).name);
  return s;
}

}  // namespace

void add_campaign_options(Command& app, CampaignCommand& c, bool mpi) {
  Spec& spec = c.spec;
  app.queries("--query", c.query_names, "a query (repeatable; default: all): " + query_names())
      .texts("--family", spec.families, "a family (repeatable; default: every family of each query): " + family_names())
      .wholes("--scale", spec.scales, -999999999, 999999999, "a scale of the families (repeatable; default: all; see cdref describe)")
      .texts("--impl", spec.impls,
             "an implementation (repeatable; default: all): book-float, book-double, book-long-double, stable-float, "
             "stable-double, robust-float, robust-double, robust-long-double, and a query's own variants (book-exact, "
             "book-double-eps, ...: see cdref describe)")
      .whole("--n", spec.n, 1, std::uint64_t(1) << 40, "cases per (query, family, scale) cell (default 1000)")
      .whole("--seed", spec.seed, 0, UINT64_MAX, "the campaign seed (default 1)")
      .whole("--threads", c.threads, 1, 4096, "worker threads (default: the hardware's)")
      .text("--shard", c.shard, "run only the cases with index % N == k, written k/N")
      .text("--checkpoint", spec.checkpoint, "write the results so far to this file as the campaign goes")
      .real("--checkpoint-every", spec.checkpoint_every, 0, 1e6,
            "seconds between checkpoints (default 10; 0: after every round of work)")
      .flag("--resume", spec.resume, "continue the campaign saved in --checkpoint")
      .text("--out", c.out, "write the results (the mergeable text form) to this file")
      .text("--json", c.json, "write the results as JSON to this file (- for standard output)")
      .text("--csv", c.csv, "write the results as CSV to this file (- for standard output)")
      .choice("--outputs", c.outputs, {"all", "cls", "certain"},
              "all (default): grade every output against the correctly rounded truth; cls: the classification alone "
              "(fast); certain: every output, but an implementation with a certificate (robust-*) only where it calls "
              "its classification certain")
      .flag("--quiet", c.quiet, "no table on standard output");
  c.mpi = mpi;
  app.flag("--mpi", c.mpi_flag,
           mpi ? "accepted for symmetry: cdref-mpi always runs across the ranks"
               : "(campaigns across MPI ranks run as cdref-mpi: see cdref-mpi --help)");
}

void finish_campaign(CampaignCommand& c, bool defaults) {
  Spec& spec = c.spec;
  spec.threads = c.threads ? int(*c.threads) : default_threads();
  if (defaults) spec.n = 1000;  // a minute and a quarter on 2 cores
  for (const auto& name : c.query_names) spec.queries.push_back(query_by_name(name));
  for (const auto& im : spec.impls) implementation_by_name(im);  // throws naming the choices
  spec.classification_only = c.outputs == "cls";
  spec.certain_outputs = c.outputs == "certain";
  if (!c.shard.empty()) {
    const auto slash = c.shard.find('/');
    const std::string k = c.shard.substr(0, slash), n = slash == std::string::npos ? "" : c.shard.substr(slash + 1);
    auto digits = [](const std::string& s) {
      return !s.empty() && s.size() <= 9 && s.find_first_not_of("0123456789") == std::string::npos;
    };
    if (!digits(k) || !digits(n) || std::stoi(k) >= std::stoi(n))
      throw std::invalid_argument("--shard wants k/N with 0 <= k < N, not '" + c.shard + "'");
    spec.shard = std::stoi(k);
    spec.shards = std::stoi(n);
  }
  if (c.mpi_flag && !c.mpi)
    throw std::invalid_argument(
        "--mpi: campaigns across MPI ranks run as `mpirun --bind-to none -np R cdref-mpi campaign ...` (built beside "
        "cdref when OpenMPI is installed)");
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
  if (spec.queries.empty()) spec.queries = all_queries();
  // a family or a scale that no chosen query has would select nothing
  for (const std::string& f : spec.families) {
    if (spec.queries.size() == 1) family_by_name(spec.queries.front(), f);  // names the query's families
    bool found = false;
    for (Query q : spec.queries)
      for (const Family& fam : families(q)) found = found || fam.name == f;
    if (!found) throw std::invalid_argument("--family " + f + ": no chosen query has this family (see cdref describe)");
  }
  for (int k : spec.scales) {
    bool found = false;
    for (Query q : spec.queries)
      for (const Family& fam : families(q))
        if (spec.families.empty() || std::find(spec.families.begin(), spec.families.end(), fam.name) != spec.families.end())
          found = found || std::find(fam.scales.begin(), fam.scales.end(), k) != fam.scales.end();
    if (!found)
      throw std::invalid_argument("--scale " + std::to_string(k) +
                                  ": no chosen family has this scale (see cdref describe)");
  }
  if (spec.impls.empty())  // every implementation of the chosen queries
    for (const Implementation& im : builtin_implementations())
      for (Query q : spec.queries)
        if (im.supports(q)) {
          spec.impls.push_back(im.name);
          break;
        }
}

std::string default_campaign_banner(const Spec& spec) {
  return "cdref: the default campaign - every query of Sections 3.1-3.4, the book's algorithms and the\n"
         "robust versions at float, double and long double (and the queries' own variants) against the\n"
         "exact answer, " +
         std::to_string(spec.n) + " cases in each (query, family, scale) cell, seed " + std::to_string(spec.seed) +
         ".\n\n";
}

CampaignOutputs open_campaign_outputs(const CampaignCommand& c) {
  CampaignOutputs o;
  if (!c.out.empty()) {
    if (c.out == "-") throw std::invalid_argument("--out wants a file (the text form is for merge and resume)");
    o.out.emplace(c.out, "--out");
  }
  if (!c.json.empty()) o.json.emplace(c.json, "--json");
  if (!c.csv.empty()) o.csv.emplace(c.csv, "--csv");
  return o;
}

void emit_campaign(const CampaignCommand& c, CampaignOutputs& o, const Results& r) {
  io::Outputs all;
  if (o.out) all.attempt([&] {
      o.out->stream() << serialize(c.spec, r, total_items(c.spec));
      o.out->commit();
    });
  if (o.json) all.attempt([&] {
      write_json(o.json->stream(), r, c.spec.seed);
      o.json->commit();
    });
  if (o.csv) all.attempt([&] {
      write_csv(o.csv->stream(), r);
      o.csv->commit();
    });
  // (with --json - or --csv -, standard output is the data's: the table goes to standard error)
  if (!c.quiet) print_table(c.json == "-" || c.csv == "-" ? std::cerr : std::cout, r, c.spec.seed);
  all.finish();
}

}  // namespace cdref::cli
