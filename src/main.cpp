// src/main.cpp - the cdref command line.
//
//   cdref                       the default campaign (every query, book at float and double)
//   cdref COMMAND --help        each command's options (campaign, merge, describe, demo, cases,
//                               oracle, score, plot, report, scene, peers)
//   cdref --version             the version and the commit
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <exception>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <cdref/exact/gmp_pool.hpp>
#include "campaign_cli.hpp"
#include "options.hpp"
#include "output.hpp"
#include <cdref/fuzz/work.hpp>
#include "casefiles.hpp"
#include "report.hpp"
#include "peers/command.hpp"
#include "scene/scene.hpp"

namespace cdref::peers {
// `cdref peers ARGS`: the gallery's program (cdref_peers, beside this executable) run in this
// process's place as `cdref peers ARGS`, no shell between; it parses, prints and exits as a
// command of cdref. Returns only by throwing, naming the program that could not run.
int run_gallery(const std::vector<std::string>& args) {
  const std::string program = beside_this_program(program_name);
  std::vector<std::string> all = {"cdref", "peers"};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::cout.flush();
  std::fflush(stdout);
  ::execv(program.c_str(), argv.data());
  throw std::runtime_error("peers: cannot run the gallery's program " + program + ": " + std::strerror(errno) +
                           " (it is built beside cdref: cmake --build --preset release --target cdref_tools)");
}
}  // namespace cdref::peers

int run_demo();

namespace {

using namespace cdref;
using namespace cdref::fuzz;
using namespace cdref::cli;

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

int campaign(CampaignCommand& c, bool defaults) {
  finish_campaign(c, defaults);
  Spec& spec = c.spec;
  CampaignOutputs outputs = open_campaign_outputs(c);  // before the work: a bad path is refused now
  if (!spec.checkpoint.empty()) io::check_replaceable(spec.checkpoint, "--checkpoint");
  Progress bar;
  spec.progress = [&bar](double d, double t) { bar(d, t); };
  if (defaults) std::cout << default_campaign_banner(spec);
  const auto t0 = std::chrono::steady_clock::now();
  const Results r = run(spec);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  emit_campaign(c, outputs, r);
  std::uint64_t cases = 0;
  for (const auto& [k, st] : r.cells) cases += st.n;
  if (!c.quiet)
    (c.json == "-" || c.csv == "-" ? std::cerr : std::cout) << "\n" << cases << " evaluations in " << secs << " s on " << spec.threads << " threads.\n";
  return 0;
}

struct MergeCommand {
  std::vector<std::string> files;
  CampaignCommand c;
};

int merge(MergeCommand& m) {
  CampaignOutputs outputs = open_campaign_outputs(m.c);
  std::vector<Saved> shards;
  for (const std::string& f : m.files) shards.push_back(deserialize(fuzz::read_whole_file(f), f));
  const Results r = merge_shards(shards);
  // the merged result is the unsharded campaign's: shard 0 of 1, complete
  io::Outputs all;
  if (outputs.out) all.attempt([&] {
      outputs.out->stream() << serialize(Saved{shards.front().fingerprint, 0, 1, shards.front().items_total,
                                               shards.front().items_total, r, shards.front().seed});
      outputs.out->commit();
    });
  m.c.out.clear();
  outputs.out.reset();
  m.c.spec.seed = shards.front().seed;
  all.attempt([&] { emit_campaign(m.c, outputs, r); });
  all.finish();
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
  io::init();                    // checked standard output; a closed pipe is not a signal
  Program program(
      "cdref",
      "cdref: the exact answer for the primitive tests of Chapter 3 of van den Bergen's Collision Detection in "
      "Interactive 3D Environments, and campaigns that measure float code against it.\n"
      "With no command: the default campaign (every query, the book's algorithms and the robust tier at float, "
      "double and long double against the exact answer) and its findings.");

  auto camp = std::make_shared<CampaignCommand>();
  Command campaign_cmd = program.add(
      "campaign",
      "run a campaign: every (query, family, scale) cell's cases through the chosen implementations, graded against "
      "the exact answer (across the ranks of an MPI job: mpirun --bind-to none -np R cdref-mpi campaign [options])",
      [camp] { return campaign(*camp, false); });
  add_campaign_options(campaign_cmd, *camp, false);

  auto mrg = std::make_shared<MergeCommand>();
  program
      .add("merge", "merge the complete shard files (--out of each shard) of one campaign", [mrg] { return merge(*mrg); })
      .files("FILE", mrg->files, "the shard files (repeatable)")
      .required()
      .text("--out", mrg->c.out, "write the merged results (text form) to this file")
      .text("--json", mrg->c.json, "write them as JSON (- for standard output)")
      .text("--csv", mrg->c.csv, "write them as CSV (- for standard output)")
      .flag("--quiet", mrg->c.quiet, "no table on standard output");

  program.add("describe", "list queries, input and output columns, families and scales", [] { return describe(); });
  program.add("demo", "the chapter's algorithms beside the exact answer on hard cases", [] { return run_demo(); });

  auto help_of = std::make_shared<std::string>();
  program
      .add("help", "this help, or a command's (cdref help COMMAND)",
           [&program, help_of] {
             if (*help_of == "peers") return peers::run_gallery({"--help"});  // (the gallery's own help)
             std::cout << program.help(*help_of);
             return 0;
           })
      .choice("COMMAND", *help_of,
              {"campaign", "merge", "describe", "demo", "cases", "oracle", "score", "plot", "report", "scene", "peers"},
              "the command");

  add_case_commands(program);
  add_plot_command(program);
  add_report_command(program);
  scene::add_scene_command(program);
  auto gallery = std::make_shared<Command>(nullptr);
  *gallery = program.add("peers", peers::description, [gallery] { return peers::run_gallery(gallery->rest()); });
  gallery->pass_through();

  auto dflt = std::make_shared<CampaignCommand>();
  return program.run(argc, argv, [dflt] { return campaign(*dflt, true); });
}
