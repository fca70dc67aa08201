// cdref/fuzz/truth_api.hpp - how <cdref/truth.hpp>'s functions are answered: a query's spec
// (spec.hpp) evaluated on typed primitives, every field of its result rounded.
//
// The oracle's path (oracle_result) is the every-output oracle of spec.hpp (oracle_truth_of)
// on primitives instead of a case's columns, and rounds the whole result struct, not only the
// answer columns (so also Cast::enters and unbounded_exit, Proximity::closest, Separation's
// direction):
//   1. a query whose answer is a classification alone: the classification oracle; a cast whose
//      outputs all exist on a hit alone: the classification oracle first, and a miss is the
//      default result (no hit, every value 0), as the book's at an exact type;
//   2. at double, the robust tier's first look where the spec has it (oracle_rounded) and it
//      proves every rounding;
//   3. the truth's formulation (or the spec's oracle_formulation) on cdref::Bounded2, accepted
//      when every comparison and every rounding is certain;
//   4. the truth's formulation at CGAL::Gmpq, rounded.
// exact_result is step 4 alone (Path::exact). The group files (fuzz/queries/*.cpp) define the
// public functions through CDREF_TRUTH_FUNCTIONS below, where the specs' instantiations already
// are: the truth API compiles no exact type a second time.
#pragma once

#include <cdref/fields.hpp>
#include <cdref/fuzz/spec.hpp>
#include <cdref/truth/basics.hpp>
#include <string>
#include <type_traits>

namespace cdref::fuzz::spec {

// ---- a result rounded to F, field by field (fields.hpp's rounded_by; spec.hpp's value: exact
// values rounded correctly, bounded ones where certain, or cdref::uncertain) ----
template <class F, template <class> class R, class S>
R<F> rounded(const R<S>& r) {
  return rounded_by<F>(r, [](const auto& x) { return static_cast<F>(value<F>(x)); });
}
template <class F> bool rounded(bool r) { return r; }

// The truth's formulation's result with every output asked, each field rounded to F.
template <class Spec, class F, class A, class B>
using TruthResult = decltype(rounded<F>(
    truth_formulation<Spec>(std::declval<const A&>(), std::declval<const B&>(), unsigned(want_all))));

// Step 4 alone: the truth's formulation at CGAL::Gmpq, each field rounded to F. a and b are
// checked (finite, in the query's domain) double primitives. Defined for every query with the
// other evaluations at the exact types, in fuzz/queries/exact_paths.cpp (spec.hpp says why).
template <class Spec, class F>
TruthResult<Spec, F, DoubleA<Spec>, DoubleB<Spec>> gmpq_result(const DoubleA<Spec>& a, const DoubleB<Spec>& b);
template <class Spec, class F, class A, class B>
TruthResult<Spec, F, A, B> exact_result(const A& a, const B& b) {
  static_assert(std::is_same_v<A, DoubleA<Spec>> && std::is_same_v<B, DoubleB<Spec>>,
                "the exact path takes the query's primitives at double");
  return gmpq_result<Spec, F>(a, b);
}

// Steps 1-4 (see the file's comment).
template <class Spec, class F, class A, class B>
TruthResult<Spec, F, A, B> oracle_result(const A& a, const B& b, bool* exact_used = nullptr) {
  using R = TruthResult<Spec, F, A, B>;
  if (exact_used) *exact_used = false;
  if constexpr (std::is_same_v<R, bool>) {
    return oracle_of<Spec>(a, b, nullptr);  // a classification alone: the classification oracle
  }
  if constexpr (is_cast<Spec>) {
    if (outputs_on_hit_alone<Spec>() && !oracle_of<Spec>(a, b, nullptr)) return R{};
  }
  if constexpr (has_oracle_rounded<Spec> && std::is_same_v<F, double>) {
    RobustResult<Spec> p;
    if (Spec::oracle_rounded(a, b, p)) return rounded<F>(p);
  }
  // (two lambdas, the other formulation's named only where the spec has it: clang instantiates
  // the parts of a generic lambda that do not depend on its own parameters)
  const auto own = [&] {
    return rounded<F>(truth_formulation<Spec>(rebind<cdref::Bounded2>(a), rebind<cdref::Bounded2>(b), unsigned(want_all)));
  };
  if constexpr (has_oracle_formulation<Spec>) {
    const auto other = [&] {
      return rounded<F>(
          Spec::oracle_formulation(rebind<cdref::Bounded2>(a), rebind<cdref::Bounded2>(b), unsigned(want_all)));
    };
    bool other_first = false;
    if constexpr (has_formulation_first<Spec>) other_first = Spec::oracle_formulation_first(a, b);
    try {
      return other_first ? R(other()) : R(own());
    } catch (const cdref::uncertain&) {
    }
    try {
      return other_first ? R(own()) : R(other());
    } catch (const cdref::uncertain&) {
    }
  } else {
    try {
      return own();
    } catch (const cdref::uncertain&) {
    }
  }
  if (exact_used) *exact_used = true;
  return exact_result<Spec, F>(a, b);
}

// The names of a query's two arguments in its error messages: "sphere", or "sphere a" and
// "sphere b" for two of one kind.
template <class P> struct ArgName;
#define CDREF_ARG_NAME(P, text) \
  template <class T> struct ArgName<P<T>> { static constexpr const char *one = text, *a = text " a", *b = text " b"; };
CDREF_ARG_NAME(Vec3, "point")
CDREF_ARG_NAME(Sphere, "sphere")
CDREF_ARG_NAME(Box, "box")
CDREF_ARG_NAME(Segment, "segment")
CDREF_ARG_NAME(Ray, "ray")
CDREF_ARG_NAME(Triangle, "triangle")
CDREF_ARG_NAME(Polygon, "polygon")
CDREF_ARG_NAME(OrientedBox, "oriented box")
CDREF_ARG_NAME(Fan, "fan")
#undef CDREF_ARG_NAME

// The public entry: F-typed primitives (F = float or double), checked by name, then answered
// at double (a float is exact in double; a double is taken as it is) with every value rounded
// to F.
template <class Spec, class F, class A, class B>
auto truth_call_at_double(const A& a, const B& b, truth::Path path) {
  constexpr bool same = std::is_same_v<A, B>;
  cdref::check(a, same ? ArgName<A>::a : ArgName<A>::one);
  cdref::check(b, same ? ArgName<B>::b : ArgName<B>::one);
  return path == truth::Path::exact ? exact_result<Spec, F>(a, b) : oracle_result<Spec, F>(a, b);
}
template <class Spec, class F, class A, class B>
auto truth_call(const A& a, const B& b, truth::Path path) {
  if constexpr (std::is_same_v<F, double>)
    return truth_call_at_double<Spec, F>(a, b, path);
  else
    return truth_call_at_double<Spec, F>(rebind<double>(a), rebind<double>(b), path);
}

// Every field of the oracle's answer against the exact path's, for the query's typed call at F
// on a case's columns: "" when they are equal bit for bit (a value and its rounding both 0 may
// differ in sign only where the truth is 0), otherwise the first field that differs. Inputs the
// query refuses give "refused: <message>" from both (the same message).
template <class Spec, class F, class Call>
std::string truth_api_check(const Inputs& in, Call call) {
  using P = decltype(Spec::template make<double>(in));
  P p;
  try {
    p = Spec::template make<double>(in);
  } catch (const invalid_input&) {
    return "";  // not the query's primitives: nothing to call it on
  }
  const auto a = rebind<F>(p.first);
  const auto b = rebind<F>(p.second);
  if constexpr (std::is_same_v<F, float>) {
    // a case whose columns float cannot hold is not a float input
    for (std::size_t k = 0; k < Spec::inputs().size(); ++k)
      if (std::isfinite(in[k]) && !std::isfinite(float(in[k]))) return "";
  }
  std::string fast_error, exact_error;
  decltype(call(a, b, truth::Path::oracle)) fast{}, exact{};
  try {
    fast = call(a, b, truth::Path::oracle);
  } catch (const invalid_input& e) {
    fast_error = e.what();
  }
  try {
    exact = call(a, b, truth::Path::exact);
  } catch (const invalid_input& e) {
    exact_error = e.what();
  }
  if (!fast_error.empty() || !exact_error.empty())
    return fast_error == exact_error ? "" : "refusals differ: '" + fast_error + "' and '" + exact_error + "'";
  return truth::first_difference(fast, exact);
}

}  // namespace cdref::fuzz::spec

namespace cdref::fuzz::spec {
// Sets the descriptor's truth_api_check and adds the truth API's timed rows: specialised for each spec by
// CDREF_TRUTH_FUNCTIONS, in the spec's group file.
template <class Spec>
void attach_truth_api(QueryInfo& qi);
template <class Spec>
QueryInfo describe_with_truth_api() {
  QueryInfo qi = describe<Spec>();
  attach_truth_api<Spec>(qi);
  return qi;
}
}  // namespace cdref::fuzz::spec

// Defines, for one spec, the public double and float functions of <cdref/truth.hpp>, the check
// of them the tests reach through the query's descriptor (QueryInfo::truth_api_check), and two
// rows of the cost report and cdref_bench that time the public call on prepared primitives
// ("truth API, every output", on the uniform and the near-boundary cases, beside the oracle's
// rows): CDREF_TRUTH_FUNCTIONS(Spec, Result,
// name, A, B), Result the result template (Cast, Proximity, ..., or detail::Bool), `name` the
// book's function (cast, proximity, separate, intersect), A and B the primitives' templates.
#define CDREF_TRUTH_FUNCTIONS(Spec, Result, fn, A, B)                                                         \
  namespace cdref::truth {                                                                                    \
  Result<double> fn(const A<double>& a, const B<double>& b, Path path) {                                      \
    return fuzz::spec::truth_call<fuzz::queries::Spec, double>(a, b, path);                                   \
  }                                                                                                           \
  Result<float> fn(const A<float>& a, const B<float>& b, Path path) {                                         \
    return fuzz::spec::truth_call<fuzz::queries::Spec, float>(a, b, path);                                    \
  }                                                                                                           \
  }                                                                                                           \
  namespace cdref::fuzz::spec {                                                                               \
  template <>                                                                                                 \
  void attach_truth_api<queries::Spec>(QueryInfo & qi) {                                                      \
    qi.truth_api_check = [](const Inputs& in, int precision) {                                                \
      const auto call = [](const auto& a, const auto& b, truth::Path p) { return truth::fn(a, b, p); };       \
      return at_precision<false>(precision,                                                                   \
                                 [&]<class F>(F*) { return truth_api_check<queries::Spec, F>(in, call); });   \
    };                                                                                                        \
    qi.timed_rows = [base = qi.timed_rows](const std::vector<Inputs>& cases, const std::vector<Inputs>& hard,   \
                                           const std::string& hard_name) {                                    \
      std::vector<TimedRow> rows = base(cases, hard, hard_name);                                              \
      const auto call = [](const auto& ab) {                                                                  \
        return classification_of(truth::fn(ab.first, ab.second, truth::Path::oracle));                         \
      };                                                                                                      \
      rows.push_back({"truth API, every output", "", "exact",                                                 \
                      batch_over(prepare<queries::Spec, double>(cases), call), false, cases.size()});         \
      rows.push_back({"truth API, every output" + hard_name, "", "exact",                                     \
                      batch_over(prepare<queries::Spec, double>(hard), call), true, hard.size()});            \
      return rows;                                                                                            \
    };                                                                                                        \
  }                                                                                                           \
  }
