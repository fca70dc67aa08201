// fuzz/validate.cpp - cdref::validate: a campaign on the caller's implementation.
#include <cdref/validate.hpp>

#include <atomic>
#include <cdref/error.hpp>
#include <sstream>
#include <stdexcept>

#include "../src/report.hpp"

namespace cdref::validate {

namespace {

std::string column_list(const fuzz::QueryInfo& qi) {
  std::string s;
  for (const auto& c : qi.inputs) s += (s.empty() ? "" : ", ") + c;
  return s;
}
std::string group_list(const fuzz::QueryInfo& qi) {
  std::string s;
  for (const auto& o : qi.outputs) s += (s.empty() ? "" : ", ") + o.name;
  return s;
}

}  // namespace

int output_group(const fuzz::QueryInfo& qi, const std::string& g, int* first) {
  int c = 0;
  for (std::size_t k = 0; k < qi.outputs.size(); ++k) {
    if (qi.outputs[k].name == g) {
      if (first) *first = c;
      return int(k);
    }
    c += qi.outputs[k].width;
  }
  throw std::invalid_argument(std::string(qi.name) + " has no output '" + g + "' (its outputs: " + group_list(qi) + ")");
}

double Case::operator()(const std::string& column) const {
  for (std::size_t k = 0; k < qi_->inputs.size(); ++k)
    if (qi_->inputs[k] == column) return (*in_)[k];
  throw std::invalid_argument(std::string(qi_->name) + " has no input column '" + column + "' (its columns: " +
                              column_list(*qi_) + ")");
}
Vec3<double> Case::vec(const std::string& prefix) const {
  return {(*this)(prefix + "_x"), (*this)(prefix + "_y"), (*this)(prefix + "_z")};
}

bool Case::exact_classification() const { return exact_ ? exact_->cls : fuzz::oracle_truth(qi_->q, *in_, precision_).cls; }
fuzz::Answer Case::exact_answer() const { return exact_ ? *exact_ : fuzz::oracle_truth(qi_->q, *in_, precision_); }
double Case::exact_value(const std::string& group, int component) const {
  int first = 0;
  const int g = output_group(*qi_, group, &first);
  if (component < 0 || component >= qi_->outputs[g].width) throw std::invalid_argument(group + ": no such component");
  return double((exact_ ? *exact_ : fuzz::oracle_truth(qi_->q, *in_, precision_)).v[first + component]);
}

Answer& Answer::value(const std::string& group, double x) {
  named_.push_back({group, {x}});
  return *this;
}
Answer& Answer::value(const std::string& group, const Vec3<double>& v) {
  named_.push_back({group, {v[0], v[1], v[2]}});
  return *this;
}

Report run_engine(const Options& o, const std::function<fuzz::Answer(const Case&)>& impl) {
  const fuzz::Query q = fuzz::query_by_name(o.query);
  const fuzz::QueryInfo& qi = fuzz::info(q);
  if (o.precision != 24 && o.precision != 53 && o.precision != 64)
    throw std::invalid_argument("precision must be 24 (float), 53 (double) or 64 (long double)");
  for (const auto& f : o.families) {
    bool known = false;
    for (const auto& fam : qi.families) known = known || fam.name == f;
    if (!known) throw std::invalid_argument(std::string(qi.name) + " has no family '" + f + "'");
  }
  fuzz::Spec spec;
  spec.queries = {q};
  spec.impls = {o.name};
  spec.families = o.families;
  spec.n = o.n;
  spec.seed = o.seed;
  spec.threads = o.threads;
  spec.custom.push_back(
      {o.name, o.precision, [&qi, &impl, &o](fuzz::Query, const fuzz::Inputs& in) { return impl(Case(qi, in, o.precision)); },
       {q}});
  // the convention's cases: set apart by the engine, in each cell (CellStats::set_apart), on the
  // exact answer it computed
  if (o.convention)
    spec.custom.back().set_apart = [&qi, &o](fuzz::Query, const fuzz::Inputs& in, const fuzz::Answer& exact) {
      return o.convention(Case(qi, in, o.precision, exact));
    };
  if (o.prefetch)
    spec.custom.back().prefetch = [&o](fuzz::Query, const fuzz::Inputs* in, std::size_t n) { o.prefetch(in, n); };
  Report rep;
  rep.query = qi.name;
  rep.name = o.name;
  rep.precision = o.precision;
  rep.seed = o.seed;
  rep.results = fuzz::run(spec);
  for (const auto& [k, st] : rep.results.cells) rep.convention_cases += st.set_apart;
  return rep;
}

Report run(const Options& o, const std::function<Answer(const Case&)>& impl) {
  const fuzz::QueryInfo& qi = fuzz::info(fuzz::query_by_name(o.query));
  return run_engine(o, [&qi, &impl](const Case& c) {
    const Answer a = impl(c);
    fuzz::Answer r;
    r.cls = r.pred = a.classification();
    r.given = 0;
    for (const auto& nv : a.values()) {
      int first = 0;
      const int g = output_group(qi, nv.group, &first);
      if (int(nv.v.size()) != qi.outputs[g].width)
        throw std::invalid_argument(nv.group + " has " + std::to_string(qi.outputs[g].width) + " components");
      for (std::size_t k = 0; k < nv.v.size(); ++k) r.v[first + k] = nv.v[k];
      r.given |= std::uint64_t(1) << g;
    }
    return r;
  });
}

std::uint64_t Report::cases() const {
  std::uint64_t n = 0;
  for (const auto& [k, st] : results.cells) n += st.n;
  return n;
}
std::uint64_t Report::false_positives() const {
  std::uint64_t n = 0;
  for (const auto& [k, st] : results.cells) n += st.cls_fp;
  return n;
}
std::uint64_t Report::false_negatives() const {
  std::uint64_t n = 0;
  for (const auto& [k, st] : results.cells) n += st.cls_fn;
  return n;
}
std::uint64_t Report::misclassified() const { return false_positives() + false_negatives(); }
std::uint64_t Report::refused() const {
  std::uint64_t n = 0;
  for (const auto& [k, st] : results.cells) n += st.refused;
  return n;
}
std::uint64_t Report::max_ulps(const std::string& group) const {
  const int g = output_group(fuzz::info(fuzz::query_by_name(query)), group);
  std::uint64_t m = 0;
  for (const auto& [k, st] : results.cells)
    if (st.out[g].worst.set && st.out[g].worst.metric > m) m = st.out[g].worst.metric;
  return m;
}
std::uint64_t Report::p99_ulps(const std::string& group) const {
  const int g = output_group(fuzz::info(fuzz::query_by_name(query)), group);
  fuzz::Histogram all;
  for (const auto& [k, st] : results.cells)
    for (int b = 0; b < fuzz::Histogram::bins; ++b) all.count[b] += st.out[g].hist.count[b];
  return all.total() ? all.quantile(0.99) : 0;
}
double Report::max_abs(const std::string& group) const {
  const int g = output_group(fuzz::info(fuzz::query_by_name(query)), group);
  double m = 0;
  for (const auto& [k, st] : results.cells) m = std::max(m, st.out[g].max_abs);
  return m;
}
double Report::max_rel(const std::string& group) const {
  const int g = output_group(fuzz::info(fuzz::query_by_name(query)), group);
  double m = 0;
  for (const auto& [k, st] : results.cells) m = std::max(m, st.out[g].max_rel);
  return m;
}
std::string Report::table() const {
  std::ostringstream o;
  cli::print_table(o, results, seed);
  return o.str();
}

}  // namespace cdref::validate
