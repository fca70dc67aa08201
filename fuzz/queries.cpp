// fuzz/queries.cpp - the queries a campaign runs: their input and output columns, and
// their evaluation by the book at float, double and (the truth) CGAL::Gmpq with exact
// square roots, rounded correctly. The one translation unit of the campaign engine that
// instantiates the exact types.
#include <cdref/exact.hpp>
#include <cdref/oracle/classify.hpp>
#include <cdref/fuzz/campaign.hpp>
#include <cdref/fuzz/eval.hpp>
#include <cdref/fuzz/primitives_of.hpp>
#include <cdref/robust/box_box.hpp>
#include <cdref/robust/ray_box.hpp>
#include <cdref/robust/ray_sphere.hpp>
#include <cdref/robust/segment_sphere.hpp>
#include <cdref/robust/sphere_box.hpp>
#include <cdref/robust/sphere_sphere.hpp>
#include <cstdio>
#include <stdexcept>

namespace cdref::fuzz {

namespace {

const std::vector<std::string> cast_outputs = {"lambda_enter", "lambda_exit", "point", "normal"};
const std::vector<int> cast_widths = {1, 1, 3, 3};
const std::vector<std::string> prox_outputs = {"distance", "depth", "witness_a", "witness_b"};
const std::vector<int> prox_widths = {1, 1, 3, 3};

std::vector<std::string> cols(std::initializer_list<std::pair<const char*, int>> parts) {
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

const std::vector<QueryInfo>& table() {
  static const std::vector<QueryInfo> t = {
      {Query::sphere_sphere, "sphere-sphere", "intersect", "intersect",
       cols({{"a_center", 3}, {"a_radius", 1}, {"b_center", 3}, {"b_radius", 1}}), prox_outputs, prox_widths,
       "Section 3.1.1: book::proximity(A, B) and book::intersect(A, B)"},
      {Query::segment_sphere_cast, "segment-sphere-cast", "hit", "hit",
       cols({{"source", 3}, {"target", 3}, {"center", 3}, {"radius", 1}}), cast_outputs, cast_widths,
       "Algorithm 3.1 on the segment source->target: book::cast and book::hit"},
      {Query::ray_sphere_cast, "ray-sphere-cast", "hit", "hit",
       cols({{"source", 3}, {"direction", 3}, {"center", 3}, {"radius", 1}}), cast_outputs, cast_widths,
       "Algorithm 3.1 on the infinite ray source + lambda direction: book::cast and book::hit"},
      {Query::segment_sphere, "segment-sphere", "intersect", "intersect",
       cols({{"source", 3}, {"target", 3}, {"center", 3}, {"radius", 1}}), prox_outputs, prox_widths,
       "Algorithm 3.2: book::proximity(segment, sphere) and book::intersect (witness_a on the segment)"},
      {Query::box_box, "box-box", "intersect", "intersect-min-max",
       cols({{"a_center", 3}, {"a_extent", 3}, {"b_center", 3}, {"b_extent", 3}}), {}, {},
       "Section 3.2: book::intersect in centre-extent form; the predicate column is the min-max form "
       "on corners rounded to the implementation's type"},
      {Query::segment_box_cast, "segment-box-cast", "hit", "hit",
       cols({{"source", 3}, {"target", 3}, {"center", 3}, {"extent", 3}}), cast_outputs, cast_widths,
       "Algorithm 3.3 on the segment source->target: book::cast and book::hit"},
      {Query::ray_box_cast, "ray-box-cast", "hit", "hit",
       cols({{"source", 3}, {"direction", 3}, {"center", 3}, {"extent", 3}}), cast_outputs, cast_widths,
       "Algorithm 3.3 on the infinite ray: book::cast and book::hit"},
      {Query::sphere_box, "sphere-box", "intersect", "intersect",
       cols({{"center", 3}, {"radius", 1}, {"box_center", 3}, {"box_extent", 3}}), prox_outputs, prox_widths,
       "Section 3.2.2: book::proximity(sphere, box) and book::intersect (witness_a on the sphere)"},
  };
  return t;
}

// The robust float formulations (float/cdref/robust): the full query, the predicate, and
// the certificate of robust::decide.
template <class F>
Answer eval_robust(Query q, const Inputs& in) {
  Answer a;
  const robust::Decision d = with_primitives<F>(q, in, [&a](const auto& x, const auto& y, bool algorithm_3_2) {
    using A = std::decay_t<decltype(x)>;
    if constexpr (std::is_same_v<A, Box<F>>) {  // box-box: the predicate column is the min-max form
      a.cls = robust::intersect(x, y);
      a.pred = robust::intersect(to_min_max(x), to_min_max(y));
      return robust::decide(x, y);
    } else if constexpr (std::is_same_v<A, Sphere<F>>) {  // sphere-sphere, sphere-box
      detail::put_prox<F>(a, robust::proximity(x, y));
      a.pred = robust::intersect(x, y);
      return robust::decide(x, y);
    } else {
      if constexpr (std::is_same_v<A, Segment<F>> && std::is_same_v<std::decay_t<decltype(y)>, Sphere<F>>)
        if (algorithm_3_2) {
          detail::put_prox<F>(a, robust::proximity(x, y));
          a.pred = robust::intersect(x, y);
          return robust::decide_closest(x, y);
        }
      detail::put_cast<F>(a, robust::cast(x, y));  // the casts on a sphere or a box
      a.pred = robust::hit(x, y);
      return robust::decide(x, y);
    }
  });
  if (d.value != a.cls) {
    std::string where;
    for (std::size_t i = 0; i < info(q).inputs.size(); ++i) {
      where += ' ';
      where += hexfloat(in[i]);
    }
    throw std::logic_error(std::string("robust::decide and the robust query disagree on ") + info(q).name +
                           " at" + where);
  }
  a.certified = true;
  a.certain = d.certain;
  return a;
}

}  // namespace

const QueryInfo& info(Query q) { return table().at(static_cast<std::size_t>(q)); }

const std::vector<Query>& all_queries() {
  static const std::vector<Query> qs = [] {
    std::vector<Query> v;
    for (const QueryInfo& i : table()) v.push_back(i.q);
    return v;
  }();
  return qs;
}

Query query_by_name(const std::string& name) {
  std::string names;
  for (const QueryInfo& i : table()) {
    if (name == i.name) return i.q;
    names += (names.empty() ? "" : ", ") + std::string(i.name);
  }
  throw std::invalid_argument("unknown query '" + name + "' (queries: " + names + ")");
}

Answer truth(Query q, const Inputs& in, int precision) {
  if (precision == 24) return eval<CGAL::Gmpq, float>(q, in);
  if (precision == 64) return eval<CGAL::Gmpq, long double>(q, in);
  return eval<CGAL::Gmpq, double>(q, in);
}

Answer oracle_truth(Query q, const Inputs& in, int precision, bool* exact_used) {
  if (exact_used) *exact_used = false;
  if (precision != 64) {
    try {
      return precision == 24 ? eval<oracle::Bounded2, float>(q, in) : eval<oracle::Bounded2, double>(q, in);
    } catch (const oracle::uncertain&) {
    }
  }
  if (exact_used) *exact_used = true;
  return truth(q, in, precision);
}

Answer oracle_classify(Query q, const Inputs& in, bool* exact_used) {
  // exact/cdref/oracle/classify.hpp: a semi-static filter, then exact floating-point
  // expansions, then the book at Gmpq; the answer is always the exact classification.
  oracle::Stage stage = oracle::Stage::filter;
  const bool c = with_primitives<double>(q, in, [&stage](const auto& a, const auto& b, bool algorithm_3_2) {
    using A = std::decay_t<decltype(a)>;
    using B = std::decay_t<decltype(b)>;
    if constexpr (std::is_same_v<A, Segment<double>> && std::is_same_v<B, Sphere<double>>)
      if (algorithm_3_2) return oracle::classify_segment_sphere(a, b, &stage);
    return oracle::classify(a, b, &stage);
  });
  if (exact_used) *exact_used = stage != oracle::Stage::filter;
  Answer a;
  a.cls = a.pred = c;  // at exact types the full query and the predicate agree (tested)
  return a;
}

Inputs float_inputs(Query q, const Inputs& in) {
  Inputs out{};
  const std::size_t n = info(q).inputs.size();
  for (std::size_t i = 0; i < n; ++i) out[i] = double(float(in[i]));
  return out;
}

const std::vector<Implementation>& builtin_implementations() {
  static const std::vector<Implementation> impls = {
      {"book-float", 24, [](Query q, const Inputs& in) { return eval<float, float>(q, in); }},
      {"book-double", 53, [](Query q, const Inputs& in) { return eval<double, double>(q, in); }},
      {"book-long-double", 64, [](Query q, const Inputs& in) { return eval<long double, long double>(q, in); }},
      {"robust-float", 24, eval_robust<float>},
      {"robust-double", 53, eval_robust<double>},
      {"robust-long-double", 64, eval_robust<long double>},
  };
  return impls;
}

const Implementation& implementation_by_name(const std::string& name) {
  std::string names;
  for (const Implementation& i : builtin_implementations()) {
    if (i.name == name) return i;
    names += (names.empty() ? "" : ", ") + i.name;
  }
  throw std::invalid_argument("unknown implementation '" + name + "' (implementations: " + names + ")");
}

std::string hexfloat(double x) {
  char b[40];
  std::snprintf(b, sizeof b, "%a", x);
  return b;
}

std::string hexfloat(long double x) {
  char b[48];
  std::snprintf(b, sizeof b, "%La", x);
  return b;
}

}  // namespace cdref::fuzz
