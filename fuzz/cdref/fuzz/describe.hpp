// cdref/fuzz/describe.hpp - describe<Spec>(): a query's spec (see spec.hpp) as its
// type-erased descriptor, with every instantiation the campaign, the case files, the fuzz
// checks and the cost report need. Included only by the few translation units that list
// the queries (fuzz/queries/*.cpp): each instantiation of the exact types costs compile time.
#pragma once

#include <cdref/exact/cgal_kernels.hpp>

#include <cdref/float/mpfr.hpp>
#include <cdref/fuzz/spec.hpp>
#include <memory>

namespace CORE {
class Expr;  // (cdref/exact/core_expr.hpp: its rows are compiled in one unit, below)
}

namespace cdref::fuzz::spec {

// ---- the rows of the cost report ----
// What a row does with case k: `full` computes every output, `classify` the book's other
// formulation (hit / intersect), `first_rounded` every output with the first rounded
// correctly to double (exact types).
enum class Mode { full, classify, first_rounded };

// A row's answer from a query's result: its classification; with Mode::first_rounded, after
// rounding its first output that is not a label (the first value column, spec.hpp's columns_of)
// correctly to double, the rounded value kept from the optimizer by a comparison that never
// holds (an exact value is never NaN).
template <class Spec, class R>
bool finish(const R& r, Mode m) {
  const bool c = classification_of(r);
  if constexpr (!std::is_same_v<R, bool>) {
    if (m != Mode::first_rounded) return c;
    const std::vector<int>& col = columns_of<Spec, R>();
    std::size_t i = 0;
    bool done = false, never = false;
    zip_fields(r, r, [&](const char*, const auto& x, const auto&) {
      using X = std::remove_cvref_t<decltype(x)>;
      if (col[i++] < 0 || done) return;
      if constexpr (!std::is_same_v<X, bool> && !std::is_same_v<X, int>) {
        double v;
        if constexpr (requires { x.rows(); })
          v = round_double(x[0]);
        else
          v = round_double(x);
        never = v != v;
        done = true;
      }
    });
    return c != never;
  }
  return c;
}

template <class Spec, class T>
auto prepare(const std::vector<Inputs>& cases) {
  using P = decltype(Spec::template make<T>(cases.front()));
  auto p = std::make_shared<std::vector<P>>();
  p->reserve(cases.size());
  for (const Inputs& in : cases) p->push_back(Spec::template make<T>(in));
  return p;
}

// A row over prepared inputs: one call answers n of them from `first` on into out[k] (the
// classification) in a loop the compiler sees whole, so a row's time is its query's alone:
// no call through a function object per case. An empty asm statement that may touch memory
// ends each case: the compiler cannot vectorise across cases (g++ does so with the bare
// formulas, four sphere pairs at a time, which a narrow phase walking its pair list or a ray
// tracer answering one ray does not get), so every row is timed as one query after another.
// (run(first, n, nullptr) reads those cases' prepared inputs into cache, one byte a cache
// line, and answers nothing: campaign.hpp's touch)
template <class P, class F>
TimedRow::Batch batch_over(std::shared_ptr<std::vector<P>> p, F f) {
  return [p, f](std::size_t first, std::size_t n, char* out) {
    const P* d = p->data() + first;
    if (!out) return touch(d, n);
    for (std::size_t k = 0; k < n; ++k) {
      out[k] = char(f(d[k]));
      asm volatile("" ::: "memory");
    }
  };
}

// Whether a query answers values beyond its classification, known when it is compiled: its
// book's result is not a bool (describe() checks this against its outputs()). A row's two
// formulations are chosen by it at compile time, so that a row instantiates the one it times.
template <class Spec>
constexpr bool has_values = !std::is_same_v<
    decltype(Spec::book(Spec::template make<double>(std::declval<const Inputs&>()).first,
                        Spec::template make<double>(std::declval<const Inputs&>()).second, 0u)),
    bool>;
// The mode of the rows that time a query's full answer: every output, or the classification
// where it has no other.
template <class Spec>
constexpr Mode full_mode = has_values<Spec> ? Mode::full : Mode::classify;

// A row of the book at T in mode M: Mode::classify times book_pred, the others book with every
// output asked (finish() says what each does with the result).
template <class Spec, class T, Mode M>
TimedRow::Batch book_row(const std::vector<Inputs>& cases) {
  auto p = prepare<Spec, T>(cases);
  if constexpr (M == Mode::classify)
    return batch_over(p, [](const auto& ab) { return Spec::book_pred(ab.first, ab.second); });
  else
    return batch_over(p, [m = M](const auto& ab) {
      return finish<Spec>(Spec::book(ab.first, ab.second, unsigned(want_all)), m);
    });
}
// The truth's formulation at an exact type T (the book, unless the spec says otherwise), in mode
// M as book_row; the exact rows' mode is exact_mode.
template <class Spec>
constexpr Mode exact_mode = has_values<Spec> ? Mode::first_rounded : Mode::classify;
template <class Spec, class T, Mode M>
TimedRow::Batch exact_row(const std::vector<Inputs>& cases) {
  auto p = prepare<Spec, T>(cases);
  if constexpr (M == Mode::classify)
    return batch_over(p, [](const auto& ab) { return truth_predicate<Spec>(ab.first, ab.second); });
  else
    return batch_over(p, [m = M](const auto& ab) {
      return finish<Spec>(truth_formulation<Spec>(ab.first, ab.second, unsigned(want_all)), m);
    });
}
// exact_row<Spec, T, exact_mode<Spec>> for T = CGAL::Gmpq, CGAL::Epeck::FT and CORE::Expr, and
// the book's row at MPFR (mode full_mode<Spec>), defined for every query in
// fuzz/queries/exact_paths.cpp alone, with the other evaluations at the exact types (spec.hpp);
// the query groups do not include CORE (cdref/exact/core_expr.hpp says what that saves).
template <class Spec, class T>
TimedRow::Batch exact_type_row(const std::vector<Inputs>& cases);
template <class Spec>
TimedRow::Batch mpfr_book_row(const std::vector<Inputs>& cases);
template <class Spec, class K>
auto prepare_cgal(const std::vector<Inputs>& cases) {
  using P = decltype(Spec::template cgal_make<K>(cases.front()));
  auto p = std::make_shared<std::vector<P>>();
  for (const Inputs& in : cases) p->push_back(Spec::template cgal_make<K>(in));
  return p;
}
template <class Spec, class F, Mode M>
TimedRow::Batch stable_row(const std::vector<Inputs>& cases) {
  auto p = prepare<Spec, F>(cases);
  if constexpr (M == Mode::classify)
    return batch_over(p, [](const auto& ab) { return Spec::stable_pred(ab.first, ab.second); });
  else
    return batch_over(p, [m = M](const auto& ab) {
      return finish<Spec>(Spec::stable(ab.first, ab.second, unsigned(want_all)), m);
    });
}
template <class Spec, class T>
TimedRow::Batch robust_row(const std::vector<Inputs>& cases) {
  auto p = prepare<Spec, T>(cases);
  return batch_over(p, [](const auto& ab) { return finish<Spec>(Spec::robust(ab.first, ab.second), Mode::full); });
}

// Rows (each answers the same prepared inputs; a row that computes a query's outputs asks
// for all of them): `bare`, the book's classification at double without its input checks
// (book::unchecked, the loop a tight engine runs: the honest baseline); the book at float,
// double (all outputs, and the classification alone), long double, MPFR-128 and MPFR-256; the
// stable tier at float and double (all outputs, the classification alone, and that without
// input checks, beside `bare`) where the query has one; robust at float, double (all outputs,
// and robust::decide: the classification with its certificate) and long double; the oracle (the classification alone, and every output correctly rounded), on the
// uniform cases and on
// the hard ones; the book at CGAL::Gmpq, CGAL::Epeck::FT and CORE::Expr (the query and its
// first output rounded correctly to double); CGAL's own do_intersect in its filtered (Epick)
// and exact (Epeck) kernels where CGAL has the pair.
template <class Spec>
std::vector<TimedRow> timed_rows(const std::vector<Inputs>& cases, const std::vector<Inputs>& hard,
                                 const std::string& hard_name) {
  constexpr bool values = has_values<Spec>;  // outputs beyond the classification
  constexpr Mode full = full_mode<Spec>;
  std::vector<TimedRow> rows;
  // the exact and multiprecision types' rows: the first slow_row_cases only (campaign.hpp)
  const std::vector<Inputs> head(cases.begin(), cases.begin() + std::ptrdiff_t(std::min(cases.size(), slow_row_cases)));
  rows.push_back({"bare (book at double, unchecked)", "", "as book",
                  batch_over(prepare<Spec, double>(cases),
                             [](const auto& ab) { return Spec::bare(ab.first, ab.second); })});
  rows.push_back({"book float", "book-float", "", book_row<Spec, float, full>(cases)});
  rows.push_back({"book double", "book-double", "", book_row<Spec, double, full>(cases)});
  if (values) {
    // a separating-axis query's classification is its full query; its predicate column is
    // another formulation, named as such
    const bool label = Spec::outputs().front().label;
    rows.push_back({label ? std::string("book double, predicate column (") + Spec::pred_name + ")"
                          : std::string("book double, classification"),
                    "", "as above", book_row<Spec, double, Mode::classify>(cases)});
  }
  rows.push_back({"book long double", "book-long-double", "", book_row<Spec, long double, full>(cases)});
  for (int bits : {128, 256}) {
    const mpfr_precision at{bits};  // inputs made at this precision
    auto row = mpfr_book_row<Spec>(head);
    rows.push_back({"book MPFR-" + std::to_string(bits), "", "not measured",
                    [row, bits](std::size_t first, std::size_t n, char* out) {
                      const mpfr_precision again{bits};  // and the constants it makes
                      row(first, n, out);
                    }});
    rows.back().cases = head.size();
  }
  if constexpr (has_stable<Spec>) {
    rows.push_back({"stable float", "stable-float", "", stable_row<Spec, float, full>(cases)});
    rows.push_back({"stable double", "stable-double", "", stable_row<Spec, double, full>(cases)});
    if (values)
      rows.push_back({"stable double, classification", "", "as above", stable_row<Spec, double, Mode::classify>(cases)});
    rows.push_back({"stable double, unchecked", "", "as above",
                    batch_over(prepare<Spec, double>(cases),
                               [](const auto& ab) { return Spec::stable_bare(ab.first, ab.second); })});
  }
  rows.push_back({"robust float", "robust-float", "", robust_row<Spec, float>(cases)});
  rows.push_back({"robust double", "robust-double", "", robust_row<Spec, double>(cases)});
  rows.push_back({"robust double, certified classification", "", "as above",
                  batch_over(prepare<Spec, double>(cases),
                             [](const auto& ab) { return Spec::robust_decide(ab.first, ab.second).value; })});
  rows.push_back({"robust long double", "robust-long-double", "", robust_row<Spec, long double>(cases)});
  auto uni = std::make_shared<std::vector<Inputs>>(cases);
  auto hc = std::make_shared<std::vector<Inputs>>(hard);
  const auto oracle = [](const auto& ab) { return oracle_of<Spec>(ab.first, ab.second, nullptr); };
  const auto rounded = [](const Inputs& in) { return oracle_truth_of<Spec>(in, 53, nullptr).cls; };
  rows.push_back({"oracle, classification", "", "exact", batch_over(prepare<Spec, double>(cases), oracle)});
  if (values) rows.push_back({"oracle, every output rounded", "", "exact", batch_over(uni, rounded)});
  // a cast's hit and lambda_enter alone, correctly rounded: the row answers the hit, the value
  // kept from the optimizer by an empty asm statement that reads it; from the prepared
  // primitives where the spec has oracle::enter, else from the case's columns (as the
  // every-output row)
  const auto answered = [](const oracle::Entry& e) {
    asm volatile("" : : "r,m"(e.lambda_enter) : "memory");
    return e.hit;
  };
  const auto enter = [answered](const auto& ab) {
    if constexpr (has_oracle_enter<Spec>)
      return answered(Spec::oracle_enter(ab.first, ab.second, nullptr));
    else
      return false;
  };
  const auto enter_generic = [answered](const Inputs& in) {
    if constexpr (is_cast<Spec>)
      return answered(oracle_enter_of<Spec>(in, nullptr));
    else
      return false;
  };
  if constexpr (has_oracle_enter<Spec>)
    rows.push_back({"oracle, lambda_enter rounded", "", "exact", batch_over(prepare<Spec, double>(cases), enter)});
  else if constexpr (is_cast<Spec>)
    rows.push_back({"oracle, lambda_enter rounded", "", "exact", batch_over(uni, enter_generic)});
  rows.push_back(
      {"oracle, classification" + hard_name, "", "exact", batch_over(prepare<Spec, double>(hard), oracle), true});
  if (values) rows.push_back({"oracle, every output" + hard_name, "", "exact", batch_over(hc, rounded), true});
  if constexpr (has_oracle_enter<Spec>)
    rows.push_back(
        {"oracle, lambda_enter" + hard_name, "", "exact", batch_over(prepare<Spec, double>(hard), enter), true});
  else if constexpr (is_cast<Spec>)
    rows.push_back({"oracle, lambda_enter" + hard_name, "", "exact", batch_over(hc, enter_generic), true});
  // the generic staged path (cdref/exact/staged.hpp: the truth's own code on a bounded
  // double, a bounded double word, then rationals), beside the oracle's hand-written filters
  // above: what those filters save, on the uniform and on the near-boundary cases
  // (the classification from the prepared primitives, as the oracle's row; every output from the
  // case's columns, as the oracle's every-output row)
  const auto staged_cls = [](const auto& ab) { return staged_classification<Spec>(ab.first, ab.second, nullptr); };
  const auto staged_all = [](const Inputs& in) { return staged_truth_of<Spec>(in, 53, nullptr).cls; };
  rows.push_back({"staged, classification", "", "exact", batch_over(prepare<Spec, double>(cases), staged_cls)});
  if (values) rows.push_back({"staged, every output rounded", "", "exact", batch_over(uni, staged_all)});
  rows.push_back(
      {"staged, classification" + hard_name, "", "exact", batch_over(prepare<Spec, double>(hard), staged_cls), true});
  if (values) rows.push_back({"staged, every output" + hard_name, "", "exact", batch_over(hc, staged_all), true});
  const std::string at = Spec::book_is_truth ? "book at " : "exact formulation at ";
  rows.push_back({at + "Gmpq", "", "exact", exact_type_row<Spec, CGAL::Gmpq>(head)});
  rows.push_back({at + "Epeck::FT", "", "exact", exact_type_row<Spec, CGAL::Epeck::FT>(head)});
  rows.push_back({at + "CORE::Expr", "", "exact", exact_type_row<Spec, CORE::Expr>(head)});
  for (std::size_t j = rows.size() - 3; j < rows.size(); ++j) rows[j].cases = head.size();
  if constexpr (requires(const Inputs& in) { Spec::template cgal_make<CGAL::Epick>(in); }) {
    const auto cgal = [](const auto& ab) { return Spec::cgal(ab.first, ab.second); };
    rows.push_back({"CGAL do_intersect, Epick", "", "exact", batch_over(prepare_cgal<Spec, CGAL::Epick>(cases), cgal)});
    rows.push_back({"CGAL do_intersect, Epeck", "", "exact", batch_over(prepare_cgal<Spec, CGAL::Epeck>(cases), cgal)});
  }
  for (TimedRow& r : rows)
    if (r.cases == 0) r.cases = r.hard ? hard.size() : cases.size();
  return rows;
}

// ---- the descriptor ----
template <class Spec>
QueryInfo describe() {
  static_assert(check<Spec>());
  if (has_values<Spec> == Spec::outputs().empty())
    throw std::logic_error(std::string(Spec::name) + ": the book's result is a bool exactly when the query has no "
                           "outputs beyond its classification");
  QueryInfo qi;
  qi.q = Query{Spec::id};
  qi.name = Spec::name;
  qi.cls_name = Spec::cls_name;
  qi.pred_name = Spec::pred_name;
  qi.inputs = Spec::inputs();
  qi.outputs = Spec::outputs();
  qi.describe = Spec::describe;
  qi.full_call = Spec::full_call;
  qi.answer_help = Spec::answer_help;
  qi.families = Spec::families();
  qi.book_is_truth = Spec::book_is_truth;
  if constexpr (requires { Spec::mesh_level; }) qi.mesh_level = Spec::mesh_level;
  if constexpr (requires { Spec::case_digest; }) qi.case_digest = Spec::case_digest;
  qi.book = [](int precision, const Inputs& in) {
    return at_precision(precision, [&in]<class F>(F*) { return book_at<Spec, F, F>(in, true); });
  };
  qi.book_classification = [](int precision, const Inputs& in) {
    return at_precision(precision, [&in]<class F>(F*) { return book_at<Spec, F, F>(in, false); });
  };
  qi.book_classification_block = [](int precision, const Inputs* in, std::size_t n, Verdict* out) {
    at_precision(precision, [&]<class F>(F*) { book_classification_block<Spec, F>(in, n, out); });
  };
  qi.robust = [](int precision, const Inputs& in) {
    return at_precision(precision, [&in]<class F>(F*) { return robust_at<Spec, F>(in); });
  };
  // (the stable tier at float and double: at_precision<false>)
  if constexpr (has_stable<Spec>)
    qi.stable = [](int precision, const Inputs& in) {
      return at_precision<false>(precision, [&in]<class F>(F*) { return stable_at<Spec, F>(in); });
    };
  if constexpr (has_stable<Spec>)
    qi.stable_classification = [](int precision, const Inputs& in) {
      return at_precision<false>(precision, [&in]<class F>(F*) { return stable_at<Spec, F>(in, false); });
    };
  if constexpr (has_stable<Spec>)
    qi.stable_classification_block = [](int precision, const Inputs* in, std::size_t n, Verdict* out) {
      at_precision<false>(precision, [&]<class F>(F*) { stable_classification_block<Spec, F>(in, n, out); });
    };
  qi.book_exact = [](Exact t, const Inputs& in) {
    return t == Exact::gmpq ? exact_book_at<Spec, CGAL::Gmpq>(in) : exact_book_at<Spec, CGAL::Epeck::FT>(in);
  };
  qi.truth = truth_of<Spec>;
  qi.truth_classification = [](const Inputs& in) { return gmpq_truth_at<Spec, double>(in, false, false); };
  qi.oracle_truth = oracle_truth_of<Spec>;
  qi.oracle_classify = oracle_classify_of<Spec>;
  qi.oracle_classify_block = oracle_classify_block_of<Spec>;
  qi.staged_classify = staged_classify_of<Spec>;
  qi.staged_truth = staged_truth_of<Spec>;
  if constexpr (is_cast<Spec>)
    qi.oracle_enter = [](const Inputs& in, bool* exact_used) {
      const oracle::Entry e = oracle_enter_of<Spec>(in, exact_used);
      Answer r;
      r.cls = r.pred = e.hit;
      r.v[0] = e.lambda_enter;
      return r;
    };
  if constexpr (requires(const Inputs& in) {
                  Spec::stage(oracle::Stage::filter, Spec::template make<double>(in).first,
                              Spec::template make<double>(in).second);
                }) {
    qi.oracle_stage = [](int stage, const Inputs& in) {
      const auto [a, b] = Spec::template make<double>(in);
      const int r = Spec::stage(static_cast<oracle::Stage>(stage), a, b);
      return r == 0 || r == 1 ? r : -1;
    };
  }
  qi.timed_rows = [](const std::vector<Inputs>& cases, const std::vector<Inputs>& hard, const std::string& hard_name) {
    return timed_rows<Spec>(cases, hard, hard_name);
  };
  if constexpr (requires(const Inputs& in) { Spec::fuzz_extra(in); }) qi.fuzz_extra = Spec::fuzz_extra;
  if constexpr (requires(const Inputs& in) { Spec::double_may_refuse(in); }) qi.double_may_refuse = Spec::double_may_refuse;
  if constexpr (requires { Spec::variants(); }) qi.variants = Spec::variants();
  return qi;
}

}  // namespace cdref::fuzz::spec
