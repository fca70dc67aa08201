// fuzz/fuzzcheck.cpp - the checks behind the fuzz targets (see fuzzcheck.hpp).
#include <cdref/fuzz/eval.hpp>
#include <cdref/fuzz/fuzzcheck.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <stdexcept>

#include "../src/casefiles.hpp"

namespace cdref::fuzz {

namespace {

[[noreturn]] void violated(Query q, const Inputs& in, const char* what) {
  std::fprintf(stderr, "cdref fuzz: %s: %s\n  inputs:", info(q).name, what);
  for (std::size_t i = 0; i < info(q).inputs.size(); ++i) std::fprintf(stderr, " %a", in[i]);
  std::fprintf(stderr, "\n");
  std::abort();
}

bool same_value(long double a, long double b) {
  return (a == b && std::signbit(a) == std::signbit(b)) || (std::isnan(a) && std::isnan(b));
}

template <class T>
bool refuses(Query q, const Inputs& in, Answer& out) {
  try {
    out = eval<T, double>(q, in);
    return false;
  } catch (const invalid_input&) {
    return true;
  }
}

}  // namespace

bool decode_inputs(Query q, const std::uint8_t* data, std::size_t size, Inputs& in) {
  const std::size_t n = info(q).inputs.size();
  std::size_t p = 0;
  for (std::size_t k = 0; k < n; ++k) {
    if (p >= size) return false;
    const std::uint8_t mode = data[p++];
    if (mode < 192) {  // a small dyadic rational: an int8 over 2^(mode % 8)
      if (p >= size) return false;
      in[k] = double(std::int8_t(data[p++])) / double(1u << (mode % 8));
    } else {  // raw IEEE bits
      if (p + 8 > size) return false;
      std::memcpy(&in[k], data + p, 8);
      p += 8;
    }
  }
  return true;
}

void check_query(Query q, const std::uint8_t* data, std::size_t size) {
  Inputs in{};
  if (!decode_inputs(q, data, size, in)) return;
  Answer d, f;
  const bool d_refused = refuses<double>(q, in, d);
  // float runs for crashes and undefined behaviour; what it refuses depends on its own
  // rounding of the inputs (overflow, a direction that underflows to zero)
  refuses<float>(q, float_inputs(q, in), f);
  for (std::size_t i = 0; i < info(q).inputs.size(); ++i)
    if (!std::isfinite(in[i])) {
      if (!d_refused) violated(q, in, "a non-finite input was not refused");
      return;  // exact types cannot hold it
    }
  Answer g, l;
  const bool g_refused = refuses<CGAL::Gmpq>(q, in, g);
  const bool l_refused = refuses<CGAL::Epeck::FT>(q, in, l);
  if (g_refused != l_refused) violated(q, in, "Gmpq and Epeck::FT disagree on refusing the input");
  // box-box: the predicate column converts to min-max corners c +- e in the implementation's
  // type; at double they may overflow where the exact types hold them (the book at double
  // then refuses the min-max form: a documented limit of that conversion, not a disagreement)
  bool corners_overflow = false;
  if (q == Query::box_box)
    for (int k : {0, 1, 2, 6, 7, 8})
      corners_overflow = corners_overflow || !std::isfinite(in[k] + in[k + 3]) || !std::isfinite(in[k] - in[k + 3]);
  if (g_refused != d_refused && !(corners_overflow && d_refused))
    violated(q, in, "double and the exact types disagree on refusing the input");
  if (g_refused) return;
  if (g.cls != l.cls || g.pred != l.pred) violated(q, in, "Gmpq and Epeck::FT classify differently");
  for (int k = 0; k < max_values; ++k)
    if (!same_value(g.v[k], l.v[k])) violated(q, in, "Gmpq and Epeck::FT give different values");
  if (g.cls != g.pred) violated(q, in, "at an exact type the predicate and the full query disagree");
  // the oracle (filter first, exact when it cannot decide) gives exactly the exact answer
  const Answer o = oracle_truth(q, in, 53);
  if (o.cls != g.cls || o.pred != g.pred) violated(q, in, "the oracle classifies differently from Gmpq");
  for (int k = 0; k < max_values; ++k)
    if (!same_value(o.v[k], g.v[k])) violated(q, in, "the oracle's values differ from Gmpq's");
  const Answer oc = oracle_classify(q, in);
  if (oc.cls != g.cls || oc.pred != g.pred) violated(q, in, "the classification oracle differs from Gmpq");
  // the robust versions: a classification they call certain is the exact one
  for (const char* name : {"robust-double", "robust-long-double"}) {
    Answer r;
    try {
      r = implementation_by_name(name).run(q, in);  // double inputs are exact in long double
    } catch (const invalid_input&) {
      if (corners_overflow) continue;  // the min-max predicate column, as above
      violated(q, in, "a robust version refused an input the exact types take");
    }
    if (!r.certified) violated(q, in, "a robust version gave no certificate");
    if (r.certain && r.cls != g.cls) violated(q, in, "a robust version is certain and wrong");
  }
  {
    const Inputs fin = float_inputs(q, in);
    bool finite = true;
    for (std::size_t i = 0; i < info(q).inputs.size(); ++i) finite = finite && std::isfinite(fin[i]);
    Answer gf;
    if (finite && !refuses<CGAL::Gmpq>(q, fin, gf)) {
      try {
        const Answer r = implementation_by_name("robust-float").run(q, fin);
        if (r.certain && r.cls != gf.cls) violated(q, fin, "robust float is certain and wrong");
      } catch (const invalid_input&) {
        // float refuses what underflows in float (a direction rounded to zero)
      }
    }
  }
  if (q == Query::segment_sphere) {
    const Segment<CGAL::Gmpq> s{detail::v3<CGAL::Gmpq>(in, 0), detail::v3<CGAL::Gmpq>(in, 3)};
    const Sphere<CGAL::Gmpq> sp{detail::v3<CGAL::Gmpq>(in, 6), CGAL::Gmpq(in[9])};
    if (book::hit(s, sp) != g.cls) violated(q, in, "Algorithm 3.1 and Algorithm 3.2 disagree at Gmpq");
  }
}

void check_case_reader(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return;
  const Query q = all_queries()[data[0] % all_queries().size()];
  std::istringstream text(std::string(reinterpret_cast<const char*>(data + 1), size - 1));
  int bad = 0;
  try {
    const auto rows = cli::parse_cases(q, text, "fuzz", bad);
    if (rows.size() > size) std::abort();  // at most one row a line
  } catch (const std::runtime_error&) {
    // a header without the query's columns: refused by name, as documented
  }
}

}  // namespace cdref::fuzz
