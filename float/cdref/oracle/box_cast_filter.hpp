// cdref/oracle/box_cast_filter.hpp - the first stage of the classification oracle for a
// segment or a ray cast on an axis-aligned box (Algorithm 3.3; exact/cdref/oracle/classify.hpp
// holds the other stages and the model of the bounds: u = 2^-53, gamma_K, the range checks),
// with the helpers every stage-1 filter there uses. Plain double arithmetic on the query's
// inputs, so that both the oracle and the robust tier's certified decisions at double
// (robust/ray_box.hpp, and segment-box and ray-box in robust/separating_axes.hpp) run it first:
// where it decides (1 a hit, 0 a miss; `unknown` leaves the case to the next stage), its
// answer is the book's at an exact type.
//
// The decision (the book keeps the largest entering parameter, from 0, and the smallest exiting
// one, from 1 for a segment, and hits iff enter <= exit): outcodes are the signs of p - c + h
// and p - c - h; every entering parameter lies in [0, 1] and every exiting one in [0, 1]
// ([0, inf) for a ray), so the cast hits iff no outcode bit is shared and, for every entering
// plane p and exiting plane q, lambda_p <= lambda_q, i.e. with lambda = n / d, d > 0,
// n_p d_q - n_q d_p <= 0 (n = -(s - c) -+ h, d = |target - source| or |direction|).
#pragma once

#include <cdref/primitives.hpp>
#include <cmath>

namespace cdref::oracle::staged {

inline constexpr int unknown = 2;  // a sign (-1, 0, 1) or this; a decision (0, 1) or this
inline constexpr double u = 0x1p-53;

// ---- stage 1 helpers ----
// Range of the sums of squares (or of the absolute terms) that the bounds rely on.
inline bool in_range(double m) { return m >= 0x1p-960 && m <= 0x1p1000; }
inline int fsign(double p, double bound) { return p > bound ? 1 : (p < -bound ? -1 : unknown); }

// Outcode filter for q~ = fl(p - c): L~ = fl(q~ + h) (lower plane), U~ = fl(q~ - h) (upper).
// |L~ - L| <= u |q~ + h| + u |q~| (fl(x) = x / (1 + delta)) and |q~ + h| <= |L~| / (1 - u), so
// the sign of L~ is certain when |L~| > 2u |q~| = fl(2^-52 |q~|): (1 - 2u) 2u > u. That
// product underflows only for |q~| < 2^-970: below 2^-1021 the difference q~ is exact, so
// L~ (rounded once, sign kept) has the exact sign, 0 included; between, the underflow loses
// at most a quarter of 2u |q~| and 1.5u > u still. |L~| <= 2^1000 excludes overflow (an
// infinite q~ makes L~ infinite or NaN).
inline int outcode_sign(double l, double e) {
  if (!(std::fabs(l) <= 0x1p1000)) return unknown;
  if (l < -e) return -1;
  if (l > e) return 1;
  return e == 0 ? 0 : unknown;  // e = 0: q~ is exact (and then l = 0 exactly)
}
// Pair filter: lambda_p <= lambda_q <=> n'_p d'_q - n'_q d'_p <= 0, n' = n sign(d), d' = |d|,
// n = -L~ or -U~ of the source on the plane's axis. K: q~ (1) + the +-h (1) + product (1) +
// leaf d (1) + final (1) = 5; P+ = (|s_i| + h_i)|d_j| + (|s_j| + h_j)|d_i| <= the same with
// computed a_i = fl(|q~_i| + h_i) and |d~| times (1 + 10u): bound 6u fl(a_i d'_q + a_j d'_p).
struct BoxFilter {
  double sL[3], sU[3], sE[3], sA[3], tL[3], tU[3], tE[3], r[3];
  bool bounded;
  BoxFilter(const Vec3<double>& src, const Vec3<double>& rt, const Box<double>& box, bool segment)
      : bounded(segment) {
    for (int i = 0; i < 3; ++i) {
      const double q = src[i] - box.center[i], h = box.extent[i];
      sL[i] = q + h;
      sU[i] = q - h;
      sE[i] = 0x1p-52 * std::fabs(q);
      sA[i] = std::fabs(q) + h;
      if (segment) {
        const double p = rt[i] - box.center[i];
        tL[i] = p + h;
        tU[i] = p - h;
        tE[i] = 0x1p-52 * std::fabs(p);
        r[i] = rt[i] - src[i];
      } else {
        r[i] = rt[i];
      }
    }
  }
  int src_lo(int i) const { return outcode_sign(sL[i], sE[i]); }  // sign(s_i + h_i)
  int src_hi(int i) const { return outcode_sign(sU[i], sE[i]); }  // sign(s_i - h_i)
  int tgt_lo(int i) const { return outcode_sign(tL[i], tE[i]); }
  int tgt_hi(int i) const { return outcode_sign(tU[i], tE[i]); }
  int dir_sign(int i) const { return r[i] > 0 ? 1 : (r[i] < 0 ? -1 : 0); }  // exact for a ray
  // sign(lambda_p - lambda_q), planes 2i (lower) / 2i + 1 (upper).
  int compare(int p, int q) const {
    const int i = p / 2, j = q / 2;
    const double np = -(p % 2 == 0 ? sL[i] : sU[i]), nq = -(q % 2 == 0 ? sL[j] : sU[j]);
    const double dp = std::fabs(r[i]), dq = std::fabs(r[j]);
    const double npp = r[i] > 0 ? np : -np, nqq = r[j] > 0 ? nq : -nq;
    const double m = sA[i] * dq + sA[j] * dp;
    if (!in_range(m)) return unknown;
    return fsign(npp * dq - nqq * dp, (6 * u) * m);
  }
};
// Algorithm 3.3's decision (book::hit on a box), over filtered or exact signs.
template <class P>
int hit_box_logic(const P& p) {
  unsigned bs = 0, bt = 0;
  for (int i = 0; i < 3; ++i) {
    const int sl = p.src_lo(i), sh = p.src_hi(i);
    if (sl == unknown || sh == unknown) return unknown;
    if (sl < 0) bs |= 1u << (2 * i);
    if (sh > 0) bs |= 2u << (2 * i);
    if (p.bounded) {
      const int tl = p.tgt_lo(i), th = p.tgt_hi(i);
      if (tl == unknown || th == unknown) return unknown;
      if (tl < 0) bt |= 1u << (2 * i);
      if (th > 0) bt |= 2u << (2 * i);
    } else {
      const int d = p.dir_sign(i);
      if (d < 0 || (d == 0 && sl < 0)) bt |= 1u << (2 * i);
      if (d > 0 || (d == 0 && sh > 0)) bt |= 2u << (2 * i);
    }
  }
  if (bs & bt) return 0;
  int res = 1;
  for (int a = 0; a < 6; ++a) {
    if (!(bs & (1u << a))) continue;
    for (int b = 0; b < 6; ++b) {
      if (!(bt & (1u << b))) continue;
      const int c = p.compare(a, b);
      if (c == unknown)
        res = unknown;
      else if (c > 0)
        return 0;
    }
  }
  return res;
}
inline int filter(const Segment<double>& seg, const Box<double>& box) {
  return hit_box_logic(BoxFilter(seg.source, seg.target, box, true));
}
inline int filter(const Ray<double>& ray, const Box<double>& box) {
  return hit_box_logic(BoxFilter(ray.source, ray.direction, box, false));
}

}  // namespace cdref::oracle::staged
