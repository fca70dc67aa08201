// fuzz/targets/fuzz_query.cpp - the libFuzzer target of every query: the environment
// variable CDREF_FUZZ_QUERY names the query (see `cdref describe`; scripts/fuzz.sh runs each).
#include <cdref/fuzz/fuzzcheck.hpp>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <stdexcept>

namespace {
cdref::fuzz::Query query;
}

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  const char* name = std::getenv("CDREF_FUZZ_QUERY");
  try {
    if (!name) throw std::invalid_argument("set CDREF_FUZZ_QUERY to the query to fuzz (see cdref describe)");
    query = cdref::fuzz::query_by_name(name);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz_query: %s\n", e.what());
    std::exit(2);
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  cdref::fuzz::check_query(query, data, size);
  return 0;
}
