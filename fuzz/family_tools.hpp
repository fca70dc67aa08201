// fuzz/family_tools.hpp - what the case families are made with: 3-vectors of doubles,
// uniform draws from a stream of random words, unit vectors, the common scale lists.
#pragma once

#include <cdref/fuzz/campaign.hpp>
#include <cmath>
#include <functional>
#include <vector>

namespace cdref::fuzz::family {

using Next = CaseStream;

struct V {
  double x, y, z;
};
inline V operator+(V a, V b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline V operator-(V a, V b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline V operator*(double k, V a) { return {k * a.x, k * a.y, k * a.z}; }
inline double dot(V a, V b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline V cross(V a, V b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline V normalized(V a) { return (1.0 / std::sqrt(dot(a, a))) * a; }

inline double uni(Next& next, double a, double b) { return a + (b - a) * double(next() >> 11) * 0x1p-53; }
inline int pick(Next& next, int n) { return int(next() % std::uint64_t(n)); }
inline double sign(Next& next) { return (next() & 1) ? 1.0 : -1.0; }
inline V uvec(Next& next, double a, double b) { return {uni(next, a, b), uni(next, a, b), uni(next, a, b)}; }
inline V unit(Next& next) {
  for (;;) {
    const V v = uvec(next, -1, 1);
    const double n = dot(v, v);
    if (n > 1e-4 && n <= 1) return normalized(v);
  }
}
// A unit vector orthogonal to u.
inline V perp(Next& next, V u) {
  for (;;) {
    const V w = cross(u, unit(next));
    if (dot(w, w) > 1e-4) return normalized(w);
  }
}
inline V axis(int i, double s = 1) { return i == 0 ? V{s, 0, 0} : (i == 1 ? V{0, s, 0} : V{0, 0, s}); }

inline void put(Inputs& in, int k, V v) {
  in[k] = v.x;
  in[k + 1] = v.y;
  in[k + 2] = v.z;
}

inline std::vector<int> range(int a, int b, int step = 1) {
  std::vector<int> v;
  for (int k = a; k <= b; k += step) v.push_back(k);
  return v;
}
// The scale lists are functions, not namespace-scope vectors: the query registry may be built
// during another translation unit's static initialisation (a benchmark's global Query), before
// such a vector would have been initialised.
inline std::vector<int> tangency_scales() { return {1, 2, 4, 8, 12, 16, 20, 24, 28, 32, 36, 40, 44, 48, 52}; }
inline std::vector<int> decades() { return range(0, 12); }
// 10^-320 and 10^-310 put the uniform family's coordinates among the subnormals.
inline std::vector<int> magnitudes() {
  std::vector<int> v = {-320, -310};
  for (int k : range(-300, 300, 50)) v.push_back(k);
  return v;
}

// Scales the first n inputs of a case (its coordinates and lengths) by 10^k.
inline void scaled(Inputs& in, int n, int k) {
  const double f = std::pow(10.0, k);
  for (int i = 0; i < n; ++i) in[i] *= f;
}

}  // namespace cdref::fuzz::family
