// fuzz/targets/fuzz_casefile.cpp - the libFuzzer target of the case-file reader.
#include <cdref/fuzz/fuzzcheck.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  cdref::fuzz::check_case_reader(data, size);
  return 0;
}
