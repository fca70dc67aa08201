// cdref/fuzz/spec.hpp - how a query's spec becomes its descriptor.
//
// A query is described in one place, its spec (fuzz/queries/<query>.hpp): a struct with
//   id, name, cls_name, pred_name, describe   the descriptor's names (id: see Query; ids are
//                                             dense, the next free one, checked by queries.cpp)
//   full_call, answer_help                    the full query's call and the answer columns'
//                                             meanings, as `cdref cases --describe` prints them
//   inputs(), outputs(), families()           its case columns, output groups and families
//   make<T>(in)                               its two primitives from a case's columns, over T
//   book(a, b, w), book_pred(a, b)            the book: the full query (a Cast, a Proximity, a
//                                             bool or a Separation; w: the want_* mask) and the
//                                             other formulation of its classification
//   book_is_truth                             false when the book at an exact type is not the
//                                             truth; then truth(a, b, w), truth_pred(a, b) are
//   robust(a, b), robust_pred(a, b), robust_decide(a, b)    the robust versions
//   bare(a, b)                                the book's classification without its input
//                                             checks (book::unchecked): the cost report's baseline
//   oracle_enter(a, b, bool*)                 (casts with that path) the hit and lambda_enter
//                                             alone, correctly rounded (oracle::enter)
// and, where they exist:
//   oracle(a, b, Stage*)                      a hand-written exact classification (oracle::classify):
//                                             a fast path, tested against the generic staged
//                                             path (without it, the staged path is the oracle)
//   stable(a, b, w), stable_pred(a, b)        the stable tier (float/cdref/stable), F = float, double;
//   stable_bare(a, b)                         its classification without input checks
//   stage(Stage, a, b)                        one stage of the classification oracle alone
//   cgal_make<K>(in), cgal(a, b)              CGAL's do_intersect on the same solids
//   fuzz_extra(in)                            further checks of the fuzz target
//   double_may_refuse(in)                     inputs the book at double may refuse
//   variants()                                the query's own implementations
//   mesh_level                                a shot against several triangles (a false
//                                             negative is a leak, a false positive a phantom)
//   oracle_formulation(a, b, w)               the truth's outputs in another formulation, equal
//                                             to the book's exactly, run on double words first
//   oracle_formulation_first(a, b)            (at double) the cases that formulation decides first
//   oracle_rounded(a, b, result)              (at double) true where the robust result is proven
//                                             correctly rounded in every output
//
// Registration: the spec's header included, and one X(Spec, Result, fn, A, B) line in its group's
// list, both in the group's header (fuzz/queries/group_<name>.hpp; groups.hpp says what an edit
// recompiles). check<Spec>() below states the required members. What the tests hold every
// query to, beyond agreement with the exact answer on every family: the classification oracle
// decides at least 99% of uniform cases at Stage::filter (tests/test_oracle_classify.cpp), the
// robust tier is certain on at least 99% of them (tests/test_campaign.cpp), the families
// include "uniform" and a near-boundary one named near-tangent, near-touching, grazing,
// watertight or near-edge (the cost report's hard rows run its hardest scale), and each query's
// cases are pinned by a digest line in tests/test_campaign.cpp (a new query adds its line, which
// the test prints; no other line changes). A query without a hand-written oracle and robust tier
// gets both from the staged path: its robust tier is cdref/robust/staged.hpp's decide() and
// result() around its book (robust/point_triangle.hpp is the example), its oracle oracle_of's
// staged branch. docs/adding-a-query.md walks through one.
// describe<Spec>() instantiates every number type the campaign, the case files, the fuzz
// checks and the cost report need and returns the type-erased QueryInfo.
#pragma once

#include <bit>
#include <concepts>

#include <cdref/exact/rationals.hpp>
#include <cdref/exact/long_double.hpp>
#include <cdref/exact/staged.hpp>
#include <cdref/fan.hpp>
#include <cdref/fields.hpp>
#include <cdref/fuzz/campaign.hpp>
#include <cdref/bounded/bounded2.hpp>
#include <cdref/oracle/stage.hpp>
#include <cdref/robust/decision.hpp>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace cdref::fuzz::spec {

// ---- columns ----
template <class T>
Vec3<T> col3(const Inputs& in, int k) {
  return Vec3<T>(T(in[k]), T(in[k + 1]), T(in[k + 2]));
}

// Column names: ("center", 3) is center_x, center_y, center_z; ("radius", 1) is radius.
inline std::vector<std::string> cols(std::initializer_list<std::pair<const char*, int>> parts) {
  std::vector<std::string> out;
  for (const auto& [name, n] : parts) {
    if (n == 1) {
      out.push_back(name);
    } else {
      for (const char* ax : {"x", "y", "z"}) out.push_back(std::string(name) + "_" + ax);
    }
  }
  return out;
}

// CGAL's solids from a case's columns (kernel K): a point, a ball (CGAL's Sphere_3 takes the
// squared radius), an axis-aligned box from its centre and extent.
template <class K>
typename K::Point_3 cgal_point(const Inputs& in, int i) {
  using FT = typename K::FT;
  return typename K::Point_3(FT(in[i]), FT(in[i + 1]), FT(in[i + 2]));
}
template <class K>
typename K::Vector_3 cgal_vector(const Inputs& in, int i) {
  using FT = typename K::FT;
  return typename K::Vector_3(FT(in[i]), FT(in[i + 1]), FT(in[i + 2]));
}
// How cdref reads a zero-area CGAL triangle, for the cross-checks: the segment between its two
// farthest-apart vertices (ties to the first pair in the order v0v1, v0v2, v1v2; compared with
// CGAL's compare_distance, exact in every kernel), a point where the two coincide.
template <class T3>
auto cgal_span(const T3& t) {
  const auto a = t.vertex(0), b = t.vertex(1), c = t.vertex(2);
  auto s0 = a, s1 = b;
  if (compare_distance(a, c, s0, s1) == CGAL::LARGER) s1 = c;
  if (compare_distance(b, c, s0, s1) == CGAL::LARGER) s0 = b, s1 = c;
  return std::pair{s0, s1};
}
template <class K>
typename K::Sphere_3 cgal_ball(const Inputs& in, int c, int r) {
  const typename K::FT rho(in[r]);
  return typename K::Sphere_3(cgal_point<K>(in, c), rho * rho);
}
template <class K>
typename K::Iso_cuboid_3 cgal_cuboid(const Inputs& in, int c, int h) {
  using FT = typename K::FT;
  FT lo[3], hi[3];
  for (int i = 0; i < 3; ++i) {
    lo[i] = FT(in[c + i]) - FT(in[h + i]);
    hi[i] = FT(in[c + i]) + FT(in[h + i]);
  }
  return typename K::Iso_cuboid_3(typename K::Point_3(lo[0], lo[1], lo[2]), typename K::Point_3(hi[0], hi[1], hi[2]));
}

inline constexpr const char* cast_help =
    "  lambda_enter, lambda_exit: the hit interval (graded only where both say hit)\n"
    "  point_[xyz]: the entry point; normal_[xyz]: the outward unit normal there (0 when the\n"
    "  source is inside)\n";
inline constexpr const char* prox_help =
    "  distance, depth: distance and penetration depth\n"
    "  witness_a_[xyz], witness_b_[xyz]: the witness points on the first and second argument\n";

// An oriented box's columns: centre, extent, axis0, axis1, axis2 (after `prefix`).
inline std::vector<std::string> obb_cols(const std::string& prefix) {
  std::vector<std::string> out;
  for (const char* part : {"center", "extent", "axis0", "axis1", "axis2"})
    for (const char* ax : {"x", "y", "z"}) out.push_back(prefix + part + "_" + ax);
  return out;
}
template <class T>
OrientedBox<T> obb(const Inputs& in, int k) {
  return {col3<T>(in, k), col3<T>(in, k + 3), {col3<T>(in, k + 6), col3<T>(in, k + 9), col3<T>(in, k + 12)}};
}
inline std::vector<std::string> concat(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// A fan of triangles around a shared vertex (the mesh-level queries): triangles
// (center, ring[k], ring[k + 1]) for k < n - 1, and (center, ring[n - 1], ring[0]) when closed.
// Its columns: n (2 to 8 ring vertices), closed (0 or 1, closed needs n >= 3), center, r0..r7.
// (the fan and its cast: cdref/fan.hpp)
using cdref::Fan;
using cdref::FanCast;
inline std::string shown(double x) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", x);
  return b;
}
// Columns a vertex list does not use (beyond its n) must still be finite, as every column of a
// case is: a NaN there is refused by its name (`r6_y is not finite (nan)`), at every type.
inline void unused_finite(const Inputs& in, int from, int to, int first_col, const std::string& name, int first_vertex,
                          const std::string& prefix = "") {
  for (int c = from; c < to; ++c)
    if (!std::isfinite(in[c])) {
      const int rel = c - first_col;
      throw invalid_input(prefix + name + std::to_string(first_vertex + rel / 3) + "_" + "xyz"[rel % 3] +
                          " is not finite (" + (std::isnan(in[c]) ? "nan" : (in[c] > 0 ? "inf" : "-inf")) + ")");
    }
}
template <class T>
Fan<T> fan(const Inputs& in, int k) {
  const double n = in[k], closed = in[k + 1];
  if (!(n >= 2 && n <= Fan<T>::max_ring && n == std::floor(n)))
    throw invalid_input("fan n must be a whole number of ring vertices from 2 to 8 (" + shown(n) + ")");
  if (!(closed == 0 || closed == 1)) throw invalid_input("fan closed must be 0 or 1 (" + shown(closed) + ")");
  if (closed == 1 && n < 3) throw invalid_input("a closed fan needs at least 3 ring vertices (n = 2)");
  Fan<T> f;
  f.n = int(n);
  f.closed = closed == 1;
  unused_finite(in, k + 5 + 3 * f.n, k + 5 + 3 * Fan<T>::max_ring, k + 5 + 3 * f.n, "r", f.n);
  f.center = col3<T>(in, k + 2);
  for (int i = 0; i < f.n; ++i) f.ring[i] = col3<T>(in, k + 5 + 3 * i);
  return f;
}
// The first hit over a fan (smallest lambda_enter; the first triangle on ties) and the number
// of triangles hit.
// (before(k, j, lk, lj): whether triangle k, entered at lk, comes before triangle j, entered at
// lj; the robust casts order near-ties exactly: robust::enters_before.)
template <class T, class Cast1, class Before>
auto first_hit(const Fan<T>& f, Cast1 cast1, Before before) {
  using C = decltype(cast1(f.triangle(0)));
  FanCast<std::decay_t<decltype(std::declval<C>().lambda_enter)>> r;
  int rk = -1;
  for (int k = 0; k < f.triangles(); ++k) {
    const C c = cast1(f.triangle(k));
    if (!c.hit) continue;
    ++r.hits;
    if (!r.first.hit || before(k, rk, c.lambda_enter, r.first.lambda_enter)) r.first = c, rk = k;
  }
  return r;
}
template <class T, class Cast1>
auto first_hit(const Fan<T>& f, Cast1 cast1) {
  return first_hit(f, cast1, [](int, int, const auto& lk, const auto& lj) { return lk < lj; });
}

inline std::vector<Output> cast_outputs() {
  return {{"lambda_enter", 1, Output::on_hit},
          {"lambda_exit", 1, Output::on_hit},
          {"point", 3, Output::on_hit},
          {"normal", 3, Output::on_hit}};
}
inline constexpr const char* triangle_cast_help =
    "  lambda_enter, lambda_exit: the hit interval (graded only where both say hit; they differ only\n"
    "  for a shot in the triangle's plane)\n"
    "  point_[xyz]: the entry point; normal_[xyz]: the triangle's unit normal facing the source (0\n"
    "  when the source lies in the triangle's plane, or the triangle has zero area)\n"
    "  u, v: the barycentric weights of v1 and v2 at the entry point\n";
inline std::vector<Output> triangle_cast_outputs() {
  auto o = cast_outputs();
  o.push_back({"u", 1, Output::on_hit});
  o.push_back({"v", 1, Output::on_hit});
  return o;
}
inline std::vector<Output> prox_outputs() {
  return {{"distance", 1}, {"depth", 1}, {"witness_a", 3}, {"witness_b", 3}};
}
inline std::vector<Output> sat_outputs() { return {{"axis", 1, Output::on_miss, true}}; }
inline constexpr const char* sat_help =
    "  axis: when they do not intersect, the index of the first separating axis in the query's\n"
    "  documented order (graded only where both say apart, as right or wrong)\n";

// ---- values ----
// A value of the sqrt type S as the implementation of type F reports it (exact values
// rounded correctly to F).
template <class F, class S>
long double value(const S& x) {
  if constexpr (std::is_same_v<S, cdref::Bounded2> || std::is_same_v<S, cdref::Bounded>)
    return staged::rounded_value<F>(x);  // certain, or it throws
  else if constexpr (!number_traits<S>::is_exact)
    return static_cast<long double>(x);
  else if constexpr (std::is_same_v<F, long double>)
    return exact::round_long_double(x);
  else
    return static_cast<long double>(round_to<F>(x));
}

// The answer columns of a result type R under a spec's output groups (Spec::outputs()): for each
// field of R in fields.hpp's zip_fields order, the first of its columns in Answer::v, or -1
// where no output group names it (a cast's hit, a proximity's closest point). Computed once per
// spec and result type; a group no field carries, or whose width is not its field's, is a
// mistake in the spec, named when the spec is first used.
template <class Spec, class R>
const std::vector<int>& columns_of() {
  static const std::vector<int> cols = [] {
    const std::vector<Output> outs = Spec::outputs();
    std::vector<int> c;
    std::vector<bool> found(outs.size(), false);
    const R r{};
    zip_fields(r, r, [&](const char* name, const auto& x, const auto&) {
      constexpr int width = requires { x.rows(); } ? 3 : 1;
      int at = 0, col = -1;
      for (std::size_t g = 0; g < outs.size(); at += outs[g].width, ++g)
        if (outs[g].name == name) {
          if (outs[g].width != width)
            throw std::logic_error(std::string(Spec::name) + ": output " + name + " has width " +
                                   std::to_string(outs[g].width) + ", its field " + std::to_string(width));
          col = at;
          found[g] = true;
          break;
        }
      c.push_back(col);
    });
    for (std::size_t g = 0; g < outs.size(); ++g)
      if (!found[g]) throw std::logic_error(std::string(Spec::name) + ": no field of its result is named " + outs[g].name);
    return c;
  }();
  return cols;
}

// A query's result into an Answer: its classification (fields.hpp's classification_of), and
// with `values` its outputs in the spec's column order (columns_of): a label (a flag or an
// index) as its number, every other value as the implementation of type F reports it (value).
template <class Spec, class F, class R>
void put(Answer& a, const R& r, bool values) {
  a.cls = classification_of(r);
  if constexpr (!std::is_same_v<R, bool>) {
    if (!values) return;
    const std::vector<int>& col = columns_of<Spec, R>();
    std::size_t i = 0;
    zip_fields(r, r, [&](const char*, const auto& x, const auto&) {
      const int c = col[i++];
      if (c < 0) return;
      using X = std::remove_cvref_t<decltype(x)>;
      if constexpr (std::is_same_v<X, bool>)
        a.v[c] = x ? 1 : 0;
      else if constexpr (std::is_same_v<X, int>)
        a.v[c] = x;
      else if constexpr (requires { x.rows(); })
        for (int k = 0; k < 3; ++k) a.v[c + k] = value<F>(x[k]);
      else
        a.v[c] = value<F>(x);
    });
  }
}

// ---- what a spec must have ----
// check<Spec>() states the required members one by one, each with the message a contributor
// reads when it is missing or has the wrong shape (describe<Spec>() calls it first, so a spec
// that lacks one fails there, not deep inside the descriptor's machinery). The optional
// members are listed in this file's header comment; each is detected where it is used.
template <class Spec>
consteval bool check() {
  static_assert(requires { { Spec::id } -> std::convertible_to<int>; },
                "a spec needs `static constexpr int id`: the next free id (fuzz/queries.cpp checks they are dense)");
  static_assert(requires {
    { Spec::name } -> std::convertible_to<const char*>;
    { Spec::cls_name } -> std::convertible_to<const char*>;
    { Spec::pred_name } -> std::convertible_to<const char*>;
    { Spec::describe } -> std::convertible_to<const char*>;
    { Spec::full_call } -> std::convertible_to<const char*>;
    { Spec::answer_help } -> std::convertible_to<const char*>;
  }, "a spec needs the names `name`, `cls_name`, `pred_name`, `describe`, `full_call` and `answer_help` "
     "(static constexpr const char*)");
  static_assert(requires { { Spec::book_is_truth } -> std::convertible_to<bool>; },
                "a spec needs `static constexpr bool book_is_truth` (false: it provides truth() and truth_pred())");
  static_assert(requires {
    { Spec::inputs() } -> std::same_as<std::vector<std::string>>;
    { Spec::outputs() } -> std::same_as<std::vector<Output>>;
    { Spec::families() } -> std::same_as<std::vector<Family>>;
  }, "a spec needs `static std::vector<std::string> inputs()`, `static std::vector<Output> outputs()` and "
     "`static std::vector<Family> families()`");
  static_assert(requires(const Inputs& in) {
    Spec::template make<double>(in).first;
    Spec::template make<double>(in).second;
    Spec::template make<cdref::Bounded>(in).first;
    Spec::template make<CGAL::Gmpq>(in).second;
  }, "a spec needs `template <class T> static std::pair<A<T>, B<T>> make(const Inputs&)`: its two primitives "
     "from a case's columns, at every number type");
  if constexpr (requires(const Inputs& in) { Spec::template make<double>(in).first; }) {
    using P = decltype(Spec::template make<double>(std::declval<const Inputs&>()));
    static_assert(requires(const P& p) {
      Spec::book(p.first, p.second, 0u);
      { Spec::book_pred(p.first, p.second) } -> std::convertible_to<bool>;
      { Spec::bare(p.first, p.second) } -> std::convertible_to<bool>;
    }, "a spec needs the book: `book(a, b, unsigned want)` (the full query), `book_pred(a, b)` (the other "
       "formulation of its classification) and `bare(a, b)` (book::unchecked), templates over the number type");
    static_assert(requires(const P& p) {
      classification_of(Spec::book(p.first, p.second, 0u));
    }, "the book's result must be a Cast, TriangleCast, FanCast, Proximity, Separation, TriangleIntersection or "
       "bool (fields.hpp: classification_of; spec.hpp: put)");
    static_assert(requires(const P& p) {
      Spec::robust(p.first, p.second);
      { Spec::robust_pred(p.first, p.second) } -> std::convertible_to<bool>;
      { Spec::robust_decide(p.first, p.second) } -> std::same_as<robust::Decision>;
    }, "a spec needs the robust tier: `robust(a, b)`, `robust_pred(a, b)` and `robust_decide(a, b)` "
       "(a robust::Decision), templates over the float type");
    if constexpr (!Spec::book_is_truth)
      static_assert(requires(const P& p) {
        Spec::truth(p.first, p.second, 0u);
        { Spec::truth_pred(p.first, p.second) } -> std::convertible_to<bool>;
      }, "a spec with book_is_truth = false needs `truth(a, b, w)` and `truth_pred(a, b)`: the exact formulation");
  }
  return true;
}

// ---- the truth's formulation ----
// The book at an exact type, unless the spec names its own exact formulation
// (book_is_truth = false: `truth` and `truth_pred`). Every place that asks for the truth
// asks through these two.
template <class Spec, class A, class B>
auto truth_formulation(const A& a, const B& b, unsigned want) {
  if constexpr (Spec::book_is_truth)
    return Spec::book(a, b, want);
  else
    return Spec::truth(a, b, want);
}
template <class Spec, class A, class B>
bool truth_predicate(const A& a, const B& b) {
  if constexpr (Spec::book_is_truth)
    return bool(Spec::book_pred(a, b));
  else
    return bool(Spec::truth_pred(a, b));
}

// The classification of the truth's formulation at T, on primitives rebound to T.
template <class Spec, class T, class A, class B>
bool classification_at(const A& a, const B& b) {
  return classification_of(truth_formulation<Spec>(rebind<T>(a), rebind<T>(b), 0u));
}

// ---- the evaluations at the exact types, compiled in one unit of their own ----
// The evaluations below reach a query at CGAL::Gmpq (and CGAL::Epeck::FT) only through these
// functions (and the rows and the truth API's exact path through theirs, describe.hpp and
// truth_api.hpp), declared here and defined for every query in fuzz/queries/exact_paths.cpp
// alone, compiled at -O1: their time is GMP's and CGAL's arithmetic, not the inliner's, and
// at -O3 they were nearly a third of the query units' compile (groups.hpp). (a hand-written
// oracle's own exact stage stays with its query)
// The primitives of a case at double.
template <class Spec>
using DoublePair = decltype(Spec::template make<double>(std::declval<const Inputs&>()));
template <class Spec>
using DoubleA = typename DoublePair<Spec>::first_type;
template <class Spec>
using DoubleB = typename DoublePair<Spec>::second_type;
// truth_at<Spec, CGAL::Gmpq, F> (F = float, double, long double).
template <class Spec, class F>
Answer gmpq_truth_at(const Inputs& in, bool values, bool certified);
// book_at<Spec, T, double>(in, true) for T = CGAL::Gmpq and CGAL::Epeck::FT.
template <class Spec, class T>
Answer exact_book_at(const Inputs& in);
// classification_at<Spec, CGAL::Gmpq> on a case's double primitives.
template <class Spec>
bool gmpq_classification(const DoubleA<Spec>& a, const DoubleB<Spec>& b);
// entry_at<Spec, CGAL::Gmpq> (below): a cast's lambda_enter, exact, rounded correctly to double.
template <class Spec>
double gmpq_enter(const Inputs& in);

// ---- the classification oracle ----
// A spec's own `oracle(a, b, Stage*)` (its hand-written filters: a fast path) where it has
// one, else the generic staged path on its primitives (cdref/exact/staged.hpp): the truth's
// formulation on a bounded double, a bounded double word, then CGAL::Gmpq. Either is exact;
// where a spec has both, the tests check them equal on every family.
template <class Spec>
constexpr bool has_hand_oracle = requires(const Inputs& in, oracle::Stage* st) {
  { Spec::oracle(Spec::template make<double>(in).first, Spec::template make<double>(in).second, st) }
      -> std::convertible_to<bool>;
};
template <class Spec, class A, class B>
bool staged_classification(const A& a, const B& b, staged::Stage* st) {
  return staged::evaluate(
      [&]<class T>(staged::at<T>) {
        if constexpr (std::is_same_v<T, CGAL::Gmpq> && std::is_same_v<A, DoubleA<Spec>> &&
                      std::is_same_v<B, DoubleB<Spec>>)
          return gmpq_classification<Spec>(a, b);
        else
          return classification_at<Spec, T>(a, b);
      },
      st);
}
template <class Spec, class A, class B>
bool oracle_of(const A& a, const B& b, oracle::Stage* st) {
  if constexpr (has_hand_oracle<Spec>) {
    return Spec::oracle(a, b, st);
  } else {
    staged::Stage s;
    const bool r = staged_classification<Spec>(a, b, &s);
    if (st) *st = s == staged::Stage::bounded ? oracle::Stage::filter
                  : s == staged::Stage::word  ? oracle::Stage::expansion
                                              : oracle::Stage::rational;
    return r;
  }
}

// ---- evaluations ----
// An exact type cannot hold NaN or an infinity (and GMP's mpq_set_d raises SIGFPE on one):
// such inputs are refused by column name before any conversion to a type that is not IEEE.
template <class Spec>
[[gnu::cold, gnu::noinline]] void refuse_not_finite(const Inputs& in) {
  for (std::size_t k = 0; k < Spec::inputs().size(); ++k)
    if (!std::isfinite(in[k]))
      throw invalid_input(Spec::inputs()[k] + " is not finite (" +
                          (std::isnan(in[k]) ? "nan" : (in[k] > 0 ? "inf" : "-inf")) + ")");
}
template <class Spec, class T>
[[gnu::always_inline]] inline void require_finite(const Inputs& in) {
  if constexpr (!std::is_floating_point_v<T>) {
    static const std::size_t n = Spec::inputs().size();
    // one branch for all of them (an exponent field of all ones: infinite or NaN), the
    // message built only when one is (inlined where it is called, the message not)
    constexpr std::uint64_t exponent = 0x7ffull << 52;
    std::uint64_t bad = 0;
    for (std::size_t k = 0; k < n; ++k) bad |= std::uint64_t((std::bit_cast<std::uint64_t>(in[k]) & exponent) == exponent);
    if (bad) [[unlikely]]
      refuse_not_finite<Spec>(in);
  }
}

// One evaluation of a query on a case's columns, the shape of every tier's: the primitives made
// at T, `full(a, b, want)` (the full query, every output asked when `values`) put into the answer
// with its values rounded to F, and `pred(a, b)` in the predicate column. `certified`: T is exact
// or certifies every decision it takes (cdref::Bounded2 throws cdref::uncertain rather than
// decide a sign it cannot), so the predicate is the full query's classification (the two
// formulations agree exactly: tested) and is not evaluated again. Columns T cannot hold
// (infinite or NaN at an exact or bounded type) are refused first (require_finite).
template <class Spec, class T, class F, class Full, class Pred>
[[gnu::always_inline]] inline Answer answer_at(const Inputs& in, bool values, bool certified, const Full& full,
                                               const Pred& pred) {
  require_finite<Spec, T>(in);
  const auto [a, b] = Spec::template make<T>(in);
  Answer r;
  put<Spec, F>(r, full(a, b, values ? unsigned(want_all) : 0u), values);
  r.pred = certified ? r.cls : bool(pred(a, b));
  return r;
}

// The book at T.
template <class Spec, class T, class F>
Answer book_at(const Inputs& in, bool values, bool certified = false) {
  return answer_at<Spec, T, F>(
      in, values, certified, [](const auto& a, const auto& b, unsigned want) { return Spec::book(a, b, want); },
      [](const auto& a, const auto& b) { return Spec::book_pred(a, b); });
}

// The truth's formulation at T (the book, unless the spec says otherwise).
template <class Spec, class T, class F>
Answer truth_at(const Inputs& in, bool values, bool certified = false) {
  return answer_at<Spec, T, F>(
      in, values, certified,
      [](const auto& a, const auto& b, unsigned want) { return truth_formulation<Spec>(a, b, want); },
      [](const auto& a, const auto& b) { return truth_predicate<Spec>(a, b); });
}

// The float type of a precision (24: float, 64: long double where the evaluation has one, any
// other: double), handed to f as a null pointer of that type: the one dispatch of the
// evaluations that report in a case's precision.
template <bool long_double = true, class Fn>
decltype(auto) at_precision(int precision, const Fn& f) {
  if (precision == 24) return f(static_cast<float*>(nullptr));
  if constexpr (long_double)
    if (precision == 64) return f(static_cast<long double*>(nullptr));
  return f(static_cast<double*>(nullptr));
}

template <class Spec>
std::string hex_inputs(const Inputs& in) {
  std::string where;
  const std::size_t n = Spec::inputs().size();
  for (std::size_t i = 0; i < n; ++i) {
    where += ' ';
    where += hexfloat(in[i]);
  }
  return where;
}

// The robust versions (float/cdref/robust): the full query, the predicate, and the
// certificate of robust::decide, which must classify as the full query does.
template <class Spec, class F>
Answer robust_at(const Inputs& in) {
  const auto [a, b] = Spec::template make<F>(in);
  Answer r;
  put<Spec, F>(r, Spec::robust(a, b), true);
  r.pred = Spec::robust_pred(a, b);
  const robust::Decision d = Spec::robust_decide(a, b);
  if (d.value != r.cls)
    throw std::logic_error(std::string("robust::decide and the robust query disagree on ") + Spec::name + " at" +
                           hex_inputs<Spec>(in));
  r.certified = true;
  r.certain = d.certain;
  return r;
}

// The stable tier (float/cdref/stable): the full query and its classification alone.
template <class Spec, class F>
Answer stable_at(const Inputs& in, bool values = true) {
  return answer_at<Spec, F, F>(
      in, values, false, [](const auto& a, const auto& b, unsigned want) { return Spec::stable(a, b, want); },
      [](const auto& a, const auto& b) { return Spec::stable_pred(a, b); });
}
// A block of cases' verdicts: set(in[k], v) fills v's classification and predicate; inputs it
// refuses (invalid_input) leave v refused and nothing else.
template <class Set>
void verdicts(const Inputs* in, std::size_t n, Verdict* out, const Set& set) {
  for (std::size_t k = 0; k < n; ++k) {
    Verdict v;
    try {
      set(in[k], v);
    } catch (const invalid_input&) {
      v = Verdict{};
      v.refused = true;
    }
    out[k] = v;
  }
}
// The book's (and the stable tier's) classification and predicate over a block of cases, as
// book_at (stable_at) with no values.
template <class Spec, class T>
void book_classification_block(const Inputs* in, std::size_t n, Verdict* out) {
  verdicts(in, n, out, [](const Inputs& x, Verdict& v) {
    require_finite<Spec, T>(x);
    const auto [a, b] = Spec::template make<T>(x);
    v.cls = classification_of(Spec::book(a, b, 0u));
    v.pred = bool(Spec::book_pred(a, b));
  });
}
template <class Spec, class F>
void stable_classification_block(const Inputs* in, std::size_t n, Verdict* out) {
  verdicts(in, n, out, [](const Inputs& x, Verdict& v) {
    const auto [a, b] = Spec::template make<F>(x);
    v.cls = classification_of(Spec::stable(a, b, 0u));
    v.pred = Spec::stable_pred(a, b);
  });
}

template <class Spec>
constexpr bool has_stable = requires(const Inputs& in) {
  Spec::stable(Spec::template make<double>(in).first, Spec::template make<double>(in).second, 0u);
  Spec::stable_pred(Spec::template make<double>(in).first, Spec::template make<double>(in).second);
  Spec::stable_bare(Spec::template make<double>(in).first, Spec::template make<double>(in).second);
};

template <class Spec>
Answer truth_of(const Inputs& in, int precision) {
  return at_precision(precision, [&in]<class F>(F*) { return gmpq_truth_at<Spec, F>(in, true, false); });
}

// The truth's formulation run on cdref::Bounded2 (a double word with a rigorous error
// bound, about 106 bits: room for a float's, a double's and a long double's rounding),
// accepted when every comparison and every rounding is certain; otherwise the exact path.
// Where the spec has `oracle_formulation` (the truth's outputs in another formulation, equal to
// the truth's at every exact type and better conditioned in double words: the casts on a sphere,
// oracle/sphere_cast_foot.hpp), it runs on cdref::Bounded2 where the truth's own formulation is
// not certain there. The truth's goes first because it is the cheaper where it is certain: on
// the uniform draws (about 99% of which it answers) the every-output path took 745-779 ns a ray
// cast trying it first and 864-895 ns with the other alone; a test checks the formulation equal
// to the truth at CGAL::Gmpq on every family.
template <class Spec>
constexpr bool has_oracle_formulation = requires(const Inputs& in) {
  Spec::oracle_formulation(Spec::template make<cdref::Bounded2>(in).first,
                           Spec::template make<cdref::Bounded2>(in).second, 0u);
};
template <class Spec, class T, class F>
  requires has_oracle_formulation<Spec>
Answer formulation_at(const Inputs& in) {
  return answer_at<Spec, T, F>(
      in, true, true, [](const auto& a, const auto& b, unsigned want) { return Spec::oracle_formulation(a, b, want); },
      [](const auto&, const auto&) { return false; });
}
// Where the spec also has `oracle_formulation_first(a, b)` (at double), the cases it names try the other
// formulation first: those where the truth's own is seldom certain, whose failed attempt (an
// evaluation, then the `uncertain` it throws) costs more than the other formulation's.
template <class Spec>
constexpr bool has_formulation_first = requires(const Inputs& in) {
  { Spec::oracle_formulation_first(Spec::template make<double>(in).first, Spec::template make<double>(in).second) }
      -> std::same_as<bool>;
};
template <class Spec, class T, class F>
Answer oracle_formulation_at(const Inputs& in) {
  if constexpr (has_oracle_formulation<Spec>) {
    if constexpr (has_formulation_first<Spec>) {
      const auto [a, b] = Spec::template make<double>(in);
      if (Spec::oracle_formulation_first(a, b)) {
        try {
          return formulation_at<Spec, T, F>(in);
        } catch (const cdref::uncertain&) {
        }
        return truth_at<Spec, T, F>(in, true, true);
      }
    }
    try {
      return truth_at<Spec, T, F>(in, true, true);
    } catch (const cdref::uncertain&) {
    }
    return formulation_at<Spec, T, F>(in);
  } else {
    return truth_at<Spec, T, F>(in, true, true);
  }
}

// A cast's lambda_enter from oracle::enter (exact/cdref/oracle/enter.hpp), where the spec has it.
template <class Spec>
constexpr bool has_oracle_enter = requires(const Inputs& in, bool* e) {
  { Spec::oracle_enter(Spec::template make<double>(in).first, Spec::template make<double>(in).second, e) }
      -> std::same_as<oracle::Entry>;
};

// Every cast's hit and lambda_enter alone: oracle::enter where the spec has it (every cast
// cdref has), otherwise the oracle's classification, then on a hit the truth's formulation
// asked for lambda_enter alone, on cdref::Bounded2 (certain, or it throws) and then at
// CGAL::Gmpq, rounded correctly to double.
template <class R>
  requires requires(const R& r) { r.lambda_enter; }
const auto& entry_value(const R& r) {
  return r.lambda_enter;
}
template <class R>
  requires requires(const R& r) { r.first.lambda_enter; }
const auto& entry_value(const R& r) {
  return r.first.lambda_enter;  // a shot against several triangles: the first hit
}
template <class Spec>
constexpr bool is_cast = requires(const Inputs& in) {
  entry_value(Spec::book(Spec::template make<double>(in).first, Spec::template make<double>(in).second, 0u));
};
// A cast's lambda_enter from the truth's formulation at T asked for it alone, rounded to double
// (at cdref::Bounded2 where certain, or it throws cdref::uncertain; at an exact type
// correctly). On a hit.
template <class Spec, class T>
double entry_at(const Inputs& in) {
  const auto [x, y] = Spec::template make<T>(in);
  return double(value<double>(entry_value(truth_formulation<Spec>(x, y, unsigned(want_lambda_enter)))));
}
template <class Spec>
oracle::Entry oracle_enter_of(const Inputs& in, bool* exact_used) {
  require_finite<Spec, CGAL::Gmpq>(in);
  const auto [a, b] = Spec::template make<double>(in);
  if constexpr (has_oracle_enter<Spec>) {
    return Spec::oracle_enter(a, b, exact_used);
  } else {
    if (exact_used) *exact_used = false;
    oracle::Entry e;
    e.hit = oracle_of<Spec>(a, b, nullptr);
    if (!e.hit) return e;
    try {
      e.lambda_enter = entry_at<Spec, cdref::Bounded2>(in);
      return e;
    } catch (const cdref::uncertain&) {
    }
    if (exact_used) *exact_used = true;
    e.lambda_enter = gmpq_enter<Spec>(in);
    return e;
  }
}

template <class Spec>
Answer oracle_classify_of(const Inputs& in, bool* exact_used) {
  require_finite<Spec, CGAL::Gmpq>(in);
  const auto [a, b] = Spec::template make<double>(in);
  oracle::Stage stage = oracle::Stage::filter;
  Answer r;
  r.cls = r.pred = oracle_of<Spec>(a, b, &stage);  // at exact types the two formulations agree (tested)
  if (exact_used) *exact_used = stage != oracle::Stage::filter;
  return r;
}

// Whether every output of the query exists on a hit alone (a cast's: Output::on_hit).
template <class Spec>
bool outputs_on_hit_alone() {
  static const bool all = [] {
    for (const Output& o : Spec::outputs())
      if (o.when != Output::on_hit) return false;
    return true;
  }();
  return all;
}

// Where the spec has `oracle_rounded(a, b, result)` (at double: true where it proves every
// value of the truth rounded correctly, the robust tier's first look on a sphere and a triangle,
// a polygon or an oriented box, and on a shot and an oriented box; `result` of the robust tier's
// type), the every-output path at double takes it first; inputs it refuses go on to the
// formulation, which refuses them by name. It is one function with every call flattened into it
// (the spec's make, the first look, put): in the merged query units g++ kept the first look's
// helpers out of line, and ray-box's every output took 1.25 times as long, segment-box's 1.17,
// sphere-triangle's 1.14 (`cdref report`, three runs alternated, 2026-12-05; with it 0.96-0.98).
template <class Spec>
using RobustResult = std::decay_t<decltype(Spec::template robust<double>(
    Spec::template make<double>(std::declval<const Inputs&>()).first,
    Spec::template make<double>(std::declval<const Inputs&>()).second))>;
template <class Spec>
constexpr bool has_oracle_rounded = requires(const Inputs& in, RobustResult<Spec>& p) {
  { Spec::oracle_rounded(Spec::template make<double>(in).first, Spec::template make<double>(in).second, p) }
      -> std::same_as<bool>;
};
template <class Spec>
[[gnu::flatten]] bool oracle_rounded_of(const Inputs& in, Answer& r) {
  try {
    const auto [a, b] = Spec::template make<double>(in);
    RobustResult<Spec> p;
    if (!Spec::oracle_rounded(a, b, p)) return false;
    put<Spec, double>(r, p, true);
    r.pred = r.cls;
    return true;
  } catch (const invalid_input&) {
    return false;
  }
}

template <class Spec>
Answer oracle_truth_of(const Inputs& in, int precision, bool* exact_used) {
  if constexpr (is_cast<Spec>) {
    // A cast that misses has no outputs (each is Output::on_hit); there the classification
    // oracle answers alone, for a tenth of the formulation's time (uniform casts on a sphere
    // miss 85 times in 100). Its Answer is the formulation's on a miss: no hit, the values 0
    // (tested bit for bit against the exact answer on every family). Inputs it refuses go on to
    // the formulation, which refuses them with its own message.
    if (outputs_on_hit_alone<Spec>()) {
      Answer c;
      bool miss = false;
      try {
        c = oracle_classify_of<Spec>(in, exact_used);
        miss = !c.cls;
      } catch (const invalid_input&) {  // (refused below, with the formulation's message)
      }
      if (miss) return c;
    }
  }
  if (exact_used) *exact_used = false;
  if constexpr (has_oracle_rounded<Spec>)
    if (Answer r; precision == 53 && oracle_rounded_of<Spec>(in, r)) return r;
  try {
    return at_precision(precision,
                        [&in]<class F>(F*) { return oracle_formulation_at<Spec, cdref::Bounded2, F>(in); });
  } catch (const cdref::uncertain&) {
  }
  if (exact_used) *exact_used = true;
  return truth_of<Spec>(in, precision);
}

// ---- the generic staged path (cdref/exact/staged.hpp) ----
// The exact classification from the truth's own code run through the stages (cls = pred).
template <class Spec>
Answer staged_classify_of(const Inputs& in, int* stage) {
  require_finite<Spec, CGAL::Gmpq>(in);
  staged::Stage st;
  Answer r;
  const auto [a, b] = Spec::template make<double>(in);
  r.cls = r.pred = staged_classification<Spec>(a, b, &st);
  if (stage) *stage = int(st);
  return r;
}
// Every output of the truth, rounded correctly to the precision, through the stages (from
// the double word on for double and long double: the bounded double's few ulps seldom round
// a value correctly to them).
template <class Spec>
Answer staged_truth_of(const Inputs& in, int precision, int* stage) {
  require_finite<Spec, CGAL::Gmpq>(in);
  staged::Stage st;
  const auto run = [&]<class F>(F*) {
    constexpr auto first = std::is_same_v<F, float> ? staged::Stage::bounded : staged::Stage::word;
    return staged::evaluate<first>(
        [&in]<class T>(staged::at<T>) {
          if constexpr (std::is_same_v<T, CGAL::Gmpq>)
            return gmpq_truth_at<Spec, F>(in, true, true);
          else
            return truth_at<Spec, T, F>(in, true, true);
        },
        &st);
  };
  const Answer r = at_precision(precision, run);
  if (stage) *stage = int(st);
  return r;
}

// ... over a block of cases, one Verdict per case (cls = pred).
template <class Spec>
void oracle_classify_block_of(const Inputs* in, std::size_t n, Verdict* out) {
  verdicts(in, n, out, [](const Inputs& x, Verdict& v) {
    require_finite<Spec, CGAL::Gmpq>(x);
    const auto [a, b] = Spec::template make<double>(x);
    v.cls = v.pred = oracle_of<Spec>(a, b, nullptr);
  });
}

// The book at an exact type, values rounded to double: beside the truth where the book assumes
// more than its inputs give (orthonormal axes), its misclassifications are that assumption's
// alone, apart from any rounding.
template <class Spec>
Implementation book_exact_variant() {
  return {"book-exact", 53, [](Query, const Inputs& in) { return exact_book_at<Spec, CGAL::Gmpq>(in); },
          {Query{Spec::id}}};
}

}  // namespace cdref::fuzz::spec
