/// \file
/// cdref/testing/tolerance.hpp - what the test matchers (catch2.hpp, gtest.hpp) accept and how
/// they say it: a value within `ulps` of the truth, or within `rel` of the scale.
#pragma once

#include <cdref/truth.hpp>
#include <cstdint>
#include <cstdio>
#include <string>

namespace cdref::testing {

/// How close a value must be to the truth: within `ulps` ulps of it, or (when rel > 0) within
/// rel * scale of it, whichever is the looser; ulps = 0 and rel = 0 ask for the truth itself.
struct Tolerance {
  std::uint64_t ulps = 0;  ///< representable values of the caller's type between value and truth
  double rel = 0;          ///< |value - truth| / scale (0: not used)
  double scale = 1;        ///< the magnitude rel is taken against (truth::scale_of gives the inputs')
};

/// Whether the deviation is within the tolerance.
inline bool accepts(const Tolerance& t, const truth::Deviation& d) {
  return d.ulps <= t.ulps || (t.rel > 0 && d.rel <= t.rel);
}

/// "is within 4 ulps of the truth 0x1.08p+2 (or 1e-15 of the scale 3)".
inline std::string describe(const Tolerance& t, double truth) {
  char b[200];
  if (t.rel > 0)
    std::snprintf(b, sizeof b, "is within %llu ulps of the truth %a (%.17g) or %g of the scale %g",
                  (unsigned long long)t.ulps, truth, truth, t.rel, t.scale);
  else if (t.ulps == 0)
    std::snprintf(b, sizeof b, "is the truth %a (%.17g)", truth, truth);
  else
    std::snprintf(b, sizeof b, "is within %llu ulps of the truth %a (%.17g)", (unsigned long long)t.ulps, truth, truth);
  return b;
}

/// "; it is 7 ulps off (abs 1.8e-15, 6e-16 of the scale)".
inline std::string describe(const truth::Deviation& d) {
  char b[160];
  std::snprintf(b, sizeof b, "; it is %llu ulps off (abs %.3g, %.3g of the scale)", (unsigned long long)d.ulps, d.abs,
                d.rel);
  return b;
}

}  // namespace cdref::testing
