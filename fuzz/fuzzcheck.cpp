// fuzz/fuzzcheck.cpp - the checks behind the fuzz targets (see fuzzcheck.hpp).
#include <cdref/error.hpp>
#include <cdref/fuzz/fuzzcheck.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <stdexcept>

#include <cdref/fuzz/work.hpp>

#include "../src/casefiles.hpp"
#include "../src/scene/scene.hpp"

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

template <class Run>
bool refuses(Run run, Answer& out) {
  try {
    out = run();
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
  const QueryInfo& qi = info(q);
  Answer d, f;
  const bool d_refused = refuses([&] { return qi.book(53, in); }, d);
  // float runs for crashes and undefined behaviour; what it refuses depends on its own
  // rounding of the inputs (overflow, a direction that underflows to zero)
  const Inputs fin = float_inputs(q, in);
  refuses([&] { return qi.book(24, fin); }, f);
  for (std::size_t i = 0; i < qi.inputs.size(); ++i)
    if (!std::isfinite(in[i])) {
      if (!d_refused) violated(q, in, "a non-finite input was not refused");
      // the exact paths refuse it by name, without a signal
      Answer t;
      if (!refuses([&] { return truth(q, in, 53); }, t)) violated(q, in, "the truth took a non-finite input");
      if (!refuses([&] { return oracle_classify(q, in); }, t)) violated(q, in, "the oracle took a non-finite input");
      if (qi.oracle_enter && !refuses([&] { return qi.oracle_enter(in, nullptr); }, t))
        violated(q, in, "oracle::enter took a non-finite input");
      return;
    }
  Answer g, l;
  const bool g_refused = refuses([&] { return qi.book_exact(Exact::gmpq, in); }, g);
  const bool l_refused = refuses([&] { return qi.book_exact(Exact::epeck, in); }, l);
  if (g_refused != l_refused) violated(q, in, "Gmpq and Epeck::FT disagree on refusing the input");
  const bool may_refuse = qi.double_may_refuse && qi.double_may_refuse(in);
  if (g_refused != d_refused && !(may_refuse && d_refused))
    violated(q, in, "double and the exact types disagree on refusing the input");
  if (g_refused) {
    // the classification oracle (campaigns and case files grading the classification alone)
    // refuses what the exact types refuse
    Answer oc;
    if (!refuses([&] { return oracle_classify(q, in); }, oc))
      violated(q, in, "the classification oracle answered an input the exact types refuse");
    return;
  }
  if (g.cls != l.cls || g.pred != l.pred) violated(q, in, "Gmpq and Epeck::FT classify differently");
  for (int k = 0; k < max_values; ++k)
    if (!same_value(g.v[k], l.v[k])) violated(q, in, "Gmpq and Epeck::FT give different values");
  // the truth (the book at an exact type, or the query's exact formulation where the book
  // assumes more than its inputs give)
  const Answer t = truth(q, in, 53);
  if (qi.book_is_truth) {
    if (g.cls != g.pred) violated(q, in, "at an exact type the predicate and the full query disagree");
    if (g.cls != t.cls) violated(q, in, "the truth differs from the book at Gmpq");
  }
  if (t.cls != t.pred) violated(q, in, "the truth's two formulations disagree");
  // the oracle (filter first, exact when it cannot decide) gives exactly the exact answer
  const Answer o = oracle_truth(q, in, 53);
  if (o.cls != t.cls || o.pred != t.pred) violated(q, in, "the oracle classifies differently from the truth");
  for (int k = 0; k < max_values; ++k)
    if (!same_value(o.v[k], t.v[k])) violated(q, in, "the oracle's values differ from the truth's");
  // and at long double precision, where the double word rounds to long double too
  const Answer t64 = truth(q, in, 64), o64 = oracle_truth(q, in, 64);
  if (o64.cls != t64.cls || o64.pred != t64.pred)
    violated(q, in, "the oracle classifies differently from the truth at long double precision");
  for (int k = 0; k < max_values; ++k)
    if (!same_value(o64.v[k], t64.v[k])) violated(q, in, "the oracle's long double values differ from the truth's");
  Answer oc;
  if (refuses([&] { return oracle_classify(q, in); }, oc))
    violated(q, in, "the classification oracle refused an input the exact types take");
  if (oc.cls != t.cls || oc.pred != t.pred) violated(q, in, "the classification oracle differs from the truth");
  // a cast's hit and lambda_enter alone (oracle::enter): the truth's, bit for bit (0 on a miss)
  if (qi.oracle_enter) {
    Answer e;
    if (refuses([&] { return qi.oracle_enter(in, nullptr); }, e))
      violated(q, in, "oracle::enter refused an input the exact types take");
    if (e.cls != t.cls) violated(q, in, "oracle::enter classifies differently from the truth");
    if (!same_value(e.v[0], t.cls ? t.v[0] : 0.0L)) violated(q, in, "oracle::enter differs from the truth's lambda_enter");
  }
  // the robust versions: a classification they call certain is the exact one
  for (int precision : {53, 64}) {
    Answer r;
    try {
      r = qi.robust(precision, in);  // double inputs are exact in long double
    } catch (const invalid_input&) {
      if (may_refuse) continue;  // as above
      violated(q, in, "a robust version refused an input the exact types take");
    }
    if (!r.certified) violated(q, in, "a robust version gave no certificate");
    if (r.certain && r.cls != t.cls) violated(q, in, "a robust version is certain and wrong");
  }
  // the stable tier (no certificate): it takes what the exact types take, and its full query
  // and its classification alone decide alike
  if (qi.stable) {
    Answer s;
    try {
      s = qi.stable(53, in);
    } catch (const invalid_input&) {
      if (!may_refuse) violated(q, in, "the stable tier refused an input the exact types take");
    }
    if (s.cls != s.pred) violated(q, in, "the stable tier's full query and classification disagree");
  }
  {
    bool finite = true;
    for (std::size_t i = 0; i < qi.inputs.size(); ++i) finite = finite && std::isfinite(fin[i]);
    Answer tf;
    if (finite && !refuses([&] { return truth(q, fin, 53); }, tf)) {
      try {
        const Answer r = qi.robust(24, fin);
        if (r.certain && r.cls != tf.cls) violated(q, fin, "robust float is certain and wrong");
      } catch (const invalid_input&) {
        // float refuses what underflows in float (a direction rounded to zero)
      }
    }
  }
  if (qi.fuzz_extra)
    if (const char* why = qi.fuzz_extra(in)) violated(q, in, why);
}

void check_case_reader(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return;
  const Query q = all_queries()[data[0] % all_queries().size()];
  // Bytes 0xf0..0xff stand for the tokens a case file must survive, so that mutations make
  // them often: non-finite values, literals beyond double's range, subnormals, empty fields.
  static const char* const tokens[16] = {"nan", "-nan", "inf", "-inf", "1e400", "-1e400", "0x1p+2000",
                                         "4.9406564584124654e-324", "0x1p-1074", "1e-400", "-0", "",
                                         "0x1.fffffffffffffp+1023", "NaN", "Infinity", "2.2250738585072009e-308"};
  std::string text;
  for (std::size_t i = 1; i < size; ++i) {
    const std::uint8_t b = data[i];
    if (b >= 0xf0)
      text += tokens[b - 0xf0];
    else
      text += char(b);
  }
  std::istringstream in(text);
  int bad = 0;
  std::vector<cli::CaseRow> rows;
  try {
    rows = cli::parse_cases(q, in, "fuzz", bad);
    if (rows.size() > size) std::abort();  // at most one row a line
  } catch (const std::runtime_error&) {
    return;  // a header without the query's columns: refused by name, as documented
  }
  // every row is answered as `cdref oracle` answers it, or refused by name (never a signal)
  std::size_t answered = 0;
  for (const cli::CaseRow& r : rows) {
    if (answered++ >= 16) break;
    for (int precision : {53, 24}) {
      try {
        cli::answer_case(q, r, precision);
      } catch (const invalid_input&) {
      }
    }
  }
}

void check_results_reader(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  // a campaign's text form (a shard, a checkpoint, --out): read whole or refused by line;
  // what is read writes back to the same statistics
  try {
    const Saved s = deserialize(text, "fuzz");
    const Saved back = deserialize(serialize(s), "fuzz (written back)");
    if (!(back.results == s.results) || back.fingerprint != s.fingerprint || back.items_done != s.items_done) {
      std::fprintf(stderr, "cdref fuzz: a results file does not survive its own round trip\n");
      std::abort();
    }
    // its counts against the campaign its fingerprint describes (as --resume and merge check
    // them): consistent or refused by name, never a signal
    try {
      Spec spec = spec_of_fingerprint(s.fingerprint);
      spec.shard = s.shard;
      spec.shards = s.shards;
      const Work work(spec);
      if (s.items_done <= work.items()) work.check(s.results, {{0, s.items_done}}, "fuzz");
    } catch (const std::exception&) {
    }
  } catch (const std::runtime_error&) {
  }
  // a rank's checkpoint (cdref-mpi): its done items and its statistics agree, or it is refused
  try {
    const PartCheckpoint c = deserialize_part(text, "fuzz");
    const PartCheckpoint back = deserialize_part(serialize(c), "fuzz (written back)");
    if (c.done.count() != c.saved.items_done || !(back.done == c.done) || !(back.saved.results == c.saved.results)) {
      std::fprintf(stderr, "cdref fuzz: a rank's checkpoint does not survive its own round trip\n");
      std::abort();
    }
  } catch (const std::runtime_error&) {
  }
}

void check_scene_reader(const std::uint8_t* data, std::size_t size) {
  // bytes 0xf0.. stand for the numbers and literals a scene file must survive
  static const char* const tokens[16] = {"1e400", "-1e400", "NaN", "Infinity", "1e39", "-0", "4.9406564584124654e-324",
                                         "1e308", "\"sphere\"", "\"mesh\"", "\"oriented-box\"", "\"ray\"",
                                         "\"time-of-impact\"", "\"contact\"", "[0, 0, 0]", "-1"};
  std::string text;
  for (std::size_t i = 0; i < size; ++i) {
    const std::uint8_t b = data[i];
    if (b >= 0xf0)
      text += tokens[b - 0xf0];
    else
      text += char(b);
  }
  scene::Scene s;
  try {
    s = scene::parse_scene(text, "fuzz");
  } catch (const scene::scene_error&) {
    return;  // refused with its place
  }
  std::size_t work = 0;
  for (const scene::Body& b : s.bodies) work += b.shape == scene::Shape::mesh ? b.faces.size() : 1;
  if (work * std::size_t(s.frames + 1) > 2000) return;  // parsed; too long to run under the sanitizers
  std::vector<scene::Run> runs;
  for (scene::Precision p : {scene::Precision::float_, scene::Precision::double_, scene::Precision::exact}) {
    try {
      runs.push_back(scene::run_scene(s, p));
    } catch (const invalid_input& e) {
      // float and double may meet a value beyond their range; the exact run takes every
      // scene the parser accepts
      if (p == scene::Precision::exact) {
        std::fprintf(stderr, "cdref fuzz: the exact run refused a parsed scene: %s\n", e.what());
        std::abort();
      }
    }
  }
  for (const scene::Run& r : runs)
    if (r.precision != scene::Precision::exact) scene::compare(s, r, runs.back());
}

}  // namespace cdref::fuzz
