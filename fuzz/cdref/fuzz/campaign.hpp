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
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace cdref::fuzz {

// ---- queries ----
enum class Query : int {
  sphere_sphere,
  segment_sphere_cast,
  ray_sphere_cast,
  segment_sphere,
  box_box,
  segment_box_cast,
  ray_box_cast,
  sphere_box,
};
inline constexpr int query_count = 8;

struct QueryInfo {
  Query q;
  const char* name;
  const char* cls_name;                   // the classification: "hit" or "intersect"
  const char* pred_name;                  // the root- and division-free predicate
  std::vector<std::string> inputs;        // input columns, in order
  std::vector<std::string> outputs;       // output groups (each 1 or 3 components)
  std::vector<int> widths;                // components per output group
  const char* describe;                   // what the query computes
};
const QueryInfo& info(Query q);
const std::vector<Query>& all_queries();
Query query_by_name(const std::string& name);  // throws std::invalid_argument naming the choices

inline constexpr int max_inputs = 12;
inline constexpr int max_values = 8;

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
};

// ---- implementations under test ----
struct Implementation {
  std::string name;    // "book-double", ...
  int precision;       // 24 (float), 53 (double) or 64 (long double): the type whose ulps measure its error
  std::function<Answer(Query, const Inputs&)> run;  // gets double inputs, rounds them itself
  std::vector<Query> queries{};  // the queries it implements (empty: all)
  bool supports(Query q) const {
    return queries.empty() || std::find(queries.begin(), queries.end(), q) != queries.end();
  }
};
const std::vector<Implementation>& builtin_implementations();
const Implementation& implementation_by_name(const std::string& name);

// The exact answer on the given inputs, each value rounded correctly to float (precision
// 24), double (53) or long double (64).
Answer truth(Query q, const Inputs& in, int precision);

// The same answer from the fast oracle: the book run on oracle::Bounded2 (a double word
// with a rigorous error bound, exact/cdref/oracle/bounded2.hpp), accepted when every
// comparison and every rounding is certain, and otherwise the exact path above (always at
// precision 64: a double word cannot certify a long double rounding of long double
// inputs). `exact_used` (if given) tells which path answered.
Answer oracle_truth(Query q, const Inputs& in, int precision, bool* exact_used = nullptr);

// The oracle for the classifications alone (Answer::cls and Answer::pred; no values):
// exact/cdref/oracle/classify.hpp (a semi-static filter, then exact floating-point
// expansions, then Gmpq). `exact_used`: the filter could not decide.
Answer oracle_classify(Query q, const Inputs& in, bool* exact_used = nullptr);

// The inputs as a float implementation sees them (each rounded to float, back in double).
Inputs float_inputs(Query q, const Inputs& in);

// ---- families ----
struct Family {
  std::string name;
  std::string describe;
  std::vector<int> scales;  // the scale parameter k; its meaning is in `describe`
  // Makes case inputs from a stream of 64-bit random words.
  std::function<Inputs(std::function<std::uint64_t()>& next, int scale)> make;
};
const std::vector<Family>& families(Query q);
const Family& family_by_name(Query q, const std::string& name);

// Case i of cell (query, family, scale): a pure function of its arguments.
Inputs make_case(std::uint64_t seed, Query q, const Family& f, int scale, std::uint64_t i);

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
};

struct CellStats {
  std::uint64_t n = 0;
  std::uint64_t refused = 0;               // inputs not finite in the implementation's type
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
  std::string checkpoint;     // file to write as it goes ("" for none)
  bool resume = false;        // continue from `checkpoint`
  std::function<void(double cases_done, double cases_total)> progress;  // optional, per cell-case
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

// Merges complete shard files of one campaign into the unsharded result; throws
// std::runtime_error if they are not the shards 0..N-1 of one campaign, each complete.
Results merge_shards(const std::vector<Saved>& shards);

// ulps between a and b in the type of the given precision (24 float, 53 double, 64 long
// double), both representable in it; saturates at 2^64 - 1.
std::uint64_t ulp_distance(long double a, long double b, int precision);

std::string hexfloat(double x);
std::string hexfloat(long double x);

}  // namespace cdref::fuzz
