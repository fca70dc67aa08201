// src/report.cpp - campaign results as a table for people, JSON and CSV.
#include "report.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace cdref::cli {

using namespace cdref::fuzz;

namespace {

std::string num(double x, const char* f = "%.3g") {
  char b[64];
  std::snprintf(b, sizeof b, f, x);
  return b;
}

struct Worst {  // the worst output of a cell (by ulps), and its absolute and relative errors
  int group = -1;
  std::uint64_t p50 = 0, p99 = 0, max = 0, nonfinite = 0;
  double max_abs = 0, max_rel = 0;
};

// Groups nothing graded (a campaign with --outputs cls, a cast that never hit) are left out:
// group -1 when no group has a graded value.
Worst worst_output(const CellKey& k, const CellStats& st) {
  Worst w;
  const QueryInfo& qi = info(k.query);
  for (std::size_t g = 0; g < qi.outputs.size(); ++g) {
    const OutputStats& os = st.out[g];
    w.nonfinite += os.nonfinite;
    if (!os.worst.set) continue;
    const std::uint64_t mx = os.worst.metric;
    if (w.group < 0 || mx > w.max) {
      w.group = int(g);
      w.max = mx;
      w.p50 = os.hist.quantile(0.5);
      w.p99 = os.hist.quantile(0.99);
      w.max_abs = os.max_abs;
      w.max_rel = os.max_rel;
    }
  }
  return w;
}

// A kept example's inputs by column name, in hex-float (exact).
std::string inputs_hex(const Exemplar& e, const QueryInfo& qi) {
  std::ostringstream s;
  for (std::size_t i = 0; i < qi.inputs.size(); ++i) s << (i ? " " : "") << qi.inputs[i] << "=" << hexfloat(e.inputs[i]);
  return s.str();
}

// A kept example as JSON: its case index, its metric, the value given and the exact one
// (hex-float, exact), and its inputs by column name (hex-float).
nlohmann::ordered_json json_ex(const Exemplar& e, const QueryInfo& qi) {
  if (!e.set) return nullptr;
  nlohmann::ordered_json inputs = nlohmann::ordered_json::object();
  for (std::size_t i = 0; i < qi.inputs.size(); ++i) inputs[qi.inputs[i]] = hexfloat(e.inputs[i]);
  return {{"index", e.index}, {"metric", e.metric}, {"got", hexfloat(e.got)}, {"want", hexfloat(e.want)},
          {"inputs", inputs}};
}

}  // namespace

std::map<int, std::uint64_t> by_power_of_two(const Histogram& h) {
  std::map<int, std::uint64_t> pow2;
  for (int b = 0; b < Histogram::bins; ++b)
    if (h.count[b]) {
      const std::uint64_t lo = Histogram::lower_edge(b);
      pow2[lo == 0 ? -1 : 63 - std::countl_zero(lo)] += h.count[b];
    }
  return pow2;
}

void print_table(std::ostream& o, const Results& r, std::uint64_t seed, int worst_rows) {
  // per (query, implementation)
  struct Sum {
    std::uint64_t n = 0, refused = 0, cls = 0, pred = 0, nonfinite = 0, max = 0, fp = 0, fn = 0;
    std::uint64_t apart = 0;  // set apart by the implementation's convention: neither graded nor refused
    std::uint64_t certified = 0, uncertain = 0, certain_wrong = 0;
    std::string max_where;
    double max_rel = 0;  // over every output group and cell
  };
  std::map<std::pair<std::string, std::string>, Sum> sums;
  for (const auto& [k, st] : r.cells) {
    Sum& s = sums[{info(k.query).name, k.impl}];
    s.n += st.n;
    s.refused += st.refused;
    s.apart += st.set_apart;
    s.cls += st.cls_fp + st.cls_fn;
    s.fp += st.cls_fp;
    s.fn += st.cls_fn;
    s.pred += st.pred_fp + st.pred_fn;
    s.certified += st.certified;
    s.uncertain += st.uncertain;
    s.certain_wrong += st.certain_wrong;
    const Worst w = worst_output(k, st);
    s.nonfinite += w.nonfinite;
    for (std::size_t g = 0; g < info(k.query).outputs.size(); ++g) s.max_rel = std::max(s.max_rel, st.out[g].max_rel);
    if (w.group >= 0 && w.max >= s.max) {
      s.max = w.max;
      s.max_where = info(k.query).outputs[w.group].name + " in " + k.family + "/" + std::to_string(k.scale);
    }
  }
  char line[512];
  o << "Per query and implementation (errors in ulps of the implementation's type, against the correctly\n"
       "rounded exact answer, and relative to the inputs' scale; misclassified: the full query / the\n"
       "predicate column, its other formulation):\n\n";
  std::snprintf(line, sizeof line, "%-20s %-17s %10s %9s %16s %16s %10s %9s  %s\n", "query", "impl", "cases", "refused",
                "misclassified", "predicate wrong", "nonfinite", "max rel", "max ulps (where)");
  o << line;
  for (const auto& [key, s] : sums) {
    const std::string miss = std::to_string(s.cls) + " (" + num(100.0 * double(s.cls) / double(std::max<std::uint64_t>(1, s.n - s.refused - s.apart)), "%.2g") + "%)";
    const std::string pmiss = std::to_string(s.pred) + " (" + num(100.0 * double(s.pred) / double(std::max<std::uint64_t>(1, s.n - s.refused - s.apart)), "%.2g") + "%)";
    std::snprintf(line, sizeof line, "%-20s %-17s %10llu %9llu %16s %16s %10llu %9s  %s\n", key.first.c_str(),
                  key.second.c_str(), (unsigned long long)s.n, (unsigned long long)s.refused, miss.c_str(),
                  pmiss.c_str(), (unsigned long long)s.nonfinite, s.max_where.empty() ? "-" : num(s.max_rel, "%.2g").c_str(),
                  s.max_where.empty() ? "-" : (num(double(s.max), "%.3g") + " (" + s.max_where + ")").c_str());
    o << line;
  }

  // the implementations that certify their classifications (robust::decide)
  bool any_cert = false;
  for (const auto& [key, s] : sums) any_cert = any_cert || s.certified;
  if (any_cert) {
    o << "\nCertificates (the implementation's own error bound says whether its classification is exact;\n"
         "every misclassification must be among the uncertain cases, so 'certain but wrong' must be 0):\n\n";
    std::snprintf(line, sizeof line, "%-20s %-17s %10s %20s %16s %16s\n", "query", "impl", "certified",
                  "uncertain", "misclassified", "certain but wrong");
    o << line;
    for (const auto& [key, s] : sums) {
      if (!s.certified) continue;
      const std::string unc = std::to_string(s.uncertain) + " (" +
                              num(100.0 * double(s.uncertain) / double(std::max<std::uint64_t>(1, s.certified)), "%.2g") + "%)";
      std::snprintf(line, sizeof line, "%-20s %-17s %10llu %20s %16llu %16llu\n", key.first.c_str(),
                    key.second.c_str(), (unsigned long long)s.certified, unc.c_str(), (unsigned long long)s.cls,
                    (unsigned long long)s.certain_wrong);
      o << line;
    }
  }

  // the mesh-level queries: leaks and phantom hits
  bool any_mesh = false;
  for (const auto& [key, s] : sums) any_mesh = any_mesh || info(query_by_name(key.first)).mesh_level;
  if (any_mesh) {
    o << "\nWatertightness (a shot against a fan of triangles that share a vertex or an edge; a leak: the exact\n"
         "shot meets the fan and the implementation hits none of its triangles; a phantom: the other way):\n\n";
    std::snprintf(line, sizeof line, "%-20s %-17s %10s %16s %16s\n", "query", "impl", "cases", "leaks", "phantom hits");
    o << line;
    for (const auto& [key, s] : sums) {
      if (!info(query_by_name(key.first)).mesh_level) continue;
      const double graded = double(std::max<std::uint64_t>(1, s.n - s.refused - s.apart));
      const std::string leaks = std::to_string(s.fn) + " (" + num(100.0 * double(s.fn) / graded, "%.2g") + "%)";
      const std::string ph = std::to_string(s.fp) + " (" + num(100.0 * double(s.fp) / graded, "%.2g") + "%)";
      std::snprintf(line, sizeof line, "%-20s %-17s %10llu %16s %16s\n", key.first.c_str(), key.second.c_str(),
                    (unsigned long long)(s.n - s.refused - s.apart), leaks.c_str(), ph.c_str());
      o << line;
    }
  }

  // worst cells first: by misclassification rate, then by max error
  std::vector<std::pair<CellKey, const CellStats*>> cells;
  for (const auto& [k, st] : r.cells) cells.push_back({k, &st});
  auto rate = [](const CellStats& st) {
    return double(st.cls_fp + st.cls_fn + st.pred_fp + st.pred_fn) / double(std::max<std::uint64_t>(1, st.n));
  };
  std::stable_sort(cells.begin(), cells.end(), [&](const auto& a, const auto& b) {
    const double ra = rate(*a.second), rb = rate(*b.second);
    if (ra != rb) return ra > rb;
    return worst_output(a.first, *a.second).max > worst_output(b.first, *b.second).max;
  });
  o << "\nWorst cells (family/scale k; see `cdref describe`):\n\n";
  std::snprintf(line, sizeof line, "%-20s %-17s %-22s %7s %12s %12s   %-12s %8s %8s %10s %9s %9s\n", "query", "impl",
                "family/scale", "cases", "wrong fp/fn", "pred fp/fn", "output", "p50", "p99", "max ulps", "max abs",
                "max rel");
  o << line;
  int shown = 0;
  for (const auto& [k, st] : cells) {
    if (shown++ >= worst_rows) break;
    const Worst w = worst_output(k, *st);
    const std::string fam = k.family + "/" + std::to_string(k.scale);
    const std::string c = std::to_string(st->cls_fp) + "/" + std::to_string(st->cls_fn);
    const std::string p = std::to_string(st->pred_fp) + "/" + std::to_string(st->pred_fn);
    std::snprintf(line, sizeof line, "%-20s %-17s %-22s %7llu %12s %12s   %-12s %8s %8s %10s %9s %9s\n",
                  info(k.query).name, k.impl.c_str(), fam.c_str(), (unsigned long long)st->n, c.c_str(), p.c_str(),
                  w.group < 0 ? "-" : info(k.query).outputs[w.group].name.c_str(),
                  w.group < 0 ? "-" : num(double(w.p50)).c_str(), w.group < 0 ? "-" : num(double(w.p99)).c_str(),
                  w.group < 0 ? "-" : num(double(w.max)).c_str(), w.group < 0 ? "-" : num(w.max_abs, "%.2g").c_str(),
                  w.group < 0 ? "-" : num(w.max_rel, "%.2g").c_str());
    o << line;
  }
  // reproducible examples for the very worst
  o << "\nExamples (seed " << seed << "; inputs in hex-float, as the implementation received them):\n";
  shown = 0;
  for (const auto& [k, st] : cells) {
    if (shown >= 5) break;
    const Exemplar& e = st->cls_example.set ? st->cls_example : st->pred_example;
    if (e.set) {
      o << "  " << info(k.query).name << " " << k.impl << " " << k.family << "/" << k.scale << " case " << e.index
        << ": " << (st->cls_example.set ? "full query" : "predicate") << " says " << (e.got != 0 ? "yes" : "no")
        << ", truth " << (e.want != 0 ? "yes" : "no") << "\n    " << inputs_hex(e, info(k.query)) << "\n";
      ++shown;
    }
  }
}

void write_json(std::ostream& o, const Results& r, std::uint64_t seed) {
  nlohmann::ordered_json cells = nlohmann::ordered_json::array();
  for (const auto& [k, st] : r.cells) {
    const QueryInfo& qi = info(k.query);
    nlohmann::ordered_json c = {{"query", qi.name},
                        {"impl", k.impl},
                        {"family", k.family},
                        {"scale", k.scale},
                        {"cases", st.n},
                        {"refused", st.refused},
                        {"false_positives", st.cls_fp},
                        {"false_negatives", st.cls_fn},
                        {"predicate_false_positives", st.pred_fp},
                        {"predicate_false_negatives", st.pred_fn},
                        {"certified", st.certified},
                        {"uncertain", st.uncertain},
                        {"certain_but_wrong", st.certain_wrong},
                        {"certain_but_wrong_example", json_ex(st.certain_wrong_example, qi)},
                        {"misclassified_example", json_ex(st.cls_example, qi)},
                        {"predicate_example", json_ex(st.pred_example, qi)}};
    // the cases an implementation's convention set apart (never one of cdref's own)
    if (st.set_apart) c["set_apart"] = st.set_apart;
    nlohmann::ordered_json outs = nlohmann::ordered_json::object();
    for (std::size_t g = 0; g < qi.outputs.size(); ++g) {
      const OutputStats& os = st.out[g];
      // powers of two: "0" for exact, then "2^j" for [2^j, 2^(j+1))
      nlohmann::ordered_json hist = nlohmann::ordered_json::object();
      for (const auto& [j, n] : by_power_of_two(os.hist)) hist[j < 0 ? "0" : "2^" + std::to_string(j)] = n;
      outs[qi.outputs[g].name] = {{"count", os.hist.total()},
                                  {"nonfinite", os.nonfinite},
                                  {"p50", os.hist.quantile(0.5)},
                                  {"p99", os.hist.quantile(0.99)},
                                  {"max", os.worst.set ? os.worst.metric : 0},
                                  {"max_abs", os.max_abs},
                                  {"max_rel", os.max_rel},
                                  {"histogram_pow2", hist},
                                  {"worst", json_ex(os.worst, qi)}};
    }
    c["outputs"] = outs;
    cells.push_back(c);
  }
  o << nlohmann::ordered_json{{"seed", seed}, {"cells", cells}}.dump(1) << "\n";
}

void write_csv(std::ostream& o, const Results& r) {
  o << "query,impl,family,scale,cases,refused,false_positives,false_negatives,predicate_false_positives,"
       "predicate_false_negatives,certified,uncertain,certain_but_wrong,output,count,nonfinite,p50_ulps,p99_ulps,"
       "max_ulps,max_abs,max_rel,worst_index\n";
  for (const auto& cell : r.cells) {
    const CellKey& k = cell.first;
    const CellStats& st = cell.second;
    const QueryInfo& qi = info(k.query);
    auto head = [&] {
      o << qi.name << "," << k.impl << "," << k.family << "," << k.scale << "," << st.n << "," << st.refused << ","
        << st.cls_fp << "," << st.cls_fn << "," << st.pred_fp << "," << st.pred_fn << "," << st.certified << ","
        << st.uncertain << "," << st.certain_wrong << ",";
    };
    if (qi.outputs.empty()) {
      head();
      o << ",,,,,,,,\n";
    }
    for (std::size_t g = 0; g < qi.outputs.size(); ++g) {
      const OutputStats& os = st.out[g];
      head();
      o << qi.outputs[g].name << "," << os.hist.total() << "," << os.nonfinite << "," << os.hist.quantile(0.5) << ","
        << os.hist.quantile(0.99) << "," << (os.worst.set ? os.worst.metric : 0) << "," << num(os.max_abs, "%.17g")
        << "," << num(os.max_rel, "%.17g") << "," << (os.worst.set ? std::to_string(os.worst.index) : "") << "\n";
    }
  }
}

}  // namespace cdref::cli
