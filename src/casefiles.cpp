// src/casefiles.cpp - case files: cases, oracle, score.
//
// A case file is CSV with a header. Its columns are `case` (an identifier, a whole
// number), then the query's input columns (`cdref cases --describe Q`), in any order;
// other columns (family, scale) are carried along and ignored. Numbers are hex-float
// (%a, exact) or decimal; decimal with 17 significant digits reads back exactly.
//
// An answer file is CSV with a header: `case`, then any subset of the query's output
// columns: the classification (`hit` or `intersect`), the predicate (`predicate`), and the
// components of each output (`lambda_enter`, `point_x`, ...). Only the columns it has are
// graded. Classifications are 0/1 (or true/false).
//
// A malformed line is reported on standard error with its file and line number; the
// rest of the file is still read and graded, and the command then exits with status 1.
#include "casefiles.hpp"

#include <cdref/error.hpp>
#include <cdref/fuzz/campaign.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "report.hpp"

namespace cdref::cli {

using namespace cdref::fuzz;

namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : line) {
    if (c == ',') {
      out.push_back(cur);
      cur.clear();
    } else if (c != '\r' && c != ' ' && c != '\t') {
      cur += c;
    }
  }
  out.push_back(cur);
  return out;
}

bool parse_real(const std::string& t, double& x) {
  if (t.empty()) return false;
  char* end = nullptr;
  x = std::strtod(t.c_str(), &end);
  return end == t.c_str() + t.size();
}

bool parse_real(const std::string& t, long double& x) {
  if (t.empty()) return false;
  char* end = nullptr;
  x = std::strtold(t.c_str(), &end);
  return end == t.c_str() + t.size();
}

bool parse_id(const std::string& t, std::uint64_t& x) {
  if (t.empty() || t[0] == '-') return false;
  char* end = nullptr;
  x = std::strtoull(t.c_str(), &end, 10);
  return end == t.c_str() + t.size();
}

// A literal beyond double's range (1e400, 0x1p+2000) is read as infinity: named here, since
// the refusal of the infinity later could not show what was written ("" when none is).
std::string overflowing_literal(const QueryInfo& qi, const CaseRow& r, const std::vector<std::string>& tokens) {
  for (std::size_t k = 0; k < qi.inputs.size(); ++k)
    if (std::isinf(r.in[k]) && tokens[k].find_first_of("iI") == std::string::npos)
      return qi.inputs[k] + " '" + tokens[k] + "' is beyond the range of double";
  return "";
}

std::string fmt_real(double x, bool decimal) {
  char b[64];
  std::snprintf(b, sizeof b, decimal ? "%.17g" : "%a", x);
  return b;
}

// An answer value of the given precision: long double needs 21 significant digits.
std::string fmt_answer(long double x, bool decimal, int precision) {
  if (precision != 64) return fmt_real(double(x), decimal);
  char b[64];
  std::snprintf(b, sizeof b, decimal ? "%.21Lg" : "%La", x);
  return b;
}

int parse_precision(const std::string& p) {
  if (p == "24" || p == "53" || p == "64") return std::stoi(p);
  throw std::invalid_argument("--precision is 24 (float), 53 (double) or 64 (long double), not '" + p + "'");
}

// The answer columns of a query: classification, predicate, then output components.
struct Column {
  std::string name;
  int kind;   // 0 classification, 1 predicate, 2 value
  int index;  // into Answer::v
  int group;  // output group (values)
};
std::vector<Column> answer_columns(Query q) {
  const QueryInfo& qi = info(q);
  std::vector<Column> cols = {{qi.cls_name, 0, 0, -1}, {"predicate", 1, 0, -1}};
  int k = 0;
  for (std::size_t g = 0; g < qi.outputs.size(); ++g) {
    if (qi.outputs[g].width == 1) {
      cols.push_back({qi.outputs[g].name, 2, k++, int(g)});
    } else {
      for (const char* ax : {"_x", "_y", "_z"}) cols.push_back({qi.outputs[g].name + ax, 2, k++, int(g)});
    }
  }
  return cols;
}

struct Opts {
  std::map<std::string, std::string> v;
  std::vector<std::string> flags;
  bool has(const std::string& f) const {
    for (const auto& x : flags)
      if (x == f) return true;
    return false;
  }
  std::string get(const std::string& k, const std::string& dflt = "") const {
    auto it = v.find(k);
    return it == v.end() ? dflt : it->second;
  }
  std::string need(const std::string& k) const {
    auto it = v.find(k);
    if (it == v.end()) throw std::invalid_argument(k + " is required");
    return it->second;
  }
};
Opts parse(const std::vector<std::string>& args, std::initializer_list<const char*> valued,
           std::initializer_list<const char*> flags) {
  Opts o;
  for (std::size_t i = 0; i < args.size(); ++i) {
    bool done = false;
    for (const char* f : flags)
      if (args[i] == f) o.flags.push_back(f), done = true;
    for (const char* k : valued)
      if (!done && args[i] == k) {
        if (i + 1 >= args.size()) throw std::invalid_argument(std::string(k) + " needs a value");
        o.v[k] = args[++i];
        done = true;
      }
    if (!done) throw std::invalid_argument("unknown option '" + args[i] + "'");
  }
  return o;
}

std::istream& open_in(const std::string& path, std::ifstream& f) {
  if (path == "-") return std::cin;
  f.open(path, std::ios::binary);
  if (!f) throw std::runtime_error("cannot read " + path);
  return f;
}

struct Out {
  std::ofstream f;
  std::ostream* o = &std::cout;
  explicit Out(const std::string& path) {
    if (!path.empty() && path != "-") {
      f.open(path, std::ios::binary);
      if (!f) throw std::runtime_error("cannot write " + path);
      o = &f;
    }
  }
};

}  // namespace

std::vector<CaseRow> parse_cases(Query q, std::istream& in, const std::string& path, int& bad) {
  const QueryInfo& qi = info(q);
  std::string line;
  int lineno = 0;
  std::vector<int> where(qi.inputs.size(), -1);
  int id_col = -1;
  std::size_t ncols = 0;
  std::vector<CaseRow> rows;
  while (std::getline(in, line)) {
    ++lineno;
    if (line.empty() || line[0] == '#') continue;
    const auto cells = split(line);
    if (id_col < 0) {  // the header
      ncols = cells.size();
      for (std::size_t c = 0; c < cells.size(); ++c) {
        if (cells[c] == "case") id_col = int(c);
        for (std::size_t k = 0; k < qi.inputs.size(); ++k)
          if (cells[c] == qi.inputs[k]) where[k] = int(c);
      }
      if (id_col < 0) throw std::runtime_error(path + ":" + std::to_string(lineno) + ": the header has no 'case' column");
      for (std::size_t k = 0; k < qi.inputs.size(); ++k)
        if (where[k] < 0)
          throw std::runtime_error(path + ":" + std::to_string(lineno) + ": the header has no '" + qi.inputs[k] +
                                   "' column (see cdref cases --describe " + qi.name + ")");
      continue;
    }
    auto complain = [&](const std::string& why) {
      std::cerr << path << ":" << lineno << ": " << why << "; line skipped\n";
      ++bad;
    };
    if (cells.size() != ncols) {
      complain("expected " + std::to_string(ncols) + " fields, found " + std::to_string(cells.size()));
      continue;
    }
    CaseRow r;
    if (!parse_id(cells[id_col], r.id)) {
      complain("case id '" + cells[id_col] + "' is not a whole number");
      continue;
    }
    bool ok = true;
    std::vector<std::string> tokens;
    for (std::size_t k = 0; k < qi.inputs.size() && ok; ++k) {
      tokens.push_back(cells[where[k]]);
      if (!parse_real(cells[where[k]], r.in[k])) {
        complain(qi.inputs[k] + " '" + cells[where[k]] + "' is not a number");
        ok = false;
      }
    }
    if (!ok) continue;
    r.refusal = overflowing_literal(qi, r, tokens);
    rows.push_back(r);
  }
  if (id_col < 0) throw std::runtime_error(path + ": no header line");
  return rows;
}

Answer answer_case(Query q, const CaseRow& r, int precision, bool values) {
  if (!r.refusal.empty()) throw invalid_input(r.refusal);
  Inputs in = r.in;
  if (precision == 24) {
    in = float_inputs(q, r.in);
    for (std::size_t k = 0; k < info(q).inputs.size(); ++k)
      if (std::isfinite(r.in[k]) && !std::isfinite(in[k]))
        throw invalid_input(info(q).inputs[k] + " is beyond the range of float (" + hexfloat(r.in[k]) + ")");
  }
  // the fast oracle: the exact answer (its equality with the exact path is tested); the
  // classification alone from the classification oracle (it refuses what the exact types
  // refuse, by the same names: the fuzz targets check both)
  return values ? oracle_truth(q, in, precision) : oracle_classify(q, in);
}

bool classification_only(const std::string& outputs) {
  if (outputs != "all" && outputs != "cls")
    throw std::invalid_argument("--outputs is all (every output) or cls (the classification alone), not '" + outputs +
                                "'");
  return outputs == "cls";
}

namespace {
std::vector<CaseRow> read_cases(Query q, const std::string& path, int& bad) {
  std::ifstream f;
  return parse_cases(q, open_in(path, f), path, bad);
}
}  // namespace

int cases_command(std::vector<std::string> args) {
  if (args.size() == 2 && args[0] == "--describe") {
    const Query q = query_by_name(args[1]);
    const QueryInfo& qi = info(q);
    std::cout << qi.name << ": " << qi.describe << "\n\ncase file columns: case";
    for (const auto& c : qi.inputs) std::cout << "," << c;
    std::cout << "\n(family and scale columns, when present, are ignored on reading)\n\nanswer file columns: case";
    for (const auto& c : answer_columns(q)) std::cout << "," << c.name;
    std::cout << "\n  " << qi.cls_name << ": 1/0, the full query's classification (" << qi.full_call
              << ")\n  predicate: 1/0, the other formulation of the classification (" << qi.pred_name << ")\n"
              << qi.answer_help;
    std::cout << "An answer file may give any subset of these columns; only those are graded.\n";
    return 0;
  }
  const Opts o = parse(args, {"--query", "--family", "--scale", "--n", "--seed", "--out"}, {"--decimal"});
  const Query q = query_by_name(o.need("--query"));
  const Family& fam = family_by_name(q, o.get("--family", "uniform"));
  const int scale = o.v.count("--scale") ? std::stoi(o.get("--scale")) : fam.scales.front();
  const std::uint64_t n = std::stoull(o.get("--n", "100"));
  const std::uint64_t seed = std::stoull(o.get("--seed", "1"));
  const bool decimal = o.has("--decimal");
  Out out(o.get("--out"));
  const QueryInfo& qi = info(q);
  *out.o << "case,family,scale";
  for (const auto& c : qi.inputs) *out.o << "," << c;
  *out.o << "\n";
  for (std::uint64_t i = 0; i < n; ++i) {
    const Inputs in = make_case(seed, q, fam, scale, i);
    *out.o << i << "," << fam.name << "," << scale;
    for (std::size_t k = 0; k < qi.inputs.size(); ++k) *out.o << "," << fmt_real(in[k], decimal);
    *out.o << "\n";
  }
  return 0;
}

int oracle_command(std::vector<std::string> args) {
  const Opts o = parse(args, {"--query", "--cases", "--out", "--precision", "--outputs"}, {"--decimal"});
  const Query q = query_by_name(o.need("--query"));
  const int precision = parse_precision(o.get("--precision", "53"));
  const bool values = !classification_only(o.get("--outputs", "all"));
  int bad = 0;
  const auto rows = read_cases(q, o.get("--cases", "-"), bad);
  Out out(o.get("--out"));
  auto cols = answer_columns(q);
  if (!values) cols.erase(std::remove_if(cols.begin(), cols.end(), [](const auto& c) { return c.kind == 2; }), cols.end());
  *out.o << "case";
  for (const auto& c : cols) *out.o << "," << c.name;
  *out.o << "\n";
  for (const CaseRow& r : rows) {
    // at precision 24 the answer is for the inputs rounded to float, as a float
    // implementation receives them
    Answer t;
    try {
      t = answer_case(q, r, precision, values);
    } catch (const invalid_input& e) {
      std::cerr << "case " << r.id << ": " << e.what() << "; no answer\n";
      ++bad;
      continue;
    }
    *out.o << r.id;
    for (const auto& c : cols)
      *out.o << "," << (c.kind == 0 ? std::to_string(int(t.cls)) : c.kind == 1 ? std::to_string(int(t.pred))
                                                                                 : fmt_answer(t.v[c.index], o.has("--decimal"), precision));
    *out.o << "\n";
  }
  return bad ? 1 : 0;
}

int score_command(std::vector<std::string> args) {
  const Opts o = parse(args, {"--query", "--cases", "--answers", "--precision", "--json", "--csv"}, {});
  const Query q = query_by_name(o.need("--query"));
  const int precision = parse_precision(o.get("--precision", "53"));
  int bad = 0;
  const auto rows = read_cases(q, o.need("--cases"), bad);
  // the answers
  const std::string apath = o.need("--answers");
  std::ifstream af;
  std::istream& ain = open_in(apath, af);
  const auto all_cols = answer_columns(q);
  std::vector<int> given;  // answer-file column -> index in all_cols (-1: the case id)
  std::map<std::uint64_t, std::vector<std::string>> answers;
  std::string line;
  int lineno = 0;
  std::size_t ncols = 0;
  bool header = false;
  while (std::getline(ain, line)) {
    ++lineno;
    if (line.empty() || line[0] == '#') continue;
    const auto cells = split(line);
    if (!header) {
      header = true;
      ncols = cells.size();
      bool has_id = false;
      for (const auto& c : cells) {
        int idx = -2;
        if (c == "case") idx = -1, has_id = true;
        for (std::size_t k = 0; k < all_cols.size(); ++k)
          if (all_cols[k].name == c) idx = int(k);
        if (idx == -2)
          throw std::runtime_error(apath + ":" + std::to_string(lineno) + ": unknown answer column '" + c +
                                   "' (see cdref cases --describe " + info(q).name + ")");
        given.push_back(idx);
      }
      if (!has_id) throw std::runtime_error(apath + ":" + std::to_string(lineno) + ": the header has no 'case' column");
      continue;
    }
    std::uint64_t id = 0;
    std::size_t id_at = 0;
    while (given[id_at] != -1) ++id_at;
    if (cells.size() != ncols) {
      std::cerr << apath << ":" << lineno << ": expected " << ncols << " fields, found " << cells.size()
                << "; line skipped\n";
      ++bad;
      continue;
    }
    if (!parse_id(cells[id_at], id)) {
      std::cerr << apath << ":" << lineno << ": case id '" << cells[id_at] << "' is not a whole number; line skipped\n";
      ++bad;
      continue;
    }
    answers[id] = cells;
  }
  if (!header) throw std::runtime_error(apath + ": no header line");
  // the exact values are needed only when the answer file gives some
  bool values = false;
  for (int idx : given) values = values || (idx >= 0 && all_cols[idx].kind == 2);

  // grade, column by column
  struct ColStats {
    std::uint64_t fp = 0, fn = 0, graded = 0;
    OutputStats s;
    Exemplar example;
  };
  std::map<int, ColStats> stats;
  std::uint64_t unanswered = 0, graded_cases = 0;
  for (const CaseRow& r : rows) {
    // a case outside the query's domain is refused by name, answered or not
    const auto it = answers.find(r.id);
    const Inputs in = precision == 24 ? float_inputs(q, r.in) : r.in;
    Answer t;
    try {
      t = answer_case(q, r, precision, values);
    } catch (const invalid_input& e) {
      std::cerr << "case " << r.id << ": " << e.what() << "; not graded\n";
      ++bad;
      continue;
    }
    if (it == answers.end()) {
      ++unanswered;
      continue;
    }
    // their classification, if given, gates the values of a cast
    std::optional<bool> their_hit;
    bool row_ok = true;
    std::vector<long double> vals(it->second.size());
    for (std::size_t c = 0; c < given.size(); ++c) {
      if (given[c] < 0) continue;
      const std::string& cell = it->second[c];
      const Column& col = all_cols[given[c]];
      if (col.kind < 2) {
        if (cell == "1" || cell == "true") vals[c] = 1;
        else if (cell == "0" || cell == "false") vals[c] = 0;
        else row_ok = false;
        if (col.kind == 0) their_hit = vals[c] != 0;
      } else if (!parse_real(cell, vals[c])) {
        row_ok = false;
      }
    }
    if (!row_ok) {
      std::cerr << apath << ": case " << r.id << ": an answer is not a number or 0/1; case skipped\n";
      ++bad;
      continue;
    }
    ++graded_cases;
    for (std::size_t c = 0; c < given.size(); ++c) {
      if (given[c] < 0) continue;
      const Column& col = all_cols[given[c]];
      ColStats& cs = stats[given[c]];
      if (col.kind < 2) {
        const bool want = col.kind == 0 ? t.cls : t.pred, got = vals[c] != 0;
        ++cs.graded;
        if (got != want) {
          ++(got ? cs.fp : cs.fn);
          cs.example.offer(0, r.id, in, got, want);
        }
        continue;
      }
      // a cast's values exist only on a hit, a separating axis only on a miss: graded where
      // both the truth and the answer (when it gives its classification) say so
      const Output& out = info(q).outputs[col.group];
      if (out.when == Output::on_hit && !(t.cls && their_hit.value_or(true))) continue;
      if (out.when == Output::on_miss && !(!t.cls && !their_hit.value_or(false))) continue;
      ++cs.graded;
      const long double want = t.v[col.index];
      if (!std::isfinite(vals[c]) && std::isfinite(want)) {
        ++cs.s.nonfinite;
        continue;
      }
      const std::uint64_t d = out.label ? std::uint64_t(vals[c] != want) : ulp_distance(vals[c], want, precision);
      cs.s.hist.add(d);
      cs.s.worst.offer(d, r.id, in, vals[c], want);
    }
  }
  // report
  const QueryInfo& qi = info(q);
  std::cout << "cdref score: " << qi.name << ", " << rows.size() << " cases, " << graded_cases << " answered and graded, "
            << unanswered << " unanswered, " << bad << " malformed or refused; errors in ulps of "
            << (precision == 24 ? "float" : (precision == 53 ? "double" : "long double"))
            << " against the correctly rounded exact answer\n\n";
  char buf[256];
  std::snprintf(buf, sizeof buf, "%-16s %8s %8s %8s %10s %10s %10s %10s  %s\n", "column", "graded", "wrong",
                "nonfin", "p50", "p99", "max", "worst case", "histogram (ulps: count)");
  std::cout << buf;
  for (const auto& [k, cs] : stats) {
    const Column& col = all_cols[k];
    std::string hist;
    if (col.kind == 2) {
      for (const auto& [j, c] : by_power_of_two(cs.s.hist)) hist += (j < 0 ? std::string("0") : "2^" + std::to_string(j)) + ":" + std::to_string(c) + " ";
    }
    const std::string wrong = col.kind < 2 ? std::to_string(cs.fp) + "/" + std::to_string(cs.fn) : "-";
    const Exemplar& ex = col.kind < 2 ? cs.example : cs.s.worst;
    std::snprintf(buf, sizeof buf, "%-16s %8llu %8s %8llu %10llu %10llu %10llu %10s  %s\n", col.name.c_str(),
                  (unsigned long long)cs.graded, wrong.c_str(), (unsigned long long)cs.s.nonfinite,
                  (unsigned long long)cs.s.hist.quantile(0.5), (unsigned long long)cs.s.hist.quantile(0.99),
                  (unsigned long long)(cs.s.worst.set ? cs.s.worst.metric : 0),
                  ex.set ? std::to_string(ex.index).c_str() : "-", hist.c_str());
    std::cout << buf;
  }
  std::cout << "(wrong: false positives/false negatives of a classification)\n";
  if (qi.mesh_level)
    for (const auto& [k, cs] : stats)
      if (all_cols[k].kind == 0)
        std::cout << "leaks (the exact shot meets the fan, the answer hits none of its triangles): " << cs.fn
                  << "; phantom hits: " << cs.fp << "\n";
  return bad ? 1 : 0;
}

}  // namespace cdref::cli
