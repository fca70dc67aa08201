// src/plot.cpp - `cdref plot`: drift against scale for one query and family, drawn by
// gnuplot as SVG: the misclassification rate of the full query and of the predicate, and
// the p99 and max error (ulps of the implementation's type) of one output, against the
// family's scale k, one curve per implementation. From a campaign it runs itself, or from the
// JSON of one already run (--from).
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "casefiles.hpp"
#include "options.hpp"
#include "output.hpp"
#include "plotting.hpp"
#include "report.hpp"

namespace cdref::cli {

using namespace cdref::fuzz;

namespace {

struct PlotOptions {
  std::string query, family, out, output, from;
  std::vector<std::string> impls;
  std::uint64_t n = 2000, seed = 1;
  int threads = default_threads();
};

// One point of a curve: a cell's misclassified shares and the chosen output's errors.
struct Point {
  double miss = 0, pred_miss = 0, p99 = 0, max = 0;
};
using Curves = std::map<std::string, std::map<int, Point>>;  // impl -> scale -> point

// (refused: the cases not graded, refused or set apart by the implementation's convention)
Point point_of(std::uint64_t n, std::uint64_t refused, std::uint64_t fp, std::uint64_t fn, std::uint64_t pfp,
               std::uint64_t pfn, double p99, double max) {
  const double base = double(std::max<std::uint64_t>(1, n - std::min(n, refused)));
  return {double(fp + fn) / base, double(pfp + pfn) / base, p99, max};
}

// The cells of (query, family) in a campaign's JSON (cdref campaign --json).
Curves curves_from_json(const std::string& path, const QueryInfo& qi, const std::string& family, int group,
                        std::vector<std::string>& impls) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw std::runtime_error("cannot read --from " + path);
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(f);
    Curves c;
    for (const auto& cell : j.at("cells")) {
      if (cell.at("query").get<std::string>() != qi.name || cell.at("family").get<std::string>() != family) continue;
      const std::string impl = cell.at("impl").get<std::string>();
      if (!impls.empty() && std::find(impls.begin(), impls.end(), impl) == impls.end()) continue;
      double p99 = 0, mx = 0;
      if (group >= 0) {
        const auto& o = cell.at("outputs").at(qi.outputs[std::size_t(group)].name);
        p99 = o.at("p99").get<double>();
        mx = o.at("max").get<double>();
      }
      c[impl][cell.at("scale").get<int>()] =
          point_of(cell.at("cases").get<std::uint64_t>(),
                   cell.at("refused").get<std::uint64_t>() + cell.value("set_apart", std::uint64_t(0)),
                   cell.at("false_positives").get<std::uint64_t>(), cell.at("false_negatives").get<std::uint64_t>(),
                   cell.at("predicate_false_positives").get<std::uint64_t>(),
                   cell.at("predicate_false_negatives").get<std::uint64_t>(), p99, mx);
    }
    if (impls.empty())
      for (const auto& [im, pts] : c) impls.push_back(im);
    return c;
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error("--from " + path + " is not a campaign's JSON (cdref campaign --json): " + e.what());
  }
}

int plot_run(PlotOptions o) {
  const Query q = query_by_name(o.query);
  const Family& fam = family_by_name(q, o.family);
  const QueryInfo& qi = info(q);
  int group = qi.outputs.empty() ? -1 : 0;
  if (!o.output.empty()) {
    group = -1;
    std::string names;
    for (std::size_t g = 0; g < qi.outputs.size(); ++g) {
      if (qi.outputs[g].name == o.output) group = int(g);
      names += (names.empty() ? "" : ", ") + qi.outputs[g].name;
    }
    if (group < 0) throw std::invalid_argument("--output: query " + o.query + " has the outputs " + names + ", not '" + o.output + "'");
  }
  for (const auto& im : o.impls) implementation_by_name(im);
  if (o.out.empty()) o.out = "drift-" + o.query + "-" + o.family + ".svg";
  io::Output svg_out(o.out, "--out");  // before the work: a path that cannot be written is refused now

  Curves curves;
  std::string source;
  if (!o.from.empty()) {
    curves = curves_from_json(o.from, qi, o.family, group, o.impls);
    if (curves.empty()) throw std::runtime_error("--from " + o.from + " has no cell of " + o.query + ", family " + o.family);
    source = "from " + o.from;
  } else {
    if (o.impls.empty()) o.impls = {"book-float", "book-double", "book-long-double"};
    Spec spec;
    spec.queries = {q};
    spec.families = {o.family};
    spec.impls = o.impls;
    spec.n = o.n;
    spec.seed = o.seed;
    spec.threads = o.threads;
    const Results r = run(spec);
    for (const auto& [k, st] : r.cells) {
      double p99 = 0, mx = 0;
      if (group >= 0) {
        p99 = double(st.out[group].hist.quantile(0.99));
        mx = st.out[group].worst.set ? double(st.out[group].worst.metric) : 0;
      }
      curves[k.impl][k.scale] = point_of(st.n, st.refused + st.set_apart, st.cls_fp, st.cls_fn, st.pred_fp, st.pred_fn, p99, mx);
    }
    source = std::to_string(o.n) + " cases per point, seed " + std::to_string(o.seed);
  }

  // the data, inline: one block per implementation, rows "scale miss pred_miss p99 max"
  // (log axes: a rate or error of 0 is drawn at the bottom of the axis)
  std::ostringstream gp;
  gp << "set terminal svg size 1100,440 dynamic font 'sans,11' background rgb 'white'\n";
  for (std::size_t i = 0; i < o.impls.size(); ++i) {
    gp << "$d" << i << " << EOD\n";
    for (const auto& [k, p] : curves[o.impls[i]])
      gp << k << " " << std::max(p.miss, 1e-5) << " " << std::max(p.pred_miss, 1e-5) << " " << std::max(p.p99, 0.5)
         << " " << std::max(p.max, 0.5) << "\n";
    gp << "EOD\n";
  }
  gp << "set multiplot layout 1," << (group >= 0 ? 2 : 1) << " title "
     << gp_string(o.query + ", family " + o.family + " (" + source + "): " + fam.describe) << " noenhanced\n"
     << "set xlabel 'scale k'\nset key top left noenhanced\nset grid\nset logscale y\n"
     << "set ylabel 'misclassified share (0 drawn at 1e-5)'\nset yrange [1e-5:1]\nset format y '10^{%L}'\nplot ";
  for (std::size_t i = 0; i < o.impls.size(); ++i)
    gp << (i ? ", " : "") << "$d" << i << " u 1:2 w lp lc " << i + 1 << " t " << gp_string(o.impls[i]) << ", $d" << i
       << " u 1:3 w lp dt 2 lc " << i + 1 << " t " << gp_string(o.impls[i] + " predicate");
  gp << "\n";
  if (group >= 0) {
    gp << "set ylabel " << gp_string(qi.outputs[std::size_t(group)].name + " error, ulps of its type (0 drawn at 0.5)")
       << " noenhanced\nset yrange [0.5:*]\nset format y '10^{%L}'\nplot ";
    for (std::size_t i = 0; i < o.impls.size(); ++i)
      gp << (i ? ", " : "") << "$d" << i << " u 1:4 w lp lc " << i + 1 << " t " << gp_string(o.impls[i] + " p99")
         << ", $d" << i << " u 1:5 w lp dt 2 lc " << i + 1 << " t " << gp_string(o.impls[i] + " max");
    gp << "\n";
  }
  gp << "unset multiplot\n";
  svg_out.stream() << gnuplot_svg(gp.str());
  svg_out.commit();
  if (!svg_out.is_stdout()) std::cout << "wrote " << o.out << "\n";
  return 0;
}

}  // namespace

void add_plot_command(Program& program) {
  auto o = std::make_shared<PlotOptions>();
  program
      .add("plot",
           "drift against scale as SVG: misclassified share and p99/max ulps of one output, one curve per implementation",
           [o] { return plot_run(*o); })
      .query("--query", o->query, "the query (see cdref describe)")
      .required()
      .text("--family", o->family, "the family (see cdref describe)")
      .required()
      .texts("--impl", o->impls,
             "an implementation (repeatable; default book-float, book-double, book-long-double; with --from, every one "
             "in the file)")
      .text("--output", o->output, "the output whose error is drawn (default: the query's first)")
      .whole("--n", o->n, 1, 100000000, "cases per point (default 2000)")
      .whole("--seed", o->seed, 0, UINT64_MAX, "the seed (default 1)")
      .whole("--threads", o->threads, 1, 4096, "worker threads (default: the hardware's)")
      .text("--from", o->from, "draw the cells of a campaign's JSON (cdref campaign --json F) instead of running")
      .excludes({"--n", "--seed", "--threads"})
      .text("--out", o->out, "the SVG to write (default drift-QUERY-FAMILY.svg)");
}

}  // namespace cdref::cli
