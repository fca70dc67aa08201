// fuzz/queries.cpp - the registry of the queries' descriptors, and the implementations a
// campaign can run on them.
#include <algorithm>
#include <cdref/fuzz/campaign.hpp>
#include <cstdio>
#include <map>
#include <stdexcept>

#include "queries/groups.hpp"

namespace cdref::fuzz {

QueryInfo::QueryInfo() = default;
QueryInfo::QueryInfo(const QueryInfo&) = default;
QueryInfo::QueryInfo(QueryInfo&&) noexcept = default;
QueryInfo& QueryInfo::operator=(const QueryInfo&) = default;
QueryInfo& QueryInfo::operator=(QueryInfo&&) noexcept = default;
QueryInfo::~QueryInfo() = default;

namespace {

const std::vector<QueryInfo>& registry() {
  static const std::vector<QueryInfo> r = [] {
    std::vector<QueryInfo> all;
#define CDREF_GROUP_FUNCTION(fn, list) fn,
    for (auto group : {CDREF_QUERY_GROUPS(CDREF_GROUP_FUNCTION)})
#undef CDREF_GROUP_FUNCTION
      for (QueryInfo& qi : group()) all.push_back(std::move(qi));
    std::sort(all.begin(), all.end(), [](const QueryInfo& a, const QueryInfo& b) { return a.q < b.q; });
    for (std::size_t i = 0; i < all.size(); ++i)
      if (all[i].q.id != int(i))
        throw std::logic_error("query ids must be 0.." + std::to_string(all.size() - 1) + " without gaps: " +
                               all[i].name + " has id " + std::to_string(all[i].q.id));
    return all;
  }();
  return r;
}

}  // namespace

const QueryInfo& info(Query q) { return registry().at(static_cast<std::size_t>(q.id)); }

const std::vector<Query>& all_queries() {
  static const std::vector<Query> qs = [] {
    std::vector<Query> v;
    for (const QueryInfo& i : registry()) v.push_back(i.q);
    return v;
  }();
  return qs;
}

Query query_by_name(const std::string& name) {
  std::string names;
  for (const QueryInfo& i : registry()) {
    if (name == i.name) return i.q;
    names += (names.empty() ? "" : ", ") + std::string(i.name);
  }
  throw std::invalid_argument("unknown query '" + name + "' (queries: " + names + ")");
}

Answer truth(Query q, const Inputs& in, int precision) { return info(q).truth(in, precision); }

Answer truth_classification(Query q, const Inputs& in) { return info(q).truth_classification(in); }

Answer oracle_truth(Query q, const Inputs& in, int precision, bool* exact_used) {
  return info(q).oracle_truth(in, precision, exact_used);
}

Answer oracle_classify(Query q, const Inputs& in, bool* exact_used) {
  return info(q).oracle_classify(in, exact_used);
}

Inputs float_inputs(Query q, const Inputs& in) {
  Inputs out{};
  const std::size_t n = info(q).inputs.size();
  for (std::size_t i = 0; i < n; ++i) out[i] = double(float(in[i]));
  return out;
}

const std::vector<Implementation>& builtin_implementations() {
  static const std::vector<Implementation> impls = [] {
    // the book at float, double, long double: the full query, its classification alone, and
    // that over a block of cases
    const auto book = [](const char* name, int precision) {
      return Implementation{name, precision, [precision](Query q, const Inputs& in) { return info(q).book(precision, in); },
                            {},
                            [precision](Query q, const Inputs& in) { return info(q).book_classification(precision, in); },
                            [precision](Query q, const Inputs* in, std::size_t n, Verdict* out) {
                              info(q).book_classification_block(precision, in, n, out);
                            }};
    };
    std::vector<Implementation> v = {
        book("book-float", 24),
        book("book-double", 53),
        book("book-long-double", 64),
        {"robust-float", 24, [](Query q, const Inputs& in) { return info(q).robust(24, in); }},
        {"robust-double", 53, [](Query q, const Inputs& in) { return info(q).robust(53, in); }},
        {"robust-long-double", 64, [](Query q, const Inputs& in) { return info(q).robust(64, in); }},
    };
    // the stable tier, over the queries that have one
    for (const auto& tier : {std::pair<const char*, int>{"stable-float", 24}, {"stable-double", 53}}) {
      const int precision = tier.second;  // (clang 14 cannot capture a structured binding)
      Implementation im{tier.first, precision,
                        [precision](Query q, const Inputs& in) { return info(q).stable(precision, in); }, {},
                        [precision](Query q, const Inputs& in) { return info(q).stable_classification(precision, in); },
                        [precision](Query q, const Inputs* in, std::size_t n, Verdict* out) {
                          info(q).stable_classification_block(precision, in, n, out);
                        }};
      for (Query q : all_queries())
        if (info(q).stable) im.queries.push_back(q);
      if (!im.queries.empty()) v.push_back(std::move(im));
    }
    // the queries' own variants; one implementation per name, over every query that has it
    std::map<std::string, std::size_t> at;
    for (Query q : all_queries())
      for (const Implementation& var : info(q).variants) {
        auto it = at.find(var.name);
        if (it == at.end()) {
          at[var.name] = v.size();
          v.push_back({var.name, var.precision, var.run, {q}});
          continue;
        }
        Implementation& im = v[it->second];
        if (im.precision != var.precision)
          throw std::logic_error("variants named " + var.name + " differ in precision");
        im.run = [prev = im.run, run = var.run, q](Query x, const Inputs& in) { return x == q ? run(x, in) : prev(x, in); };
        im.queries.push_back(q);
      }
    return v;
  }();
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
