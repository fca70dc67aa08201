// cdref/oracle/sphere_sphere.hpp - the exact classification of two spheres at double inputs: the
// filter, the robust tier's double words, the expansion and the rationals.
// The decision at an exact type (every difference exact, so a sign of a polynomial in the
// inputs; expansions.hpp: the model of the three stages):
//   sphere-sphere   S^2 - |D|^2 >= 0, D = cA - cB, S = rhoA + rhoB.
//
// Its classify() is at the end of this file; <cdref/oracle/stages.hpp> runs the stages in order.
#pragma once

#include <cdref/oracle/expansions.hpp>
#include <cdref/oracle/stages.hpp>
#include <cdref/robust/sphere_sphere.hpp>

namespace cdref::oracle {

namespace staged {

// ======================= sphere-sphere =======================
// Filter: P = S~^2 - sum D~_i^2 with D~_i = fl(cA_i - cB_i), S~ = fl(rhoA + rhoB).
// K: D_x^2 has 2 (leaves) + 1 (square) + 2 (sums) + 1 (final) = 6 factors, S^2 has 4: K = 6,
// P+ = |D|^2 + S^2 <= (xx + yy)(1 + 8u) from the computed terms, so bound 7u fl(xx + yy).
inline int filter(const Sphere<double>& a, const Sphere<double>& b, plain = {}) {
  const double dx = a.center[0] - b.center[0], dy = a.center[1] - b.center[1], dz = a.center[2] - b.center[2];
  const double s = a.radius + b.radius;
  const double xx = dx * dx + dy * dy + dz * dz, yy = s * s, m = xx + yy;
  if (!in_range(m)) return unknown;
  return positive_or_unknown(yy - xx, (7 * u) * m);  // ge0(fsign(..))
}
inline int expansion(const Sphere<double>& a0, const Sphere<double>& b0, plain = {}) {
  Sphere<double> a, b;
  if (!scaled(a0, b0, a, b)) return unknown;
  Exp<2> s, d;
  Exp<8> sq;
  Exp<32> acc[2];
  set2(s, a.radius, b.radius);
  mul(s, s, sq);
  int cur = 0;
  acc[0].n = sq.n;
  for (int k = 0; k < sq.n; ++k) acc[0].c[k] = sq.c[k];
  for (int i = 0; i < 3; ++i) {
    set2(d, a.center[i], -b.center[i]);
    mul(d, d, sq);
    add(acc[cur], sq, acc[1 - cur], true);
    cur ^= 1;
  }
  return int(sign(acc[cur]) >= 0);
}

inline bool rational(const Sphere<double>& a, const Sphere<double>& b, plain = {}) { return book::intersect(toq(a), toq(b)); }

// Between the filter and the expansions, for the sphere queries: the robust tier's
// certified decision (float/cdref/robust: the inputs' differences as exact pairs, every
// decisive quantity in double words with a rigorous bound; its certificate is fuzzed against
// the exact answer). Where it is certain its answer is exact, and it decides every case but
// those within about u^2 of the boundary (2^-52 from tangency costs it 0.17 us where the
// expansions took 1.1 us); it reports as the expansion stage, the second.
inline int double_word(const Sphere<double>& a, const Sphere<double>& b, plain = {}) { return certain_or_unknown(robust::decide(a, b)); }

}  // namespace staged

// ---- the oracle: the filter (the input checks folded into it: stages.hpp), then the stages ----
inline bool classify(const Sphere<double>& a, const Sphere<double>& b, Stage* used = nullptr) {
  return staged::filter_first(used, a, "sphere A", b, "sphere B");
}

}  // namespace cdref::oracle
