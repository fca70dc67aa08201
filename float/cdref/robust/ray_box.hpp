// cdref/robust/ray_box.hpp - ray casts on an axis-aligned box (Algorithm 3.3) that keep
// their accuracy where the book's float version loses it, for F = float, double, long
// double. Same signatures and results as cdref::book (hit, cast for a segment s->t and for
// an infinite ray s + lambda d; Cast<F> from results.hpp), plus decide() (decision.hpp). At
// F = float every entry point runs the double version on the same inputs and rounds each value
// once (decision.hpp, widened).
//
// What goes wrong in the book at F: it rounds s - c, t - c and t - s before anything else,
// so at long range (source 1e8..1e12 box sizes away) the outcodes and the numerators
// +-eta_i - sigma_i are already off by an ulp of the range; hit() cross-multiplies the
// parameters, and the products overflow to infinity or underflow to zero past the square
// root of the range (2^500 and 2^-500 in double), where inf <= inf and 0 <= 0 call a miss a
// hit. Notation: u = 2^-p the unit roundoff of F (p = 24, 53, 64), eta = half the smallest
// subnormal; "exact pair" (hi, lo) means hi + lo equals the value exactly, hi = fl(value).
//
//  1. Outcodes, exactly. sigma_i < -eta_i is decided on the exact s_i - c_i: with
//     (dh, dl) = two_sum(s_i, -c_i) (exact, also when it underflows), rounding to nearest
//     is monotone, so dh < -eta_i proves sigma_i < -eta_i, dh > -eta_i proves the opposite,
//     and dh = -eta_i leaves the sign of dl. An overflowing dh = +-inf is compared
//     correctly the same way. The same for the upper planes, the target, and for a ray
//     the book's "t at infinity" (signs of d_i, exact). So the early miss (shared bit) and
//     the set of entering planes E and exiting planes X are exactly the book's.
//  2. Scale. With M the largest input magnitude, all inputs are multiplied by 2^-ilogb(M)
//     when M < 1 (exact: scaling up, bringing subnormal inputs into the normal range) or
//     M >= 2^(emax-5) (so nothing below can overflow; exact unless some input is below
//     2^(emin+p) times M). Otherwise the inputs are used as they are (M < 2^(emax-5): no sum
//     below overflows). Every lambda is invariant under the scaling. If the scaling was
//     inexact the outputs carry no bound and the filter of step 5b is skipped (the
//     classification does not depend on this scaling: step 5c scales on its own).
//  3. Numerators as accurate pairs. For plane (i, +-): N = c_i - s_i +- eta_i. With
//     (a, b) = two_sum(c_i, -s_i), (N1, e) = two_sum(a, +-eta_i), z = fl(b + e) and
//     (Nh, Nl) = two_sum(N1, z): Nh + Nl - N = fl(b + e) - (b + e). Either a + -eta_i is
//     exact (Sterbenz: opposite signs within a factor 2), e = 0 and z = b exactly, or
//     |a +- eta_i| >= |a|/2, so |a| <= 2|N1|, |b| <= u|a|, |e| <= u|N1| and
//     |b + e| <= 3u|N1|. Hence |Nh + Nl - N| <= 3u^2 |N1| <= 4u^2 |N| and |Nl| <= u|Nh|
//     (sums only: no underflow error). Directions: r_i = t_i - s_i as the exact pair
//     two_sum(t_i, -s_i) for a segment, (d_i, 0) for a ray.
//  4. One quotient, corrected. lambda = (Nh + Nl) / (rh + rl) up to the 4u^2 above:
//       q0 = fl(Nh / rh), rho = fma(-q0, rh, Nh), a = fl(rho + Nl),
//       num = fma(-q0, rl, a), corr = fl(num / rh), lambda^ = fl(q0 + corr).
//     Exactly, lambda' - q0 = (rho + Nl - q0 rl) / (rh + rl), and rho, Nl, q0 rl are each
//     at most about u |Nh|; each of the four operations forming corr errs by u of a
//     quantity of size <= 3u |lambda| (plus at most eta each where a product or quotient
//     underflows), dropping rl from the divisor by u |corr|. With the 4u^2 of step 3 this
//     gives, with q0 + corr the exact sum,
//       |q0 + corr - lambda| <= 17 u^2 |lambda| + 2 eta (1 + 1/|rh|),
//     and after the last rounding
//       |lambda^ - lambda| <= u (1 + 18u) |lambda| + 3 eta (1 + 1/|rh|)          (*)
//     that is, in the normal range, at most 1/2 ulp + 36u ulp of lambda: lambda^ is the
//     correctly rounded value or its neighbour, where the book's errs by u|s|/|N| ulps.
//     (The ray's lambda, unbounded, may overflow; the bound is then void.) Only the two
//     parameters that are output, of the entering face and of the first exiting plane
//     chosen in step 5, are computed this way, and only when asked for.
//  5. The decision, exactly. Every entering parameter is > 0 and <= 1 (segment), every
//     exiting one >= 0 and < 1 exactly (the outcodes say on which side of each plane s and
//     t lie), so the book's max(0, max_E) <= min(1, min_X) is max_E <= min_X (E empty or,
//     for a segment whose target is in the box, X empty: hit). The book's cast() takes
//     the largest entering parameter with a strict > in the plane order x-, x+, y-, y+,
//     z-, z+ (on exact ties the first plane wins), the smallest exiting one with a strict
//     <, and hits iff enter <= exit (not strict; hit() decides the same). Here each of
//     these at most 2 + 2 + 1 comparisons is made on the exact parameters, so the face,
//     the exiting plane and the classification are the book's at an exact type.
//     (a) Signs. lambda_p - lambda_q has the sign of (N_p D_q - N_q D_p) sgn(D_p) sgn(D_q),
//     N_p = c_i - s_i +- eta_i, D_p = t_i - s_i (segment) or d_i (ray) on the axis i of p;
//     D != 0 for every plane crossed (s and t lie strictly on opposite sides of it or on
//     it, or the ray's d_i points through it).
//     (b) The filter, on q0 = fl(Nh / rh) (step 3's pair; rh = fl(r)). Nh = N(1 + d1) with
//     |d1| <= u + 6u^2 (|Nl| <= u|Nh| plus the 4u^2), rh = r(1 + d2), |d2| <= u (a sum:
//     no underflow error), and the quotient rounds once: q0 = (Nh/rh)(1 + d3) + e3,
//     |d3| <= u, |e3| <= eta. Hence |q0 - lambda| <= (3u + 11u^2)|lambda| + eta <=
//     4u|lambda| + eta, and with |lambda| <= (|q0| + eta)/(1 - 4u),
//       eps := |q0 - lambda| <= 4.01u |q0| + 0.51 eta'        (eta' = 2 eta, denorm_min).
//     If |fl(q0_p - q0_q)| > B = fl(8u (|q0_p| + |q0_q|) + 4 eta'), its sign is that of
//     lambda_p - lambda_q: the subtraction errs by u of its result, B by three roundings
//     and at most eta where 8u(..) underflows, so |q0_p - q0_q| > B/(1 + u) >=
//     7.9u(|q0_p| + |q0_q|) + 3.4 eta' > eps_p + eps_q. An infinite q0 (a ray's parameter
//     overflowing) or a NaN difference never passes, nor does an exact tie (|q0_p - q0_q|
//     <= eps_p + eps_q there). The filter needs the scaling of step 2 to be exact.
//     (c) Otherwise the sign of N_p D_q - N_q D_p, exactly. In W = F, except W = double for
//     F = float, the 12 inputs are multiplied by 2^sigma, sigma = K - ilogb(M) (M the
//     largest input magnitude, K = floor((emax - 10)/2): 507 at double, 8187 at long
//     double; at float no scaling is needed). Each N_p is then a nonoverlapping expansion
//     of at most three components (Grow-Expansion with zero elimination over c_i, -s_i,
//     +-eta_i; two_sum is exact barring overflow, also where results are subnormal), each
//     D_i one of at most two; N_p D_q - N_q D_p is the sum of at most 2 x 3 x 2 products of
//     components, each split by two_prod (hi = fl(ab), lo = fma(a, b, -hi)), the 24 parts
//     summed by Grow-Expansion (Shewchuk 1997, Theorem 10: the result is a nonoverlapping
//     expansion of the exact sum, whose sign is that of its largest component).
//     Overflow: a nonoverlapping expansion's components sum in magnitude to at most
//     (1 + 5u) times its value, so the 24 parts sum to at most 2 * (3 * 2^(K+1)) *
//     (2 * 2^(K+1)) (1 + 12u) < 2^(2K+6), and every intermediate of Grow-Expansion stays
//     below twice that, 2^(2K+7) <= 2^(emax-3). At float in double: below 2^262.
//     Underflow: two_prod(a, b) is exact when lsb(a) + lsb(b) >= dexp (lsb the exponent of
//     the lowest set bit, 2^dexp = eta' the smallest subnormal): ab is then a multiple of
//     2^dexp with at most 2p significant bits, and ab - fl(ab), a multiple of 2^dexp below
//     ulp(fl(ab))/2, has at most p bits, so the fma returns it exactly. Otherwise (counted,
//     k products) ab has a bit below 2^dexp and at most 2p bits, so |ab| < 2^(dexp + 2p)
//     = 2^(emin_normal + p + 1), |ab - fl(ab)| <= 2^emin_normal, and the fma rounds it to
//     the subnormal grid: |hi + lo - ab| <= eta. The computed sum S' is then within
//     k eta' of the true S: S > 0 if the expansion S' - k eta' is positive, S < 0 if
//     S' + k eta' is negative (both signs exact), and otherwise the comparison is
//     uncertain and follows q0.
//     Where that can happen: the scaled inputs are multiples of 2^(lam + sigma), lam the
//     exponent of the lowest set bit of any nonzero input, and so is every component
//     (two_sum of multiples of g gives multiples of g); hence k = 0 whenever
//     2 (lam + sigma) >= dexp, that is
//       2 (mu - lam) <= 2K - dexp,   mu = ilogb(M),                                    (**)
//     a span of up to 1044 binades at double and 16409 at long double, and then the scaling
//     (down only when mu > K) is exact as well (lam + sigma >= dexp/2 > dexp). At float, in
//     double, inputs have lsb >= -149 and products >= -298 > dexp = -1074: never.
//     (Step 2's scaling plays no part here, nor does its exactness.)
//     Cost: the filter settles everything but near-ties (at F's resolution) and exact
//     ties; the exact step is a few hundred flops, built once per query when first needed.
//  6. Outputs. lambda_enter, lambda_exit: (*). The entry point: on the entering axis i the
//     book's point lies on the face plane by construction, s_i + lambda (t_i - s_i) =
//     c_i +- eta_i exactly, so it is fl(c_i +- eta_i), correctly rounded (0 ulps). On the
//     other axes, p_j = s_j + lambda r_j, computed with s_j, t_j (or d_j) scaled by the power
//     of two of their own larger magnitude (so that a point coordinate far smaller than the
//     largest input does not underflow), and lambda as the quotient's double word (lh, ll)
//     before its rounding (lh + ll is within a few u^2 |lambda| of lambda: the remainder
//     fma(-lh, rh, nh) is exact and the three roundings after it act on terms of size
//     u |lambda|): x1 = fma(lh, rh_j, s_j), x2 = fl(lh rl_j + ll rh_j), p^_j = fl(x1 + x2)
//     (scaled back exactly), with
//       |p^_j - p_j| <= 2u(1 + u) |p_j| + O(u^2) |lambda r_j|,
//     plus eta where p_j is subnormal (scaling back rounds it to the subnormal grid). With the
//     rounded lambda the second term was u |lambda r_j|: at range (|lambda r_j| ~ |s_j| far
//     above |p_j|) every digit of a point near the box. The source (when it is in the box:
//     enters = false, lambda_enter = 0) is returned exactly.
//     The normal is the book's unit vector of the entering face.
//
// At double the oracle's first stage runs first (filters/box_cast_filter.hpp: the outcodes and
// the plane pairs in double against static bounds): where it decides, decide(), hit() and the
// cast's classification take its answer, the book's at an exact type (the steps above give
// the same wherever they are certain); the cast still computes its values by the steps above.
// Where it cannot decide, the same signs on double words come next (filters/box_cast_words.hpp,
// aabb_cast_words: certain except at exact zeros), before the steps above.
//
// decide(): value = the classification above; certain == false iff some comparison of
// step 5 was left uncertain by (c), which (**) excludes: outside that (inputs mixing, at
// double, magnitudes near 2^-1000 with ones near 2^+50) only where S is within k eta' of
// 0 or the scaling of (c) was inexact. certain == true promises that robust::hit and
// cast().hit equal book::hit at an exact type on the same inputs, ties included.
#pragma once

#include <algorithm>
#include <bit>
#include <cdref/filters/box_cast_filter.hpp>
#include <cdref/filters/box_cast_words.hpp>
#include <cdref/primitives.hpp>
#include <cdref/results.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <type_traits>

#include "decision.hpp"
#include <cdref/bounded/eft.hpp>

namespace cdref::robust {

using namespace cdref::eft;  // the error-free transformations (bounded/eft.hpp)

namespace box_detail {

// Exactly sign(x - y + k) < 0, i.e. x - y < -k, for finite floats (step 1).
template <class F>
bool diff_below(F x, F y, F k) {
  const Pair<F> d = two_sum(x, F(-y));
  if (d.hi != -k) return d.hi < -k;
  return d.lo < F(0);
}

// Exactly x - y > k.
template <class F>
bool diff_above(F x, F y, F k) {
  const Pair<F> d = two_sum(x, F(-y));
  if (d.hi != k) return d.hi > k;
  return d.lo > F(0);
}

template <class F>
unsigned outcode(const Vec3<F>& p, const Box<F>& b) {
  unsigned bits = 0;
  for (int i = 0; i < 3; ++i) {
    if (diff_below(p[i], b.center[i], b.extent[i])) bits |= 1u << (2 * i);
    if (diff_above(p[i], b.center[i], b.extent[i])) bits |= 1u << (2 * i + 1);
  }
  return bits;
}

template <class F>
unsigned outcode_at_infinity(const Vec3<F>& s, const Vec3<F>& d, const Box<F>& b) {
  unsigned bits = 0;
  for (int i = 0; i < 3; ++i) {
    if (d[i] < F(0) || (d[i] == F(0) && diff_below(s[i], b.center[i], b.extent[i]))) bits |= 1u << (2 * i);
    if (d[i] > F(0) || (d[i] == F(0) && diff_above(s[i], b.center[i], b.extent[i]))) bits |= 1u << (2 * i + 1);
  }
  return bits;
}

// The scaled local data of step 2.
template <class F>
struct Scaled {
  F s[3], c[3], h[3];
  Pair<F> r[3];
  int scale = 0;     // inputs were multiplied by 2^-scale
  bool exact = true;  // and that was exact
};

template <class F>
Scaled<F> scaled(const Vec3<F>& s, const Vec3<F>& t_or_d, const Box<F>& b, bool bounded) {
  F m(0);
  for (int i = 0; i < 3; ++i)
    m = std::max({m, std::fabs(s[i]), std::fabs(t_or_d[i]), std::fabs(b.center[i]), std::fabs(b.extent[i])});
  Scaled<F> L;
  const int e = m > F(0) ? exponent_of(m) : 0;
  if (e < 0 || e >= std::numeric_limits<F>::max_exponent - 6) L.scale = e;
  // Multiplying by 2^-scale rounds exactly as ldexp does; where 2^-scale is not a normal
  // number, ldexp itself. Scaling up (scale < 0) is exact (the result stays below 2).
  const int k = -L.scale;
  const bool by_mul = k >= std::numeric_limits<F>::min_exponent && k < std::numeric_limits<F>::max_exponent - 1;
  const F f = by_mul ? exp2_of<F>(k) : F(1), inv = by_mul ? exp2_of<F>(-k) : F(1);
  auto sc = [&](F x) {
    if (L.scale == 0) return x;
    const F y = by_mul ? F(x * f) : std::ldexp(x, k);
    if (k < 0 && (by_mul ? F(y * inv) : std::ldexp(y, -k)) != x) L.exact = false;
    return y;
  };
  for (int i = 0; i < 3; ++i) {
    L.s[i] = sc(s[i]);
    L.c[i] = sc(b.center[i]);
    L.h[i] = sc(b.extent[i]);
    const F td = sc(t_or_d[i]);
    L.r[i] = bounded ? two_sum(td, F(-L.s[i])) : Pair<F>{td, F(0)};
  }
  return L;
}

// Step 3: c_i - s_i +- eta_i as a pair (Nh, Nl) within 4u^2 of the exact value.
template <class F>
Pair<F> numerator(const Scaled<F>& L, int plane) {
  const int i = plane / 2;
  const Pair<F> ab = two_sum(L.c[i], F(-L.s[i]));
  const Pair<F> ne = two_sum(ab.hi, plane % 2 == 0 ? F(-L.h[i]) : L.h[i]);
  const F z = ab.lo + ne.lo;
  return two_sum(ne.hi, z);
}

// Step 4: (nh + nl) / (rh + rl), rh != 0.
template <class F>
Pair<F> quotient_pair(const Pair<F>& n, const Pair<F>& r) {
  const F q0 = n.hi / r.hi;
  if (!std::isfinite(q0)) return {q0, F(0)};
  const F rho = std::fma(-q0, r.hi, n.hi);
  const F a = rho + n.lo;
  const F num = std::fma(-q0, r.lo, a);
  const F corr = num / r.hi;
  return {q0, corr};
}

// Step 6: s_j + lambda r_j on one axis, lambda the quotient's double word (lh, ll), scaled by
// the axis's own power of two (so that neither the point nor r_j under- or overflows where
// the other axes are much larger).
template <class F>
F point_coordinate(F s, F t_or_d, const Pair<F>& lambda, bool bounded) {
  const F m = std::max(std::fabs(s), std::fabs(t_or_d));
  if (m == F(0)) return s;
  const int e = exponent_of(m);
  const F ss = std::ldexp(s, -e), td = std::ldexp(t_or_d, -e);
  const Pair<F> r = bounded ? two_sum(td, F(-ss)) : Pair<F>{td, F(0)};
  const F x1 = std::fma(lambda.hi, r.hi, ss);
  const F x2 = lambda.hi * r.lo + lambda.lo * r.hi;
  return std::ldexp(F(x1 + x2), e);
}

// ---- Step 5: exact comparison of two parameters (see the header) ----

// The type the exact comparison is carried out in: float's expansions are held in double,
// where every product of two components is exact and nothing over- or underflows.
template <class F>
using Wide = std::conditional_t<std::is_same_v<F, float>, double, F>;

// A nonoverlapping expansion (Shewchuk 1997), components in increasing magnitude, zeros
// eliminated: its value is the exact sum, its sign that of its last component.
template <class W, int Cap>
struct Expansion {
  W c[Cap];
  int lsb[Cap];  // exponent of the lowest set bit of each component (filled by with_lsb())
  int n = 0;
  // Grow-Expansion: adds b exactly (Shewchuk's Theorem 10; in place, as m <= i).
  void grow(W b) {
    int m = 0;
    W q = b;
    for (int i = 0; i < n; ++i) {
      const Pair<W> s = two_sum(q, c[i]);
      q = s.hi;
      if (s.lo != W(0)) c[m++] = s.lo;
    }
    if (q != W(0)) c[m++] = q;
    n = m;
  }
  int sign() const { return n == 0 ? 0 : (c[n - 1] > W(0) ? 1 : -1); }
  void with_lsb() {
    for (int i = 0; i < n; ++i) {
      int e = 0;
      const W f = std::frexp(std::fabs(c[i]), &e);  // c = f 2^e, f in [1/2, 1)
      constexpr int p = std::numeric_limits<W>::digits;
      const auto q = static_cast<std::uint64_t>(std::ldexp(f, p));  // an integer below 2^p, exactly
      lsb[i] = e - p + std::countr_zero(q);
    }
  }
};

// The exact data of step 5 in W: numerators N (per plane) and denominators D (per axis),
// scaled by 2^sigma so that the largest input lies in [2^K, 2^(K+1)).
template <class F>
struct ExactData {
  using W = Wide<F>;
  Expansion<W, 4> N[6];
  Expansion<W, 4> D[3];
  bool exact = true;  // the scaling was exact

  ExactData(const Vec3<F>& s, const Vec3<F>& t_or_d, const Box<F>& b, bool bounded) {
    W v[4][3];
    W m(0);
    for (int i = 0; i < 3; ++i) {
      v[0][i] = W(s[i]), v[1][i] = W(t_or_d[i]), v[2][i] = W(b.center[i]), v[3][i] = W(b.extent[i]);
      for (int k = 0; k < 4; ++k) m = std::max(m, W(std::fabs(v[k][i])));
    }
    if constexpr (std::is_same_v<W, F>) {
      constexpr int K = (std::numeric_limits<W>::max_exponent - 10) / 2;
      if (m > W(0)) {
        const int sigma = K - exponent_of(m);
        for (auto& row : v)
          for (W& x : row) {
            const W y = std::ldexp(x, sigma);
            if (sigma < 0 && std::ldexp(y, -sigma) != x) exact = false;
            x = y;
          }
      }
    }
    for (int i = 0; i < 3; ++i) {
      D[i].grow(v[1][i]);
      if (bounded) D[i].grow(-v[0][i]);
      D[i].with_lsb();
      for (int side = 0; side < 2; ++side) {
        Expansion<W, 4>& n = N[2 * i + side];
        n.grow(v[2][i]);
        n.grow(-v[0][i]);
        n.grow(side == 0 ? W(-v[3][i]) : v[3][i]);
        n.with_lsb();
      }
    }
  }

  // sign(lambda_p - lambda_q) = sign(N_p D_q - N_q D_p) sign(D_p) sign(D_q), or 2 where it
  // cannot be certified (an inexact scaling, or products below the underflow threshold
  // whose error could change the sign).
  int compare(int p, int q) const {
    if (!exact) return 2;
    constexpr int dexp = std::numeric_limits<W>::min_exponent - std::numeric_limits<W>::digits;  // denorm_min
    Expansion<W, 26> S;
    int inexact = 0;
    auto add = [&](const Expansion<W, 4>& a, const Expansion<W, 4>& d, bool neg) {
      for (int i = 0; i < a.n; ++i)
        for (int j = 0; j < d.n; ++j) {
          const Pair<W> pr = two_prod(a.c[i], d.c[j]);
          if (a.lsb[i] + d.lsb[j] < dexp) ++inexact;
          S.grow(neg ? W(-pr.lo) : pr.lo);
          S.grow(neg ? W(-pr.hi) : pr.hi);
        }
    };
    add(N[p], D[q / 2], false);
    add(N[q], D[p / 2], true);
    const int sd = D[p / 2].sign() * D[q / 2].sign();
    if (inexact == 0) return S.sign() * sd;
    constexpr W tiny = std::numeric_limits<W>::denorm_min();  // (constexpr: see abs_term below)
    const W margin = W(inexact) * tiny;
    Expansion<W, 26> up = S, down = S;
    up.grow(-margin);
    down.grow(margin);
    if (up.sign() > 0) return sd;
    if (down.sign() < 0) return -sd;
    return 2;
  }
};

template <class F>
struct Eval {
  Cast<F> cast;
  Decision decision;
};

template <class F>
Eval<F> evaluate(const Vec3<F>& s, const Vec3<F>& t_or_d, const Box<F>& box, bool bounded, unsigned w) {
  Eval<F> out;
  const unsigned bs = outcode(s, box);
  const unsigned bt = bounded ? outcode(t_or_d, box) : outcode_at_infinity(s, t_or_d, box);
  if (bs & bt) {
    out.decision = {false, true};
    return out;
  }
  const Scaled<F> L = scaled(s, t_or_d, box, bounded);
  // Step 5a: the quick parameters q0 = fl(Nh / rh) of every plane crossed.
  Pair<F> num[6];
  F q0[6];
  for (int plane = 0; plane < 6; ++plane) {
    if (!((bs | bt) & (1u << plane))) continue;
    num[plane] = numerator(L, plane);
    q0[plane] = num[plane].hi / L.r[plane / 2].hi;
  }
  // Step 5b: sign(lambda_p - lambda_q), by the filter on q0, else exactly.
  const F eight_u = std::numeric_limits<F>::epsilon() * F(4);
  constexpr F abs_term = F(4) * std::numeric_limits<F>::denorm_min();  // constexpr: g++ with -frounding-math loads it at run time otherwise
  std::optional<ExactData<F>> exact;  // built on the first comparison the filter leaves open
  bool certain = true;
  auto compare = [&](int p, int q) {
    if (L.exact) {
      const F diff = q0[p] - q0[q];
      const F bound = eight_u * (std::fabs(q0[p]) + std::fabs(q0[q])) + abs_term;
      if (diff > bound) return 1;
      if (-diff > bound) return -1;
    }
    if (!exact) exact.emplace(s, t_or_d, box, bounded);
    const int c = exact->compare(p, q);
    if (c != 2) return c;
    certain = false;  // fall back on the quick parameters
    return q0[p] > q0[q] ? 1 : (q0[p] < q0[q] ? -1 : 0);
  };
  int face = -1, xplane = -1;
  for (int plane = 0; plane < 6; ++plane) {
    const unsigned bit = 1u << plane;
    if (bs & bit) {  // entering: the largest, the first in plane order on ties
      if (face < 0 || compare(plane, face) > 0) face = plane;
    } else if (bt & bit) {  // exiting: the smallest
      if (xplane < 0 || compare(plane, xplane) < 0) xplane = plane;
    }
  }
  const bool hit = face < 0 || xplane < 0 || compare(face, xplane) <= 0;
  out.decision = {hit, certain};
  if (!hit) return out;

  // Step 6: outputs.
  Cast<F>& res = out.cast;
  res.hit = true;
  res.enters = face >= 0;
  res.unbounded_exit = !bounded && xplane < 0;
  // a parameter as a double word, clamped to [0, 1] (a ray: [0, inf)) as the book clamps it
  const auto accurate_pair = [&](int plane) {
    const Pair<F> q = quotient_pair(num[plane], L.r[plane / 2]);
    const F v = q.hi + q.lo;
    if (v < F(0)) return Pair<F>{F(0), F(0)};
    if (bounded && v > F(1)) return Pair<F>{F(1), F(0)};
    return q;
  };
  const auto accurate = [&](int plane) {
    const Pair<F> q = accurate_pair(plane);
    return F(q.hi + q.lo);
  };
  const Pair<F> enter =
      face >= 0 && (w & (want_lambda_enter | want_point)) ? accurate_pair(face) : Pair<F>{F(0), F(0)};
  if (w & want_lambda_enter) res.lambda_enter = enter.hi + enter.lo;
  if (w & want_lambda_exit) {
    if (xplane >= 0)
      res.lambda_exit = accurate(xplane);
    else if (bounded)
      res.lambda_exit = F(1);
  }
  if (w & want_point) {
    if (face < 0) {
      res.point = s;
    } else {
      for (int j = 0; j < 3; ++j) res.point[j] = point_coordinate(s[j], t_or_d[j], enter, bounded);
      const int i = face / 2;
      res.point[i] = face % 2 == 0 ? F(box.center[i] - box.extent[i]) : F(box.center[i] + box.extent[i]);
    }
  }
  if ((w & want_normal) && face >= 0) res.normal = unit_vec<F>(face / 2, face % 2 == 0 ? -1 : 1);
  return out;
}

// At double, the oracle's first stage (filters/box_cast_filter.hpp: the outcodes and the plane
// pairs in double against static bounds) before the steps above: 1 (a hit), 0 (a miss) or 2
// (undecided; always at float and long double). Where it decides, its answer is the book's at
// an exact type, so every entry point takes it (decide(), hit() and the cast classify alike).
template <class F>
int first_stage(const Segment<F>& seg, const Box<F>& box) {
  if constexpr (std::is_same_v<F, double>) return filters::staged::filter(seg, box);
  else return filters::staged::unknown;
}
template <class F>
int first_stage(const Ray<F>& ray, const Box<F>& box) {
  if constexpr (std::is_same_v<F, double>) return filters::staged::filter(ray, box);
  else return filters::staged::unknown;
}

// At double, where the first stage cannot decide: Algorithm 3.3's signs on double words
// (filters/box_cast_words.hpp, aabb_cast_words), certain except at exact zeros, before the steps
// above (2^-52 from grazing they take a few hundred nanoseconds where the steps above take
// several times that). Where it decides, its answer is the book's at an exact type.
template <class F, class Shot>
int words_stage(const Shot& shot, const Box<F>& box) {
  if constexpr (std::is_same_v<F, double>) return filters::box_cast_words::aabb_cast_words(shot, box);
  else return filters::staged::unknown;
}

}  // namespace box_detail

// Every mask bit is honoured as results.hpp says (a quantity not asked for stays 0); hit,
// enters and unbounded_exit are always set.
template <class F>
Cast<F> cast(const Segment<F>& seg, const Box<F>& box, unsigned w = want_cast) {
  check(seg, "segment");
  check(box, "box");
  if constexpr (std::is_same_v<F, float>) return detail::rounded(cast(detail::widened(seg), detail::widened(box), w));
  auto e = box_detail::evaluate(seg.source, seg.target, box, true, w);
  // where the steps above are certain their classification is exact already
  if (!e.decision.certain) {
    int f = box_detail::first_stage(seg, box);
    if (f == filters::staged::unknown) f = box_detail::words_stage(seg, box);
    if (f != filters::staged::unknown) e.cast.hit = f != 0;
  }
  return e.cast;
}

template <class F>
Cast<F> cast(const Ray<F>& ray, const Box<F>& box, unsigned w = want_cast) {
  check(ray, "ray");
  check(box, "box");
  if constexpr (std::is_same_v<F, float>) return detail::rounded(cast(detail::widened(ray), detail::widened(box), w));
  auto e = box_detail::evaluate(ray.source, ray.direction, box, false, w);
  // where the steps above are certain their classification is exact already
  if (!e.decision.certain) {
    int f = box_detail::first_stage(ray, box);
    if (f == filters::staged::unknown) f = box_detail::words_stage(ray, box);
    if (f != filters::staged::unknown) e.cast.hit = f != 0;
  }
  return e.cast;
}

template <class F>
[[gnu::noinline]] Decision decide_checked(const Segment<F>& seg, const Box<F>& box) {
  check(seg, "segment");
  check(box, "box");
  if constexpr (std::is_same_v<F, float>) return decide_checked(detail::widened(seg), detail::widened(box));
  if (const int f = box_detail::first_stage(seg, box); f != filters::staged::unknown) return {f != 0, true};
  if (const int f = box_detail::words_stage(seg, box); f != filters::staged::unknown) return {f != 0, true};
  return box_detail::evaluate(seg.source, seg.target, box, true, 0).decision;
}
// (at double the first stage before the input checks: its outcodes' range tests refuse every
// infinity or NaN of the points, the centre and the extents, oracle/stages.hpp; the extents'
// signs tested first)
template <class F>
Decision decide(const Segment<F>& seg, const Box<F>& box) {
  if constexpr (std::is_same_v<F, double>)
    if (filters::staged::signs_valid(box))
      if (const int f = box_detail::first_stage(seg, box); f != filters::staged::unknown) [[likely]]
        return {f != 0, true};
  return decide_checked(seg, box);
}

template <class F>
[[gnu::noinline]] Decision decide_checked(const Ray<F>& ray, const Box<F>& box) {
  check(ray, "ray");
  check(box, "box");
  if constexpr (std::is_same_v<F, float>) return decide_checked(detail::widened(ray), detail::widened(box));
  if (const int f = box_detail::first_stage(ray, box); f != filters::staged::unknown) return {f != 0, true};
  if (const int f = box_detail::words_stage(ray, box); f != filters::staged::unknown) return {f != 0, true};
  return box_detail::evaluate(ray.source, ray.direction, box, false, 0).decision;
}
// (at double the first stage before the input checks: its outcodes' range tests refuse every
// infinity or NaN of the points, the centre and the extents, oracle/stages.hpp; the extents'
// signs and the direction tested first)
template <class F>
Decision decide(const Ray<F>& ray, const Box<F>& box) {
  if constexpr (std::is_same_v<F, double>)
    if (filters::staged::signs_valid(box) && filters::staged::direction_valid(ray.direction))
      if (const int f = box_detail::first_stage(ray, box); f != filters::staged::unknown) [[likely]]
        return {f != 0, true};
  return decide_checked(ray, box);
}

// The decision alone (the first stage, the signs on double words, else the parameters of step 5;
// the outputs are not needed).
template <class F>
bool hit(const Segment<F>& seg, const Box<F>& box) {
  return decide(seg, box).value;
}

template <class F>
bool hit(const Ray<F>& ray, const Box<F>& box) {
  return decide(ray, box).value;
}

}  // namespace cdref::robust
