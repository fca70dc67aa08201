// cdref/oracle/enter_box.hpp - oracle::enter on an axis-aligned box (Algorithm 3.3): a segment's
// or a ray's lambda_enter correctly rounded to double (what every cast shares, and the exact
// path: enter.hpp).
//
// ---- A box: the largest entering parameter, each quotient rounded ---------------------------
// In the book (book/ray_box.hpp) lambda_enter is the largest lambda_p = n_p / d_p over the
// planes p the source lies outside of (none: 0), n_p = (c_i -+ h_i) - source_i, d_p =
// target_i - source_i (a ray: direction_i); on a hit every such lambda_p lies in [0, 1] (or
// [0, inf)). Rounding to nearest is monotone, so round(max_p lambda_p) = max_p round(lambda_p).
// For each axis: (p, pe) = two_sum(c_i, -source_i), (m, me) = two_sum(p, -+h_i), so n = m + t
// exactly with t = me + pe, rounded once to t^ (|t - t^| <= u |t^|). The outcode bit is the
// sign of n: sign(m) where |m| > 2 |t^|, sign(t^) where m = 0 (then t = pe exactly), else
// undecided. d = dh + dl exactly (two_sum; a ray's dl = 0). The quotient: q1 = fl(m / dh); the
// residual R = n - q1 d = (m - P) - Pe + t - q1 dl with (P, Pe) = two_prod_split(q1, dh)
// exact and m - P exact (P is within 2u of m: Sterbenz), the small terms summed with three
// roundings: |R^ - R| <= 4u (|m - P| + |Pe| + |t^| + |q1 dl|)(1 + 8u). Then n / d = q1 + R / d
// exactly, and q2 = fl(R^ / dh) is off by |R^ - R| / |d| + 2.1 u |q2| (dl against d, q2's
// rounding); q1 + q2 as a double word by two_sum, the bound doubled, Bounded2::try_rounded.
// Range: |m|, |dh| and |q1| in [2^-900, 2^900] (no product below the normal range); outside,
// or any sign or rounding undecided: the exact path.
#pragma once

#include <cdref/oracle/box_casts.hpp>
#include <cdref/oracle/enter.hpp>

namespace cdref::oracle {

namespace enter_detail {

// The box's double path on a hit (header, "A box"): the value, or nothing when a sign or a
// rounding is uncertain.
template <class Shot>
std::optional<double> box_double(const Shot& x, const Box<double>& box) {
  using std::fabs;
  constexpr double u = 0x1p-53, lo_lim = 0x1p-900, hi_lim = 0x1p900;
  double best = 0.0;
  for (int i = 0; i < 3; ++i) {
    // n = (c_i - source_i) -+ h_i = m + t exactly, t = me + pe rounded once (|t - t^| <= u |t^|)
    const Pair<double> p = eft::two_sum(box.center[i], -x.source[i]);
    const Pair<double> lower = eft::two_sum(p.hi, -box.extent[i]), upper = eft::two_sum(p.hi, box.extent[i]);
    const double tl = lower.lo + p.lo, tu = upper.lo + p.lo;
    // the source's outcode bits: the signs of n (certain when m dominates, or m = 0: then t
    // is exact and its rounding keeps its sign)
    auto sign = [](const Pair<double>& mm, double tt) -> int {
      if (mm.hi == 0) return tt > 0 ? 1 : (tt < 0 ? -1 : 0);
      if (fabs(mm.hi) > 2 * fabs(tt)) return mm.hi > 0 ? 1 : -1;
      return 2;
    };
    const int sl = sign(lower, tl), su = sign(upper, tu);
    if (sl == 2 || su == 2) return std::nullopt;
    const bool below = sl > 0, above = su < 0;
    if (!below && !above) continue;
    const double m = below ? lower.hi : upper.hi, tn = below ? tl : tu;
    // d = dh + dl exactly (a ray: dl = 0)
    Pair<double> d;
    if constexpr (std::is_same_v<Shot, Segment<double>>)
      d = eft::two_sum(x.target[i], -x.source[i]);
    else
      d = {x.direction[i], 0.0};
    if (!(fabs(m) >= lo_lim && fabs(m) <= hi_lim && fabs(d.hi) >= lo_lim && fabs(d.hi) <= hi_lim))
      return std::nullopt;
    // q1 = m / dh; the residual R = n - q1 d: m - P exact (P = fl(q1 dh) is within 2u of m),
    // the small terms summed with three roundings
    const double q1 = m / d.hi;
    const Pair<double> P = eft::two_prod_split(q1, d.hi);
    const double r0 = m - P.hi, qd = q1 * d.lo;
    const double R = ((r0 - P.lo) + tn) - qd;
    const double eR = 4 * u * (((fabs(r0) + fabs(P.lo)) + fabs(tn)) + fabs(qd)) * (1 + 8 * u);
    // z = q1 + R_exact / d: q2 = R / dh off by eR / |d| + 2.1 u |q2| (dl, and q2's rounding)
    const double q2 = R / d.hi;
    const double E = 2 * (eR / (fabs(d.hi) * (1 - u)) + 2.1 * u * fabs(q2)) + under;
    const Pair<double> z = eft::two_sum(q1, q2);
    double v;
    if (!(fabs(q1) >= lo_lim && fabs(q1) <= hi_lim) || !Bounded2::within(z.hi, z.lo, E).try_rounded(v))
      return std::nullopt;
    best = std::max(best, v);
  }
  return best;
}

template <class Shot>
Entry box_enter(const Shot& x, const char* name, const Box<double>& box, bool* exact_used) {
  return entry_of(staged::filter_first(nullptr, x, name, box, "box"), x, box, exact_used,
                  [&] { return box_double(x, box); });
}

}  // namespace enter_detail

// A segment or a ray against an axis-aligned box.
inline Entry enter(const Segment<double>& seg, const Box<double>& box, bool* exact_used = nullptr) {
  return enter_detail::box_enter(seg, "segment", box, exact_used);
}
inline Entry enter(const Ray<double>& ray, const Box<double>& box, bool* exact_used = nullptr) {
  return enter_detail::box_enter(ray, "ray", box, exact_used);
}

}  // namespace cdref::oracle
