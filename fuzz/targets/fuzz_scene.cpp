// fuzz/targets/fuzz_scene.cpp - the libFuzzer target of the scene reader (and, for small
// scenes, of the runs and their comparison).
#include <cdref/fuzz/fuzzcheck.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  cdref::fuzz::check_scene_reader(data, size);
  return 0;
}
