// src/costreport.cpp - `cdref report`: what accuracy costs in time, measured side by side in
// one run, for every query of Sections 3.1-3.2 the campaign engine runs.
//
// Rows (each answers the same prepared inputs; a row that computes a query's outputs asks
// for all of them):
//   book at float, double (all outputs, and the classification alone: book::hit or
//   book::intersect), long double, MPFR-128 and MPFR-256; robust at float, double and long
//   double; the oracle (the classification alone, and every output correctly rounded); the
//   book at CGAL::Gmpq, CGAL::Epeck::FT and CORE::Expr (the query and its first output
//   rounded correctly to double); CGAL's own do_intersect in its filtered (Epick) and exact
//   (Epeck) kernels, classification only, translated to closed solids as the cross-check
//   test does (tests/test_cgal_crosscheck.cpp: CGAL's sphere pairs test surfaces).
// Columns: nanoseconds per query (median of interleaved repetitions over the same inputs, one
// thread), ratio to the book at double, and for the rows the campaign engine runs: the share
// misclassified on the uniform family and on the query's hard families (every other family),
// and the p99 and max error in ulps of the row's type of the first output (lambda_enter or
// distance) over all families. Exact rows and the oracle have no error by construction (the
// oracle's equality with the exact path is tested); MPFR's error is not measured here.
// Output: the table, and on request CSV, JSON and an SVG of cost against error (log-log, one
// point per row, one panel per query; gnuplot).
#include <cdref/exact/cgal_kernels.hpp>

#include <algorithm>
#include <cdref/exact.hpp>
#include <cdref/float/mpfr.hpp>
#include <cdref/fuzz/campaign.hpp>
#include <cdref/fuzz/eval.hpp>
#include <cdref/fuzz/primitives_of.hpp>
#include <cdref/robust/box_box.hpp>
#include <cdref/robust/ray_box.hpp>
#include <cdref/robust/ray_sphere.hpp>
#include <cdref/robust/segment_sphere.hpp>
#include <cdref/robust/sphere_box.hpp>
#include <cdref/robust/sphere_sphere.hpp>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "casefiles.hpp"

namespace cdref::cli {

using namespace cdref::fuzz;

namespace {

// The primitives of each query, in the column order of the campaign's case files.
template <class T>
struct Pair2 {
  std::vector<Sphere<T>> sa;
  std::vector<Segment<T>> seg;
  std::vector<Ray<T>> ray;
  std::vector<Box<T>> ba;
  std::vector<Sphere<T>> sb;
  std::vector<Box<T>> bb;
};

template <class T> void keep(Pair2<T>& p, const Sphere<T>& x, bool first) { (first ? p.sa : p.sb).push_back(x); }
template <class T> void keep(Pair2<T>& p, const Box<T>& x, bool first) { (first ? p.ba : p.bb).push_back(x); }
template <class T> void keep(Pair2<T>& p, const Segment<T>& x, bool) { p.seg.push_back(x); }
template <class T> void keep(Pair2<T>& p, const Ray<T>& x, bool) { p.ray.push_back(x); }

template <class T>
std::shared_ptr<Pair2<T>> prepare(Query q, const std::vector<Inputs>& cases) {
  auto p = std::make_shared<Pair2<T>>();
  for (const Inputs& in : cases)
    with_primitives<T>(q, in, [&p](const auto& a, const auto& b, bool) {
      keep(*p, a, true);
      keep(*p, b, false);
      return 0;
    });
  return p;
}

// What a row does with case k: Mode::full computes every output, Mode::classify the
// classification alone (book::hit / book::intersect); Mode::first_rounded computes every
// output and rounds the first correctly to double (exact types).
enum class Mode { full, classify, first_rounded };

template <class X>
double first_rounded(const X& x) {
  return round_double(x);
}

// The book (namespace B = book) or the robust versions (B = robust) on prepared case k.
#define CDREF_REPORT_DISPATCH(NS)                                                                        \
  template <class T>                                                                                   \
  bool NS##_run(Query q, const Pair2<T>& p, std::size_t k, Mode m) {                                   \
    switch (q) {                                                                                       \
      case Query::sphere_sphere:                                                                       \
        if (m == Mode::classify) return NS::intersect(p.sa[k], p.sb[k]);                               \
        return finish(NS::proximity(p.sa[k], p.sb[k]), m);                                             \
      case Query::segment_sphere_cast:                                                                 \
        if (m == Mode::classify) return NS::hit(p.seg[k], p.sb[k]);                                    \
        return finish(NS::cast(p.seg[k], p.sb[k]), m);                                                 \
      case Query::ray_sphere_cast:                                                                     \
        if (m == Mode::classify) return NS::hit(p.ray[k], p.sb[k]);                                    \
        return finish(NS::cast(p.ray[k], p.sb[k]), m);                                                 \
      case Query::segment_sphere:                                                                      \
        if (m == Mode::classify) return NS::intersect(p.seg[k], p.sb[k]);                              \
        return finish(NS::proximity(p.seg[k], p.sb[k]), m);                                            \
      case Query::box_box:                                                                             \
        return NS::intersect(p.ba[k], p.bb[k]);                                                        \
      case Query::segment_box_cast:                                                                    \
        if (m == Mode::classify) return NS::hit(p.seg[k], p.bb[k]);                                    \
        return finish(NS::cast(p.seg[k], p.bb[k]), m);                                                 \
      case Query::ray_box_cast:                                                                        \
        if (m == Mode::classify) return NS::hit(p.ray[k], p.bb[k]);                                    \
        return finish(NS::cast(p.ray[k], p.bb[k]), m);                                                 \
      case Query::sphere_box:                                                                          \
        if (m == Mode::classify) return NS::intersect(p.sa[k], p.bb[k]);                               \
        return finish(NS::proximity(p.sa[k], p.bb[k]), m);                                             \
    }                                                                                                  \
    return false;                                                                                      \
  }

template <class S>
bool finish(const Cast<S>& c, Mode m) {
  if (m == Mode::first_rounded) return c.hit != (first_rounded(c.lambda_enter) < 0);  // never negative
  return c.hit;
}
template <class S>
bool finish(const Proximity<S>& p, Mode m) {
  if (m == Mode::first_rounded) return p.intersect != (first_rounded(p.distance) < 0);  // never negative
  return p.intersect;
}

CDREF_REPORT_DISPATCH(book)
CDREF_REPORT_DISPATCH(robust)
#undef CDREF_REPORT_DISPATCH

// CGAL's kernels, classification in closed-solid semantics.
template <class K>
struct CgalCases {
  std::vector<typename K::Sphere_3> sa, sb;
  std::vector<typename K::Segment_3> seg;
  std::vector<typename K::Ray_3> ray;
  std::vector<typename K::Iso_cuboid_3> ba, bb;
};

template <class K>
std::shared_ptr<CgalCases<K>> prepare_cgal(Query q, const std::vector<Inputs>& cases) {
  using FT = typename K::FT;
  using P = typename K::Point_3;
  auto pt = [](const Inputs& in, int i) { return P(FT(in[i]), FT(in[i + 1]), FT(in[i + 2])); };
  auto sphere = [&](const Inputs& in, int c, int r) {
    const FT rho(in[r]);
    return typename K::Sphere_3(pt(in, c), rho * rho);  // CGAL takes the squared radius
  };
  auto cuboid = [](const Inputs& in, int c, int h) {
    FT lo[3], hi[3];
    for (int i = 0; i < 3; ++i) {
      lo[i] = FT(in[c + i]) - FT(in[h + i]);
      hi[i] = FT(in[c + i]) + FT(in[h + i]);
    }
    return typename K::Iso_cuboid_3(P(lo[0], lo[1], lo[2]), P(hi[0], hi[1], hi[2]));
  };
  auto p = std::make_shared<CgalCases<K>>();
  for (const Inputs& in : cases) {
    switch (q) {
      case Query::sphere_sphere:
        p->sa.push_back(sphere(in, 0, 3));
        p->sb.push_back(sphere(in, 4, 7));
        break;
      case Query::segment_sphere_cast:
      case Query::segment_sphere:
        p->seg.emplace_back(pt(in, 0), pt(in, 3));
        p->sb.push_back(sphere(in, 6, 9));
        break;
      case Query::ray_sphere_cast:
        p->ray.emplace_back(pt(in, 0), typename K::Vector_3(FT(in[3]), FT(in[4]), FT(in[5])));
        p->sb.push_back(sphere(in, 6, 9));
        break;
      case Query::box_box:
        p->ba.push_back(cuboid(in, 0, 3));
        p->bb.push_back(cuboid(in, 6, 9));
        break;
      case Query::segment_box_cast:
        p->seg.emplace_back(pt(in, 0), pt(in, 3));
        p->bb.push_back(cuboid(in, 6, 9));
        break;
      case Query::ray_box_cast:
        p->ray.emplace_back(pt(in, 0), typename K::Vector_3(FT(in[3]), FT(in[4]), FT(in[5])));
        p->bb.push_back(cuboid(in, 6, 9));
        break;
      case Query::sphere_box:
        p->sa.push_back(sphere(in, 0, 3));
        p->bb.push_back(cuboid(in, 4, 7));
        break;
    }
  }
  return p;
}

template <class K>
bool cgal_run(Query q, const CgalCases<K>& p, std::size_t k) {
  switch (q) {
    case Query::sphere_sphere:  // surfaces meet, or one centre inside the other ball
      return CGAL::do_intersect(p.sa[k], p.sb[k]) || p.sa[k].bounded_side(p.sb[k].center()) != CGAL::ON_UNBOUNDED_SIDE ||
             p.sb[k].bounded_side(p.sa[k].center()) != CGAL::ON_UNBOUNDED_SIDE;
    case Query::segment_sphere_cast:
    case Query::segment_sphere:  // the surface, or a segment inside the open ball
      return CGAL::do_intersect(p.seg[k], p.sb[k]) || p.sb[k].has_on_bounded_side(p.seg[k].source());
    case Query::ray_sphere_cast:
      return CGAL::do_intersect(p.ray[k], p.sb[k]);
    case Query::box_box:
      return CGAL::do_intersect(p.ba[k], p.bb[k]);
    case Query::segment_box_cast:
      return CGAL::do_intersect(p.seg[k], p.bb[k]);
    case Query::ray_box_cast:
      return CGAL::do_intersect(p.ray[k], p.bb[k]);
    case Query::sphere_box:
      return CGAL::do_intersect(p.sa[k], p.bb[k]);
  }
  return false;
}

struct Row {
  std::string name;
  std::string campaign_impl;  // the campaign implementation measuring its error ("" none)
  std::string error_note;     // shown when there is no campaign row
  std::function<bool(std::size_t)> run;  // evaluates prepared case k; returns the classification
  double ns = 0;
  bool hard = false;  // timed on the near-boundary cases instead of the uniform ones
  // errors, from the campaign
  bool measured = false;
  double miss_uniform = 0, miss_hard = 0;
  std::uint64_t p99 = 0, max = 0;
};

struct QueryReport {
  Query q;
  std::vector<Row> rows;
  double base = 0;  // book at double, all outputs
  std::size_t sink = 0;  // results of the near-boundary rows, kept so no row is optimized away
};

std::string pct(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g%%", 100 * x);
  return b;
}
std::string gnum(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", x);
  return b;
}

QueryReport measure(Query q, std::uint64_t n, int reps, std::uint64_t err_n, int threads) {
  const Family& uni = family_by_name(q, "uniform");
  std::vector<Inputs> cases;
  for (std::uint64_t i = 0; i < n; ++i) cases.push_back(make_case(1, q, uni, uni.scales.front(), i));

  auto pf = prepare<float>(q, cases);
  auto pd = prepare<double>(q, cases);
  auto pl = prepare<long double>(q, cases);
  auto pq = prepare<CGAL::Gmpq>(q, cases);
  auto pe = prepare<CGAL::Epeck::FT>(q, cases);
  auto px = prepare<CORE::Expr>(q, cases);
  auto ck = prepare_cgal<CGAL::Epick>(q, cases);
  auto ce = prepare_cgal<CGAL::Epeck>(q, cases);
  const bool values = !info(q).outputs.empty();
  const Mode full = values ? Mode::full : Mode::classify;

  QueryReport rep{q, {}, 0, 0};
  auto& rows = rep.rows;
  rows.push_back({"book float", "book-float", "", [=](std::size_t k) { return book_run(q, *pf, k, full); }});
  rows.push_back({"book double", "book-double", "", [=](std::size_t k) { return book_run(q, *pd, k, full); }});
  if (values)
    rows.push_back({"book double, classification", "", "as above",
                    [=](std::size_t k) { return book_run(q, *pd, k, Mode::classify); }});
  rows.push_back(
      {"book long double", "book-long-double", "", [=](std::size_t k) { return book_run(q, *pl, k, full); }});
  for (int bits : {128, 256}) {
    const mpfr_precision at{bits};  // inputs made at this precision
    auto pm = prepare<mpfr::mpreal>(q, cases);
    rows.push_back({"book MPFR-" + std::to_string(bits), "", "not measured", [=](std::size_t k) {
                      const mpfr_precision again{bits};  // and the constants it makes
                      return book_run(q, *pm, k, full);
                    }});
  }
  rows.push_back({"robust float", "robust-float", "", [=](std::size_t k) { return robust_run(q, *pf, k, full); }});
  rows.push_back({"robust double", "robust-double", "", [=](std::size_t k) { return robust_run(q, *pd, k, full); }});
  rows.push_back({"robust long double", "robust-long-double", "",
                  [=](std::size_t k) { return robust_run(q, *pl, k, full); }});
  rows.push_back({"oracle, classification", "", "exact", [q, &cases](std::size_t k) { return oracle_classify(q, cases[k]).cls; }});
  if (values)
    rows.push_back({"oracle, every output rounded", "", "exact",
                    [q, &cases](std::size_t k) { return oracle_truth(q, cases[k], 53).cls; }});
  // the oracle where its filters fail by nature: the query's near-boundary family at its
  // hardest scale (2^-52 from tangency or touching, or grazing edges and corners)
  const Family* hp = nullptr;
  for (const char* name : {"near-tangent", "near-touching", "grazing"})
    for (const Family& f : families(q))
      if (!hp && f.name == name) hp = &f;
  if (!hp) throw std::logic_error(std::string("no near-boundary family for ") + info(q).name);
  const Family& hard = *hp;
  std::vector<Inputs> hard_cases;
  for (std::uint64_t i = 0; i < std::max<std::uint64_t>(1, n / 4); ++i)
    hard_cases.push_back(make_case(1, q, hard, hard.scales.back(), i));
  const std::string hard_name = " (" + hard.name + " " + std::to_string(hard.scales.back()) + ")";
  rows.push_back({"oracle, classification" + hard_name, "", "exact",
                  [q, &hard_cases](std::size_t k) { return oracle_classify(q, hard_cases[k]).cls; }});
  rows.back().hard = true;
  if (values) {
    rows.push_back({"oracle, every output" + hard_name, "", "exact",
                    [q, &hard_cases](std::size_t k) { return oracle_truth(q, hard_cases[k], 53).cls; }});
    rows.back().hard = true;
  }
  const Mode exact_mode = values ? Mode::first_rounded : Mode::classify;
  rows.push_back({"book at Gmpq", "", "exact", [=](std::size_t k) { return book_run(q, *pq, k, exact_mode); }});
  rows.push_back({"book at Epeck::FT", "", "exact", [=](std::size_t k) { return book_run(q, *pe, k, exact_mode); }});
  rows.push_back({"book at CORE::Expr", "", "exact", [=](std::size_t k) { return book_run(q, *px, k, exact_mode); }});
  rows.push_back({"CGAL do_intersect, Epick", "", "exact", [=](std::size_t k) { return cgal_run(q, *ck, k); }});
  rows.push_back({"CGAL do_intersect, Epeck", "", "exact", [=](std::size_t k) { return cgal_run(q, *ce, k); }});

  // timing: every row over the same inputs, `reps` times, interleaved; the median per row.
  // Every row must agree with the oracle's classification on every input it times (the
  // uniform family keeps clear of the boundaries), so no row is timed doing less work.
  std::vector<char> want(cases.size());
  for (std::size_t k = 0; k < cases.size(); ++k) want[k] = oracle_classify(q, cases[k]).cls;
  std::vector<std::vector<double>> times(rows.size());
  std::size_t sink = 0;
  for (int r = 0; r < reps; ++r)
    for (std::size_t j = 0; j < rows.size(); ++j) {
      std::size_t disagree = 0;
      const std::size_t count = rows[j].hard ? hard_cases.size() : cases.size();
      const auto t0 = std::chrono::steady_clock::now();
      if (rows[j].hard)
        for (std::size_t k = 0; k < count; ++k) disagree += rows[j].run(k);  // (a count, not checked)
      else
        for (std::size_t k = 0; k < count; ++k) disagree += rows[j].run(k) != bool(want[k]);
      const auto t1 = std::chrono::steady_clock::now();
      if (disagree && !rows[j].hard && rows[j].campaign_impl.empty() && rows[j].error_note == "exact")
        throw std::logic_error(rows[j].name + " disagrees with the oracle on " + std::to_string(disagree) + " of " +
                               std::to_string(cases.size()) + " " + info(q).name + " cases");
      times[j].push_back(std::chrono::duration<double, std::nano>(t1 - t0).count() / double(count));
      if (rows[j].hard) sink += disagree;
    }
  for (std::size_t j = 0; j < rows.size(); ++j) {
    std::sort(times[j].begin(), times[j].end());
    rows[j].ns = times[j][times[j].size() / 2];
  }
  rep.base = rows[1].ns;
  rep.sink = sink;

  // accuracy: a campaign over every family of the query
  Spec spec;
  spec.queries = {q};
  spec.impls = {"book-float", "book-double", "book-long-double", "robust-float", "robust-double", "robust-long-double"};
  spec.n = err_n;
  spec.threads = threads;
  const Results res = run(spec);
  struct Acc {
    std::uint64_t nu = 0, wu = 0, nh = 0, wh = 0, max = 0;
    Histogram h;
  };
  std::map<std::string, Acc> acc;
  for (const auto& [key, st] : res.cells) {
    Acc& a = acc[key.impl];
    const std::uint64_t m = st.n - st.refused, w = st.cls_fp + st.cls_fn;
    if (key.family == "uniform") a.nu += m, a.wu += w;
    else a.nh += m, a.wh += w;
    for (int b = 0; b < Histogram::bins; ++b) a.h.count[b] += st.out[0].hist.count[b];
    if (st.out[0].worst.set) a.max = std::max(a.max, st.out[0].worst.metric);
  }
  for (Row& r : rows) {
    if (r.campaign_impl.empty()) continue;
    const Acc& a = acc.at(r.campaign_impl);
    r.measured = true;
    r.miss_uniform = double(a.wu) / double(std::max<std::uint64_t>(1, a.nu));
    r.miss_hard = double(a.wh) / double(std::max<std::uint64_t>(1, a.nh));
    r.p99 = a.h.quantile(0.99);
    r.max = a.max;
  }
  return rep;
}

const Row* find_row(const QueryReport& r, const std::string& name) {
  for (const Row& row : r.rows)
    if (row.name == name) return &row;
  return nullptr;
}

void print(std::ostream& o, const QueryReport& r) {
  const bool values = !info(r.q).outputs.empty();
  o << info(r.q).name << " (" << info(r.q).describe << ")\n";
  char line[320];
  std::snprintf(line, sizeof line, "  %-30s %10s %9s %14s %14s %12s %12s\n", "implementation", "ns/query", "x double",
                "miss uniform", "miss hard", values ? "p99 ulps" : "", values ? "max ulps" : "");
  o << line;
  for (const Row& row : r.rows) {
    std::string mu = row.error_note, mh = row.error_note, p99 = values ? row.error_note : "",
                mx = values ? row.error_note : "";
    if (row.measured) {
      mu = pct(row.miss_uniform);
      mh = pct(row.miss_hard);
      if (values) p99 = gnum(double(row.p99)), mx = gnum(double(row.max));
    }
    std::snprintf(line, sizeof line, "  %-30s %10.1f %9.2f %14s %14s %12s %12s\n", row.name.c_str(), row.ns,
                  row.ns / r.base, mu.c_str(), mh.c_str(), p99.c_str(), mx.c_str());
    o << line;
  }
  // the two targets the report exists to watch
  const Row* oc = find_row(r, "oracle, classification");
  const Row* bc = find_row(r, values ? "book double, classification" : "book double");
  const Row* oa = find_row(r, "oracle, every output rounded");
  const Row* rd = find_row(r, "robust double");
  std::snprintf(line, sizeof line, "  oracle classification / book double classification = %.2f", oc->ns / bc->ns);
  o << line;
  if (oa) {
    std::snprintf(line, sizeof line, "; oracle every output rounded / robust double = %.2f", oa->ns / rd->ns);
    o << line;
  }
  o << "\n\n";
}

std::string json_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out;
}

void write_json(std::ostream& o, const std::vector<QueryReport>& reps, std::uint64_t n, int reps_n, std::uint64_t err_n) {
  o << "{\"cdref_report\": 1, \"cases_timed\": " << n << ", \"repetitions\": " << reps_n
    << ", \"error_cases_per_cell\": " << err_n << ", \"queries\": [";
  for (std::size_t i = 0; i < reps.size(); ++i) {
    const QueryReport& r = reps[i];
    o << (i ? ", " : "") << "{\"query\": \"" << info(r.q).name << "\", \"rows\": [";
    for (std::size_t j = 0; j < r.rows.size(); ++j) {
      const Row& row = r.rows[j];
      o << (j ? ", " : "") << "{\"implementation\": \"" << json_escape(row.name) << "\", \"ns_per_query\": " << row.ns
        << ", \"ratio_to_book_double\": " << row.ns / r.base;
      if (row.measured)
        o << ", \"misclassified_uniform\": " << row.miss_uniform << ", \"misclassified_hard\": " << row.miss_hard
          << ", \"p99_ulps\": " << row.p99 << ", \"max_ulps\": " << row.max;
      else
        o << ", \"error\": \"" << json_escape(row.error_note) << "\"";
      o << "}";
    }
    o << "]}";
  }
  o << "]}\n";
}

void write_csv(std::ostream& o, const std::vector<QueryReport>& reps) {
  o << "query,implementation,ns_per_query,ratio_to_book_double,misclassified_uniform,misclassified_hard,p99_ulps,max_"
       "ulps\n";
  for (const QueryReport& r : reps)
    for (const Row& row : r.rows) {
      o << info(r.q).name << "," << row.name << "," << row.ns << "," << row.ns / r.base << ",";
      if (row.measured)
        o << row.miss_uniform << "," << row.miss_hard << "," << row.p99 << "," << row.max << "\n";
      else
        o << row.error_note << "," << row.error_note << "," << row.error_note << "," << row.error_note << "\n";
    }
}

// Cost against error, log-log, one panel per query and one point per row: x the time, y the
// max error of the first output in ulps (box-box: the share misclassified on the hard
// families). Exact rows (open circles, slanted labels) sit on the bottom line; MPFR's error
// is not measured and is left out.
void write_svg(const std::string& out, const std::vector<QueryReport>& reps) {
  const std::string dat = out + ".dat";
  {
    std::ofstream d(dat);
    for (std::size_t i = 0; i < reps.size(); ++i) {
      const bool values = !info(reps[i].q).outputs.empty();
      d << "# " << info(reps[i].q).name << ": name ns error exact\n";
      for (const Row& row : reps[i].rows) {
        if (!row.measured && row.error_note != "exact") continue;
        const double err = !row.measured ? 0 : values ? double(row.max) : row.miss_hard;
        const double floor = values ? 0.5 : 1e-5;
        d << "\"" << row.name << "\" " << row.ns << " " << std::max(err, floor) << " " << (row.measured ? 0 : 1)
          << "\n";
      }
      d << "\n\n";  // a gnuplot index per query
    }
  }
  FILE* gp = popen("gnuplot", "w");
  if (!gp) throw std::runtime_error("cannot run gnuplot (install gnuplot-nox)");
  const int cols = 2, nrows = int((reps.size() + cols - 1) / cols);
  std::fprintf(gp,
               "set terminal svg size 1200,%d dynamic font 'sans,10' background rgb 'white'\nset output '%s'\n"
               "set multiplot layout %d,%d title 'cdref report: cost against error (one point per implementation)'\n"
               "set logscale xy\nset grid\nset xlabel 'ns per query'\nset format y '10^{%%L}'\nunset key\n",
               420 * nrows, out.c_str(), nrows, cols);
  for (std::size_t i = 0; i < reps.size(); ++i) {
    const bool values = !info(reps[i].q).outputs.empty();
    std::fprintf(gp, "set title '%s'\nset ylabel '%s'\nset yrange [%s:*]\n", info(reps[i].q).name,
                 values ? "max error of the first output, ulps (exact: 0.5)" : "misclassified, hard families (exact: 1e-5)",
                 values ? "0.3" : "5e-6");
    std::fprintf(gp,
                 "plot '%s' index %zu u 2:($4 == 0 ? $3 : 1/0) w p pt 7 ps 0.8 lc 1, "
                 "'' index %zu u 2:($4 == 0 ? $3 : 1/0):1 w labels left offset 0.6,0 font ',7' noenhanced, "
                 "'' index %zu u 2:($4 == 1 ? $3 : 1/0) w p pt 6 ps 0.8 lc 2, "
                 "'' index %zu u 2:($4 == 1 ? $3 : 1/0):1 w labels rotate by 50 left offset 0.3,0.5 font ',6' "
                 "noenhanced tc lt 2\n",
                 dat.c_str(), i, i, i, i);
  }
  std::fprintf(gp, "unset multiplot\n");
  if (pclose(gp) != 0) throw std::runtime_error("gnuplot failed drawing " + out);
}

}  // namespace

int report_command(std::vector<std::string> args) {
  std::uint64_t n = 2000, err_n = 1000;
  int reps = 5;
  int threads = int(std::max(1u, std::thread::hardware_concurrency()));
  std::string csv, json, svg;
  std::vector<Query> queries;
  for (std::size_t i = 0; i < args.size(); ++i) {
    auto val = [&]() -> std::string {
      if (i + 1 >= args.size()) throw std::invalid_argument(args[i] + " needs a value");
      return args[++i];
    };
    if (args[i] == "--n") n = std::stoull(val());
    else if (args[i] == "--error-n") err_n = std::stoull(val());
    else if (args[i] == "--reps") reps = std::stoi(val());
    else if (args[i] == "--threads") threads = std::stoi(val());
    else if (args[i] == "--query") queries.push_back(query_by_name(val()));
    else if (args[i] == "--csv") csv = val();
    else if (args[i] == "--json") json = val();
    else if (args[i] == "--svg") svg = val();
    else throw std::invalid_argument("unknown option '" + args[i] + "'");
  }
  if (n == 0 || reps < 1 || err_n == 0) throw std::invalid_argument("report needs --n, --reps and --error-n of at least 1");
  if (queries.empty()) queries = all_queries();
  std::cout << "cdref report: " << n << " uniform cases timed per query, median of " << reps
            << " interleaved repetitions, one thread; errors from " << err_n
            << " cases per cell of every family (first output, ulps of the row's type).\n\n";
  std::vector<QueryReport> out;
  for (Query q : queries) {
    out.push_back(measure(q, n, reps, err_n, threads));
    print(std::cout, out.back());
    std::cout.flush();
  }
  auto write = [](const std::string& path, auto&& body) {
    std::ofstream f(path);
    body(f);
    if (!f) throw std::runtime_error("cannot write " + path);
    std::cout << "wrote " << path << "\n";
  };
  if (!csv.empty()) write(csv, [&](std::ostream& f) { write_csv(f, out); });
  if (!json.empty()) write(json, [&](std::ostream& f) { write_json(f, out, n, reps, err_n); });
  if (!svg.empty()) {
    write_svg(svg, out);
    std::cout << "wrote " << svg << " (data in " << svg << ".dat)\n";
  }
  std::size_t sink = 0;
  for (const QueryReport& r : out) sink += r.sink;
  return sink == std::size_t(-1) ? 1 : 0;
}

}  // namespace cdref::cli
