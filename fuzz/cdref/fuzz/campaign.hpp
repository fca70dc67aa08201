// cdref/fuzz/campaign.hpp - fuzz campaigns: how far the float versions of the chapter's
// queries drift from the exact answer, on families of generated cases.
//
// A cell is (query, family, scale). Case i of a cell is a pure function of
// (seed, query, family, scale, i): a counter-based generator (SplitMix64 over a hash of
// the tuple), so any case is reproduced on its own and a campaign splits into shards.
//
// For each case the exact answer is computed once on the double inputs and once on their
// float rounding (the book at CGAL::Gmpq, square roots kept as a + b sqrt d), and rounded
// correctly to the type of each implementation. An implementation's float type runs on its
// own rounding of the inputs and is judged against the truth for those inputs.
//
// Statistics are sums and maxima with deterministic tie-breaks, so shards merge into
// exactly the result of the unsharded run, and an interrupted run resumed from its
// checkpoint ends with exactly the totals of an uninterrupted one.
#pragma once

#include <algorithm>
#include <array>
#include <compare>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace cdref::fuzz {

// ---- queries ----
// A query is described once, by its descriptor (a QueryInfo, built from the query's spec in
// fuzz/queries/: its columns, how its primitives are made from them, its book, robust and
// oracle calls, its families). Campaigns, case files, the oracle, scoring, the report, the
// fuzz targets and the benchmarks iterate over the descriptors.
//
// A Query is the descriptor's stable id: its place in the registry, mixed into the case
// generator (so an id is never reused or renumbered: the cases of a query stay the same).
struct Query {
  int id = -1;
  auto operator<=>(const Query&) const = default;
};

inline constexpr int max_inputs = 64;
inline constexpr int max_values = 12;

using Inputs = std::array<double, max_inputs>;

// One evaluation: the classification from the full query (cast().hit,
// proximity().intersect), the predicate (hit() / intersect()), and the output values
// in schema order, as doubles (a float implementation's values are exact in double).
// An implementation with a certificate (the robust ones: robust::decide) also says whether
// its classification is certain: `certain` promises it equals the exact one, and a campaign
// counts the cases where that promise fails (there must be none).
struct Answer {
  bool cls = false;
  bool pred = false;
  bool certified = false;  // the implementation gives a certificate
  bool certain = false;    // ... and it says its classification is the exact one
  std::array<long double, max_values> v{};  // exact for float, double and long double
  // The output groups the implementation answers (bit g: QueryInfo::outputs[g]); the others
  // are not graded. The built-in implementations answer every group.
  std::uint64_t given = ~std::uint64_t(0);
};

// A classification alone, as an evaluation over a block of cases gives it (QueryInfo's
// *_block members, Implementation::classify_block): the fields of Answer a campaign grading
// the classifications reads, and whether the evaluation refused the inputs (invalid_input).
struct Verdict {
  bool cls = false;
  bool pred = false;
  bool certified = false;
  bool certain = false;
  bool refused = false;
};

// ---- families ----
// The stream of random words a case is made from: word n of case key k is SplitMix64's
// mixing function of k + n * 0x632be59bd9b4e019 (a counter-based generator: no state but the
// counter, so a case is a pure function of its key).
struct CaseStream {
  std::uint64_t key = 0;
  std::uint64_t counter = 0;
  static constexpr std::uint64_t mix(std::uint64_t z) {
    z += 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  std::uint64_t operator()() { return mix(key + 0x632be59bd9b4e019ull * ++counter); }
};

struct Family {
  std::string name;
  std::string describe;
  std::vector<int> scales;  // the scale parameter k; its meaning is in `describe`
  // Makes a case's inputs from a stream of 64-bit random words, writing them into `in`, which
  // is all zero on entry. It writes no slot past its query's inputs (QueryInfo::inputs) and
  // may leave some of those zero (a polygon's unused vertices): a block of cases reuses its
  // storage by zeroing only the query's inputs between cases. Written into place, not
  // returned: returning a case cleared all 64 slots each time (without it, a ray-sphere
  // campaign graded on the classification alone ran 8-15% faster, README).
  std::function<void(CaseStream& next, int scale, Inputs& in)> make;
};

// An output group of a query: 1 or 3 components (`name`, or `name_x`, `name_y`, `name_z`).
struct Output {
  enum When { always, on_hit, on_miss };
  std::string name;
  int width = 1;
  When when = always;  // graded where the implementation and the truth both classify so
                       // (a cast's lambdas exist only on a hit, a separating axis only on a miss)
  bool label = false;  // an index, graded as right (0) or wrong (1), not in ulps
};

// A timed row of the cost report: case k of the prepared inputs evaluated one way.
struct TimedRow {
  std::string name;           // "book double", ...
  std::string campaign_impl;  // the campaign implementation measuring its error ("" none)
  std::string error_note;     // shown when there is no campaign row ("exact", "not measured", ...)
  // answers n prepared cases from `first` on: out[k] is case first + k's classification; with
  // out null, reads those cases' inputs into cache and answers nothing (touch, below)
  using Batch = std::function<void(std::size_t first, std::size_t n, char* out)>;
  Batch run;
  bool hard = false;          // timed on the near-boundary cases instead of the uniform ones
  std::size_t cases = 0;      // how many cases it has prepared (all it was given, or slow_row_cases)
};
// A row over an exact or multiprecision type (the book at Gmpq, Epeck::FT, CORE::Expr, MPFR)
// prepares only the first slow_row_cases cases: the harnesses time it on those (it takes
// microseconds a query, and a mispredicted branch costs it nothing measurable).
constexpr std::size_t slow_row_cases = 2000;
// The fast rows are timed on fresh cases: the harnesses (`cdref report`, `cdref_bench`) prepare
// timing_windows sets of cases and time each pass on the next set. Over one set repeated, this
// machine's branch predictor learns the outcomes: the ray cast's `bare`, pass by pass over the
// same 16,384 cases, took 5.1, 2.9, 2.1, 2.0, 2.0 ... ns a query, and over 8 sets in turn
// 4.1 (README, "Fresh cases for every timed pass").
constexpr std::size_t timing_windows = 8;
// Reads n objects from p on, one byte a 64-byte line, so that a timed pass finds them in cache
// without the branch predictor having seen the pass's outcomes.
template <class P>
void touch(const P* p, std::size_t n) {
  const unsigned char* b = reinterpret_cast<const unsigned char*>(p);
  unsigned sum = 0;
  for (std::size_t i = 0; i < n * sizeof(P); i += 64) sum += b[i];
  asm volatile("" : : "r"(sum));
}

// ---- implementations under test ----
struct Implementation {
  std::string name;    // "book-double", ...
  int precision;       // 24 (float), 53 (double) or 64 (long double): the type whose ulps measure its error
  std::function<Answer(Query, const Inputs&)> run;  // gets double inputs, rounds them itself
  std::vector<Query> queries{};  // the queries it implements (empty: all)
  // The classification and predicate alone, no values (a campaign with --outputs cls calls
  // it); empty: run.
  std::function<Answer(Query, const Inputs&)> classify{};
  // The same over a block of cases, out[k] for in[k] (a campaign grading the classifications
  // calls it once per block); empty: classify (or run) case by case.
  std::function<void(Query, const Inputs* in, std::size_t n, Verdict* out)> classify_block{};
  // Where the implementation's own convention gives another meaning than cdref's (a ray whose
  // source lies on the shape, a library that reports touching as apart): true sets the case
  // apart, counted in CellStats::set_apart and not graded. Called before run, with the case as
  // the implementation sees it and the engine's exact answer to it (its classification alone
  // in a campaign grading the classification); empty: no case is set apart.
  std::function<bool(Query, const Inputs& seen, const Answer& truth)> set_apart{};
  // Told a block's cases (as the implementation sees them: rounded to float at precision 24,
  // those finite there) before they are run one by one, so that an implementation in another
  // process can answer them in one exchange and run() then read its answers; run is still
  // called for every case graded, and the results are the same without it. Empty: not told.
  std::function<void(Query, const Inputs* seen, std::size_t n)> prefetch{};
  bool supports(Query q) const {
    return queries.empty() || std::find(queries.begin(), queries.end(), q) != queries.end();
  }
};
enum class Exact { gmpq, epeck };  // the exact number types the fuzz checks compare

// What pins a query's cases: the number of its (family, scale) cells and a digest (FNV-1a over
// the bit patterns) of the first 16 cases of every cell at seed 1, as tests/test_campaign.cpp
// computes it. A spec states its own (fuzz/cdref/fuzz/spec.hpp); cells 0: none stated.
struct CaseDigest {
  std::size_t cells = 0;
  std::uint64_t digest = 0;
};

struct QueryInfo {
  Query q;
  const char* name;
  const char* cls_name;                   // the classification: "hit" or "intersect"
  const char* pred_name;                  // the other formulation in the predicate column
  std::vector<std::string> inputs;        // input columns, in order
  std::vector<Output> outputs;            // output groups
  const char* describe;                   // what the query computes
  const char* full_call;                  // the full query's call ("cast().hit", ...)
  const char* answer_help;                // what the answer columns mean (cdref cases --describe)
  std::vector<Family> families;
  bool mesh_level = false;    // a shot against several triangles: a false negative is a leak
  bool book_is_truth = true;  // the book at an exact type is the truth (false: the book
                              // assumes what the inputs do not give, e.g. orthonormal axes)
  CaseDigest case_digest{};   // the spec's pin of its cases (none: {})
  // Evaluations on double inputs, each converting them itself (precision 24: float, 53:
  // double, 64: long double; values reported in that type).
  std::function<Answer(int precision, const Inputs&)> book;
  std::function<Answer(int precision, const Inputs&)> robust;  // with robust::decide's certificate
  // The stable tier (float/cdref/stable: the formulation careful float code ships) at 24 or
  // 53; empty for a query without one.
  std::function<Answer(int precision, const Inputs&)> stable;
  std::function<Answer(Exact, const Inputs&)> book_exact;  // the book at an exact type, values rounded to double
  // The book's and the stable tier's full query asked for no outputs (its classification) and
  // the predicate, no values: what a campaign grading the classification alone runs.
  std::function<Answer(int precision, const Inputs&)> book_classification;
  std::function<Answer(int precision, const Inputs&)> stable_classification;  // empty without a stable tier
  // The two above over a block of cases, out[k] for in[k], a refusal as out[k].refused: one
  // call per block and the per-case work inlined, where a call per case cost as much as the
  // evaluation itself (a classification-only campaign calls these).
  std::function<void(int precision, const Inputs* in, std::size_t n, Verdict* out)> book_classification_block;
  std::function<void(int precision, const Inputs* in, std::size_t n, Verdict* out)> stable_classification_block;
  // The exact answer, each value rounded correctly to the precision.
  std::function<Answer(const Inputs&, int precision)> truth;
  // The exact classification alone (cls and pred; no values): the truth's formulation at
  // CGAL::Gmpq asked for no outputs. The reference the classification oracle is tested against
  // and a classification-only campaign's exact truth.
  std::function<Answer(const Inputs&)> truth_classification;
  // The same from the fast oracle (a filter with a rigorous error bound, the exact path when
  // it cannot decide); `exact_used` tells which path answered.
  std::function<Answer(const Inputs&, int precision, bool* exact_used)> oracle_truth;
  // The exact classification alone (cls = pred), from oracle::classify.
  std::function<Answer(const Inputs&, bool* exact_used)> oracle_classify;
  // ... over a block of cases, out[k] for in[k] (cls = pred; a refusal as out[k].refused).
  std::function<void(const Inputs* in, std::size_t n, Verdict* out)> oracle_classify_block;
  // A cast's classification and lambda_enter alone (cls = pred, v[0]; the other values 0),
  // lambda_enter correctly rounded to double (0 on a miss): oracle::enter (exact/cdref/oracle/
  // enter.hpp) for the sphere, box, oriented-box, triangle, fan and polygon casts (a cast whose
  // descriptor has none: the classification oracle and the truth asked for lambda_enter alone,
  // spec.hpp's oracle_enter_of); empty for the
  // queries that are not casts.
  std::function<Answer(const Inputs&, bool* exact_used)> oracle_enter;
  // The generic staged path (cdref/exact/staged.hpp): the truth's own formulation run on
  // cdref::Bounded, then cdref::Bounded2, then CGAL::Gmpq, the first certain answer taken;
  // no error analysis of the query's own. `stage` (may be null) receives the stage that
  // answered (0 bounded double, 1 bounded double word, 2 exact). The classification alone
  // (cls = pred), and every output correctly rounded to the precision (24, 53 or 64). The
  // reference every hand-written filter (oracle_classify, oracle_truth) is tested against.
  std::function<Answer(const Inputs&, int* stage)> staged_classify;
  std::function<Answer(const Inputs&, int precision, int* stage)> staged_truth;
  // A stage of the classification oracle alone (0 filter, 1 expansion, 2 rational): the
  // decision, or -1 when that stage cannot decide. Empty for queries without stages.
  std::function<int(int stage, const Inputs&)> oracle_stage;
  // The rows of the cost report over prepared uniform and near-boundary cases (`hard_name`
  // names the latter in the rows timed on them).
  std::function<std::vector<TimedRow>(const std::vector<Inputs>& cases, const std::vector<Inputs>& hard,
                                      const std::string& hard_name)>
      timed_rows;
  // Checks of the fuzz targets beyond the common ones (may be empty): abort with a message.
  std::function<const char*(const Inputs&)> fuzz_extra;
  // Inputs the book at double may refuse although the exact types take them (a documented
  // limit of a conversion, e.g. min-max corners that overflow). May be empty.
  std::function<bool(const Inputs&)> double_may_refuse;
  // The query's function of <cdref/truth.hpp> (cdref/fuzz/truth_api.hpp): at precision 24 or
  // 53, every field of its oracle answer on a case's columns against its exact path's, "" when
  // equal bit for bit (else the first field that differs).
  std::function<std::string(const Inputs&, int precision)> truth_api_check;
  // Implementations of this query alone (a campaign may name them like the built-in ones):
  // the patched float variants engines ship, the book at an exact type where it is not the
  // truth. Each has `queries` = {q}; variants of several queries may share a name.
  std::vector<Implementation> variants;

  // A descriptor's construction, copies, moves and destruction (about forty members, most of
  // them std::function) are compiled once, in fuzz/queries.cpp, not in every unit that
  // describes a query.
  QueryInfo();
  QueryInfo(const QueryInfo&);                 // a copy of every member
  QueryInfo(QueryInfo&&) noexcept;             // every member moved
  QueryInfo& operator=(const QueryInfo&);      // every member copied
  QueryInfo& operator=(QueryInfo&&) noexcept;  // every member moved
  ~QueryInfo();
};
const QueryInfo& info(Query q);
const std::vector<Query>& all_queries();
Query query_by_name(const std::string& name);  // throws std::invalid_argument naming the choices

// The book and robust versions at float, double and long double (every query), then the
// queries' own variants.
const std::vector<Implementation>& builtin_implementations();
const Implementation& implementation_by_name(const std::string& name);

// The exact answer on the given inputs, each value rounded correctly to float (precision
// 24), double (53) or long double (64).
Answer truth(Query q, const Inputs& in, int precision);

// The exact classification alone (see QueryInfo::truth_classification).
Answer truth_classification(Query q, const Inputs& in);

// The same answer from the fast oracle (see QueryInfo::oracle_truth).
Answer oracle_truth(Query q, const Inputs& in, int precision, bool* exact_used = nullptr);

// The oracle for the classifications alone (Answer::cls and Answer::pred; no values).
Answer oracle_classify(Query q, const Inputs& in, bool* exact_used = nullptr);

// The inputs as a float implementation sees them (each rounded to float, back in double).
Inputs float_inputs(Query q, const Inputs& in);

const std::vector<Family>& families(Query q);
const Family& family_by_name(Query q, const std::string& name);

// Case i of cell (query, family, scale): a pure function of its arguments.
Inputs make_case(std::uint64_t seed, Query q, const Family& f, int scale, std::uint64_t i);
// The same in two steps, the cell's key computed once: make_case(seed, q, f, scale, i) ==
// make_case_of(cell_key(seed, q, f, scale), f, scale, i).
std::uint64_t cell_key(std::uint64_t seed, Query q, const Family& f, int scale);
Inputs make_case_of(std::uint64_t key, const Family& f, int scale, std::uint64_t i);
// The same written into `out`, which must hold zero in every slot the family may write (the
// query's inputs) and keeps its other slots.
void make_case_into(std::uint64_t key, const Family& f, int scale, std::uint64_t i, Inputs& out);

// ---- statistics ----
// Errors are distances in ulps between a value and the correctly rounded truth: the
// number of representable values between them, an integer. The histogram keeps each of
// 0..15 exactly and above that 8 bins per power of two, so quantiles are exact below 16
// ulps and within 1/8 of a power of two above.
struct Histogram {
  static constexpr int bins = 16 + 8 * 60;
  std::array<std::uint64_t, bins> count{};
  static int bin_of(std::uint64_t d);
  static std::uint64_t lower_edge(int bin);
  void add(std::uint64_t d) { ++count[bin_of(d)]; }
  std::uint64_t total() const;
  std::uint64_t quantile(double q) const;  // lower edge of the bin holding the q-quantile
};

// A case kept as an example: the worst of its kind (largest error, then smallest index).
struct Exemplar {
  bool set = false;
  std::uint64_t metric = 0;  // ulps (or 0 for a misclassification)
  std::uint64_t index = 0;
  Inputs inputs{};
  long double got = 0, want = 0;  // the implementation's value and the truth (or 0/1 for classes)
  // better = larger metric, then smaller index
  void offer(std::uint64_t m, std::uint64_t i, const Inputs& in, long double g, long double w);
  void merge(const Exemplar& o) {
    if (o.set) offer(o.metric, o.index, o.inputs, o.got, o.want);
  }
};

struct OutputStats {
  Histogram hist;
  std::uint64_t nonfinite = 0;  // implementation gave NaN or infinity where the truth is finite
  Exemplar worst;
  // The largest absolute error and the largest error relative to the case's natural scale
  // (natural_scale): beside ulps, so that a value near an exact 0 reads as what it is.
  double max_abs = 0, max_rel = 0;
};

struct CellStats {
  std::uint64_t n = 0;
  std::uint64_t refused = 0;               // inputs not finite in the implementation's type
  std::uint64_t set_apart = 0;             // its convention's cases (Implementation::set_apart): not graded
  std::uint64_t cls_fp = 0, cls_fn = 0;    // full query says yes / no, truth says the other
  std::uint64_t pred_fp = 0, pred_fn = 0;  // the same for the predicate
  Exemplar cls_example, pred_example;      // smallest index among misclassifications
  // Implementations with a certificate (Answer::certified): cases certified, those marked
  // uncertain, and those certain but misclassified (a broken error bound: must stay 0).
  std::uint64_t certified = 0, uncertain = 0, certain_wrong = 0;
  Exemplar certain_wrong_example;
  std::array<OutputStats, max_values> out{};
  void merge(const CellStats& o);
};

struct CellKey {
  Query query;
  std::string impl, family;
  int scale;
  auto tie() const { return std::tie(query, impl, family, scale); }
  bool operator<(const CellKey& o) const { return tie() < o.tie(); }
  bool operator==(const CellKey& o) const { return tie() == o.tie(); }
};

struct Results {
  std::map<CellKey, CellStats> cells;
  void merge(const Results& o);
  bool operator==(const Results& o) const;
};

// ---- a campaign ----
struct Spec {
  std::vector<Query> queries;
  std::vector<std::string> impls;
  std::vector<std::string> families;  // empty: all families of each query
  std::vector<int> scales;            // empty: every scale of each family
  std::uint64_t n = 1000;             // cases per cell
  std::uint64_t seed = 1;
  int threads = 1;
  int shard = 0, shards = 1;  // this process runs the cases with i % shards == shard
  bool exact_truth = false;   // compute every truth exactly instead of through the oracle
  // grade the classification alone (the truth from the classification oracle, no rounded
  // outputs: the fast mode for hunting misclassifications)
  bool classification_only = false;
  // grade the values of an implementation with a certificate (Answer::certified) only where
  // it calls its classification certain (`--outputs certain`): what its certificate promises.
  // The classification is graded on every case, and implementations without a certificate on
  // every case too.
  bool certain_outputs = false;
  std::string checkpoint;     // file to write as it goes ("" for none)
  double checkpoint_every = 10;  // seconds between checkpoints (0: after every round of work
                                 // items); always one when the campaign is done
  bool resume = false;        // continue from `checkpoint`
  std::function<void(double cases_done, double cases_total)> progress;  // optional, per cell-case
  // Implementations the caller brings (cdref/validate.hpp): named in `impls` like the
  // built-in ones, which they take precedence over.
  std::vector<Implementation> custom;
  std::string fingerprint() const;  // identifies the work, for merge and resume checks
};

Results run(const Spec& spec);

// The number of work items (blocks of cases) of a campaign.
std::uint64_t total_items(const Spec& spec);

// Text serialisation (one record a line), for shards, checkpoints and merge.
struct Saved {
  std::string fingerprint;  // Spec::fingerprint() of the run
  int shard = 0, shards = 1;
  std::uint64_t items_done = 0, items_total = 0;
  Results results;
  std::uint64_t seed = 0;
};
std::string serialize(const Saved& saved);
std::string serialize(const Spec& spec, const Results& r, std::uint64_t items_done);
// Throws std::runtime_error naming the source, the line number and the problem.
Saved deserialize(const std::string& text, const std::string& source);

// The campaign a fingerprint (Spec::fingerprint) describes; throws std::runtime_error when it
// is not one.
Spec spec_of_fingerprint(const std::string& fingerprint);

// Merges complete shard files of one campaign into the unsharded result; throws
// std::runtime_error if they are not the shards 0..N-1 of one campaign, each complete, with
// counts that agree with the campaign their fingerprint describes.
Results merge_shards(const std::vector<Saved>& shards);

// ulps between a and b in the type of the given precision (24 float, 53 double, 64 long
// double), both representable in it; saturates at 2^64 - 1.
std::uint64_t ulp_distance(long double a, long double b, int precision);

std::string hexfloat(double x);
std::string hexfloat(long double x);

// The magnitude an error in output group `group` of query q is taken relative to, for the
// case `in` (so that 1e-15 against an exact 0 reads as what it is, not as 10^18 ulps): the
// inputs' scale (the largest magnitude among its coordinates and lengths; a polygon's vertex
// count, an oriented box's axes and a ray's direction are not lengths) for points, distances
// and depths; its square for squared quantities; 1 for normals, directions, u, v and lambda on
// a segment; the inputs' scale over the direction's largest component for lambda on a ray.
// At least the smallest normal double.
double natural_scale(Query q, int group, const Inputs& in);

}  // namespace cdref::fuzz
