// fuzz/targets/fuzz_query.cpp - the libFuzzer target of one query (CDREF_FUZZ_QUERY).
#include <cdref/fuzz/fuzzcheck.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  cdref::fuzz::check_query(static_cast<cdref::fuzz::Query>(CDREF_FUZZ_QUERY), data, size);
  return 0;
}
