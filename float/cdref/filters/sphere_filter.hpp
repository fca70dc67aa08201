// cdref/filters/sphere_filter.hpp - the first stage of the classification oracle for a segment
// or a ray cast on a sphere (Algorithm 3.1), for Algorithm 3.2 and for sphere-box (exact/cdref/oracle/
// sphere_casts.hpp and sphere_box.hpp hold the other stages and the polynomials these signs
// decide, expansions.hpp the model of the bounds: u = 2^-53, gamma_K, the range checks). Plain double arithmetic on the query's inputs,
// so that both the oracle and the robust tier's certified decisions at double
// (robust/ray_sphere.hpp, robust/segment_sphere.hpp, robust/sphere_box.hpp) run it first: where it decides (1 a hit,
// 0 a miss; `unknown` leaves the case to the next stage), its answer is the book's at an exact
// type. The logic over signs (hit_sphere_logic, segment_sphere_logic) is the oracle's for its
// exact stages too.
#pragma once

#include <cdref/filters/box_cast_filter.hpp>
#include <cdref/primitives.hpp>
#include <cmath>

namespace cdref::filters::staged {

inline int le0(int s) { return s == unknown ? unknown : int(s <= 0); }
inline int ge0(int s) { return s == unknown ? unknown : int(s >= 0); }

// Filter signs. Leaves s~ = fl(p - c), r~ = fl(target - source) (or the direction, exact),
// t~ = fl(target - c); ss, rr, tt, rho2 their computed squares (sums left to right).
struct SphereFilter {
  double s[3], r[3], t[3], ss, rr, tt = 0, rho2;
  bool rzero;
  SphereFilter(const Vec3<double>& src, const Vec3<double>& rt, const Sphere<double>& sp, bool segment) {
    for (int i = 0; i < 3; ++i) {
      s[i] = src[i] - sp.center[i];
      r[i] = segment ? rt[i] - src[i] : rt[i];
    }
    rzero = segment && rt[0] == src[0] && rt[1] == src[1] && rt[2] == src[2];
    ss = s[0] * s[0] + s[1] * s[1] + s[2] * s[2];
    rr = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
    rho2 = sp.radius * sp.radius;
    if (segment) {
      for (int i = 0; i < 3; ++i) t[i] = rt[i] - sp.center[i];
      tt = t[0] * t[0] + t[1] * t[1] + t[2] * t[2];
    }
  }
  // |x|^2 - rho^2: K = 6 as for sphere-sphere; bound 7u fl(xx + rho2).
  static int sq_minus_rho2(double xx, double rho2) {
    const double m = xx + rho2;
    if (!in_range(m)) return unknown;
    return fsign(xx - rho2, (7 * u) * m);
  }
  int ss_rho2() const { return sq_minus_rho2(ss, rho2); }
  int tt_rho2() const { return sq_minus_rho2(tt, rho2); }
  // a.b: K = 2 + 1 + 2 = 5, P+ = sum |a_i b_i|, bounded by the computed products' absolute
  // values (1 + 4u): bound 6u fl(sum |fl(a_i b_i)|), component by component, so that a long
  // vector against a short one is judged by their products and not by |a|^2 + |b|^2. The range
  // check on aa + bb keeps the products below 2^1000; the absolute 2^-1060 covers three
  // underflowing products (2^-1075 each).
  static int dot(const double* a, const double* b, double aa, double bb) {
    if (!in_range(aa + bb)) return unknown;
    const double p0 = a[0] * b[0], p1 = a[1] * b[1], p2 = a[2] * b[2];
    return fsign(p0 + p1 + p2, (6 * u) * (std::fabs(p0) + std::fabs(p1) + std::fabs(p2)) + 0x1p-1060);
  }
  int sr() const { return dot(s, r, ss, rr); }
  int tr() const { return dot(t, r, tt, rr); }
  // sigma = rr rho^2 - |c|^2, c = s x r, with the error of c bounded component by component
  // (the bound of a monomial expansion, 13u rr (rho^2 + 2 ss), grows like |s|^2 and decides
  // nothing at range or near tangency). Each c_k = p - q, p = s_i r_j, q = s_j r_i, carries 4
  // factors (two leaves, the product, the difference): |c~_k - c_k| <= e_k = gamma_4 m_k,
  // m_k = |p| + |q| (exact; the computed ones are within 1 + 2u of it). Then
  //   |sum c~_k^2 - sum c_k^2| <= sum e_k (2 |c~_k| + e_k),
  // the computed cc adds gamma_3 cc (a square and two sums), rr rho^2 carries 7 factors (a
  // leaf twice in each square, the square, two sums, rho^2, the product) and the final
  // difference one more on each side:
  //   |P~ - P| <= 9u rr rho2 + 5u (sum m_k (2 |c~_k| + 5u m_k) + cc)
  // (9u > gamma_8, 5u > gamma_4 (1 + 2u) and gamma_3 + u; the bound's own evaluation loses a
  // few u of itself, inside those margins). Near tangency (|c| ~ rho |r|) it is about
  // u |r|^2 rho (9 rho + 17 |s|): the line is decided unless it passes within about
  // u (5 rho + 9 |s|) of tangency, linear in |s| rather than quadratic. Ranges: ss, rr in
  // [2^-480, 2^480] and rho2 <= 2^480 exclude overflow; an underflowing product (2^-1075)
  // perturbs c_k absolutely and is multiplied by |c_k| <= 2^481: the absolute 2^-590 covers it.
  // The cruder bound first: |c_k| <= m_k and |c~_k| <= m_k (1 + gamma_4), so the sum is at most
  // (2 + 14u) sum m_k^2, and sum m_k^2 <= 2 |s|^2 |r|^2 (m_k^2 <= 2 (s_i^2 r_j^2 + s_j^2 r_i^2))
  // <= 2 ss rr (1 + 14u) (the leaves and the computed squares): 5u times the sum is at most
  // 21u ss rr, and 23u fl(ss rr) covers it with the roundings of its own evaluation (ss rr >=
  // 2^-960 by the ranges, no underflow). It decides every case but those at range or near
  // tangency, where |s|^2 |r|^2 is far above |s| |c| |r|, without the finer bound's six
  // products and nine absolute values: the ray cast's oracle on uniform cases went from 10.5
  // to 8.7 ns a case, 4% slower at long range (standalone loop over 16,384 cases).
  // Where it declines, Cauchy-Schwarz on the finer sum, with no absolute value: sum m_k |c~_k|
  // <= sqrt(sum m_k^2) sqrt(sum c~_k^2) <= sqrt(2 ss rr (1 + 14u)) sqrt(cc (1 + 4u)) (cc, a
  // square and two sums, is at least sum c~_k^2 (1 - u)^3) and 25u^2 sum m_k^2 <= 51u^2 ss rr,
  // so with F = 9u rr rho2 + 5u cc + 2^-590 + 51u^2 ss rr (the terms without c~ in them)
  //   |P~ - P| <= F + G,   G = 10 sqrt(2) u (1 + 10u) sqrt(ss rr cc).
  // G is linear in |s| as the finer bound is (about 14u |s| |r|^2 rho near tangency, against the
  // finer's 10u sum m_k |c_k|), and needs no square root: with L~ = fl(|P~| - F~) the sign is
  // certain where L~ > 0 and fl(L~^2) > fl(201u^2 fl(fl(ss rr) cc) + 2^-1000). Then x = |P~| - F >=
  // L~ / (1 + u); fl(L~^2) > 2^-1000 (1 - u) keeps L~^2 normal, so L~^2 >= fl(L~^2) / (1 + u); the
  // two products lose at most a relative u each and 2^-1075 absolutely each where they underflow
  // (the 2^-1000 covers that), and fl(ss rr) >= ss rr (1 - u): x^2 > 201u^2 ss rr cc
  // (1 - u)^4 / (1 + u)^3 > G^2, as 201 / 200 exceeds (1 + 10u)^2 (1 + u)^3 / (1 - u)^4. (F~,
  // computed, stands for F as the other bounds' evaluations do: 51u^2 exceeds 50u^2 (1 + 14u)
  // by more than its rounding.) Overflow cannot fool it: within the ranges P~, F~ and L~ are
  // finite; fl(ss rr cc) past 2^1024 is infinite and the test fails; fl(L~^2) infinite means
  // L~^2 above every finite right side, and the inequality holds. A certain sign comes back
  // with the bound 0 (|P~| > F >= 2^-590 > 0). The finer bound, out of line, remains for the
  // rest (near tangency, where the sums' factor matters). oracle::classify in a standalone loop
  // over 16,384 cases a family (ns a case, best of 300 runs, 2-core AMD EPYC, g++ 12.2 -O3,
  // 2026-11-30), before -> after, `bare` (book::unchecked::hit) beside: ray uniform 8.22 -> 7.66
  // (bare 2.48), ray at 10^12 radii 11.45 -> 8.66 (2.58), segment uniform 12.80 -> 11.74 (3.11),
  // segment at 10^12 radii 15.35 -> 13.04 (3.30), Algorithm 3.2 uniform 12.76 -> 11.72 (2.99)
  // and at 10^12 radii 15.36 -> 13.05 (3.06); the cases left to the exact stages pay the test
  // and the call (ray within 2^-52 of tangency 93.6 -> 100.4). The filter decides the same
  // cases as before in every family and scale of the three queries.
  // sigma's value P~ and the bound B on its error: the cruder where it decides, else 0 where
  // Cauchy-Schwarz's test certifies the sign, else the finer (the flags below read the same
  // pair). Within the range tests of sigma().
  struct Bounded {
    double P, B;
  };
  [[gnu::always_inline]] static Bounded sigma_bounded(const double* s, const double* r, double ss, double rr,
                                                      double rho2) {
    double c[3], cc = 0;
    for (int k = 0; k < 3; ++k) {
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      c[k] = s[i] * r[j] - s[j] * r[i];
      cc += c[k] * c[k];
    }
    const double rrr = rr * rho2, P = rrr - cc, fixed = (9 * u) * rrr + (5 * u) * cc + 0x1p-590;
    const double ssrr = ss * rr, crude = fixed + (23 * u) * ssrr;
    if (std::fabs(P) > crude) return {P, crude};
    const double L = std::fabs(P) - (fixed + (51 * u * u) * ssrr);
    if ((L > 0) & (L * L > (201 * u * u) * (ssrr * cc) + 0x1p-1000)) return {P, 0.0};
    return {P, finer_bound(s, r, c, fixed)};
  }
  // The finer bound: fixed + 5u sum m_k (2 |c~_k| + 5u m_k).
  [[gnu::noinline]] static double finer_bound(const double* s, const double* r, const double* c, double fixed) {
    double dev = 0;
    for (int k = 0; k < 3; ++k) {
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      const double m = std::fabs(s[i] * r[j]) + std::fabs(s[j] * r[i]);
      dev += m * (2 * std::fabs(c[k]) + (5 * u) * m);
    }
    return fixed + (5 * u) * dev;
  }
  static bool sigma_in_range(double ss, double rr, double rho2) {
    // one branch for the five range tests (each false on a NaN)
    return (ss >= 0x1p-480) & (ss <= 0x1p480) & (rr >= 0x1p-480) & (rr <= 0x1p480) & (rho2 <= 0x1p480);
  }
  int sigma() const {
    if (!sigma_in_range(ss, rr, rho2)) return unknown;
    const Bounded b = sigma_bounded(s, r, ss, rr, rho2);
    return fsign(b.P, b.B);
  }
};

// Algorithm 3.1's decision (book::hit), over filtered or exact signs.
template <class P>
int hit_sphere_logic(const P& p, bool bounded) {
  if (p.rzero) return le0(p.ss_rho2());
  const int sg = p.sigma();
  if (sg == unknown) return unknown;
  if (sg < 0) return 0;
  int ahead = le0(p.sr());  // lambda_2 >= 0
  if (ahead != 1) {
    const int in = le0(p.ss_rho2());
    ahead = in == 1 ? 1 : (ahead == 0 && in == 0 ? 0 : unknown);
  }
  if (!bounded || ahead == 0) return ahead;
  int before = ge0(p.tr());  // lambda_1 <= 1
  if (before != 1) {
    const int in = le0(p.tt_rho2());
    before = in == 1 ? 1 : (before == 0 && in == 0 ? 0 : unknown);
  }
  if (before == 0) return 0;
  return ahead == 1 && before == 1 ? 1 : unknown;
}
// Algorithm 3.2's decision (book::intersect(Segment, Sphere)).
template <class P>
int segment_sphere_logic(const P& p) {
  const int sr = p.sr();
  if (sr == unknown) return unknown;
  if (sr >= 0) return le0(p.ss_rho2());  // delta <= 0: s is closest
  const int tr = p.tr();
  if (tr == unknown) return unknown;
  if (tr <= 0) return le0(p.tt_rho2());  // delta >= |r|^2: t is closest
  return ge0(p.sigma());
}

// The cast's filter on its inputs: 1 hit, 0 miss, `unknown`. `to` is the target (segment) or
// the direction (ray). The same signs, bounds and logic as hit_sphere_logic over SphereFilter,
// and the same decisions, taken without a branch on any sign: every sign hit_sphere_logic might
// read is computed, each as two flags (certainly positive, certainly negative), and the flags
// are combined with & and |,
//   hit  = sigma > 0 and (s.r < 0 or |s|^2 < rho^2) and, for a segment, (t.r > 0 or |t|^2 < rho^2),
//   miss = sigma < 0, or sigma > 0 and s.r > 0 and |s|^2 > rho^2, or (a segment) sigma > 0
//          and t.r < 0 and |t|^2 > rho^2,
// each comparison against its bound (a sign inside its bound sets neither flag); the answer is
// hit where hit or miss is set, else `unknown`. hit_sphere_logic branches on sigma's sign, then
// on s.r's and |s|^2 - rho^2's: on uniform cases each goes either way, and the mispredictions
// cost more than the few products the flags compute in their place. Ranges: sigma's test
// (|s|^2, |r|^2 in [2^-480, 2^480], rho^2 <= 2^480) implies those of s.r (|s|^2 + |r|^2) and of
// |s|^2 - rho^2; |t|^2 <= (|s| + |r|)^2 (1 + 4u) then lies below 2^483, so t.r's holds too, and
// |t|^2 - rho^2's lower one (|t|^2 + rho^2 >= 2^-960, below which underflow is not covered by its
// bound) gates that sign alone. Where sigma's test fails (a point segment, r = 0, among them) the
// branching form answers, as before. Standalone loop over 16,384 cases of each family, best of
// 40 interleaved runs, ns per case (2-core AMD EPYC, g++ 12.2 -O3, 2026-11-28), branching ->
// this: ray uniform 16.3 -> 10.7, ray at 10^12 radii 23.0 -> 14.3, segment uniform 17.4 ->
// 14.6, segment at 10^12 radii 24.4 -> 18.1.
template <bool Segment>
[[gnu::always_inline]] inline int sphere_cast_filter_flags(const Vec3<double>& from, const Vec3<double>& to,
                                                           const Sphere<double>& sp) {
  double s[3], r[3], t[3];
  for (int i = 0; i < 3; ++i) {
    s[i] = from[i] - sp.center[i];
    r[i] = Segment ? to[i] - from[i] : to[i];
    if constexpr (Segment) t[i] = to[i] - sp.center[i];
  }
  const double ss = s[0] * s[0] + s[1] * s[1] + s[2] * s[2];
  const double rr = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
  const double rho2 = sp.radius * sp.radius;
  if (!SphereFilter::sigma_in_range(ss, rr, rho2)) [[unlikely]]
    return hit_sphere_logic(SphereFilter(from, to, sp, Segment), Segment);
  const auto [P, B] = SphereFilter::sigma_bounded(s, r, ss, rr, rho2);  // as SphereFilter::sigma
  const bool sg_pos = P > B, sg_neg = P < -B;
  // s.r (SphereFilter::dot) and |s|^2 - rho^2 (sq_minus_rho2)
  const double p0 = s[0] * r[0], p1 = s[1] * r[1], p2 = s[2] * r[2], sr = p0 + p1 + p2;
  const double Bs = (6 * u) * (std::fabs(p0) + std::fabs(p1) + std::fabs(p2)) + 0x1p-1060;
  const double ds = ss - rho2, Bd = (7 * u) * (ss + rho2);
  bool hit = sg_pos & ((sr < -Bs) | (ds < -Bd));
  bool miss = sg_neg | (sg_pos & (sr > Bs) & (ds > Bd));
  if constexpr (Segment) {
    const double tt = t[0] * t[0] + t[1] * t[1] + t[2] * t[2];
    const double q0 = t[0] * r[0], q1 = t[1] * r[1], q2 = t[2] * r[2], tr = q0 + q1 + q2;
    const double Bt = (6 * u) * (std::fabs(q0) + std::fabs(q1) + std::fabs(q2)) + 0x1p-1060;
    const double m = tt + rho2, dt = tt - rho2, Bu = (7 * u) * m;
    const bool t_in = m >= 0x1p-960;
    hit = hit & ((tr > Bt) | (t_in & (dt < -Bu)));
    miss = miss | (sg_pos & (tr < -Bt) & t_in & (dt > Bu));
  }
  return (hit | miss) ? int(hit) : unknown;
}
// Flattened and specialized: with sigma() and the logic called out of line, the segment's
// filter (the cast's and Algorithm 3.2's) took twice as long (Algorithm 3.2's oracle 34.1 ->
// 17.5 ns uniform, 37.1 -> 24.7 ns at 10^12, before the flags above). Inlined where it is
// called, so that `segment` is a constant there: called out of line, with both forms in one
// function and `segment` tested at run time, the ray cast's oracle took 16.5 ns a case on
// uniform inputs where inlined it took 12.6 (standalone loop, 2026-11-28).
[[gnu::always_inline]] inline int sphere_cast_filter(const Vec3<double>& from, const Vec3<double>& to,
                                                     const Sphere<double>& sp, bool segment) {
  return segment ? sphere_cast_filter_flags<true>(from, to, sp) : sphere_cast_filter_flags<false>(from, to, sp);
}

// Sphere-box (Section 3.2.2). Filter: with c~ = fl(centre - box centre), x~_i = fl(|c~_i| - h_i),
// v~_i = max(0, x~_i)
// (= |v_i| whichever branch: max(0, .) is 1-Lipschitz, so |v~_i - v_i| <= |x~_i - x_i| <=
// gamma_2 w_i, w_i = |c_i| + h_i, and v~_i, v_i <= w_i (1 + gamma_2)), P = fl(sum v~_i^2 - rho2).
// |P~ - P| <= sum |v~_i^2 - v_i^2| + gamma_4 (sum v~_i^2 + rho^2)
//          <= (2 gamma_2 + gamma_4 + O(u^2)) (sum w_i^2 + rho^2) <= 8u (1 + 10u) (...):
// bound 9u fl(sum w~_i^2 + rho2), w~_i = fl(|c~_i| + h_i).
inline int filter(const Sphere<double>& sp, const Box<double>& box, plain = {}) {
  double vv = 0, ww = 0;
  for (int i = 0; i < 3; ++i) {
    const double c = std::fabs(sp.center[i] - box.center[i]), h = box.extent[i];
    // v = max(0, x) as (x + |x|) / 2, exactly (2x is exact, and so is its half; above 2^1023,
    // where 2x overflows, w^2 fails the range test anyway, as it does for a NaN): g++ turned
    // the conditional and std::max into a branch per axis, mispredicted as often as the
    // centre lies inside the slab
    const double x = c - h, v = (x + std::fabs(x)) * 0.5, w = c + h;
    vv += v * v;
    ww += w * w;
  }
  const double rho2 = sp.radius * sp.radius, m = ww + rho2;
  if (!in_range(m)) return unknown;
  return positive_or_unknown(rho2 - vv, (9 * u) * m);  // le0(fsign(vv - rho2, ..)): fl(a - b) = -fl(b - a)
}

}  // namespace cdref::filters::staged
