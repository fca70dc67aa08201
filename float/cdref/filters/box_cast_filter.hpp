// cdref/filters/box_cast_filter.hpp - the first stage of the classification oracle for a
// segment or a ray cast on an axis-aligned box (Algorithm 3.3; exact/cdref/oracle/box_casts.hpp
// holds the other stages, oracle/expansions.hpp the model of the bounds: u = 2^-53, gamma_K, the range checks),
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

#include <cdref/filters/stage_tags.hpp>
#include <cdref/primitives.hpp>
#include <algorithm>
#include <cmath>
#include <type_traits>

namespace cdref::filters::staged {

inline constexpr int unknown = 2;  // a sign (-1, 0, 1) or this; a decision (0, 1) or this
inline constexpr double u = 0x1p-53;

// ---- stage 1 helpers ----
// Range of the sums of squares (or of the absolute terms) that the bounds rely on.
inline bool in_range(double m) { return m >= 0x1p-960 && m <= 0x1p1000; }
inline int fsign(double p, double bound) { return p > bound ? 1 : (p < -bound ? -1 : unknown); }
// ge0(fsign(p, bound)) with one branch, on whether the sign is certain, none on which sign it
// is: 1 when p > bound, 0 when p < -bound, else unknown (= 2). Where a filter's answer is its
// last sign (hit or miss, half the cases each on uniform inputs), fsign's two branches and the
// caller's were mispredicted about half the time, which cost more than the filter's arithmetic
// (sphere-sphere's oracle took 4.3x `bare` over 16,384 cases). Here |p| > bound (bound >= 0; a
// NaN fails it) is the certainty, the caller's test of `unknown` is that one branch, taken
// alike on hits and misses, and the answer is p > 0 as a value.
inline int positive_or_unknown(double p, double bound) { return std::fabs(p) > bound ? int(p > 0) : unknown; }

// What the box casts' range tests below do not see, tested before them where the input checks
// come after (oracle/stages.hpp, filter_first; robust/ray_box.hpp): the extents' signs, and a ray's
// direction (finite, not zero), which enters only through its signs and the pairs.
inline bool signs_valid(const Box<double>& b, plain = {}) { return b.extent[0] >= 0 && b.extent[1] >= 0 && b.extent[2] >= 0; }
inline bool direction_valid(const Vec3<double>& d) {
  return (d[0] - d[0]) + (d[1] - d[1]) + (d[2] - d[2]) == 0 && (d[0] != 0 || d[1] != 0 || d[2] != 0);
}

// Outcode filter for q~ = fl(p - c): L~ = fl(q~ + h) (lower plane), U~ = fl(q~ - h) (upper).
// |L~ - L| <= u |q~ + h| + u |q~| (fl(x) = x / (1 + delta)) and |q~ + h| <= |L~| / (1 - u), so
// the sign of L~ is certain when |L~| > 2u |q~| = fl(2^-52 |q~|): (1 - 2u) 2u > u. That
// product underflows only for |q~| < 2^-970: below 2^-1021 the difference q~ is exact, so
// L~ (rounded once, sign kept) has the exact sign, 0 included; between, the underflow loses
// at most a quarter of 2u |q~| and 1.5u > u still. |L~| <= 2^1000 excludes overflow (an
// infinite q~ makes L~ infinite or NaN); outcode_sign_in_range leaves that test to its caller.
inline int outcode_sign_in_range(double l, double e) {
  if (l < -e) return -1;
  if (l > e) return 1;
  return e == 0 ? 0 : unknown;  // e = 0: q~ is exact (and then l = 0 exactly)
}
inline int outcode_sign(double l, double e) {
  if (!(std::fabs(l) <= 0x1p1000)) return unknown;
  return outcode_sign_in_range(l, e);
}
// Pair filter: lambda_p <= lambda_q <=> n'_p d'_q - n'_q d'_p <= 0, n' = n sign(d), d' = |d|,
// n = -L~ or -U~ of the source on the plane's axis. K: q~ (1) + the +-h (1) + product (1) +
// leaf d (1) + final (1) = 5; P+ = (|s_i| + h_i)|d_j| + (|s_j| + h_j)|d_i| <= the same with
// computed a_i = fl(|q~_i| + h_i) and |d~| times (1 + 10u): bound 6u fl(a_i d'_q + a_j d'_p).
// The outcodes' range test once for the case: |L~|, |U~| <= fl(|q~| + h) (h >= 0: the callers
// test the extents' signs first; rounding is monotone and odd), so fl(|q~| + h) <= 2^1000 at the
// source and the target (a NaN fails it) stands for every outcode's |L~| <= 2^1000 (`ok`; the
// filter answers unknown without it, as an outcode would).
struct BoxFilter {
  double sL[3], sU[3], sE[3], sA[3], tL[3], tU[3], tE[3], r[3];
  bool bounded, ok;
  BoxFilter(const Vec3<double>& src, const Vec3<double>& rt, const Box<double>& box, bool segment)
      : bounded(segment) {
    bool in = true;
    for (int i = 0; i < 3; ++i) {
      const double q = src[i] - box.center[i], h = box.extent[i];
      sL[i] = q + h;
      sU[i] = q - h;
      sE[i] = 0x1p-52 * std::fabs(q);
      sA[i] = std::fabs(q) + h;
      in &= sA[i] <= 0x1p1000;
      if (segment) {
        const double p = rt[i] - box.center[i];
        tL[i] = p + h;
        tU[i] = p - h;
        tE[i] = 0x1p-52 * std::fabs(p);
        r[i] = rt[i] - src[i];
        in &= std::fabs(p) + h <= 0x1p1000;
      } else {
        r[i] = rt[i];
      }
    }
    ok = in;
  }
  int src_lo(int i) const { return outcode_sign_in_range(sL[i], sE[i]); }  // sign(s_i + h_i)
  int src_hi(int i) const { return outcode_sign_in_range(sU[i], sE[i]); }  // sign(s_i - h_i)
  int tgt_lo(int i) const { return outcode_sign_in_range(tL[i], tE[i]); }
  int tgt_hi(int i) const { return outcode_sign_in_range(tU[i], tE[i]); }
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
  // hit_box_logic's loop over every (entering, exiting) pair at once, each pair as compare()
  // evaluates it, combined without branches on the data: a pair certainly in the wrong order
  // is a miss; else an undecided pair leaves the case undecided; else a hit. (At most one
  // entering and one exiting plane per axis; a pair's direction components are nonzero.)
  int pairs(unsigned bs, unsigned bt) const {
    double ne[3], nx[3], ar[3];
    bool ent[3], ext[3];
    for (int i = 0; i < 3; ++i) {
      const double sg = r[i] > 0 ? 1.0 : -1.0;
      ne[i] = -sg * ((bs >> (2 * i)) & 1 ? sL[i] : sU[i]);
      nx[i] = -sg * ((bt >> (2 * i)) & 1 ? sL[i] : sU[i]);
      ar[i] = std::fabs(r[i]);
      ent[i] = (bs >> (2 * i)) & 3;
      ext[i] = (bt >> (2 * i)) & 3;
    }
    bool miss = false, undecided = false;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const bool valid = ent[i] & ext[j];
        const double m = sA[i] * ar[j] + sA[j] * ar[i];
        const double v = ne[i] * ar[j] - nx[j] * ar[i], e = (6 * u) * m;
        const bool ok = in_range(m);
        miss |= valid & ok & (v > e);
        undecided |= valid & !(ok & ((v > e) | (v < -e)));
      }
    return miss ? 0 : (undecided ? unknown : 1);
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
      if (d == unknown) return unknown;
      if (d < 0 || (d == 0 && sl < 0)) bt |= 1u << (2 * i);
      if (d > 0 || (d == 0 && sh > 0)) bt |= 2u << (2 * i);
    }
  }
  if (bs & bt) return 0;
  if (bs == 0 || bt == 0) return 1;  // no pair
  if constexpr (requires { p.pairs(bs, bt); }) return p.pairs(bs, bt);  // the loop below at once
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
// ---- Algorithm 3.3 on an oriented box, in face coordinates ----
// The solid (solid/obb.hpp) is P = {c + sum_k g_k a_k : |g_k| <= h_k}. With the face normals
// n_i = a_{i+1} x a_{i+2} and delta = a_0 . n_0 (n_i . a_k = delta [i = k]), the coordinate
// Y_i = n_i . (p - c) of a point p is g_i delta, so p lies in P exactly when |Y_i| <= H_i =
// h_i |delta| for every i: P is the axis-aligned box [-H, H] in Y (a linear map; a ray's
// parameters are unchanged), and a segment or a ray meets P exactly when Algorithm 3.3 hits
// that box (which is how the solid casts; the sign of delta, which swaps axis i's two planes of
// a symmetric box, does not matter). So hit_box_logic decides it from these signs:
//   outcodes   Y_i -+ H_i at the source and the target (or the sign of d_i = n_i . r, a ray);
//   pairs      lambda_a <= lambda_b for an entering plane a (axis i) and an exiting plane b
//              (axis j): with N = -(Y_s -+ H) on the plane's side, d = Y_t - Y_s (segment) or
//              n . r (ray), lambda = N / d, and the sign of d known from the plane's role
//              (entering the lower plane d_i > 0, the upper d_i < 0; leaving through the lower
//              d_j < 0, the upper d_j > 0: both are certain once the outcodes are), the sign of
//              lambda_a - lambda_b is sigma_i sigma_j sign(N_a d_j - N_b d_i).
// Error bounds. Computed in double: n_i (2 roundings a component), D = a_0 . n_0 (5),
// X = fl(p - c) (1), Y_i = n_i . X (6), H_i = h_i |D| (6; |D~| approximates |delta| as D~
// does delta), Y -+ H (7), d = fl(Y_t - Y_s) (7) or n . r (5), N_a d_j - N_b d_i (16). Each is a
// sum of monomials (a a X, h a a a, a a r and their products) whose roundings are at most the
// counts above, so its error is at most gamma_K times the sum of the monomials' absolute values
// (Higham 3.1, 3.3). The filter runs first with the static sums below (M_Y, M_d) and, where
// they leave the case undecided, again with each quantity's own: with n+_i the cross
// product's absolute expansion
// (|a_{i+1,c+1} a_{i+2,c+2}| + |a_{i+1,c+2} a_{i+2,c+1}| for component c),
//   P_i = n+_i . |X| + h_i D+  (Y -+ H; D+ = |a_0| . n+_0),  d: n+_i . (|X_s| + |X_t|) or n+_i . |r|,
//   P_i(s) d+_j + P_j(s) d+_i  (N_a d_j - N_b d_i),
// each from |X~| (|X| <= |X~| / (1 - u)) and a few roundings of nonnegative terms, which the
// margins hold: an outcode's sign is certain beyond 8u P (gamma_7 <= 7.1u), a ray's d_i beyond
// 6u d+_i (gamma_5), a pair's beyond 17u (P d+ + P d+) (gamma_16 <= 16.3u). Range: with m =
// the largest |a_kc|, A = 2 m^2 and the static sums M_Y = A max(|X_s|_1, |X_t|_1) + 3 A m
// max_i h_i (>= every P) and M_d = A (|X_s|_1 + |X_t|_1) or A |r|_1 (>= every d+), the filter
// runs only for m in [2^-300, 2^300] and M_Y, M_d in [2^-450, 2^500]: then no value overflows
// (each is below its own sum, M_Y M_d <= 2^1000), and the roundings that underflow (each off by
// at most 2^-1075, carried through at most a factor |X|_1, m h or a d+) add less than 2^-100 u
// M_Y to an outcode, 2^-100 u M_d to a d and 2^-90 u M_Y M_d to a pair, which every bound adds
// too. Elsewhere the filter answers unknown.
struct ObbFilter {
  double sL[3], sU[3], tL[3], tU[3], d[3];
  double es[3], et[3], ed[3], ps[3], dp[3], fc = 0, fo = 0, fd = 0;
  bool bounded, ok = false, tight = false;
  const Vec3<double>& src;
  const Vec3<double>& rt;
  const OrientedBox<double>& box;
  // The values and the static bounds (every P at most M_Y, every d+ at most M_d).
  ObbFilter(const Vec3<double>& src_, const Vec3<double>& rt_, const OrientedBox<double>& b, bool segment)
      : bounded(segment), src(src_), rt(rt_), box(b) {
    const auto& a = b.axis;
    double n[3][3];
    for (int i = 0; i < 3; ++i) {
      const auto& p = a[(i + 1) % 3];
      const auto& q = a[(i + 2) % 3];
      n[i][0] = p[1] * q[2] - p[2] * q[1];
      n[i][1] = p[2] * q[0] - p[0] * q[2];
      n[i][2] = p[0] * q[1] - p[1] * q[0];
    }
    const double D = std::fabs(a[0][0] * n[0][0] + a[0][1] * n[0][1] + a[0][2] * n[0][2]);
    double m = 0, hmax = 0;
    for (int k = 0; k < 3; ++k) {
      m = std::max(m, std::max(std::fabs(a[k][0]), std::max(std::fabs(a[k][1]), std::fabs(a[k][2]))));
      hmax = std::max(hmax, b.extent[k]);
    }
    double xs[3], xt[3];
    for (int c = 0; c < 3; ++c) {
      xs[c] = src[c] - b.center[c];
      xt[c] = segment ? rt[c] - b.center[c] : rt[c];  // a ray's direction, as it is
    }
    const double ns = std::fabs(xs[0]) + std::fabs(xs[1]) + std::fabs(xs[2]);
    const double nt = std::fabs(xt[0]) + std::fabs(xt[1]) + std::fabs(xt[2]);
    const double A = 2 * m * m;
    const double my = A * (segment ? std::max(ns, nt) : ns) + 3 * A * m * hmax;
    const double md = A * (segment ? ns + nt : nt);
    ok = m >= 0x1p-300 && m <= 0x1p300 && my >= 0x1p-450 && my <= 0x1p500 && md >= 0x1p-450 && md <= 0x1p500;
    if (!ok) return;
    fo = 0x1p-100 * u * my;
    fd = 0x1p-100 * u * md;
    fc = 0x1p-90 * u * my * md;
    for (int i = 0; i < 3; ++i) {
      const double H = b.extent[i] * D;
      const double ys = n[i][0] * xs[0] + n[i][1] * xs[1] + n[i][2] * xs[2];
      const double yt = n[i][0] * xt[0] + n[i][1] * xt[1] + n[i][2] * xt[2];
      sL[i] = ys + H;
      sU[i] = ys - H;
      tL[i] = yt + H;
      tU[i] = yt - H;
      d[i] = segment ? yt - ys : yt;
      ps[i] = my;
      dp[i] = md;
      es[i] = et[i] = 8 * u * my + fo;
      ed[i] = 6 * u * md + fd;
    }
  }
  // The bounds from each quantity's own sum of monomials (P_i, d+_i), for the cases the static
  // ones leave undecided (a shot from far away, a frame with small components).
  void tighten() {
    tight = true;
    const auto& a = box.axis;
    double na[3][3];
    for (int i = 0; i < 3; ++i) {
      const auto& p = a[(i + 1) % 3];
      const auto& q = a[(i + 2) % 3];
      for (int c = 0; c < 3; ++c) {
        const int c1 = (c + 1) % 3, c2 = (c + 2) % 3;
        na[i][c] = std::fabs(p[c1] * q[c2]) + std::fabs(p[c2] * q[c1]);
      }
    }
    const double Dp = std::fabs(a[0][0]) * na[0][0] + std::fabs(a[0][1]) * na[0][1] + std::fabs(a[0][2]) * na[0][2];
    double as[3], at[3];
    for (int c = 0; c < 3; ++c) {
      as[c] = std::fabs(src[c] - box.center[c]);
      at[c] = std::fabs(bounded ? rt[c] - box.center[c] : rt[c]);
    }
    for (int i = 0; i < 3; ++i) {
      const double hp = box.extent[i] * Dp;
      const double ss = na[i][0] * as[0] + na[i][1] * as[1] + na[i][2] * as[2];
      const double st = na[i][0] * at[0] + na[i][1] * at[1] + na[i][2] * at[2];
      ps[i] = ss + hp;
      es[i] = 8 * u * ps[i] + fo;
      et[i] = 8 * u * (st + hp) + fo;
      dp[i] = bounded ? ss + st : st;
      ed[i] = 6 * u * dp[i] + fd;
    }
  }
  static int sign_of(double x, double e) { return x > e ? 1 : (x < -e ? -1 : unknown); }
  int src_lo(int i) const { return sign_of(sL[i], es[i]); }
  int src_hi(int i) const { return sign_of(sU[i], es[i]); }
  int tgt_lo(int i) const { return sign_of(tL[i], et[i]); }
  int tgt_hi(int i) const { return sign_of(tU[i], et[i]); }
  int dir_sign(int i) const { return sign_of(d[i], ed[i]); }  // a ray's; never a certain 0
  // |d~_i - n_i . (t - s)| (a segment) or |d~_i - n_i . r| (a ray): a ray's ed_i; a segment's
  // d~ = fl(Y~(t) - Y~(s)) carries X's rounding and the difference besides (gamma_6 of each
  // n+ . |X| and u |d~|, |d~| <= (1 + 7u) d+): 8u d+ (oracle/enter_obb.hpp takes D from here)
  double d_bound(int i) const { return bounded ? 8 * u * dp[i] + fd : ed[i]; }
  // sign(lambda_a - lambda_b): a an entering plane, b an exiting one (2i lower, 2i + 1 upper)
  int compare(int a, int b) const {
    const int i = a / 2, j = b / 2;
    const double Na = -(a % 2 == 0 ? sL[i] : sU[i]), Nb = -(b % 2 == 0 ? sL[j] : sU[j]);
    const int sigma = (a % 2 == 0 ? 1 : -1) * (b % 2 == 0 ? -1 : 1);
    const int r = sign_of(Na * d[j] - Nb * d[i], 17 * u * (ps[i] * dp[j] + ps[j] * dp[i]) + fc);
    return r == unknown ? unknown : sigma * r;
  }
  // sign(lambda_a - lambda_b) for two entering planes of different axes, on a shot that hits:
  // each is crossed, so d has the sign of its role (entering the lower plane d > 0, the upper
  // d < 0), and lambda_a - lambda_b = (N_a d_j - N_b d_i) / (d_i d_j), the same expression and
  // bound as compare() (oracle/enter_obb.hpp picks the entering face with it)
  int compare_entering(int a, int b) const {
    const int i = a / 2, j = b / 2;
    const double Na = -(a % 2 == 0 ? sL[i] : sU[i]), Nb = -(b % 2 == 0 ? sL[j] : sU[j]);
    const int sigma = (a % 2 == 0 ? 1 : -1) * (b % 2 == 0 ? 1 : -1);
    const int r = sign_of(Na * d[j] - Nb * d[i], 17 * u * (ps[i] * dp[j] + ps[j] * dp[i]) + fc);
    return r == unknown ? unknown : sigma * r;
  }
  // hit_box_logic's loop over every (entering, exiting) pair at once, each as compare() above
  // (each sign sigma folded into its plane's numerator and d), without branches on the data.
  int pairs(unsigned bs, unsigned bt) const {
    double ne[3], de[3], nx[3], dx[3];
    bool ent[3], ext[3];
    for (int i = 0; i < 3; ++i) {
      const bool lo_in = (bs >> (2 * i)) & 1, lo_out = (bt >> (2 * i)) & 1;
      const double se = lo_in ? 1.0 : -1.0, sx = lo_out ? -1.0 : 1.0;
      ne[i] = -se * (lo_in ? sL[i] : sU[i]);
      de[i] = se * d[i];
      nx[i] = -sx * (lo_out ? sL[i] : sU[i]);
      dx[i] = sx * d[i];
      ent[i] = (bs >> (2 * i)) & 3;
      ext[i] = (bt >> (2 * i)) & 3;
    }
    bool miss = false, undecided = false;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const bool valid = ent[i] & ext[j];
        const double w = ne[i] * dx[j] - nx[j] * de[i], e = 17 * u * (ps[i] * dp[j] + ps[j] * dp[i]) + fc;
        miss |= valid & (w > e);
        undecided |= valid & !((w > e) | (w < -e));
      }
    return miss ? 0 : (undecided ? unknown : 1);
  }
  // hit_box_logic's decision with every outcode taken at once, without a branch per sign (on
  // uniform shots those branches go either way, and their mispredictions cost more than the
  // arithmetic): the same outcodes, bits and pairs, and one more certainty, a shared outcode
  // bit on an axis whose signs are certain is a miss whatever the other axes say (both ends,
  // or the source and the direction, beyond the same plane). A ray's d_i is never a certain 0
  // here, so its exiting bits are d_i < 0 (lower) and d_i > 0 (upper).
  int decide() const {
    unsigned bs = 0, bt = 0, sure = 0;
    for (int i = 0; i < 3; ++i) {
      const bool sl_neg = sL[i] < -es[i], sl_pos = sL[i] > es[i];
      const bool sh_neg = sU[i] < -es[i], sh_pos = sU[i] > es[i];
      bool xl, xh, tsure;
      if (bounded) {
        xl = tL[i] < -et[i];
        xh = tU[i] > et[i];
        tsure = (xl | (tL[i] > et[i])) & (xh | (tU[i] < -et[i]));
      } else {
        xl = d[i] < -ed[i];
        xh = d[i] > ed[i];
        tsure = xl | xh;
      }
      const bool axis_sure = (sl_neg | sl_pos) & (sh_neg | sh_pos) & tsure;
      bs |= (unsigned(sl_neg) | unsigned(sh_pos) << 1) << (2 * i);
      bt |= (unsigned(xl) | unsigned(xh) << 1) << (2 * i);
      sure |= unsigned(axis_sure) * (3u << (2 * i));
    }
    if (bs & bt & sure) return 0;
    if (sure != 0x3f) return unknown;
    if (bs == 0 || bt == 0) return 1;  // no pair
    return pairs(bs, bt);
  }
};
// The filter on a shot and an oriented box; the caller may keep it (oracle/enter_obb.hpp picks the
// entering face from its signs).
template <class Shot>
ObbFilter obb_filter(const Shot& x, const OrientedBox<double>& box) {
  if constexpr (std::is_same_v<Shot, Segment<double>>)
    return ObbFilter(x.source, x.target, box, true);
  else
    return ObbFilter(x.source, x.direction, box, false);
}
inline int filter(ObbFilter& f) {
  if (!f.ok) return unknown;
  if (const int r = f.decide(); r != unknown) return r;
  f.tighten();
  return f.decide();
}
inline int filter(const Segment<double>& seg, const OrientedBox<double>& box) {
  ObbFilter f = obb_filter(seg, box);
  return filter(f);
}
inline int filter(const Ray<double>& ray, const OrientedBox<double>& box) {
  ObbFilter f = obb_filter(ray, box);
  return filter(f);
}

// ---- The separating axes first: a segment or a ray and an axis-aligned box ----
// A segment (a ray) meets the closed box exactly when Algorithm 3.3 hits, and exactly when none
// of Theorem 3.1's six axes separates them (book/segment_box.hpp: the box's faces e_i, and
// r x e_j with r = t - s or the ray's d). On uniform and far-away shots these six signs cost
// about what the book's own test does, where the slab pairs above take a product and a bound
// per (entering, exiting) pair, so they run first; the slab logic takes what they leave open.
// With a = s - c:
//   face i     a segment is beyond the upper plane when min(s_i, t_i) - c_i - h_i > 0, below
//              the lower when max(s_i, t_i) - c_i + h_i < 0; fl is monotone, so the min and max
//              of fl(s_i - c_i), fl(t_i - c_i) are fl(min - c_i), fl(max - c_i), whose sign
//              against -+h is the outcode filter's (certain beyond 2^-52 |q~|, above). A ray
//              is beyond the upper plane when a_i > h_i and d_i >= 0, the lower when
//              a_i < -h_i and d_i <= 0 (d exact: its signs are).
//   r x e_j    (j1 = j + 1, j2 = j + 2) separates when |a_j1 r_j2 - a_j2 r_j1| > h_j1 |r_j2| +
//              h_j2 |r_j1| (the segment projects onto one point). Computed on A = fl(s - c)
//              and R = fl(t - s) (d itself for a ray), each product, the difference, the
//              radius's sum and the final |P| - Rad rounded once: every monomial (a r, h r)
//              carries at most K = 5 factors (1 + delta), so |S~ - S| <= gamma_5 S+ with S+
//              the monomials' absolute sum, which fl(|A_j1 R_j2| + |A_j2 R_j1| + Rad) bounds
//              up to a factor 1 + 6u: certain beyond 6u of it (5u (1 + 6u)^2 < 6u (1 - u)),
//              plus 8 * 2^-1074 for the at most 8 roundings that can underflow (each off by
//              at most 2^-1075). An axis whose R_j1 = R_j2 = 0 is exactly zero (fl(t - s) = 0
//              only where t = s): it never separates.
// Range: M_A = sum_i |A_i| + |B_i| + |h_i| (B = fl(t - c)) and M_R = |R|_1, with M_A, M_R and
// M_A M_R at most 2^1000 (a NaN or an infinity among the inputs fails it: these filters decide
// nothing then, as stages.hpp's filter_first relies on); then no product or sum overflows.
// A negative extent is the caller's to refuse (signs_valid), and a ray whose direction is zero
// is left to the checks. A zero-length segment has R = 0: only the faces decide, whether the
// point lies in the box.
// 1 (they meet), 0 (disjoint) or unknown.
inline int axes_filter(const Vec3<double>& src, const Vec3<double>& rt, const Box<double>& box, bool segment) {
  double A[3], R[3], up[3], ue[3], lo[3], le[3];
  double ma = 0, mr = 0;
  for (int i = 0; i < 3; ++i) {
    const double h = box.extent[i];
    A[i] = src[i] - box.center[i];
    double qa = A[i], qb = A[i];  // the lowest and highest point's coordinate
    if (segment) {
      const double B = rt[i] - box.center[i];
      R[i] = rt[i] - src[i];
      qa = std::min(A[i], B);
      qb = std::max(A[i], B);
      ma += std::fabs(B);
    } else {
      R[i] = rt[i];
    }
    ma += std::fabs(A[i]) + std::fabs(h);  // sums, which a NaN reaches (std::max would drop it)
    mr += std::fabs(R[i]);
    up[i] = qa - h;  // > 0: beyond the upper plane
    ue[i] = 0x1p-52 * std::fabs(qa);
    lo[i] = qb + h;  // < 0: below the lower plane
    le[i] = 0x1p-52 * std::fabs(qb);
  }
  if (!(ma <= 0x1p1000 && mr <= 0x1p1000 && ma * mr <= 0x1p1000)) return unknown;
  if (!segment && mr == 0) return unknown;
  bool apart = false, meets = true;
  for (int i = 0; i < 3; ++i) {
    bool above = up[i] > ue[i], below = lo[i] < -le[i];
    bool not_above = up[i] < -ue[i], not_below = lo[i] > le[i];
    if (!segment) {
      above &= R[i] >= 0;
      below &= R[i] <= 0;
      not_above |= R[i] < 0;
      not_below |= R[i] > 0;
    }
    apart |= above | below;
    meets &= not_above & not_below;
  }
  for (int j = 0; j < 3; ++j) {
    const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
    const double p1 = A[j1] * R[j2], p2 = A[j2] * R[j1];
    const double rad = box.extent[j1] * std::fabs(R[j2]) + box.extent[j2] * std::fabs(R[j1]);
    const double s = std::fabs(p1 - p2) - rad;
    const double e = (6 * u) * (std::fabs(p1) + std::fabs(p2) + rad) + 8 * 0x1p-1074;
    apart |= s > e;
    meets &= (s < -e) | ((R[j1] == 0) & (R[j2] == 0));
  }
  return apart ? 0 : (meets ? 1 : unknown);
}

inline int filter(const Segment<double>& seg, const Box<double>& box, plain = {}) {
  if (const int r = axes_filter(seg.source, seg.target, box, true); r != unknown) return r;
  const BoxFilter f(seg.source, seg.target, box, true);
  return f.ok ? hit_box_logic(f) : unknown;
}
inline int filter(const Ray<double>& ray, const Box<double>& box, plain = {}) {
  if (const int r = axes_filter(ray.source, ray.direction, box, false); r != unknown) return r;
  const BoxFilter f(ray.source, ray.direction, box, false);
  return f.ok ? hit_box_logic(f) : unknown;
}

}  // namespace cdref::filters::staged
