// tests/peers_hand.hpp - what the gallery's hand-case tests share (tests/test_peers_*.cpp): a
// case from a list of its columns, an adapter found by its query, and the values it answered.
#pragma once

#include <catch2/catch.hpp>

#include <initializer_list>
#include <string>
#include <vector>

#include "peers/adapter.hpp"

namespace test_peers {

using cdref::peers::Adapter;
using cdref::peers::Answer;
using cdref::peers::Inputs;

/// The case whose columns are v, in the query's order (`cdref cases --describe QUERY`).
inline Inputs of(std::initializer_list<double> v) {
  Inputs in{};
  std::size_t k = 0;
  for (double x : v) in[k++] = x;
  return in;
}
/// The adapter of `all` for the query whose function's name contains `mark` (any, when empty;
/// one without it, when `without`).
inline const Adapter& adapter(const std::vector<Adapter>& all, const std::string& query, const std::string& mark = "",
                              bool without = false) {
  for (const Adapter& a : all)
    if (a.query == query && (mark.empty() || (a.function.find(mark) != std::string::npos) != without)) return a;
  FAIL("no adapter for " << query);
  return all.front();
}
/// The values of an output group the adapter answered (it must have answered it).
inline std::vector<double> values(const Adapter& a, const Answer& r, const std::string& g) {
  const cdref::fuzz::Query q = cdref::fuzz::query_by_name(a.query);
  int first = 0;
  const int k = cdref::peers::group(q, g, &first);
  REQUIRE(((r.given >> k) & 1) == 1);
  const int w = cdref::fuzz::info(q).outputs[std::size_t(k)].width;
  return std::vector<double>(r.v.begin() + first, r.v.begin() + first + w);
}

}  // namespace test_peers
