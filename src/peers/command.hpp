// src/peers/command.hpp - `cdref peers`, the gallery: its description, shared by cdref's list of
// commands (src/main.cpp) and the gallery's own program (cdref_peers, src/peers/peers.cpp), which
// `cdref peers ARGS` runs in its place as `cdref peers ARGS`.
#pragma once

#include <filesystem>
#include <string>

namespace cdref::peers {

// The gallery's line in `cdref --help` and its own help.
inline constexpr const char* description =
    "GLM's, Bullet's, Eigen's, Embree's, ODE's, FCL's, Open3D's and Rapier's functions on cdref's families at float "
    "(ODE, FCL and Bullet's float64 build at double) against the exact answer: cases where their convention gives "
    "another meaning set apart, misclassifications, p99/max ulps";

// The gallery's program, beside cdref.
inline constexpr const char* program_name = "cdref_peers";

// The path of the program `name` in the folder of the running executable (where cdref's build
// and install put cdref, the gallery's program and its float64 helper side by side).
inline std::string beside_this_program(const std::string& name) {
  const std::string exe = std::filesystem::read_symlink("/proc/self/exe").string();
  return exe.substr(0, exe.rfind('/') + 1) + name;
}

}  // namespace cdref::peers
