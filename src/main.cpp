// src/main.cpp - the cdref command line.
//
//   cdref                       the default campaign (every query, book at float and double)
//   cdref COMMAND --help        each command's options (campaign, merge, describe, demo, cases,
//                               oracle, score, plot, report, scene, peers)
//   cdref --version             the version and the commit
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
#include "options.hpp"
#include "output.hpp"
#include <cdref/fuzz/work.hpp>
#include "casefiles.hpp"
#include "report.hpp"
#include "scene/scene.hpp"

namespace cdref::peers {
void add_peers_command(CLI::App& app, cli::Commands& cmds);  // src/peers/peers.cpp
}

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
    std::cout << "\n" << cases << " evaluations in " << secs << " s on " << spec.threads << " threads.\n";
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
  CLI::App app{
      "cdref: the exact answer for the primitive tests of Chapter 3 of van den Bergen's Collision Detection in "
      "Interactive 3D Environments, and campaigns that measure float code against it.\n"
      "With no command: the default campaign (every query, the book's algorithms and the robust tier at float, "
      "double and long double against the exact answer) and its findings.",
      "cdref"};
  conventions(app);
  app.set_version_flag("--version", version_text(), "print the version and the commit, then exit");
  app.require_subcommand(0, 1);
  Commands cmds;

  auto camp = std::make_shared<CampaignCommand>();
  CLI::App* campaign_app = app.add_subcommand(
      "campaign",
      "run a campaign: every (query, family, scale) cell's cases through the chosen implementations, graded against "
      "the exact answer (across the ranks of an MPI job: mpirun --bind-to none -np R cdref-mpi campaign [options])");
  conventions(*campaign_app);
  add_campaign_options(*campaign_app, *camp, false);
  cmds.add(campaign_app, [camp] { return campaign(*camp, false); });

  auto mrg = std::make_shared<MergeCommand>();
  CLI::App* merge_app = app.add_subcommand("merge", "merge the complete shard files (--out of each shard) of one campaign");
  conventions(*merge_app);
  merge_app->add_option("FILE", mrg->files, "the shard files (repeatable)")->required()->check(CLI::ExistingFile);
  merge_app->add_option("--out", mrg->c.out, "write the merged results (text form) to this file");
  merge_app->add_option("--json", mrg->c.json, "write them as JSON (- for standard output)");
  merge_app->add_option("--csv", mrg->c.csv, "write them as CSV (- for standard output)");
  merge_app->add_flag("--quiet", mrg->c.quiet, "no table on standard output");
  cmds.add(merge_app, [mrg] { return merge(*mrg); });

  CLI::App* describe_app = app.add_subcommand("describe", "list queries, input and output columns, families and scales");
  conventions(*describe_app);
  cmds.add(describe_app, [] { return describe(); });

  CLI::App* demo_app = app.add_subcommand("demo", "the chapter's algorithms beside the exact answer on hard cases");
  conventions(*demo_app);
  cmds.add(demo_app, [] { return run_demo(); });

  auto help_of = std::make_shared<std::string>();
  CLI::App* help_app = app.add_subcommand("help", "this help, or a command's (cdref help COMMAND)");
  conventions(*help_app);
  help_app->add_option("COMMAND", *help_of, "the command")
      ->check(one_of({"campaign", "merge", "describe", "demo", "cases", "oracle", "score", "plot", "report", "scene", "peers"}));
  cmds.add(help_app, [&app, help_of] {
    // (App::help would print the help of the subcommand given, `help` itself)
    const CLI::App* of = help_of->empty() ? &app : app.get_subcommand(*help_of);
    std::cout << app.get_formatter()->make_help(of, of == &app ? "cdref" : "cdref " + *help_of, CLI::AppFormatMode::Normal);
    return 0;
  });

  cli::add_case_commands(app, cmds);
  cli::add_plot_command(app, cmds);
  cli::add_report_command(app, cmds);
  scene::add_scene_command(app, cmds);
  peers::add_peers_command(app, cmds);

  auto dflt = std::make_shared<CampaignCommand>();
  return run_app(app, cmds, argc, argv, [dflt] { return campaign(*dflt, true); }, "cdref");
}
