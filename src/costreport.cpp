// src/costreport.cpp - `cdref report`: what accuracy costs in time, measured side by side in
// one run. For now one query, the segment cast on a sphere (Algorithm 3.1); each row
// answers the same inputs:
//   book at float, double, long double, MPFR-128 and MPFR-256; robust at float, double, long
//   double; the oracle (classification alone, and every output correctly rounded); the book
//   at CGAL::Gmpq, CGAL::Epeck::FT and CORE::Expr (the cast and its lambda_enter rounded
//   correctly); CGAL's own do_intersect(Segment_3, Sphere_3) in its filtered (Epick) and
//   exact (Epeck) kernels (classification only; a segment inside the open ball counts as a
//   hit, as in cdref, through has_on_bounded_side of its source).
// Columns: nanoseconds per query (median of repetitions over the same prepared inputs),
// ratio to the book at double, and, for the rows the campaign engine runs, the share
// misclassified and the p99 / max error of lambda_enter in ulps of the row's type on the
// uniform, long-range and near-tangent families. The exact rows and the oracle have no
// error by construction (the oracle's equality with the exact path is tested); MPFR's error
// is not measured here.
#include <cdref/exact/cgal_kernels.hpp>

#include <algorithm>
#include <cdref/exact.hpp>
#include <cdref/float/mpfr.hpp>
#include <cdref/fuzz/campaign.hpp>
#include <cdref/robust/ray_sphere.hpp>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "casefiles.hpp"

namespace cdref::cli {

using namespace cdref::fuzz;

namespace {

struct Row {
  std::string name;
  std::string campaign_impl;  // the campaign implementation measuring its error ("" none)
  std::string error_note;     // shown when there is no campaign row
  std::function<bool(std::size_t)> run;  // evaluates prepared case k; returns the hit flag
  double ns = 0;
};

template <class T>
Segment<T> seg_of(const Inputs& in) {
  return {Vec3<T>(T(in[0]), T(in[1]), T(in[2])), Vec3<T>(T(in[3]), T(in[4]), T(in[5]))};
}
template <class T>
Sphere<T> sph_of(const Inputs& in) {
  return {Vec3<T>(T(in[6]), T(in[7]), T(in[8])), T(in[9])};
}

// Prepared inputs per type, so conversion is not timed.
template <class T>
struct Prepared {
  std::vector<Segment<T>> seg;
  std::vector<Sphere<T>> sph;
  explicit Prepared(const std::vector<Inputs>& cases) {
    for (const Inputs& in : cases) {
      seg.push_back(seg_of<T>(in));
      sph.push_back(sph_of<T>(in));
    }
  }
};

}  // namespace

int report_command(std::vector<std::string> args) {
  std::uint64_t n = 2000, err_n = 2000;
  int reps = 5;
  std::string csv, family = "uniform";
  for (std::size_t i = 0; i < args.size(); ++i) {
    auto val = [&]() -> std::string {
      if (i + 1 >= args.size()) throw std::invalid_argument(args[i] + " needs a value");
      return args[++i];
    };
    if (args[i] == "--n") n = std::stoull(val());
    else if (args[i] == "--error-n") err_n = std::stoull(val());
    else if (args[i] == "--reps") reps = std::stoi(val());
    else if (args[i] == "--family") family = val();
    else if (args[i] == "--csv") csv = val();
    else throw std::invalid_argument("unknown option '" + args[i] + "'");
  }
  const Query q = Query::segment_sphere_cast;
  const Family& fam = family_by_name(q, family);
  std::vector<Inputs> cases;
  for (std::uint64_t i = 0; i < n; ++i) cases.push_back(make_case(1, q, fam, fam.scales.front(), i));

  const Prepared<float> pf(cases);
  const Prepared<double> pd(cases);
  const Prepared<long double> pl(cases);
  const Prepared<CGAL::Gmpq> pq(cases);
  const Prepared<CGAL::Epeck::FT> pe(cases);
  const Prepared<CORE::Expr> px(cases);
  using Epick = CGAL::Epick;
  using Epeck = CGAL::Epeck;
  std::vector<Epick::Segment_3> ck_seg;
  std::vector<Epick::Sphere_3> ck_sph;
  std::vector<Epeck::Segment_3> ce_seg;
  std::vector<Epeck::Sphere_3> ce_sph;
  for (const Inputs& in : cases) {
    ck_seg.emplace_back(Epick::Point_3(in[0], in[1], in[2]), Epick::Point_3(in[3], in[4], in[5]));
    ck_sph.emplace_back(Epick::Point_3(in[6], in[7], in[8]), in[9] * in[9]);  // squared radius
    ce_seg.emplace_back(Epeck::Point_3(in[0], in[1], in[2]), Epeck::Point_3(in[3], in[4], in[5]));
    const Epeck::FT r(in[9]);
    ce_sph.emplace_back(Epeck::Point_3(in[6], in[7], in[8]), r * r);
  }
  std::vector<Row> rows;
  rows.push_back({"book float", "book-float", "", [&](std::size_t k) { return book::cast(pf.seg[k], pf.sph[k]).hit; }});
  rows.push_back({"book double", "book-double", "", [&](std::size_t k) { return book::cast(pd.seg[k], pd.sph[k]).hit; }});
  rows.push_back({"book long double", "book-long-double", "",
                  [&](std::size_t k) { return book::cast(pl.seg[k], pl.sph[k]).hit; }});
  const mpfr_precision restore{static_cast<int>(mpfr::mpreal::get_default_prec())};
  for (int bits : {128, 256}) {
    mpfr::mpreal::set_default_prec(bits);  // inputs made at this precision
    auto pm = std::make_shared<Prepared<mpfr::mpreal>>(cases);
    rows.push_back({"book MPFR-" + std::to_string(bits), "", "not measured", [pm, bits](std::size_t k) {
                      mpfr::mpreal::set_default_prec(bits);  // and the constants it makes
                      return book::cast(pm->seg[k], pm->sph[k]).hit;
                    }});
  }
  rows.push_back({"robust float", "robust-float", "", [&](std::size_t k) { return robust::cast(pf.seg[k], pf.sph[k]).hit; }});
  rows.push_back({"robust double", "robust-double", "", [&](std::size_t k) { return robust::cast(pd.seg[k], pd.sph[k]).hit; }});
  rows.push_back({"robust long double", "robust-long-double", "",
                  [&](std::size_t k) { return robust::cast(pl.seg[k], pl.sph[k]).hit; }});
  rows.push_back({"oracle, classification", "", "exact", [&](std::size_t k) { return oracle_classify(q, cases[k]).cls; }});
  rows.push_back({"oracle, every output rounded", "", "exact", [&](std::size_t k) { return oracle_truth(q, cases[k], 53).cls; }});
  // the exact rows: the cast and its lambda_enter rounded correctly
  rows.push_back({"book at Gmpq (a + b sqrt d)", "", "exact", [&](std::size_t k) {
                    const auto c = book::cast(pq.seg[k], pq.sph[k]);
                    return c.hit && round_double(c.lambda_enter) >= 0;
                  }});
  rows.push_back({"book at Epeck::FT", "", "exact", [&](std::size_t k) {
                    const auto c = book::cast(pe.seg[k], pe.sph[k]);
                    return c.hit && round_double(c.lambda_enter) >= 0;
                  }});
  rows.push_back({"book at CORE::Expr", "", "exact", [&](std::size_t k) {
                    const auto c = book::cast(px.seg[k], px.sph[k]);
                    return c.hit && round_double(c.lambda_enter) >= 0;
                  }});
  rows.push_back({"CGAL do_intersect, Epick (hit only)", "", "exact",
                  [&](std::size_t k) { return CGAL::do_intersect(ck_seg[k], ck_sph[k]) || ck_sph[k].has_on_bounded_side(ck_seg[k].source()); }});
  rows.push_back({"CGAL do_intersect, Epeck (hit only)", "", "exact",
                  [&](std::size_t k) { return CGAL::do_intersect(ce_seg[k], ce_sph[k]) || ce_sph[k].has_on_bounded_side(ce_seg[k].source()); }});

  // timing: every row over the same inputs, `reps` times, interleaved; the median per row
  std::vector<std::vector<double>> times(rows.size());
  volatile std::size_t sink = 0;
  for (int r = 0; r < reps; ++r)
    for (std::size_t j = 0; j < rows.size(); ++j) {
      const auto t0 = std::chrono::steady_clock::now();
      std::size_t hits = 0;
      for (std::size_t k = 0; k < cases.size(); ++k) hits += rows[j].run(k);
      const auto t1 = std::chrono::steady_clock::now();
      sink = sink + hits;
      times[j].push_back(std::chrono::duration<double, std::nano>(t1 - t0).count() / double(cases.size()));
    }
  for (std::size_t j = 0; j < rows.size(); ++j) {
    std::sort(times[j].begin(), times[j].end());
    rows[j].ns = times[j][times[j].size() / 2];
  }
  const double base = rows[1].ns;

  // accuracy: a campaign over the uniform, long-range and near-tangent families
  Spec spec;
  spec.queries = {q};
  spec.families = {"uniform", "long-range", "near-tangent"};
  spec.impls = {"book-float", "book-double", "book-long-double", "robust-float", "robust-double", "robust-long-double"};
  spec.n = err_n;
  spec.threads = 2;
  const Results res = run(spec);
  struct Acc {
    std::uint64_t n = 0, wrong = 0;
    Histogram h;
    std::uint64_t max = 0;
  };
  std::map<std::string, Acc> acc;
  for (const auto& [k, st] : res.cells) {
    Acc& a = acc[k.impl];
    a.n += st.n - st.refused;
    a.wrong += st.cls_fp + st.cls_fn;
    for (int b = 0; b < Histogram::bins; ++b) a.h.count[b] += st.out[0].hist.count[b];
    if (st.out[0].worst.set) a.max = std::max(a.max, st.out[0].worst.metric);
  }

  std::ostringstream table, csvout;
  char line[256];
  std::snprintf(line, sizeof line, "%-38s %12s %10s %14s %14s %14s\n", "implementation", "ns/query", "x double",
                "misclassified", "p99 ulps", "max ulps");
  table << line;
  csvout << "implementation,ns_per_query,ratio_to_book_double,misclassified_share,p99_ulps,max_ulps\n";
  for (const Row& r : rows) {
    std::string miss = r.error_note, p99 = r.error_note, mx = r.error_note;
    if (!r.campaign_impl.empty()) {
      const Acc& a = acc.at(r.campaign_impl);
      char b[64];
      std::snprintf(b, sizeof b, "%.3g%%", 100.0 * double(a.wrong) / double(std::max<std::uint64_t>(1, a.n)));
      miss = b;
      p99 = std::to_string(a.h.quantile(0.99));
      std::snprintf(b, sizeof b, "%.3g", double(a.max));
      mx = b;
    }
    std::snprintf(line, sizeof line, "%-38s %12.1f %10.2f %14s %14s %14s\n", r.name.c_str(), r.ns, r.ns / base,
                  miss.c_str(), p99.c_str(), mx.c_str());
    table << line;
    csvout << r.name << "," << r.ns << "," << r.ns / base << "," << miss << "," << p99 << "," << mx << "\n";
  }
  std::cout << "cdref report: segment-sphere cast (Algorithm 3.1), " << n << " " << family
            << " cases timed, median of " << reps << " interleaved repetitions, one thread.\n"
            << "Errors: lambda_enter in ulps of the row's type, and the share misclassified, over " << err_n
            << " cases per cell of the uniform, long-range and near-tangent families.\n\n"
            << table.str();
  if (!csv.empty()) {
    std::ofstream f(csv);
    f << csvout.str();
    if (!f) throw std::runtime_error("cannot write " + csv);
  }
  return sink == 0xffffffff ? 1 : 0;
}

}  // namespace cdref::cli
