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
#include <set>
#include <sstream>
#include <stdexcept>

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <memory>
#include <nlohmann/json.hpp>

#include "options.hpp"
#include "output.hpp"
#include "report.hpp"

namespace cdref::cli {

using namespace cdref::fuzz;

namespace {

// The fields of a CSV line, each with its surrounding blanks (and a final CR) removed; a
// blank inside a field is kept, so that "1 2" is refused as a number rather than read as 12.
std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::size_t start = 0;
  auto trim = [](std::string f) {
    const auto b = f.find_first_not_of(" \t\r"), e = f.find_last_not_of(" \t\r");
    return b == std::string::npos ? std::string() : f.substr(b, e - b + 1);
  };
  for (std::size_t i = 0; i <= line.size(); ++i)
    if (i == line.size() || line[i] == ',') {
      out.push_back(trim(line.substr(start, i - start)));
      start = i + 1;
    }
  return out;
}

// Whether a numeric literal's digits are all zero ("0", "-0.0e5", "0x0p+3"): a literal that is
// not, but reads as 0, has underflowed.
bool literal_is_zero(const std::string& t) {
  std::size_t i = 0;
  if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
  const bool hex = t.size() > i + 1 && t[i] == '0' && (t[i + 1] == 'x' || t[i + 1] == 'X');
  if (hex) i += 2;
  for (; i < t.size(); ++i) {
    const char c = t[i];
    if (hex ? (c == 'p' || c == 'P') : (c == 'e' || c == 'E')) break;
    if (c != '0' && c != '.') return false;
  }
  return true;
}

// A real number: the whole field, finite or not; "" when it reads exactly as written up to
// the usual rounding, or what is wrong with it.
template <class F>
std::string parse_real(const std::string& t, F& x) {
  if (t.empty()) return "is empty";
  if (t.find_first_of(" \t") != std::string::npos) return "has a blank inside";
  char* end = nullptr;
  errno = 0;
  if constexpr (std::is_same_v<F, long double>)
    x = std::strtold(t.c_str(), &end);
  else
    x = std::strtod(t.c_str(), &end);
  if (end != t.c_str() + t.size()) return "is not a number";
  if (x == 0 && !literal_is_zero(t)) return "underflows: it is below the range of its type and would read as 0";
  return "";
}

std::string parse_id(const std::string& t, std::uint64_t& x) {
  if (t.empty() || t.find_first_not_of("0123456789") != std::string::npos) return "is not a whole number";
  errno = 0;
  x = std::strtoull(t.c_str(), nullptr, 10);
  if (errno == ERANGE) return "is beyond 2^64 - 1";
  return "";
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

// An input file ("-": standard input). A directory, or a file that cannot be opened, is named.
std::istream& open_in(const std::string& path, std::ifstream& f, const std::string& what) {
  if (path == "-") return std::cin;
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
    throw std::runtime_error("cannot read " + what + " " + path + ": it is a directory");
  f.open(path, std::ios::binary);
  if (!f) throw std::runtime_error("cannot read " + what + " " + path + ": " + std::strerror(errno));
  return f;
}

// What is wrong with a raw line before it is split: a NUL byte (a binary file, or text cut by
// one), or "" when nothing is. A UTF-8 byte-order mark opening the file is removed.
std::string raw_line_problem(std::string& line, int lineno) {
  if (lineno == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
  if (line.find('\0') != std::string::npos) return "holds a NUL byte (is this a text file?)";
  return "";
}

}  // namespace

std::vector<CaseRow> parse_cases(Query q, std::istream& in, const std::string& path, int& bad,
                                 std::vector<std::uint64_t>* skipped) {
  const QueryInfo& qi = info(q);
  std::string line;
  int lineno = 0;
  std::vector<int> where(qi.inputs.size(), -1);
  int id_col = -1;
  std::size_t ncols = 0;
  std::vector<CaseRow> rows;
  std::map<std::uint64_t, int> seen;  // case id -> its line
  auto at = [&](int l) { return path + ":" + std::to_string(l) + ": "; };
  while (std::getline(in, line)) {
    ++lineno;
    const std::string raw = raw_line_problem(line, lineno);
    if (!raw.empty() && id_col < 0) throw std::runtime_error(at(lineno) + "the line " + raw);
    auto complain = [&](const std::string& why) {
      std::cerr << at(lineno) << why << "; line skipped\n";
      ++bad;
    };
    if (!raw.empty()) {
      complain("the line " + raw);
      continue;
    }
    if (line.empty() || line[0] == '#' || line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const auto cells = split(line);
    if (id_col < 0) {  // the header
      ncols = cells.size();
      for (std::size_t c = 0; c < cells.size(); ++c) {
        for (std::size_t d = 0; d < c; ++d)
          if (cells[d] == cells[c])
            throw std::runtime_error(at(lineno) + "the header names column '" + cells[c] + "' twice (columns " +
                                     std::to_string(d + 1) + " and " + std::to_string(c + 1) + ")");
        if (cells[c] == "case") id_col = int(c);
        for (std::size_t k = 0; k < qi.inputs.size(); ++k)
          if (cells[c] == qi.inputs[k]) where[k] = int(c);
      }
      if (id_col < 0) throw std::runtime_error(at(lineno) + "the header has no 'case' column");
      for (std::size_t k = 0; k < qi.inputs.size(); ++k)
        if (where[k] < 0)
          throw std::runtime_error(at(lineno) + "the header has no '" + qi.inputs[k] +
                                   "' column (see cdref cases --describe " + qi.name + ")");
      continue;
    }
    if (cells.size() != ncols) {
      complain("expected " + std::to_string(ncols) + " fields, found " + std::to_string(cells.size()));
      continue;
    }
    CaseRow r;
    if (const std::string e = parse_id(cells[id_col], r.id); !e.empty()) {
      complain("case id '" + cells[id_col] + "' " + e);
      continue;
    }
    if (const auto it = seen.find(r.id); it != seen.end()) {
      complain("case id " + cells[id_col] + " is already on line " + std::to_string(it->second));
      continue;
    }
    bool ok = true;
    std::vector<std::string> tokens;
    for (std::size_t k = 0; k < qi.inputs.size() && ok; ++k) {
      tokens.push_back(cells[where[k]]);
      if (const std::string e = parse_real(cells[where[k]], r.in[k]); !e.empty()) {
        complain(qi.inputs[k] + " '" + cells[where[k]] + "' " + e);
        ok = false;
      }
    }
    if (!ok) {
      if (skipped) skipped->push_back(r.id);
      continue;
    }
    seen[r.id] = lineno;
    r.refusal = overflowing_literal(qi, r, tokens);
    rows.push_back(r);
  }
  if (in.bad()) throw std::runtime_error("cannot read " + path + ": a read failed");
  if (id_col < 0) throw std::runtime_error(path + ": no header line");
  return rows;
}

Answer answer_case(Query q, const CaseRow& r, int precision, bool values) {
  if (!r.refusal.empty()) throw invalid_input(r.refusal);
  Inputs in = r.in;
  if (precision == 24) {
    in = float_inputs(q, r.in);
    for (std::size_t k = 0; k < info(q).inputs.size(); ++k) {
      if (std::isfinite(r.in[k]) && !std::isfinite(in[k]))
        throw invalid_input(info(q).inputs[k] + " is beyond the range of float (" + hexfloat(r.in[k]) + ")");
      if (r.in[k] != 0 && in[k] == 0)
        throw invalid_input(info(q).inputs[k] + " underflows: it is below the range of float and would round to 0 (" +
                            hexfloat(r.in[k]) + ")");
    }
  }
  // the fast oracle: the exact answer (its equality with the exact path is tested); the
  // classification alone from the classification oracle (it refuses what the exact types
  // refuse, by the same names: the fuzz targets check both)
  return values ? oracle_truth(q, in, precision) : oracle_classify(q, in);
}

namespace {

std::vector<CaseRow> read_cases(Query q, const std::string& path, int& bad,
                                std::vector<std::uint64_t>* skipped = nullptr) {
  std::ifstream f;
  return parse_cases(q, open_in(path, f, "the case file"), path, bad, skipped);
}

std::string query_list() {
  std::string s;
  for (Query q : all_queries()) s += (s.empty() ? "" : ", ") + std::string(info(q).name);
  return s;
}

// ---- cases ----
struct CasesOptions {
  std::string query, describe, out;
  std::vector<std::string> families, scales;
  std::uint64_t n = 100, seed = 1;
  bool decimal = false;
};

int describe_query(const std::string& name) {
  const Query q = query_by_name(name);
  const QueryInfo& qi = info(q);
  std::cout << qi.name << ": " << qi.describe << "\n\ncase file columns: case";
  for (const auto& c : qi.inputs) std::cout << "," << c;
  std::cout << "\n(family and scale columns, when present, are ignored on reading)\n\nanswer file columns: case";
  for (const auto& c : answer_columns(q)) std::cout << "," << c.name;
  std::cout << "\n  " << qi.cls_name << ": 1/0, the full query's classification (" << qi.full_call
            << ")\n  predicate: 1/0, the other formulation of the classification (" << qi.pred_name << ")\n"
            << qi.answer_help;
  std::cout << "An answer file may give any subset of these columns; only those are graded. For `cdref score` it\n"
               "may also give set_apart (1/0): cases where your documented convention gives another meaning,\n"
               "counted and not graded.\n";
  return 0;
}

int cases_run(const CasesOptions& o) {
  if (!o.describe.empty()) {
    if (!o.query.empty() || !o.families.empty() || !o.scales.empty() || !o.out.empty())
      throw std::invalid_argument("--describe Q takes no other option");
    return describe_query(o.describe);
  }
  if (o.query.empty()) throw std::invalid_argument("cases needs --query Q (or --describe Q)");
  const Query q = query_by_name(o.query);
  const QueryInfo& qi = info(q);
  // the cells: each chosen family at each chosen scale
  std::vector<const Family*> fams;
  const bool all_families = std::find(o.families.begin(), o.families.end(), "all") != o.families.end();
  if (all_families && o.families.size() > 1) throw std::invalid_argument("--family all takes no other family");
  if (all_families)
    for (const Family& f : families(q)) fams.push_back(&f);
  for (const std::string& name : o.families)
    if (name != "all") {
      const Family* f = &family_by_name(q, name);
      if (std::find(fams.begin(), fams.end(), f) != fams.end())
        throw std::invalid_argument("--family " + name + " is given twice");
      fams.push_back(f);
    }
  if (fams.empty()) fams.push_back(&family_by_name(q, "uniform"));
  const bool all_scales = std::find(o.scales.begin(), o.scales.end(), "all") != o.scales.end();
  if (all_scales && o.scales.size() > 1) throw std::invalid_argument("--scale all takes no other scale");
  std::vector<std::pair<const Family*, int>> cells;
  for (const Family* f : fams) {
    if (o.scales.empty()) cells.push_back({f, f->scales.front()});
    if (all_scales)
      for (int k : f->scales) cells.push_back({f, k});
    else
      for (const std::string& s : o.scales) {
        const int k = std::stoi(s);  // checked by the option's validator
        if (std::find(f->scales.begin(), f->scales.end(), k) == f->scales.end()) {
          std::string list;
          for (int j : f->scales) {
            if (!list.empty()) list += ' ';
            list += std::to_string(j);
          }
          throw std::invalid_argument("--scale " + s + ": family " + f->name + " of " + qi.name +
                                      " has the scales " + list + " (or --scale all)");
        }
        for (const auto& c : cells)
          if (c.first == f && c.second == k) throw std::invalid_argument("--scale " + s + " is given twice");
        cells.push_back({f, k});
      }
  }
  io::Output out(o.out.empty() ? "-" : o.out, "the case file");
  std::ostream& os = out.stream();
  os << "case,family,scale";
  for (const auto& c : qi.inputs) os << "," << c;
  os << "\n";
  std::uint64_t id = 0;  // ids run on across the cells: every case of the file has its own
  for (const auto& [fam, scale] : cells)
    for (std::uint64_t i = 0; i < o.n && !(out.is_stdout() && io::stdout_closed()); ++i, ++id) {
      const Inputs in = make_case(o.seed, q, *fam, scale, i);
      os << id << "," << fam->name << "," << scale;
      for (std::size_t k = 0; k < qi.inputs.size(); ++k) os << "," << fmt_real(in[k], o.decimal);
      os << "\n";
    }
  out.commit();
  return 0;
}

// ---- oracle ----
struct OracleOptions {
  std::string query, cases = "-", out, outputs = "all";
  int precision = 53;
  bool decimal = false;
};

int oracle_run(const OracleOptions& o) {
  const Query q = query_by_name(o.query);
  const bool values = o.outputs == "all";
  io::Output out(o.out.empty() ? "-" : o.out, "the answer file");
  int bad = 0;
  const auto rows = read_cases(q, o.cases, bad);
  auto cols = answer_columns(q);
  if (!values) cols.erase(std::remove_if(cols.begin(), cols.end(), [](const auto& c) { return c.kind == 2; }), cols.end());
  std::ostream& os = out.stream();
  os << "case";
  for (const auto& c : cols) os << "," << c.name;
  os << "\n";
  for (const CaseRow& r : rows) {
    if (out.is_stdout() && io::stdout_closed()) break;
    // at precision 24 the answer is for the inputs rounded to float, as a float
    // implementation receives them
    Answer t;
    try {
      t = answer_case(q, r, o.precision, values);
    } catch (const invalid_input& e) {
      std::cerr << "case " << r.id << ": " << e.what() << "; no answer\n";
      ++bad;
      continue;
    }
    os << r.id;
    for (const auto& c : cols)
      os << "," << (c.kind == 0 ? std::to_string(int(t.cls)) : c.kind == 1 ? std::to_string(int(t.pred))
                                                                             : fmt_answer(t.v[c.index], o.decimal, o.precision));
    os << "\n";
  }
  out.commit();
  return bad ? 1 : 0;
}

// ---- score ----
struct ScoreOptions {
  std::string query, cases, answers, json, csv;
  int precision = 53;
  std::optional<std::uint64_t> max_ulps;
  std::optional<double> max_abs, max_rel;
  std::uint64_t examples = 3;
};

// One graded case of a column, kept as an example.
struct Example {
  std::uint64_t id = 0;
  long double given = 0, exact = 0;
  std::uint64_t ulps = 0;
  double abs = 0, rel = 0;
  Inputs in{};
};

struct ColumnScore {
  std::uint64_t graded = 0, fp = 0, fn = 0, nonfinite = 0, beyond = 0;
  Histogram hist;
  std::uint64_t max_ulps = 0;
  double max_abs = 0, max_rel = 0;
  std::vector<Example> examples;  // the worst failures (or, with no failure, the worst cases)
  void keep(const Example& e, std::size_t k) {
    examples.push_back(e);
    std::sort(examples.begin(), examples.end(), [](const Example& a, const Example& b) {
      return a.ulps != b.ulps ? a.ulps > b.ulps : a.id < b.id;
    });
    if (examples.size() > k) examples.resize(k);
  }
};

// A count of ulps for a table column: whole up to 10^7, then with three digits (a value
// against an exact 0 is some 10^18 ulps away: its absolute error says what it is).
std::string ulps_text(std::uint64_t u) {
  char b[32];
  if (u < 10000000)
    std::snprintf(b, sizeof b, "%llu", (unsigned long long)u);
  else
    std::snprintf(b, sizeof b, "%.3g", double(u));
  return b;
}

std::string num(long double x) {
  char b[64];
  std::snprintf(b, sizeof b, "%.17Lg", x);
  return b;
}

int score_run(const ScoreOptions& o) {
  const Query q = query_by_name(o.query);
  const QueryInfo& qi = info(q);
  const int precision = o.precision;
  std::optional<io::Output> json_out, csv_out;  // opened first: a bad path is refused before the work
  if (!o.json.empty()) json_out.emplace(o.json, "--json");
  if (!o.csv.empty()) csv_out.emplace(o.csv, "--csv");
  int bad = 0;
  std::vector<std::uint64_t> skipped;  // malformed case lines (reported): their answers are not graded
  const auto rows = read_cases(q, o.cases, bad, &skipped);
  std::map<std::uint64_t, std::size_t> case_at;
  for (std::size_t i = 0; i < rows.size(); ++i) case_at[rows[i].id] = i;
  const std::set<std::uint64_t> skipped_ids(skipped.begin(), skipped.end());

  // the answers: a header naming each column once, then one line per case id
  std::ifstream af;
  std::istream& ain = open_in(o.answers, af, "the answer file");
  const auto all_cols = answer_columns(q);
  constexpr int id_column = -1, set_apart_column = -3;
  std::vector<int> given;  // answer-file column -> index in all_cols (or id_column, set_apart_column)
  struct Line {
    int lineno;
    std::vector<std::string> cells;
  };
  std::map<std::uint64_t, Line> answers;
  std::string line;
  int lineno = 0;
  bool header = false;
  std::size_t id_at = 0;
  int set_apart_at = -1;
  auto at = [&](int l) { return o.answers + ":" + std::to_string(l) + ": "; };
  while (std::getline(ain, line)) {
    ++lineno;
    if (const std::string raw = raw_line_problem(line, lineno); !raw.empty()) {
      if (!header) throw std::runtime_error(at(lineno) + "the line " + raw);
      std::cerr << at(lineno) << "the line " << raw << "; line skipped\n";
      ++bad;
      continue;
    }
    if (line.empty() || line[0] == '#' || line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const auto cells = split(line);
    if (!header) {
      header = true;
      bool has_id = false;
      for (std::size_t c = 0; c < cells.size(); ++c) {
        for (std::size_t d = 0; d < c; ++d)
          if (cells[d] == cells[c])
            throw std::runtime_error(at(lineno) + "the header names column '" + cells[c] + "' twice (columns " +
                                     std::to_string(d + 1) + " and " + std::to_string(c + 1) + ")");
        int idx = -2;
        if (cells[c] == "case") idx = id_column, has_id = true, id_at = c;
        if (cells[c] == "set_apart") idx = set_apart_column, set_apart_at = int(c);
        for (std::size_t k = 0; k < all_cols.size(); ++k)
          if (all_cols[k].name == cells[c]) idx = int(k);
        if (idx == -2)
          throw std::runtime_error(at(lineno) + "unknown answer column '" + cells[c] + "' (see cdref cases --describe " +
                                   qi.name + ")");
        given.push_back(idx);
      }
      if (!has_id) throw std::runtime_error(at(lineno) + "the header has no 'case' column");
      continue;
    }
    if (cells.size() != given.size()) {
      std::cerr << at(lineno) << "expected " << given.size() << " fields, found " << cells.size() << "; line skipped\n";
      ++bad;
      continue;
    }
    std::uint64_t id = 0;
    if (const std::string e = parse_id(cells[id_at], id); !e.empty()) {
      std::cerr << at(lineno) << "case id '" << cells[id_at] << "' " << e << "; line skipped\n";
      ++bad;
      continue;
    }
    // an answer given twice, or for a case the case file does not have, makes the grade
    // depend on which line is read: the file is refused
    if (const auto it = answers.find(id); it != answers.end())
      throw std::runtime_error(at(lineno) + "case " + cells[id_at] + " is answered twice (also on line " +
                               std::to_string(it->second.lineno) + ")");
    if (!case_at.count(id) && !skipped_ids.count(id))
      throw std::runtime_error(at(lineno) + "case " + cells[id_at] + " is not in the case file " + o.cases);
    answers[id] = {lineno, cells};
  }
  if (ain.bad()) throw std::runtime_error("cannot read the answer file " + o.answers + ": a read failed");
  if (!header) throw std::runtime_error(o.answers + ": no header line");
  bool values = false;  // the exact values are needed only when the answer file gives some
  for (int idx : given) values = values || (idx >= 0 && all_cols[idx].kind == 2);
  const bool bounded = o.max_ulps || o.max_abs || o.max_rel;

  std::map<int, ColumnScore> stats;
  std::uint64_t unanswered = 0, graded_cases = 0, set_apart = 0;
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
    const std::vector<std::string>& cells = it->second.cells;
    // their classification, if given, gates the values of a cast
    std::optional<bool> their_hit;
    std::string problem;
    std::vector<long double> vals(cells.size());
    for (std::size_t c = 0; c < given.size() && problem.empty(); ++c) {
      if (given[c] == id_column) continue;
      const std::string& cell = cells[c];
      if (given[c] == set_apart_column || all_cols[given[c]].kind < 2) {
        if (cell == "1" || cell == "true") vals[c] = 1;
        else if (cell == "0" || cell == "false") vals[c] = 0;
        else problem = (given[c] == set_apart_column ? std::string("set_apart") : all_cols[given[c]].name) + " '" + cell + "' is not 0 or 1";
        if (given[c] >= 0 && all_cols[given[c]].kind == 0) their_hit = vals[c] != 0;
      } else if (const std::string e = parse_real(cell, vals[c]); !e.empty()) {
        problem = all_cols[given[c]].name + " '" + cell + "' " + e;
      }
    }
    if (!problem.empty()) {
      std::cerr << at(it->second.lineno) << "case " << r.id << ": " << problem << "; case skipped\n";
      ++bad;
      continue;
    }
    if (set_apart_at >= 0 && vals[std::size_t(set_apart_at)] != 0) {
      ++set_apart;
      continue;
    }
    ++graded_cases;
    for (std::size_t c = 0; c < given.size(); ++c) {
      if (given[c] < 0) continue;
      const Column& col = all_cols[given[c]];
      ColumnScore& cs = stats[given[c]];
      if (col.kind < 2) {
        const bool want = col.kind == 0 ? t.cls : t.pred, got = vals[c] != 0;
        ++cs.graded;
        if (got != want) {
          ++(got ? cs.fp : cs.fn);
          if (cs.examples.size() < o.examples) cs.examples.push_back({r.id, got ? 1.0L : 0.0L, want ? 1.0L : 0.0L, 0, 1, 1, in});
        }
        continue;
      }
      // a cast's values exist only on a hit, a separating axis only on a miss: graded where
      // both the truth and the answer (when it gives its classification) say so
      const Output& out = qi.outputs[col.group];
      if (out.when == Output::on_hit && !(t.cls && their_hit.value_or(true))) continue;
      if (out.when == Output::on_miss && !(!t.cls && !their_hit.value_or(false))) continue;
      ++cs.graded;
      const long double want = t.v[col.index], got = vals[c];
      if (!std::isfinite(got) && std::isfinite(want)) {
        ++cs.nonfinite;
        cs.keep({r.id, got, want, ~std::uint64_t(0), INFINITY, INFINITY, in}, o.examples);
        continue;
      }
      Example e{r.id, got, want, 0, 0, 0, in};
      e.ulps = out.label ? std::uint64_t(got != want) : ulp_distance(got, want, precision);
      e.abs = double(std::fabs(got - want));
      e.rel = out.label ? e.abs : e.abs / natural_scale(q, col.group, in);
      cs.hist.add(e.ulps);
      cs.max_ulps = std::max(cs.max_ulps, e.ulps);
      cs.max_abs = std::max(cs.max_abs, e.abs);
      cs.max_rel = std::max(cs.max_rel, e.rel);
      const bool within = !bounded || (o.max_ulps && e.ulps <= *o.max_ulps) || (o.max_abs && e.abs <= *o.max_abs) ||
                          (o.max_rel && e.rel <= *o.max_rel);
      if (!within) ++cs.beyond;
      if (!within || (!bounded && e.ulps > 0)) cs.keep(e, o.examples);
    }
  }

  // the verdict: misclassified cases, non-finite values, and values beyond every bound given
  std::uint64_t failures = 0;
  for (const auto& [k, cs] : stats) failures += cs.fp + cs.fn + cs.nonfinite + cs.beyond;
  const char* type = precision == 24 ? "float" : (precision == 53 ? "double" : "long double");
  std::string bounds;
  if (o.max_ulps) bounds += " --max-ulps " + std::to_string(*o.max_ulps);
  if (o.max_abs) bounds += " --max-abs " + num(*o.max_abs);
  if (o.max_rel) bounds += " --max-rel " + num(*o.max_rel);

  // (with --json - or --csv -, standard output is the data's: the table goes to standard error)
  std::ostream& os = o.json == "-" || o.csv == "-" ? std::cerr : std::cout;
  os << "cdref score: " << qi.name << ", " << rows.size() << " cases, " << graded_cases << " answered and graded, "
     << unanswered << " unanswered, " << bad << " malformed or refused, " << set_apart
     << " set apart by the answers' convention; errors in ulps of " << type
     << ", absolute, and relative to the inputs' scale, against the correctly rounded exact answer\n\n";
  char buf[512];
  std::snprintf(buf, sizeof buf, "%-16s %8s %9s %7s %8s %8s %10s %10s %10s %8s\n", "column", "graded", "wrong",
                "nonfin", "p50", "p99", "max ulps", "max abs", "max rel", "beyond");
  os << buf;
  for (const auto& [k, cs] : stats) {
    const Column& col = all_cols[k];
    const std::string wrong = col.kind < 2 ? std::to_string(cs.fp) + "/" + std::to_string(cs.fn) : "-";
    if (col.kind < 2)
      std::snprintf(buf, sizeof buf, "%-16s %8llu %9s %7s %8s %8s %10s %10s %10s %8s\n", col.name.c_str(),
                    (unsigned long long)cs.graded, wrong.c_str(), "-", "-", "-", "-", "-", "-", "-");
    else
      std::snprintf(buf, sizeof buf, "%-16s %8llu %9s %7llu %8s %8s %10s %10.3g %10.3g %8s\n", col.name.c_str(),
                    (unsigned long long)cs.graded, wrong.c_str(), (unsigned long long)cs.nonfinite,
                    ulps_text(cs.hist.quantile(0.5)).c_str(), ulps_text(cs.hist.quantile(0.99)).c_str(),
                    ulps_text(cs.max_ulps).c_str(), cs.max_abs, cs.max_rel, bounded ? std::to_string(cs.beyond).c_str() : "-");
    os << buf;
  }
  os << "(wrong: false positives/false negatives of a classification; beyond: values outside every bound given)\n";
  if (qi.mesh_level)
    for (const auto& [k, cs] : stats)
      if (all_cols[k].kind == 0)
        os << "leaks (the exact shot meets the fan, the answer hits none of its triangles): " << cs.fn
           << "; phantom hits: " << cs.fp << "\n";
  bool any_example = false;
  for (const auto& [k, cs] : stats) {
    if (cs.examples.empty()) continue;
    if (!any_example) os << "\n" << (failures ? "failures" : "largest errors") << " (inputs as the implementation receives them):\n";
    any_example = true;
    const Column& col = all_cols[k];
    for (const Example& e : cs.examples) {
      os << "  " << col.name << ", case " << e.id << ": given " << num(e.given) << ", exact " << num(e.exact);
      if (col.kind == 2) os << " (" << (e.ulps == ~std::uint64_t(0) ? std::string("not finite") : std::to_string(e.ulps) + " ulps, abs " + num(e.abs) + ", rel " + num(e.rel)) << ")";
      os << "\n   ";
      for (std::size_t i = 0; i < qi.inputs.size(); ++i) os << " " << qi.inputs[i] << "=" << num(e.in[i]);
      os << "\n";
    }
  }
  const std::string what = std::string("misclassified, not finite") + (bounded ? " or beyond" + bounds : "");
  if (failures)
    os << "\nFAIL: " << failures << " graded value" << (failures == 1 ? " is " : "s are ") << what << "\n";
  else
    os << "\nPASS: no graded value is " << what << "\n";

  // the same as JSON and CSV
  auto column_json = [&](int k, const ColumnScore& cs) {
    const Column& col = all_cols[k];
    nlohmann::json j = {{"column", col.name}, {"graded", cs.graded}};
    if (col.kind < 2) {
      j["false_positives"] = cs.fp;
      j["false_negatives"] = cs.fn;
    } else {
      j["nonfinite"] = cs.nonfinite;
      j["p50_ulps"] = cs.hist.quantile(0.5);
      j["p99_ulps"] = cs.hist.quantile(0.99);
      j["max_ulps"] = cs.max_ulps;
      j["max_abs"] = cs.max_abs;
      j["max_rel"] = cs.max_rel;
      if (bounded) j["beyond"] = cs.beyond;
    }
    nlohmann::json ex = nlohmann::json::array();
    for (const Example& e : cs.examples) {
      nlohmann::json x = {{"case", e.id}, {"given", double(e.given)}, {"exact", double(e.exact)}};
      if (col.kind == 2 && e.ulps != ~std::uint64_t(0)) x["ulps"] = e.ulps, x["abs"] = e.abs, x["rel"] = e.rel;
      nlohmann::json inputs = nlohmann::json::object();
      for (std::size_t i = 0; i < qi.inputs.size(); ++i) inputs[qi.inputs[i]] = e.in[i];
      x["inputs"] = inputs;
      ex.push_back(x);
    }
    j["examples"] = ex;
    return j;
  };
  io::Outputs all;
  if (json_out) all.attempt([&] {
      nlohmann::json j = {{"query", qi.name}, {"precision", precision}, {"cases", rows.size()},
                          {"graded", graded_cases}, {"unanswered", unanswered}, {"malformed_or_refused", bad},
                          {"set_apart", set_apart}, {"failures", failures}, {"pass", failures == 0}};
      nlohmann::json b = nlohmann::json::object();
      if (o.max_ulps) b["max_ulps"] = *o.max_ulps;
      if (o.max_abs) b["max_abs"] = *o.max_abs;
      if (o.max_rel) b["max_rel"] = *o.max_rel;
      j["bounds"] = b;
      nlohmann::json cols = nlohmann::json::array();
      for (const auto& [k, cs] : stats) cols.push_back(column_json(k, cs));
      j["columns"] = cols;
      json_out->stream() << j.dump(1) << "\n";
      json_out->commit();
    });
  if (csv_out) all.attempt([&] {
      std::ostream& c = csv_out->stream();
      c << "query,column,graded,false_positives,false_negatives,nonfinite,p50_ulps,p99_ulps,max_ulps,max_abs,max_rel,"
           "beyond,worst_case\n";
      for (const auto& [k, cs] : stats) {
        const bool cls = all_cols[k].kind < 2;
        c << qi.name << "," << all_cols[k].name << "," << cs.graded << ",";
        if (cls)
          c << cs.fp << "," << cs.fn << ",,,,,,,,";
        else
          c << ",," << cs.nonfinite << "," << cs.hist.quantile(0.5) << "," << cs.hist.quantile(0.99) << ","
            << cs.max_ulps << "," << num(cs.max_abs) << "," << num(cs.max_rel) << "," << (bounded ? std::to_string(cs.beyond) : "") << ",";
        c << (cs.examples.empty() ? "" : std::to_string(cs.examples.front().id)) << "\n";
      }
      csv_out->commit();
    });
  all.finish();
  return failures || bad ? 1 : 0;
}

}  // namespace

void add_case_commands(Program& program) {
  auto co = std::make_shared<CasesOptions>();
  program
      .add("cases", "write case inputs as CSV (hex-float exact; --decimal: 17 digits, also exact)",
           [co] { return cases_run(*co); })
      .query("--query", co->query, "the query: " + query_list())
      .texts("--family", co->families, "a family of the query (repeatable, or all; default uniform; see cdref describe)")
      .scales("--scale", co->scales, "a scale of the families (repeatable, or all; default: each family's first)")
      .whole("--n", co->n, 1, 100000000, "cases per (family, scale) (default 100)")
      .whole("--seed", co->seed, 0, UINT64_MAX, "the seed (default 1)")
      .flag("--decimal", co->decimal, "decimal with 17 significant digits instead of hex-float")
      .text("--out", co->out, "the file to write (default: standard output)")
      .query("--describe", co->describe, "print the case and answer columns of this query instead")
      .excludes({"--query", "--family", "--scale", "--n", "--seed", "--decimal", "--out"});

  auto oo = std::make_shared<OracleOptions>();
  program.add("oracle", "the exact answers to a case file, correctly rounded", [oo] { return oracle_run(*oo); })
      .query("--query", oo->query, "the query: " + query_list())
      .required()
      .text("--cases", oo->cases, "the case file (default: standard input)")
      .choice("--precision", oo->precision, {24, 53, 64},
              "24: for the inputs rounded to float, as float; 53 (default): double; 64: long double")
      .choice("--outputs", oo->outputs, {"all", "cls"}, "all (default), or cls: the classification columns alone")
      .flag("--decimal", oo->decimal, "decimal (17 or 21 significant digits) instead of hex-float")
      .text("--out", oo->out, "the file to write (default: standard output)");

  auto so = std::make_shared<ScoreOptions>();
  program
      .add("score",
           "grade an answer file (any subset of the answer columns, see cases --describe) against the exact answer; "
           "exit status 0 when nothing graded is wrong, 1 when a case is misclassified, not finite, beyond every bound "
           "given, malformed or refused, 2 when the files cannot be used",
           [so] { return score_run(*so); })
      .query("--query", so->query, "the query: " + query_list())
      .required()
      .text("--cases", so->cases, "the case file")
      .required()
      .text("--answers", so->answers, "the answer file")
      .required()
      .choice("--precision", so->precision, {24, 53, 64}, "the answers' type: 24 float, 53 double (default), 64 long double")
      .whole("--max-ulps", so->max_ulps, 0, UINT64_MAX, "a value within this many ulps passes")
      .real("--max-abs", so->max_abs, 0, 1e308, "a value within this absolute error passes")
      .real("--max-rel", so->max_rel, 0, 1e308, "a value within this error relative to the inputs' scale passes")
      .whole("--examples", so->examples, 0, 1000, "failing cases shown per column (default 3)")
      .text("--json", so->json, "write the grades as JSON to this file (- for standard output)")
      .text("--csv", so->csv, "write the grades as CSV to this file (- for standard output)");
}

}  // namespace cdref::cli
