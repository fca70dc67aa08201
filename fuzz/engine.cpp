// fuzz/engine.cpp - running a campaign: cells, work items, threads, statistics, shards,
// checkpoints and their text form.
#include <algorithm>
#include <atomic>
#include <bit>
#include <cdref/error.hpp>
#include <charconv>
#include <limits>
#include <chrono>
#include <cdref/fuzz/campaign.hpp>
#include <cdref/fuzz/work.hpp>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <mutex>
#include <new>
#include <type_traits>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace cdref::fuzz {

// ---- histogram ----
int Histogram::bin_of(std::uint64_t d) {
  if (d < 16) return int(d);
  const int j = 63 - std::countl_zero(d);  // 4..63
  const int sub = int((d >> (j - 3)) & 7);
  return 16 + (j - 4) * 8 + sub;
}
std::uint64_t Histogram::lower_edge(int bin) {
  if (bin < 16) return std::uint64_t(bin);
  const int j = (bin - 16) / 8 + 4, sub = (bin - 16) % 8;
  return std::uint64_t(8 + sub) << (j - 3);
}
std::uint64_t Histogram::total() const {
  std::uint64_t t = 0;
  for (auto c : count) t += c;
  return t;
}
std::uint64_t Histogram::quantile(double q) const {
  const std::uint64_t t = total();
  if (t == 0) return 0;
  // the smallest bin whose cumulative count reaches ceil(q t)
  const std::uint64_t rank = std::max<std::uint64_t>(1, std::uint64_t(std::ceil(q * double(t))));
  std::uint64_t cum = 0;
  for (int b = 0; b < bins; ++b) {
    cum += count[b];
    if (cum >= rank) return lower_edge(b);
  }
  return lower_edge(bins - 1);
}

void Exemplar::offer(std::uint64_t m, std::uint64_t i, const Inputs& in, long double g, long double w) {
  if (set && (m < metric || (m == metric && i >= index))) return;
  set = true;
  metric = m;
  index = i;
  inputs = in;
  got = g;
  want = w;
}

void CellStats::merge(const CellStats& o) {
  n += o.n;
  refused += o.refused;
  set_apart += o.set_apart;
  cls_fp += o.cls_fp;
  cls_fn += o.cls_fn;
  pred_fp += o.pred_fp;
  pred_fn += o.pred_fn;
  certified += o.certified;
  uncertain += o.uncertain;
  certain_wrong += o.certain_wrong;
  certain_wrong_example.merge(o.certain_wrong_example);
  cls_example.merge(o.cls_example);
  pred_example.merge(o.pred_example);
  for (int k = 0; k < max_values; ++k) {
    for (int b = 0; b < Histogram::bins; ++b) out[k].hist.count[b] += o.out[k].hist.count[b];
    out[k].nonfinite += o.out[k].nonfinite;
    out[k].worst.merge(o.out[k].worst);
    out[k].max_abs = std::max(out[k].max_abs, o.out[k].max_abs);
    out[k].max_rel = std::max(out[k].max_rel, o.out[k].max_rel);
  }
}

void Results::merge(const Results& o) {
  for (const auto& [k, v] : o.cells) cells[k].merge(v);
}

namespace {
bool same_value(long double a, long double b) {
  return (a == b && std::signbit(a) == std::signbit(b)) || (std::isnan(a) && std::isnan(b));
}
bool same(const Exemplar& a, const Exemplar& b) {
  if (a.set != b.set) return false;
  if (!a.set) return true;
  return a.metric == b.metric && a.index == b.index && a.inputs == b.inputs &&
         same_value(a.got, b.got) && same_value(a.want, b.want);
}
}  // namespace

bool Results::operator==(const Results& o) const {
  if (cells.size() != o.cells.size()) return false;
  for (auto a = cells.begin(), b = o.cells.begin(); a != cells.end(); ++a, ++b) {
    if (!(a->first == b->first)) return false;
    const CellStats &x = a->second, &y = b->second;
    if (x.n != y.n || x.refused != y.refused || x.set_apart != y.set_apart || x.cls_fp != y.cls_fp || x.cls_fn != y.cls_fn ||
        x.pred_fp != y.pred_fp || x.pred_fn != y.pred_fn || !same(x.cls_example, y.cls_example) ||
        !same(x.pred_example, y.pred_example) || x.certified != y.certified || x.uncertain != y.uncertain ||
        x.certain_wrong != y.certain_wrong || !same(x.certain_wrong_example, y.certain_wrong_example))
      return false;
    for (int k = 0; k < max_values; ++k)
      if (x.out[k].hist.count != y.out[k].hist.count || x.out[k].nonfinite != y.out[k].nonfinite ||
          !same(x.out[k].worst, y.out[k].worst) || x.out[k].max_abs != y.out[k].max_abs ||
          x.out[k].max_rel != y.out[k].max_rel)
        return false;
  }
  return true;
}

namespace {
// What natural_scale needs of a query, worked out once from its column names: which inputs
// are lengths and which a direction, and the kind of each output group.
struct ScalePlan {
  std::vector<int> lengths, directions;
  std::vector<char> kind;  // 's' the inputs' scale, 'q' its square, 'u' unit, 'l' lambda
};
const ScalePlan& scale_plan(Query q) {
  static const std::vector<ScalePlan> plans = [] {
    std::vector<ScalePlan> out;
    for (Query x : all_queries()) {
      const QueryInfo& qi = info(x);
      if (int(out.size()) <= x.id) out.resize(std::size_t(x.id) + 1);
      ScalePlan& p = out[std::size_t(x.id)];
      auto has = [](const std::string& s, const char* part) { return s.find(part) != std::string::npos; };
      for (std::size_t k = 0; k < qi.inputs.size(); ++k) {
        const std::string& c = qi.inputs[k];
        if (has(c, "direction")) p.directions.push_back(int(k));
        else if (!(c == "n" || c == "closed" || (c.size() > 2 && c.compare(c.size() - 2, 2, "_n") == 0)) && !has(c, "axis"))
          p.lengths.push_back(int(k));
      }
      for (const Output& o : qi.outputs) {
        const std::string& n = o.name;
        p.kind.push_back(n == "normal" || n == "u" || n == "v" || has(n, "axis") || has(n, "direction") || o.label
                             ? 'u'
                         : has(n, "lambda")  ? 'l'
                         : has(n, "squared") ? 'q'
                                             : 's');
      }
    }
    return out;
  }();
  return plans.at(std::size_t(q.id));
}
}  // namespace

double natural_scale(Query q, int group, const Inputs& in) {
  const ScalePlan& p = scale_plan(q);
  double scene = 0, dir = 0;
  for (int k : p.lengths) scene = std::fmax(scene, std::fabs(in[std::size_t(k)]));
  for (int k : p.directions) dir = std::fmax(dir, std::fabs(in[std::size_t(k)]));
  double s = scene;
  switch (p.kind.at(std::size_t(group))) {
    case 'u': s = 1; break;
    case 'l': s = dir > 0 ? scene / dir : 1; break;
    case 'q': s = scene * scene; break;
    default: break;
  }
  return std::fmax(s, std::numeric_limits<double>::min());
}

std::uint64_t ulp_distance(long double a, long double b, int precision) {
  // Keys in the order of the values, with -0 and +0 on one key: 2^63 -+ the magnitude's bits.
  if (precision == 64) {
    // x87 extended: order by (biased exponent, significand); subnormals have exponent 0
    auto key = [](long double x) -> unsigned __int128 {
      const bool neg = std::signbit(x);
      x = std::fabs(x);
      unsigned __int128 mag;
      if (std::isinf(x)) {
        mag = static_cast<unsigned __int128>(32767) << 63;
      } else if (x == 0) {
        mag = 0;
      } else {
        int e;
        const long double m = std::frexp(x, &e);  // [0.5, 1)
        if (e >= -16381) {                        // normal: significand 2^63 + fraction
          const auto sig = static_cast<std::uint64_t>(std::ldexp(m, 64));
          mag = (static_cast<unsigned __int128>(e + 16382) << 63) | (sig & 0x7fffffffffffffffull);
        } else {  // subnormal: the significand alone
          mag = static_cast<std::uint64_t>(std::ldexp(x, 16382 + 63));
        }
      }
      const unsigned __int128 mid = static_cast<unsigned __int128>(1) << 80;
      return neg ? mid - mag : mid + mag;
    };
    const unsigned __int128 ka = key(a), kb = key(b), d = ka > kb ? ka - kb : kb - ka;
    return d > ~std::uint64_t(0) ? ~std::uint64_t(0) : static_cast<std::uint64_t>(d);
  }
  auto key = [precision](double x) -> std::uint64_t {
    std::uint64_t mag;
    bool neg;
    if (precision == 24) {
      const std::uint32_t u = std::bit_cast<std::uint32_t>(float(x));
      mag = u & 0x7fffffffu;
      neg = (u >> 31) != 0;
    } else {
      const std::uint64_t u = std::bit_cast<std::uint64_t>(x);
      mag = u & 0x7fffffffffffffffull;
      neg = (u >> 63) != 0;
    }
    return neg ? (1ull << 63) - mag : (1ull << 63) + mag;
  };
  const std::uint64_t ka = key(double(a)), kb = key(double(b));
  return ka > kb ? ka - kb : kb - ka;
}

// ---- the work ----
namespace {

constexpr std::uint64_t block = 256;  // cases per work item

struct Cell {
  Query q;
  const Family* family;
  int scale;
  std::uint64_t key;  // cell_key(seed, q, *family, scale)
};

std::vector<Cell> cells_of(const Spec& spec) {
  // (a fingerprint read from a file may name families with no query; the checks below name
  // a family through the first query)
  if (spec.queries.empty()) throw std::invalid_argument("the campaign names no query");
  std::vector<Cell> cells;
  for (Query q : spec.queries) {
    std::vector<const Family*> fams;
    if (spec.families.empty()) {
      for (const Family& f : families(q)) fams.push_back(&f);
    } else {
      for (const std::string& name : spec.families)
        for (const Family& f : families(q))
          if (f.name == name) fams.push_back(&f);
      if (fams.empty()) family_by_name(q, spec.families.front());  // throws, naming the choices
    }
    for (const Family* f : fams)
      for (int k : f->scales) {
        bool wanted = spec.scales.empty();
        for (int s : spec.scales) wanted = wanted || s == k;
        if (wanted) cells.push_back({q, f, k, cell_key(spec.seed, q, *f, k)});
      }
  }
  // a family named for none of the queries is a mistake, not a filter (one that only some of
  // them have is fine when each query has at least one of the named families)
  for (const std::string& name : spec.families) {
    bool known = false;
    for (Query q : spec.queries)
      for (const Family& f : families(q)) known = known || f.name == name;
    if (!known) family_by_name(spec.queries.front(), name);  // throws, naming the choices
  }
  if (cells.empty()) throw std::invalid_argument("the campaign selects no (query, family, scale) cell");
  return cells;
}

bool all_finite(const Inputs& in, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(in[i])) return false;
  return true;
}

// Case i's classification and predicate, `a` from an implementation against the truth `t`
// (an Answer or a Verdict each), into its statistics.
template <class A, class T>
void grade_classification(CellStats& st, std::uint64_t i, const Inputs& seen, const A& a, const T& t) {
  if (a.cls != t.cls) {
    ++(a.cls ? st.cls_fp : st.cls_fn);
    st.cls_example.offer(0, i, seen, a.cls, t.cls);
  }
  if (a.certified) {
    ++st.certified;
    if (!a.certain) {
      ++st.uncertain;
    } else if (a.cls != t.cls) {
      ++st.certain_wrong;
      st.certain_wrong_example.offer(0, i, seen, a.cls, t.cls);
    }
  }
  if (a.pred != t.pred) {
    ++(a.pred ? st.pred_fp : st.pred_fn);
    st.pred_example.offer(0, i, seen, a.pred, t.pred);
  }
}

// stats[j]: the cell's statistics of impls[j] (null when it does not implement the query).
void run_case(const Cell& cell, std::uint64_t i, const std::vector<const Implementation*>& impls,
              const Spec& spec, const std::vector<CellStats*>& stats) {
  const QueryInfo& qi = info(cell.q);
  const Inputs in = make_case_of(cell.key, *cell.family, cell.scale, i);
  // The truth on the double inputs (rounded to double or long double), and on their
  // float rounding (rounded to float). Inputs outside a query's domain in a type (overflow
  // to infinity, a ray direction that underflows to zero in float) are refused for the
  // implementations of that type and counted as such.
  bool need[3] = {false, false, false};  // precision 24, 53, 64
  auto slot = [](int precision) { return precision == 24 ? 0 : (precision == 53 ? 1 : 2); };
  for (std::size_t j = 0; j < impls.size(); ++j)
    if (stats[j]) need[slot(impls[j]->precision)] = true;
  Inputs rounded;  // the float rounding, when a float implementation runs (no copy of `in` otherwise)
  if (need[0]) rounded = float_inputs(cell.q, in);
  const Inputs& in_f = need[0] ? rounded : in;
  // The truths in raw storage, each constructed in place by its call (an Answer zeroes its
  // values on construction; in a campaign grading the classification alone that zeroing and
  // a copy were a tenth of a case's time). Answer is trivially destructible.
  struct Slot {
    alignas(Answer) unsigned char bytes[sizeof(Answer)];
    const Answer& get() const { return *std::launder(reinterpret_cast<const Answer*>(bytes)); }
  } truths[3];
  static_assert(std::is_trivially_destructible_v<Answer>);
  bool valid[3] = {need[0] && all_finite(in_f, qi.inputs.size()), need[1], need[2]};
  for (int k = 0; k < 3; ++k) {
    try {
      if (valid[k]) {
        const Inputs& x = k == 0 ? in_f : in;
        const int p = k == 0 ? 24 : (k == 1 ? 53 : 64);
        // the classification alone needs no rounded outputs: the classification oracle, or
        // the exact formulation asked for none
        ::new (truths[k].bytes) Answer(spec.classification_only ? (spec.exact_truth ? truth_classification(cell.q, x)
                                                                                    : oracle_classify(cell.q, x))
                                       : spec.exact_truth       ? truth(cell.q, x, p)
                                                                : oracle_truth(cell.q, x, p));
      }
    } catch (const invalid_input&) {
      valid[k] = false;
    }
  }

  for (std::size_t j = 0; j < impls.size(); ++j) {
    if (!stats[j]) continue;
    const Implementation* im = impls[j];
    CellStats& st = *stats[j];
    ++st.n;
    const bool f24 = im->precision == 24;
    if (!valid[slot(im->precision)]) {
      ++st.refused;
      continue;
    }
    const Inputs& seen = f24 ? in_f : in;
    const Answer& t = truths[slot(im->precision)].get();
    if (im->set_apart && im->set_apart(cell.q, seen, t)) {
      ++st.set_apart;
      continue;
    }
    bool refused = false;
    const Answer a = [&]() -> Answer {  // (returned in place)
      try {
        return spec.classification_only && im->classify ? im->classify(cell.q, seen) : im->run(cell.q, seen);
      } catch (const invalid_input&) {
        refused = true;
        return Answer{};
      }
    }();
    if (refused) {
      ++st.refused;
      continue;
    }
    grade_classification(st, i, seen, a, t);
    if (spec.classification_only) continue;
    if (spec.certain_outputs && a.certified && !a.certain) continue;
    int c = 0;
    for (std::size_t g = 0; g < qi.outputs.size(); ++g) {
      const Output& out = qi.outputs[g];
      const int w = out.width;
      const int at_c = c;
      c += w;
      // a cast's lambdas and points exist only on a hit, a separating axis only on a miss
      if (out.when != Output::always && !(a.cls == t.cls && a.cls == (out.when == Output::on_hit))) continue;
      if (!((a.given >> g) & 1)) continue;  // not answered by this implementation
      OutputStats& os = st.out[g];
      bool nonfinite = false;
      std::uint64_t worst = 0;
      int at = at_c;
      long double abs = 0;
      for (int k = at_c; k < at_c + w; ++k) {
        if (!std::isfinite(a.v[k]) && std::isfinite(t.v[k])) nonfinite = true;
        const std::uint64_t d = out.label ? std::uint64_t(a.v[k] != t.v[k]) : ulp_distance(a.v[k], t.v[k], im->precision);
        if (d > worst) worst = d, at = k;
        abs = std::max(abs, out.label ? (long double)(a.v[k] != t.v[k]) : std::fabs(a.v[k] - t.v[k]));
      }
      if (nonfinite)
        ++os.nonfinite;
      else {
        os.hist.add(worst);
        os.worst.offer(worst, i, seen, a.v[at], t.v[at]);
        if (abs > 0) {
          os.max_abs = std::max(os.max_abs, double(abs));
          os.max_rel = std::max(os.max_rel, out.label ? double(abs) : double(abs) / natural_scale(cell.q, int(g), seen));
        }
      }
    }
  }
}

// A campaign grading the classifications alone against the oracle (the default truth): the
// cases of a block made first, then each evaluation over all of them in one call (the query's
// descriptor inlines the per-case work there; a call per case through the registry cost as
// much as the evaluations). The same counts and examples as run_case on each case.
struct BlockScratch {
  std::vector<Inputs> in, rounded;  // the cases, and their float rounding
  std::size_t width = 0;  // slots of `in` that may be nonzero: the most inputs of a query made here
  std::vector<Verdict> truth[2];    // the truth on `rounded` (0) and on `in` (1)
  std::vector<Verdict> got;         // an implementation's answers
};
void run_block_classification(const Cell& cell, const std::uint64_t* index, std::size_t m,
                              const std::vector<const Implementation*>& impls, const std::vector<CellStats*>& stats,
                              BlockScratch& s) {
  const QueryInfo& qi = info(cell.q);
  bool need_float = false, need_wide = false;  // precision 24; 53 or 64 (the same truth)
  for (std::size_t j = 0; j < impls.size(); ++j)
    if (stats[j]) (impls[j]->precision == 24 ? need_float : need_wide) = true;
  // each case made in its place, over the slots its query's inputs can take, zeroed first; the
  // slots past `width` are zero from the first resize on (Family::make says why)
  s.in.resize(m);
  s.width = std::max(s.width, qi.inputs.size());
  for (std::size_t k = 0; k < m; ++k) {
    std::fill_n(s.in[k].begin(), s.width, 0.0);
    make_case_into(cell.key, *cell.family, cell.scale, index[k], s.in[k]);
  }
  if (need_float) {
    s.rounded.resize(m);
    for (std::size_t k = 0; k < m; ++k) ::new (&s.rounded[k]) Inputs(float_inputs(cell.q, s.in[k]));
    s.truth[0].resize(m);
    qi.oracle_classify_block(s.rounded.data(), m, s.truth[0].data());
  }
  if (need_wide) {
    s.truth[1].resize(m);
    qi.oracle_classify_block(s.in.data(), m, s.truth[1].data());
  }
  s.got.resize(m);
  for (std::size_t j = 0; j < impls.size(); ++j) {
    if (!stats[j]) continue;
    const Implementation* im = impls[j];
    CellStats& st = *stats[j];
    const bool f24 = im->precision == 24;
    const std::vector<Inputs>& seen = f24 ? s.rounded : s.in;
    const std::vector<Verdict>& truth = s.truth[f24 ? 0 : 1];
    if (im->classify_block) {
      im->classify_block(cell.q, seen.data(), m, s.got.data());
    } else {
      for (std::size_t k = 0; k < m; ++k) {
        Verdict& v = s.got[k];
        v = Verdict{};
        if (truth[k].refused) continue;  // not evaluated, as in run_case
        try {
          const Answer a = im->classify ? im->classify(cell.q, seen[k]) : im->run(cell.q, seen[k]);
          v.cls = a.cls, v.pred = a.pred, v.certified = a.certified, v.certain = a.certain;
        } catch (const invalid_input&) {
          v.refused = true;
        }
      }
    }
    st.n += m;
    for (std::size_t k = 0; k < m; ++k) {
      if (truth[k].refused || s.got[k].refused) {
        ++st.refused;
        continue;
      }
      grade_classification(st, index[k], seen[k], s.got[k], truth[k]);
    }
  }
}

struct Item {
  std::size_t cell;
  std::uint64_t first;  // first case index of the block
};

// Work items are numbered cell by cell, ceil(n / block) of them per cell: item k is block
// k % per_cell of cell k / per_cell. Computed, not stored: a campaign's memory does not grow
// with the n it is asked for.
std::uint64_t items_per_cell(const Spec& spec) { return spec.n / block + (spec.n % block != 0); }
Item item_at(const Spec& spec, std::uint64_t k) {
  const std::uint64_t per = items_per_cell(spec);
  return {std::size_t(k / per), (k % per) * block};
}

}  // namespace

// exact_truth is left out: the oracle and the exact path give identical results (tested),
// so a campaign may be resumed or merged across the two.
std::string Spec::fingerprint() const {
  std::ostringstream o;
  o << "seed=" << seed << ";n=" << n;
  if (classification_only) o << ";outputs=cls";  // (absent: every output graded)
  if (certain_outputs) o << ";outputs=certain";
  o << ";queries=";
  for (Query q : queries) o << info(q).name << ",";
  o << ";impls=";
  for (const auto& i : impls) o << i << ",";
  o << ";families=";
  for (const auto& f : families) o << f << ",";
  o << ";scales=";
  for (int s : scales) o << s << ",";
  return o.str();
}

std::uint64_t total_items(const Spec& spec) {
  const std::uint64_t cells = cells_of(spec).size(), per = items_per_cell(spec);
  if (per && cells > UINT64_MAX / per) throw std::invalid_argument("the campaign has more than 2^64 work items");
  return cells * per;
}

Spec spec_of_fingerprint(const std::string& fp) {
  Spec spec;
  auto list = [](const std::string& v) {
    std::vector<std::string> out;
    std::size_t start = 0;
    for (std::size_t i = 0; i < v.size(); ++i)
      if (v[i] == ',') out.push_back(v.substr(start, i - start)), start = i + 1;
    if (start != v.size()) throw std::runtime_error("malformed fingerprint list '" + v + "'");
    return out;
  };
  auto whole = [&](const std::string& v) {
    std::uint64_t x = 0;
    const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), x);
    if (ec != std::errc() || end != v.data() + v.size() || v.empty())
      throw std::runtime_error("malformed fingerprint number '" + v + "'");
    return x;
  };
  std::size_t start = 0;
  std::vector<std::string> parts;
  for (std::size_t i = 0; i <= fp.size(); ++i)
    if (i == fp.size() || fp[i] == ';') parts.push_back(fp.substr(start, i - start)), start = i + 1;
  for (const std::string& part : parts) {
    const auto eq = part.find('=');
    if (eq == std::string::npos) throw std::runtime_error("malformed fingerprint '" + fp + "'");
    const std::string k = part.substr(0, eq), v = part.substr(eq + 1);
    if (k == "seed") spec.seed = whole(v);
    else if (k == "n") spec.n = whole(v);
    else if (k == "outputs" && v == "cls") spec.classification_only = true;
    else if (k == "outputs" && v == "certain") spec.certain_outputs = true;
    else if (k == "queries")
      for (const auto& q : list(v)) spec.queries.push_back(query_by_name(q));
    else if (k == "impls") spec.impls = list(v);
    else if (k == "families") spec.families = list(v);
    else if (k == "scales")
      for (const auto& x : list(v)) {  // (a scale may be negative)
        int k = 0;
        const auto [end, ec] = std::from_chars(x.data(), x.data() + x.size(), k);
        if (ec != std::errc() || end != x.data() + x.size() || x.empty())
          throw std::runtime_error("malformed fingerprint scale '" + x + "'");
        spec.scales.push_back(k);
      }
    else throw std::runtime_error("malformed fingerprint '" + fp + "'");
  }
  if (spec.fingerprint() != fp) throw std::runtime_error("malformed fingerprint '" + fp + "'");
  return spec;
}

// ---- work items ----
struct Work::State {
  Spec spec;
  std::vector<Cell> cells;
  std::uint64_t items = 0;
  std::vector<const Implementation*> impls;
};

Work::Work(const Spec& spec) {
  if (spec.shards < 1 || spec.shard < 0 || spec.shard >= spec.shards)
    throw std::invalid_argument("shard must be k/N with 0 <= k < N");
  auto s = std::make_shared<State>();
  s->spec = spec;
  s->spec.progress = nullptr;
  s->cells = cells_of(spec);
  s->items = total_items(spec);
  for (const auto& name : spec.impls) {
    const Implementation* found = nullptr;
    for (const Implementation& c : s->spec.custom)
      if (c.name == name) found = &c;
    s->impls.push_back(found ? found : &implementation_by_name(name));
  }
  if (s->impls.empty()) throw std::invalid_argument("the campaign names no implementation");
  s_ = std::move(s);
}

const Spec& Work::spec() const { return s_->spec; }
std::uint64_t Work::items() const { return s_->items; }

// The cases of this shard among the first `r` items of a cell.
std::uint64_t Work::cell_cases(std::uint64_t r) const {
  const Spec& spec = s_->spec;
  // the cases i < x of this shard (i % shards == shard)
  const std::uint64_t shards = std::uint64_t(spec.shards), shard = std::uint64_t(spec.shard);
  const auto below = [&](std::uint64_t x) { return x / shards + std::uint64_t(x % shards > shard); };
  const std::uint64_t per = items_per_cell(spec);
  return below(r >= per ? spec.n : r * block);
}

std::uint64_t Work::cases(std::uint64_t begin, std::uint64_t end) const {
  end = std::min(end, s_->items);
  if (begin >= end) return 0;  // (so a campaign of n = 0 has no items, and no division by 0 below)
  // the cases of items [0, x): whole cells, then the first items of the next
  const std::uint64_t per = items_per_cell(s_->spec);
  const auto upto = [&](std::uint64_t x) { return (x / per) * cell_cases(per) + cell_cases(x % per); };
  return upto(end) - upto(begin);
}

void Work::check(const Results& r, const std::vector<std::pair<std::uint64_t, std::uint64_t>>& done,
                 const std::string& source) const {
  const Spec& spec = s_->spec;
  const std::uint64_t per = items_per_cell(spec);
  // the cases each cell must have counted, from the items said to be done
  std::vector<std::uint64_t> expected(s_->cells.size(), 0);
  for (auto [b, e] : done) {
    if (b == e) continue;
    if (b > e || e > s_->items)
      throw std::runtime_error(source + ": items " + std::to_string(b) + "-" + std::to_string(e) +
                               " are not items of this campaign (it has " + std::to_string(s_->items) + ")");
    for (std::uint64_t c = b / per; c < s_->cells.size() && c * per < e; ++c) {
      const std::uint64_t lo = std::max(b, c * per) - c * per, hi = std::min(e, (c + 1) * per) - c * per;
      expected[c] += cell_cases(hi) - cell_cases(lo);
    }
  }
  std::map<CellKey, std::uint64_t> want;
  for (std::size_t c = 0; c < s_->cells.size(); ++c)
    for (const Implementation* im : s_->impls)
      if (im->supports(s_->cells[c].q) && expected[c])
        want[{s_->cells[c].q, im->name, s_->cells[c].family->name, s_->cells[c].scale}] = expected[c];
  auto name = [](const CellKey& k) {
    return std::string(info(k.query).name) + " " + k.impl + " " + k.family + " " + std::to_string(k.scale);
  };
  for (const auto& [k, st] : r.cells) {
    const auto it = want.find(k);
    if (it == want.end())
      throw std::runtime_error(source + ": cell " + name(k) + " has statistics but none of its items is done");
    if (st.n != it->second)
      throw std::runtime_error(source + ": cell " + name(k) + " counts " + std::to_string(st.n) + " cases; its done items hold " +
                               std::to_string(it->second));
    const std::uint64_t graded = st.n - std::min(st.n, st.refused + st.set_apart);
    bool ok = st.refused + st.set_apart <= st.n && st.cls_fp + st.cls_fn <= graded && st.pred_fp + st.pred_fn <= graded &&
              st.certified <= st.n && st.uncertain <= st.certified && st.certain_wrong <= st.certified;
    for (std::size_t g = 0; g < info(k.query).outputs.size(); ++g)
      ok = ok && st.out[g].hist.total() + st.out[g].nonfinite <= st.n;
    if (!ok) throw std::runtime_error(source + ": cell " + name(k) + " has counts that do not add up");
  }
  for (const auto& [k, n] : want)
    if (!r.cells.count(k))
      throw std::runtime_error(source + ": cell " + name(k) + " is missing (" + std::to_string(n) + " cases done)");
}

// The cases from, from + step, ... below last told to each implementation of the cell's query
// that asks for them (Implementation::prefetch), as it will see them.
static void prefetch_block(const Cell& cell, std::uint64_t from, std::uint64_t last, std::uint64_t step,
                    const std::vector<const Implementation*>& impls) {
  const QueryInfo& qi = info(cell.q);
  std::vector<Inputs> made, rounded;
  for (std::uint64_t i = from; i < last; i += step) made.push_back(make_case_of(cell.key, *cell.family, cell.scale, i));
  for (const Implementation* im : impls) {
    if (!im || !im->prefetch || !im->supports(cell.q)) continue;
    if (im->precision != 24) {
      im->prefetch(cell.q, made.data(), made.size());
      continue;
    }
    if (rounded.empty())
      for (const Inputs& in : made) {
        Inputs f = float_inputs(cell.q, in);
        if (all_finite(f, qi.inputs.size())) rounded.push_back(f);
      }
    im->prefetch(cell.q, rounded.data(), rounded.size());
  }
}

void Work::run(std::uint64_t begin, std::uint64_t end, Results& into) const {
  const Spec& spec = s_->spec;
  const std::vector<Cell>& cells = s_->cells;
  const std::vector<const Implementation*>& impls = s_->impls;
  end = std::min<std::uint64_t>(end, s_->items);
  if (begin >= end) return;
  const int threads = int(std::min<std::uint64_t>(std::max(1, spec.threads), end - begin));
  std::atomic<std::uint64_t> next{begin};
  std::vector<Results> local(threads);
  std::vector<std::exception_ptr> errors(threads);
  // the classifications alone against the oracle: graded a block at a time
  // (an implementation that sets cases apart is asked case by case, with the truth as an Answer)
  bool sets_apart = false;
  for (const Implementation* im : impls) sets_apart = sets_apart || (im && im->set_apart);
  const bool by_block = spec.classification_only && !spec.exact_truth && !sets_apart;
  bool prefetching = false;
  for (const Implementation* im : impls) prefetching = prefetching || (im && im->prefetch);
  auto work = [&](int t) {
    try {
      std::vector<std::uint64_t> index(by_block ? block : 0);
      thread_local BlockScratch scratch;  // (kept: a new one per round was a tenth of the time in page faults)
      for (std::uint64_t k; (k = next++) < end;) {
        const Item it = item_at(spec, k);
        const Cell& cell = cells[it.cell];
        std::vector<CellStats*> stats;  // looked up once per block, at its first case of this shard
        const std::uint64_t last = std::min(spec.n, it.first + block);
        std::size_t m = 0;  // the block's cases of this shard, graded together
        // the block's cases of this shard: i % shards == shard
        const std::uint64_t shards = std::uint64_t(spec.shards);
        const std::uint64_t from = it.first + (std::uint64_t(spec.shard) + shards - it.first % shards) % shards;
        if (prefetching && !by_block) prefetch_block(cell, from, last, shards, impls);
        for (std::uint64_t i = from; i < last; i += shards) {
          if (stats.empty())
            for (const Implementation* im : impls)
              stats.push_back(im->supports(cell.q) ? &local[t].cells[{cell.q, im->name, cell.family->name, cell.scale}]
                                                   : nullptr);
          if (by_block)
            index[m++] = i;
          else
            run_case(cell, i, impls, spec, stats);
        }
        if (m) run_block_classification(cell, index.data(), m, impls, stats, scratch);
      }
    } catch (...) {
      errors[t] = std::current_exception();
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work, t);
  work(0);
  for (auto& th : pool) th.join();
  for (auto& e : errors)
    if (e) std::rethrow_exception(e);
  for (Results& r : local) merge_into(into, std::move(r));
}

Results run(const Spec& spec) {
  const Work work(spec);
  const std::uint64_t n_items = work.items();
  Results total;
  std::uint64_t done = 0;
  if (spec.resume) {
    const Saved saved = deserialize(read_whole_file(spec.checkpoint), spec.checkpoint);
    if (saved.fingerprint != spec.fingerprint() || saved.shard != spec.shard || saved.shards != spec.shards)
      throw std::runtime_error("checkpoint " + spec.checkpoint + " belongs to another campaign (" + saved.fingerprint +
                               ", shard " + std::to_string(saved.shard) + "/" + std::to_string(saved.shards) + ")");
    if (saved.items_total != n_items || saved.items_done > n_items)
      throw std::runtime_error("checkpoint " + spec.checkpoint + " says " + std::to_string(saved.items_done) + " of " +
                               std::to_string(saved.items_total) + " items are done; this campaign has " +
                               std::to_string(n_items));
    work.check(saved.results, {{0, saved.items_done}}, "checkpoint " + spec.checkpoint);
    total = saved.results;
    done = saved.items_done;
  }
  const std::uint64_t cases_total = work.cases(0, n_items);
  std::uint64_t cases_done = work.cases(0, done);
  const std::uint64_t round = std::uint64_t(std::max(1, spec.threads)) * 8;
  auto last_checkpoint = std::chrono::steady_clock::now();
  while (done < n_items) {
    const std::uint64_t end = std::min<std::uint64_t>(n_items, done + round);
    work.run(done, end, total);
    cases_done += work.cases(done, end);
    done = end;
    const auto now = std::chrono::steady_clock::now();
    if (!spec.checkpoint.empty() &&
        (done == n_items || std::chrono::duration<double>(now - last_checkpoint).count() >= spec.checkpoint_every)) {
      write_file_atomically(spec.checkpoint, serialize(spec, total, done));
      last_checkpoint = now;
    }
    if (spec.progress) spec.progress(double(cases_done), double(cases_total));
  }
  return total;
}

// ---- text form ----
namespace {

void put_ex(std::ostream& o, const char* tag, const Exemplar& e, std::size_t n_in) {
  if (!e.set) return;
  o << "ex " << tag << " " << e.metric << " " << e.index << " " << hexfloat(e.got) << " " << hexfloat(e.want);
  for (std::size_t i = 0; i < n_in; ++i) o << " " << hexfloat(e.inputs[i]);
  o << "\n";
}

}  // namespace

std::string serialize(const Spec& spec, const Results& r, std::uint64_t items_done) {
  return serialize(Saved{spec.fingerprint(), spec.shard, spec.shards, items_done, total_items(spec), r, spec.seed});
}

std::string serialize(const Saved& saved) {
  std::ostringstream o;
  o << "cdref-results 2\n";
  o << "fingerprint " << saved.fingerprint << "\n";
  o << "shard " << saved.shard << " " << saved.shards << "\n";
  o << "items " << saved.items_done << " " << saved.items_total << "\n";
  o << "seed " << saved.seed << "\n";
  for (const auto& [k, st] : saved.results.cells) {
    const QueryInfo& qi = info(k.query);
    const std::size_t n_in = qi.inputs.size();
    o << "cell " << qi.name << " " << k.impl << " " << k.family << " " << k.scale << " " << st.n << " " << st.refused
      << " " << st.cls_fp << " " << st.cls_fn << " " << st.pred_fp << " " << st.pred_fn << " " << st.certified << " "
      << st.uncertain << " " << st.certain_wrong;
    // the cases set apart by an implementation's convention, where there are any (a campaign of
    // cdref's own implementations has none: its files read as before)
    if (st.set_apart) o << " " << st.set_apart;
    o << "\n";
    put_ex(o, "cls", st.cls_example, n_in);
    put_ex(o, "certain", st.certain_wrong_example, n_in);
    put_ex(o, "pred", st.pred_example, n_in);
    for (std::size_t g = 0; g < qi.outputs.size(); ++g) {
      const OutputStats& os = st.out[g];
      o << "out " << g << " " << os.nonfinite;
      for (int b = 0; b < Histogram::bins; ++b)
        if (os.hist.count[b]) o << " " << b << ":" << os.hist.count[b];
      o << "\n";
      put_ex(o, ("out" + std::to_string(g)).c_str(), os.worst, n_in);
      if (os.max_abs > 0 || os.max_rel > 0)
        o << "err " << g << " " << hexfloat(os.max_abs) << " " << hexfloat(os.max_rel) << "\n";
    }
  }
  o << "end\n";
  return o.str();
}

Saved deserialize(const std::string& text, const std::string& source) {
  Saved s;
  std::istringstream in(text);
  std::string line;
  int lineno = 0;
  CellStats* cur = nullptr;
  std::size_t n_in = 0, n_out = 0;
  bool header = false, ended = false;
  int version = 0;
  auto fail = [&](const std::string& why) {
    throw std::runtime_error(source + ":" + std::to_string(lineno) + ": " + why);
  };
  auto number = [&](const std::string& t) -> std::uint64_t {
    std::uint64_t x = 0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), x);
    if (ec != std::errc() || end != t.data() + t.size() || t.empty()) fail("malformed number '" + t + "'");
    return x;
  };
  auto real = [&](const std::string& t) {
    char* end = nullptr;
    const long double x = std::strtold(t.c_str(), &end);
    if (t.empty() || end != t.c_str() + t.size()) fail("malformed number '" + t + "'");
    return x;
  };
  auto read_ex = [&](std::istringstream& ls, Exemplar& e) {
    std::string got, want;
    if (!(ls >> e.metric >> e.index >> got >> want)) fail("malformed example record");
    e.got = real(got);
    e.want = real(want);
    for (std::size_t i = 0; i < n_in; ++i) {
      std::string x;
      if (!(ls >> x)) fail("example record has too few inputs");
      e.inputs[i] = real(x);
    }
    e.set = true;
  };
  while (std::getline(in, line)) {
    ++lineno;
    while (!line.empty() && line.back() == '\r') line.pop_back();  // a file that passed through CRLF line ends
    std::istringstream ls(line);
    std::string tag;
    ls >> tag;
    if (!header) {
      if (tag != "cdref-results") fail("not a cdref results file");
      if (!(ls >> version) || version < 1 || version > 2) fail("unknown cdref results version");
      header = true;
    } else if (tag == "fingerprint") {
      std::getline(ls >> std::ws, s.fingerprint);
    } else if (tag == "shard") {
      if (!(ls >> s.shard >> s.shards)) fail("malformed shard record");
    } else if (tag == "seed") {
      if (!(ls >> s.seed)) fail("malformed seed record");
    } else if (tag == "items") {
      if (!(ls >> s.items_done >> s.items_total)) fail("malformed items record");
    } else if (tag == "cell") {
      std::string q, impl, fam;
      int scale;
      if (!(ls >> q >> impl >> fam >> scale)) fail("malformed cell record");
      Query query;
      try {
        query = query_by_name(q);
      } catch (const std::exception& e) {
        fail(e.what());
      }
      n_in = info(query).inputs.size();
      n_out = info(query).outputs.size();
      // read into the map's own node (a cell's statistics are some 60 KB, mostly histogram
      // bins: a copy through a local doubled the cost of reading a large file)
      const auto [at, fresh] = s.results.cells.try_emplace(CellKey{query, impl, fam, scale});
      cur = &at->second;
      if (!fresh) fail("cell " + q + " " + impl + " " + fam + " " + std::to_string(scale) + " is given twice");
      CellStats& st = *cur;
      if (!(ls >> st.n >> st.refused >> st.cls_fp >> st.cls_fn >> st.pred_fp >> st.pred_fn))
        fail("malformed cell record");
      // version 2 adds the certificate counts (version 1 files have none)
      if (version >= 2 && !(ls >> st.certified >> st.uncertain >> st.certain_wrong))
        fail("malformed cell record (certificate counts)");
      // then the cases set apart, where there are any
      if (std::string more; ls >> more) {
        std::size_t used = 0;
        try {
          st.set_apart = std::stoull(more, &used);
        } catch (const std::exception&) {
          used = 0;
        }
        if (used != more.size() || more[0] == '-' || (ls >> more)) fail("malformed cell record (cases set apart)");
      }
    } else if (tag == "ex" || tag == "out") {
      if (!cur) fail("record before any cell");
      if (tag == "ex") {
        std::string which;
        ls >> which;
        if (which == "cls")
          read_ex(ls, cur->cls_example);
        else if (which == "pred")
          read_ex(ls, cur->pred_example);
        else if (which == "certain")
          read_ex(ls, cur->certain_wrong_example);
        else if (which.rfind("out", 0) == 0 && number(which.substr(3)) < n_out)
          read_ex(ls, cur->out[number(which.substr(3))].worst);
        else
          fail("unknown example kind '" + which + "'");
      } else {
        std::size_t g;
        if (!(ls >> g >> cur->out.at(g < max_values ? g : 0).nonfinite) || g >= n_out)
          fail("malformed out record (the query has " + std::to_string(n_out) + " output groups)");
        std::string bc;
        while (ls >> bc) {
          const auto colon = bc.find(':');
          if (colon == std::string::npos) fail("malformed histogram bin '" + bc + "'");
          const std::uint64_t b = number(bc.substr(0, colon));
          if (b >= std::uint64_t(Histogram::bins)) fail("histogram bin out of range");
          cur->out[g].hist.count[b] = number(bc.substr(colon + 1));
        }
      }
    } else if (tag == "err") {  // the largest absolute and relative errors of an output group
      if (!cur) fail("record before any cell");
      std::size_t g;
      std::string ab, re;
      if (!(ls >> g >> ab >> re) || g >= n_out) fail("malformed err record");
      cur->out[g].max_abs = double(real(ab));
      cur->out[g].max_rel = double(real(re));
      if (!(cur->out[g].max_abs >= 0) || !(cur->out[g].max_rel >= 0)) fail("malformed err record");
    } else if (tag == "end") {
      ended = true;
    } else if (!tag.empty()) {
      fail("unknown record '" + tag + "'");
    }
  }
  if (!header) throw std::runtime_error(source + ": empty file");
  if (!ended) throw std::runtime_error(source + ": truncated (no end record)");
  return s;
}

Results merge_shards(const std::vector<Saved>& shards) {
  if (shards.empty()) throw std::runtime_error("nothing to merge");
  const int n = shards.front().shards;
  std::vector<int> seen(n, 0);
  Results total;
  for (const Saved& s : shards) {
    if (s.fingerprint != shards.front().fingerprint) throw std::runtime_error("shards of different campaigns");
    if (s.shards != n || s.shard < 0 || s.shard >= n) throw std::runtime_error("shard numbering differs");
    if (s.items_done != s.items_total)
      throw std::runtime_error("shard " + std::to_string(s.shard) + " is incomplete (resume it first)");
    if (seen[s.shard]++) throw std::runtime_error("shard " + std::to_string(s.shard) + " given twice");
    total.merge(s.results);
  }
  for (int k = 0; k < n; ++k)
    if (!seen[k]) throw std::runtime_error("shard " + std::to_string(k) + "/" + std::to_string(n) + " is missing");
  // each shard's counts against the campaign its fingerprint describes
  for (const Saved& s : shards) {
    Spec spec = spec_of_fingerprint(s.fingerprint);
    spec.shard = s.shard;
    spec.shards = s.shards;
    const Work work(spec);
    if (s.items_total != work.items())
      throw std::runtime_error("shard " + std::to_string(s.shard) + " says the campaign has " +
                               std::to_string(s.items_total) + " items; its fingerprint gives " + std::to_string(work.items()));
    work.check(s.results, {{0, s.items_done}}, "shard " + std::to_string(s.shard));
  }
  return total;
}

}  // namespace cdref::fuzz
