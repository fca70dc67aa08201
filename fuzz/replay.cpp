// fuzz/replay.cpp - replays a fuzz corpus through the same checks as the libFuzzer targets,
// in any build (g++ included): cdref_fuzz_replay TARGET FILE-OR-DIRECTORY...
// TARGET is a query name or "casefile". Prints the number of inputs replayed.
#include <cdref/fuzz/fuzzcheck.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: cdref_fuzz_replay TARGET FILE-OR-DIRECTORY...\n");
    return 2;
  }
  const std::string target = argv[1];
  const bool casefile = target == "casefile";
  const cdref::fuzz::Query q = casefile ? cdref::fuzz::Query::sphere_sphere : cdref::fuzz::query_by_name(target);
  std::vector<std::filesystem::path> files;
  for (int i = 2; i < argc; ++i) {
    const std::filesystem::path p = argv[i];
    if (std::filesystem::is_directory(p)) {
      for (const auto& e : std::filesystem::directory_iterator(p))
        if (e.is_regular_file()) files.push_back(e.path());
    } else {
      files.push_back(p);
    }
  }
  for (const auto& f : files) {
    std::ifstream in(f, std::ios::binary);
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto* data = reinterpret_cast<const std::uint8_t*>(bytes.data());
    if (casefile)
      cdref::fuzz::check_case_reader(data, bytes.size());
    else
      cdref::fuzz::check_query(q, data, bytes.size());
  }
  std::printf("%s: %zu inputs replayed, all checks held\n", target.c_str(), files.size());
  return files.empty() ? 1 : 0;
}
