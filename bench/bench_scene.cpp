// bench/bench_scene.cpp - a crowd: 10^4 moving spheres (and the scene's static boxes, walls
// and floor) over 100 frames with a trigger, a contact, a time of impact and ray casts, run
// at double and exactly in one process. Prints frames per second of each, their ratio, and
// the share of pair queries the effects and the broad phase avoided (against every quantity
// of every pair every frame).
//   cdref_bench_scene [BODIES] [FRAMES] [SEED]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <sstream>
#include <vector>

#include "scene.hpp"

using namespace cdref::scene;

int main(int argc, char** argv) {
  const int bodies = argc > 1 ? std::atoi(argv[1]) : 10000;
  const int frames = argc > 2 ? std::atoi(argv[2]) : 100;
  const unsigned seed = argc > 3 ? unsigned(std::atoi(argv[3])) : 1;
  // the area holds the crowd at a quarter of a body per square unit
  const double side = std::sqrt(bodies * 4.0);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::ostringstream j;
  j.precision(17);
  j << "{\"time_step\": 0.016666666666666666, \"frames\": " << frames << ", \"bodies\": [\n";
  for (int i = 0; i < bodies; ++i) {
    const double a = 2 * M_PI * u(rng), speed = 0.5 + 1.5 * u(rng);
    j << "{\"name\": \"p" << i << "\", \"group\": \"crowd\", \"shape\": \"sphere\", \"radius\": " << 0.3 + 0.2 * u(rng)
      << ", \"position\": [" << side * u(rng) << ", " << side * u(rng) << ", 0.5], \"velocity\": [" << speed * std::cos(a)
      << ", " << speed * std::sin(a) << ", 0]},\n";
  }
  const int crates = bodies / 100;
  for (int i = 0; i < crates; ++i)
    j << "{\"name\": \"c" << i << "\", \"group\": \"crates\", \"shape\": \"box\", \"extent\": [1, 1, 1], \"position\": ["
      << side * u(rng) << ", " << side * u(rng) << ", 1]},\n";
  j << "{\"name\": \"west\", \"group\": \"walls\", \"shape\": \"box\", \"extent\": [0.5, " << side / 2 + 1 << ", 2], \"position\": [-0.5, "
    << side / 2 << ", 2]},\n"
    << "{\"name\": \"east\", \"group\": \"walls\", \"shape\": \"box\", \"extent\": [0.5, " << side / 2 + 1 << ", 2], \"position\": ["
    << side + 0.5 << ", " << side / 2 << ", 2]},\n"
    << "{\"name\": \"floor\", \"shape\": \"mesh\", \"vertices\": [[-1, -1, 0], [" << side + 1 << ", -1, 0], [" << side + 1 << ", "
    << side + 1 << ", 0], [-1, " << side + 1 << ", 0]], \"faces\": [[0, 1, 2], [0, 2, 3]]},\n";
  for (int i = 0; i < 4; ++i)
    j << "{\"name\": \"eye" << i << "\", \"shape\": \"ray\", \"position\": [0, " << side * (i + 0.5) / 4
      << ", 0.5], \"direction\": [1, 0, 0]}" << (i < 3 ? ",\n" : "\n");
  j << "], \"effects\": [\n"
       "{\"type\": \"trigger\", \"name\": \"meet\", \"a\": \"group:crowd\", \"b\": \"group:crowd\"},\n"
       "{\"type\": \"contact\", \"name\": \"bump\", \"a\": \"group:crowd\", \"b\": \"group:crates\"},\n"
       "{\"type\": \"time-of-impact\", \"name\": \"hit-wall\", \"a\": \"group:crowd\", \"b\": \"group:walls\"},\n"
       "{\"type\": \"raycast\", \"name\": \"look\", \"sensor\": [\"eye0\", \"eye1\", \"eye2\", \"eye3\"], \"targets\": \"group:crates\"}\n"
       "]}\n";
  const auto t0 = std::chrono::steady_clock::now();
  const Scene s = parse_scene(j.str(), "crowd");
  const double parse_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("crowd: %d spheres, %d crates, 2 walls, a floor, 4 rays; %d frames (seed %u); parsed in %.2f s\n", bodies,
              crates, frames, seed, parse_s);
  double fps[2] = {0, 0};
  int k = 0;
  std::vector<Run> runs;
  for (Precision p : {Precision::double_, Precision::exact}) {
    runs.push_back(run_scene(s, p));
    const Run& r = runs.back();
    std::uint64_t evaluated = 0;
    for (const auto& [name, n] : r.counts)
      if (name != "broad") evaluated += n;
    fps[k++] = (frames + 1) / r.seconds;
    std::printf("%-6s %8.2f frames/s (%.2f s), %zu events; pair queries %llu (broad-phase pairs %llu) of %llu naive: "
                "%.4f%% evaluated, %.4f%% avoided\n",
                precision_name(p), (frames + 1) / r.seconds, r.seconds, r.events.size(), (unsigned long long)evaluated,
                (unsigned long long)r.counts.at("broad"), (unsigned long long)r.naive, 100.0 * evaluated / r.naive,
                100.0 - 100.0 * evaluated / r.naive);
    for (const auto& [name, n] : r.counts) std::printf("         %-10s %llu\n", name.c_str(), (unsigned long long)n);
  }
  std::printf("exact / double time per frame: %.1f\n", fps[0] / fps[1]);
  const Comparison c = compare(s, runs[0], runs[1]);
  std::printf("double against exact: %zu events at the same frame, %zu missing, %zu extra, %zu at another frame\n",
              c.matched, c.missing.size(), c.extra.size(), c.shifted.size());
  return 0;
}
