// src/plot.cpp - `cdref plot`: drift against scale for one query and family, drawn by
// gnuplot as SVG: the misclassification rate of the full query and of the predicate, and
// the p99 and max error (ulps of the implementation's type) of one output, against the
// family's scale k, one curve per implementation.
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "casefiles.hpp"
#include "report.hpp"

namespace cdref::cli {

using namespace cdref::fuzz;

int plot_command(std::vector<std::string> args) {
  std::string query, family, out, output;
  std::uint64_t n = 2000, seed = 1;
  int threads = int(std::max(1u, std::thread::hardware_concurrency()));
  for (std::size_t i = 0; i < args.size(); ++i) {
    auto val = [&]() -> std::string {
      if (i + 1 >= args.size()) throw std::invalid_argument(args[i] + " needs a value");
      return args[++i];
    };
    if (args[i] == "--query") query = val();
    else if (args[i] == "--family") family = val();
    else if (args[i] == "--out") out = val();
    else if (args[i] == "--output") output = val();
    else if (args[i] == "--n") n = std::stoull(val());
    else if (args[i] == "--seed") seed = std::stoull(val());
    else if (args[i] == "--threads") threads = std::stoi(val());
    else throw std::invalid_argument("unknown option '" + args[i] + "'");
  }
  if (query.empty() || family.empty()) throw std::invalid_argument("plot needs --query and --family");
  const Query q = query_by_name(query);
  const Family& fam = family_by_name(q, family);
  const QueryInfo& qi = info(q);
  int group = qi.outputs.empty() ? -1 : 0;
  if (!output.empty()) {
    group = -1;
    for (std::size_t g = 0; g < qi.outputs.size(); ++g)
      if (qi.outputs[g].name == output) group = int(g);
    if (group < 0) throw std::invalid_argument("query " + query + " has no output '" + output + "'");
  }
  if (out.empty()) out = "drift-" + query + "-" + family + ".svg";

  Spec spec;
  spec.queries = {q};
  spec.families = {family};
  spec.impls = {"book-float", "book-double", "book-long-double"};
  spec.n = n;
  spec.seed = seed;
  spec.threads = threads;
  const Results r = run(spec);

  const std::string dat = out + ".dat";
  {
    std::ofstream d(dat);
    d << "# scale";
    for (const auto& im : spec.impls) d << " " << im << ":misclassified " << im << ":predicate " << im << ":p99 " << im << ":max";
    d << "\n";
    for (int k : fam.scales) {
      d << k;
      for (const auto& im : spec.impls) {
        const CellStats& st = r.cells.at({q, im, family, k});
        const double base = double(std::max<std::uint64_t>(1, st.n - st.refused));
        const double miss = double(st.cls_fp + st.cls_fn) / base, pmiss = double(st.pred_fp + st.pred_fn) / base;
        double p99 = 0, mx = 0;
        if (group >= 0) {
          p99 = double(st.out[group].hist.quantile(0.99));
          mx = st.out[group].worst.set ? double(st.out[group].worst.metric) : 0;
        }
        // log axes: a rate or error of 0 is drawn at the bottom of the axis
        d << " " << std::max(miss, 1e-5) << " " << std::max(pmiss, 1e-5) << " " << std::max(p99, 0.5) << " "
          << std::max(mx, 0.5);
      }
      d << "\n";
    }
  }
  FILE* gp = popen("gnuplot", "w");
  if (!gp) throw std::runtime_error("cannot run gnuplot (install gnuplot-nox)");
  const std::string what = group >= 0 ? qi.outputs[group].name : "";
  // columns: 1 scale, then per implementation i: 2+4i misclassified, 3+4i predicate, 4+4i p99, 5+4i max
  std::string miss_plot, err_plot;
  for (std::size_t i = 0; i < spec.impls.size(); ++i) {
    const std::string im = spec.impls[i], c = std::to_string(2 + 4 * i), lc = std::to_string(i + 1);
    miss_plot += std::string(i ? ", " : "") + "'" + dat + "' u 1:" + c + " w lp lc " + lc + " t '" + im + "', '' u 1:" +
                 std::to_string(3 + 4 * i) + " w lp dt 2 lc " + lc + " t '" + im + " predicate'";
    err_plot += std::string(i ? ", " : "") + "'" + dat + "' u 1:" + std::to_string(4 + 4 * i) + " w lp lc " + lc +
                " t '" + im + " p99', '' u 1:" + std::to_string(5 + 4 * i) + " w lp dt 2 lc " + lc + " t '" + im + " max'";
  }
  std::fprintf(gp,
               "set terminal svg size 1100,440 dynamic font 'sans,11' background rgb 'white'\nset output '%s'\n"
               "set multiplot layout 1,2 title '%s, family %s (%llu cases per point, seed %llu): %s'\n"
               "set xlabel 'scale k'\nset key top left\nset grid\nset logscale y\n"
               "set ylabel 'misclassified share (0 drawn at 1e-5)'\nset yrange [1e-5:1]\nset format y '10^{%%L}'\nplot %s\n",
               out.c_str(), query.c_str(), family.c_str(), (unsigned long long)n, (unsigned long long)seed,
               fam.describe.c_str(), miss_plot.c_str());
  if (group >= 0)
    std::fprintf(gp,
                 "set ylabel '%s error, ulps of its type (0 drawn at 0.5)' noenhanced\nset yrange [0.5:*]\n"
                 "set format y '10^{%%L}'\nplot %s\n",
                 what.c_str(), err_plot.c_str());
  std::fprintf(gp, "unset multiplot\n");
  if (pclose(gp) != 0) throw std::runtime_error("gnuplot failed drawing " + out);
  std::cout << "wrote " << out << " (data in " << dat << ")\n";
  return 0;
}

}  // namespace cdref::cli
