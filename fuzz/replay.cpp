// fuzz/replay.cpp - replays a fuzz corpus through the same checks as the libFuzzer targets,
// in any build (g++ included):
//   cdref_fuzz_replay TARGET FILE-OR-DIRECTORY...   TARGET is a query name, "casefile", "scene"
//                                                   or "results"
//   cdref_fuzz_replay --all CORPUS                  every query's CORPUS/<query>,
//                                                   CORPUS/casefile, CORPUS/scene and
//                                                   CORPUS/results, each
//                                                   required non-empty
//   cdref_fuzz_replay --list                        the targets, one a line
// Prints the number of inputs replayed per target.
#include <cdref/fuzz/fuzzcheck.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace {

std::size_t replay(const std::string& target, const std::vector<std::filesystem::path>& paths) {
  const bool casefile = target == "casefile", scene = target == "scene", results = target == "results";
  const cdref::fuzz::Query q =
      casefile || scene || results ? cdref::fuzz::Query{} : cdref::fuzz::query_by_name(target);
  std::vector<std::filesystem::path> files;
  for (const auto& p : paths) {
    if (std::filesystem::is_directory(p)) {
      for (const auto& e : std::filesystem::directory_iterator(p))
        if (e.is_regular_file()) files.push_back(e.path());
    } else if (std::filesystem::exists(p)) {
      files.push_back(p);
    }
  }
  for (const auto& f : files) {
    std::ifstream in(f, std::ios::binary);
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto* data = reinterpret_cast<const std::uint8_t*>(bytes.data());
    if (casefile)
      cdref::fuzz::check_case_reader(data, bytes.size());
    else if (scene)
      cdref::fuzz::check_scene_reader(data, bytes.size());
    else if (results)
      cdref::fuzz::check_results_reader(data, bytes.size());
    else
      cdref::fuzz::check_query(q, data, bytes.size());
  }
  std::printf("%s: %zu inputs replayed, all checks held\n", target.c_str(), files.size());
  return files.size();
}

}  // namespace

int main(int argc, char** argv) {
  const std::string first = argc > 1 ? argv[1] : "";
  std::vector<std::string> targets;
  for (cdref::fuzz::Query q : cdref::fuzz::all_queries()) targets.push_back(cdref::fuzz::info(q).name);
  targets.push_back("casefile");
  targets.push_back("scene");
  targets.push_back("results");
  if (first == "--list") {
    for (const auto& t : targets) std::printf("%s\n", t.c_str());
    return 0;
  }
  if (argc < 3) {
    std::fprintf(stderr, "usage: cdref_fuzz_replay TARGET FILE-OR-DIRECTORY... | --all CORPUS | --list\n");
    return 2;
  }
  if (first == "--all") {
    int empty = 0;
    for (const auto& t : targets)
      if (replay(t, {std::filesystem::path(argv[2]) / t}) == 0) {
        std::fprintf(stderr, "%s: no corpus in %s/%s\n", t.c_str(), argv[2], t.c_str());
        ++empty;
      }
    return empty ? 1 : 0;
  }
  std::vector<std::filesystem::path> paths(argv + 2, argv + argc);
  return replay(first, paths) ? 0 : 1;
}
