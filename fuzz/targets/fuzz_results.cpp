// fuzz/targets/fuzz_results.cpp - the libFuzzer target of the results readers: a campaign's
// text form (shards, checkpoints) and a cdref-mpi rank's checkpoint.
#include <cdref/fuzz/fuzzcheck.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  cdref::fuzz::check_results_reader(data, size);
  return 0;
}
