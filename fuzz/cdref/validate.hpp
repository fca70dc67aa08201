/// \file
/// cdref/validate.hpp - validating your own float code against the exact answer, from C++.
///
/// Wrap your implementation of one of cdref's queries in a callable that reads a case's
/// inputs by column name and answers what it computes; cdref::validate::run runs a campaign
/// on it (the query's families, n cases each, a seed) against the exact answer and returns
/// a report to assert on in your own tests:
///
///   auto report = cdref::validate::run({.query = "ray-sphere-cast", .n = 2000},
///       [](const cdref::validate::Case& c) {
///         const MyRay ray{c.vec("source"), c.vec("direction")};
///         const MySphere s{c.vec("center"), c("radius")};
///         const MyHit h = my_raycast(ray, s);
///         return cdref::validate::Answer(h.hit).value("lambda_enter", h.t);
///       });
///   REQUIRE(report.misclassified() == 0);
///   REQUIRE(report.max_ulps("lambda_enter") <= 64);
///
/// The columns are those of `cdref cases --describe QUERY` (`vec("source")` reads source_x,
/// source_y, source_z); the answer gives the classification (hit / intersect) and any subset of
/// the output groups, and only those are graded. At precision 24 the inputs are the float
/// roundings of the cases (convert them to float) and errors are ulps of float.
#pragma once

#include <cdref/fuzz/campaign.hpp>
#include <cdref/vec.hpp>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace cdref::validate {

class Case;

/// What `run` validates: the query, its families, how many cases, at which precision.
struct Options {
  std::string query;                  ///< a query's name: "ray-sphere-cast", "sphere-box", ...
  std::vector<std::string> families;  ///< empty: every family of the query
  std::uint64_t n = 1000;             ///< cases per (family, scale)
  std::uint64_t seed = 1;             ///< the campaign's seed: the same seed, the same cases
  int precision = 53;                 ///< 24 float, 53 double, 64 long double
  int threads = 1;                    ///< threads running the cases
  std::string name = "yours";         ///< the implementation's name in the report
  /// Where your implementation's convention gives another meaning than cdref's (a ray starting
  /// inside reported at its exit, a one-sided triangle, hits behind the source), say so: the
  /// cases for which this returns true are set apart by the campaign engine (counted per cell,
  /// fuzz::CellStats::set_apart, and in all in Report::convention_cases), not graded and your
  /// callable not called on them, so a difference of meaning is never reported as drift. It
  /// may read the exact answer through Case::exact_*.
  std::function<bool(const Case&)> convention;
  /// Optional: told a block's cases (their inputs at the precision) before your callable runs on
  /// them one by one, for an implementation in another process that answers a block in one
  /// exchange (fuzz::Implementation::prefetch; the gallery's Rapier rows). The results are the
  /// same without it.
  std::function<void(const fuzz::Inputs* in, std::size_t n)> prefetch;
};

/// One case's inputs, by column name.
class Case {
 public:
  /// A case of query `qi` with inputs `in`, read at `precision` (24: rounded to float).
  Case(const fuzz::QueryInfo& qi, const fuzz::Inputs& in, int precision = 53)
      : qi_(&qi), in_(&in), precision_(precision) {}
  /// The same, with the exact answer the campaign engine already computed for it (a
  /// convention's case: Case::exact_* then read it instead of asking the oracle again).
  Case(const fuzz::QueryInfo& qi, const fuzz::Inputs& in, int precision, const fuzz::Answer& exact)
      : qi_(&qi), in_(&in), precision_(precision), exact_(&exact) {}
  double operator()(const std::string& column) const;  ///< throws std::invalid_argument naming the columns
  Vec3<double> vec(const std::string& prefix) const;   ///< prefix_x, prefix_y, prefix_z
  const fuzz::Inputs& inputs() const { return *in_; }  ///< every input column, in the query's order
  /// The exact answer for this case (from the oracle, values rounded to the precision).
  bool exact_classification() const;
  /// One component of an output group's exact value, rounded to the precision.
  double exact_value(const std::string& group, int component = 0) const;
  /// The whole exact answer in the engine's form (classification, values by index, rounded to
  /// the precision).
  fuzz::Answer exact_answer() const;

 private:
  const fuzz::QueryInfo* qi_;
  const fuzz::Inputs* in_;
  int precision_;
  const fuzz::Answer* exact_ = nullptr;
};

/// An implementation's answer: the classification, and the output groups it computes.
class Answer {
 public:
  /// An answer with its classification (hit or intersect) and no values yet.
  explicit Answer(bool classification) { a_.cls = a_.pred = classification; a_.given = 0; }
  /// Adds the value of a scalar output group (e.g. "lambda_enter"); returns *this.
  Answer& value(const std::string& group, double x);
  /// Adds the value of a vector output group (e.g. "point"); returns *this.
  Answer& value(const std::string& group, const Vec3<double>& v);
  /// internal: resolved against the query's output groups by run()
  struct Named {
    std::string group;      ///< the output group's name
    std::vector<double> v;  ///< its components
  };
  bool classification() const { return a_.cls; }               ///< the classification given
  const std::vector<Named>& values() const { return named_; }  ///< the values given, in order

 private:
  fuzz::Answer a_;
  std::vector<Named> named_;
};

/// The result of `run`: counts, errors per output group, and the campaign's table.
class Report {
 public:
  ///@{
  /// The query validated, and the implementation's name (Options::name).
  std::string query, name;
  ///@}
  int precision = 53;     ///< the precision of the inputs and of the ulps
  std::uint64_t seed = 1;  ///< the campaign's seed
  fuzz::Results results;  ///< the campaign's full results, cell by cell

  std::uint64_t cases() const;  ///< cases run
  std::uint64_t misclassified() const;   ///< the classification differs from the exact one
  std::uint64_t false_positives() const;  ///< says hit / intersect where the exact answer does not
  std::uint64_t false_negatives() const;  ///< says miss / apart where the exact answer does not
  std::uint64_t refused() const;          ///< inputs the precision cannot hold, or the callable refused
  std::uint64_t convention_cases = 0;     ///< set apart by Options::convention (not graded, not refused)
  /// Over every graded case of an output group: the largest error, and the 99th percentile
  /// (the lower edge of its histogram bin, an eighth of an octave wide), in ulps of the
  /// precision. An unknown group throws std::invalid_argument naming the groups.
  std::uint64_t max_ulps(const std::string& group) const;
  std::uint64_t p99_ulps(const std::string& group) const;  ///< the 99th percentile, as above
  /// The largest absolute error of an output group, and the largest relative to each case's
  /// natural scale (fuzz::natural_scale: the inputs' scale for points and distances, 1 for
  /// normals, u and v, ...): a value near an exact 0 is many ulps away but little in these.
  double max_abs(const std::string& group) const;
  double max_rel(const std::string& group) const;  ///< the largest relative error, as above
  /// The table `cdref campaign` prints, with the worst cases' inputs in hex-float.
  std::string table() const;
};

/// Runs `implementation` on every case of the campaign `options` describes, against the exact
/// answer, and returns the report. An unknown query, family or output group throws
/// std::invalid_argument naming the valid ones.
Report run(const Options& options, const std::function<Answer(const Case&)>& implementation);
/// The same for a callable that answers in the engine's form (fuzz::Answer: the classification,
/// the values by index and the bits of the groups given), as the gallery's adapters do
/// (src/peers/adapter.hpp): no lookup of group names per case.
Report run_engine(const Options& options, const std::function<fuzz::Answer(const Case&)>& implementation);

/// The index of a query's output group, and (first_value) where its values start in an
/// answer; throws std::invalid_argument naming the query's groups.
int output_group(const fuzz::QueryInfo& qi, const std::string& group, int* first_value = nullptr);

}  // namespace cdref::validate
