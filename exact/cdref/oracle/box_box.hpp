// cdref/oracle/box_box.hpp - the exact classification of two axis-aligned boxes at double inputs:
// the filter, the expansion and the rationals.
// The decision at an exact type (every difference exact, so a sign of a polynomial in the
// inputs; expansions.hpp: the model of the three stages):
//   box-box         per axis |a - b| <= ea + eb <=> sign(ea + eb - |a - b|) >= 0.
//
// Its classify() is at the end of this file; <cdref/oracle/stages.hpp> runs the stages in order.
#pragma once

#include <cdref/oracle/expansions.hpp>
#include <cdref/oracle/stages.hpp>

namespace cdref::oracle {

namespace staged {

// ======================= box-box =======================
// Filter per axis: P = e~ - |d~|, e~ = fl(ea + eb), d~ = fl(a - b): K = 2, P+ = e + |d|, bound
// 3u fl(e~ + |d~|). Additions have no underflow error; m = 0 means e = d = 0 exactly.
inline int filter(const Box<double>& a, const Box<double>& b, plain = {}) {
  int res = 1;
  for (int i = 0; i < 3; ++i) {
    const double d = std::fabs(a.center[i] - b.center[i]), e = a.extent[i] + b.extent[i], m = e + d;
    if (m == 0) continue;
    if (!in_range(m)) {
      res = unknown;
      continue;
    }
    const int sg = fsign(e - d, (3 * u) * m);
    if (sg == unknown)
      res = unknown;
    else if (sg < 0)
      return 0;
  }
  return res;
}
inline int expansion(const Box<double>& a0, const Box<double>& b0, plain = {}) {
  Box<double> a, b;
  if (!scaled(a0, b0, a, b)) return unknown;
  // ea + eb - |a - b| >= 0 on every axis (the book's two tests, ea + eb -+ (a - b) >= 0, of
  // which the one with the sign of a - b is the binding one: the other adds two nonnegative
  // sums). a - b is the pair set2 makes, its sign that of its larger component (0 for none).
  for (int i = 0; i < 3; ++i) {
    Exp<2> e, d;
    Exp<4> p;
    set2(e, a.extent[i], b.extent[i]);
    set2(d, a.center[i], -b.center[i]);
    if (d.n > 0 && d.c[d.n - 1] < 0) negate(d);
    add(e, d, p, true);
    if (sign(p) < 0) return 0;
  }
  return 1;
}

inline bool rational(const Box<double>& a, const Box<double>& b, plain = {}) { return book::intersect(toq(a), toq(b)); }

}  // namespace staged

// ---- the oracle: the filter (the input checks folded into it: stages.hpp), then the stages ----
inline bool classify(const Box<double>& a, const Box<double>& b, Stage* used = nullptr) {
  return staged::filter_first(used, a, "box A", b, "box B");
}

}  // namespace cdref::oracle
