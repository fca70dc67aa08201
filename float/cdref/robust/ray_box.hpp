// cdref/robust/ray_box.hpp - ray casts on an axis-aligned box (Algorithm 3.3) that keep
// their accuracy where the book's float version loses it, for F = float, double, long
// double. Same signatures and results as cdref::book (hit, cast for a segment s->t and for
// an infinite ray s + lambda d; Cast<F> from results.hpp), plus decide() (decision.hpp).
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
//     inexact the outputs carry no bound and decide() reports uncertain when it needs a
//     parameter.
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
//     (The ray's lambda, unbounded, may overflow; the bound is then void.)
//  5. The decision. Every entering parameter is > 0 and <= 1 (segment), every exiting one
//     >= 0 exactly (the outcodes say which side of each plane s and t lie), so the book's
//     max(0, max_E) <= min(1, min_X) is max_E <= min_X (with min_X = 1 for a segment
//     whose target is in the box, and E empty meaning enter = 0). enter^ = max over E and
//     exit^ = min over X of lambda^ (clamped to [0, 1] for a segment, >= 0 for a ray, which
//     can only bring them closer to the truth); ties between planes go to the first in the
//     order x-, x+, y-, y+, z-, z+, as in the book.
//  6. Outputs. lambda_enter, lambda_exit: (*). The entry point: on the entering axis i the
//     book's point lies on the face plane by construction, s_i + lambda (t_i - s_i) =
//     c_i +- eta_i exactly, so it is fl(c_i +- eta_i), correctly rounded (0 ulps). On the
//     other axes, p_j = s_j + lambda r_j, computed with s_j, t_j (or d_j) scaled by the power
//     of two of their own larger magnitude (so that a point coordinate far smaller than the
//     largest input does not underflow): x1 = fma(lambda^, rh_j, s_j), x2 = fl(lambda^ rl_j),
//     p^_j = fl(x1 + x2) (scaled back exactly), with
//       |p^_j - p_j| <= 2u(1 + u) |p_j| + (1 + 2u) |lambda^ - lambda| |r_j| + 2u^2 |lambda r_j|,
//     in the normal range <= u (2(1 + u) |p_j| + (1 + 64u) |lambda r_j|), plus eta where p_j is
//     subnormal (scaling back rounds it to the subnormal grid): the error is that of
//     lambda carried along r_j, which no formulation with a rounded lambda avoids. The
//     source (when it is in the box: enters = false, lambda_enter = 0) is returned exactly.
//     The normal is the book's unit vector of the entering face.
//
// decide(): the book hits iff lambda_p <= lambda_q for every entering plane p and exiting
// plane q (step 5). A pair on one axis is ordered by geometry (h_i >= 0: the lower plane
// comes first along r), so only pairs on different axes need the parameters. From (*),
// |lambda^ - lambda| <= beta = (kappa |lambda^| + alpha) / (1 - kappa), kappa = u(1 + 18u),
// alpha = 3 eta (1 + 1/r_min) (r_min the smallest |rh| of the planes crossed). A pair is
// decided when fl(lambda^_q - lambda^_p) exceeds, in absolute value,
//   B = fl(4u (lambda^_p + lambda^_q) + 16 eta' (2 + 1/r_min)),   eta' the smallest subnormal:
// B is at least twice beta_p + beta_q, which absorbs the rounding of B and of the
// difference (a few u relative). certain == true iff the outcodes decide (shared bit: miss;
// no entering plane, or no exiting plane of a segment: hit), or the answer is hit and every
// pair on different axes is decided, or it is miss and one pair is decided the other way;
// the answer is then the book's at an exact type on the same inputs. B is infinite
// (uncertain) where 1/r_min or the parameters overflow; exact ties between axes (through
// an edge or a corner) are uncertain by design, as is everything after an inexact scaling.
#pragma once

#include <algorithm>
#include <cdref/primitives.hpp>
#include <cdref/results.hpp>
#include <cmath>
#include <limits>

#include "decision.hpp"
#include "eft.hpp"

namespace cdref::robust {

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
  const int e = m > F(0) ? std::ilogb(m) : 0;
  if (e < 0 || e >= std::numeric_limits<F>::max_exponent - 6) L.scale = e;
  auto sc = [&](F x) {
    const F y = std::ldexp(x, -L.scale);
    if (std::ldexp(y, L.scale) != x) L.exact = false;
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
F quotient(const Pair<F>& n, const Pair<F>& r) {
  const F q0 = n.hi / r.hi;
  if (!std::isfinite(q0)) return q0;
  const F rho = std::fma(-q0, r.hi, n.hi);
  const F a = rho + n.lo;
  const F num = std::fma(-q0, r.lo, a);
  const F corr = num / r.hi;
  return q0 + corr;
}

// Step 6: s_j + lambda r_j on one axis, scaled by its own power of two (so that neither
// the point nor r_j under- or overflows where the other axes are much larger).
template <class F>
F point_coordinate(F s, F t_or_d, F lambda, bool bounded) {
  const F m = std::max(std::fabs(s), std::fabs(t_or_d));
  if (m == F(0)) return s;
  const int e = std::ilogb(m);
  const F ss = std::ldexp(s, -e), td = std::ldexp(t_or_d, -e);
  const Pair<F> r = bounded ? two_sum(td, F(-ss)) : Pair<F>{td, F(0)};
  const F x1 = std::fma(lambda, r.hi, ss);
  const F x2 = lambda * r.lo;
  return std::ldexp(F(x1 + x2), e);
}

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
  F enter(0), exit(1);
  bool has_exit = bounded, exit_from_plane = false;
  int face = -1;
  F r_min = std::numeric_limits<F>::infinity();
  F lam[6];
  for (int plane = 0; plane < 6; ++plane) {
    const unsigned bit = 1u << plane;
    if (!((bs | bt) & bit)) continue;
    const Pair<F>& r = L.r[plane / 2];
    // Step 5: the exact parameters lie in [0, 1] (segment) or [0, inf) (ray).
    const F q = quotient(numerator(L, plane), r);
    lam[plane] = bounded ? std::clamp(q, F(0), F(1)) : std::max(q, F(0));
    r_min = std::min(r_min, std::fabs(r.hi));
    if (bs & bit) {
      if (face < 0 || lam[plane] > enter) enter = lam[plane], face = plane;
    } else if (!has_exit || !exit_from_plane || lam[plane] < exit) {
      exit = lam[plane], has_exit = true, exit_from_plane = true;
    }
  }
  const bool hit = !has_exit || enter <= exit;

  // decide(): pairs (entering p, exiting q) on different axes, compared with the margin
  // B; a pair on one axis is ordered by geometry (lower before upper along r).
  out.decision.value = hit;
  if (face < 0 || !exit_from_plane) {
    out.decision.certain = true;
  } else if (L.exact) {
    const F four_u = std::numeric_limits<F>::epsilon() * F(2);
    const F abs_term = F(16) * std::numeric_limits<F>::denorm_min() * (F(2) + F(1) / r_min);
    bool all_below = true, some_above = false;
    for (int p = 0; p < 6; ++p) {
      if (!(bs & (1u << p))) continue;
      for (int q = 0; q < 6; ++q) {
        if (!(bt & (1u << q)) || p / 2 == q / 2) continue;
        const F bound = four_u * (lam[p] + lam[q]) + abs_term;
        const F diff = lam[q] - lam[p];
        if (!(diff > bound)) all_below = false;
        if (-diff > bound) some_above = true;
      }
    }
    out.decision.certain = hit ? all_below : some_above;
  }
  if (!hit) return out;

  // Step 6: outputs.
  Cast<F>& res = out.cast;
  res.hit = true;
  res.enters = face >= 0;
  res.unbounded_exit = !has_exit;
  if (w & want_lambda_enter) res.lambda_enter = enter;
  if ((w & want_lambda_exit) && has_exit) res.lambda_exit = exit;
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

}  // namespace box_detail

// Every mask bit is honoured as results.hpp says (a quantity not asked for stays 0); hit,
// enters and unbounded_exit are always set.
template <class F>
Cast<F> cast(const Segment<F>& seg, const Box<F>& box, unsigned w = want_cast) {
  check(seg, "segment");
  check(box, "box");
  return box_detail::evaluate(seg.source, seg.target, box, true, w).cast;
}

template <class F>
Cast<F> cast(const Ray<F>& ray, const Box<F>& box, unsigned w = want_cast) {
  check(ray, "ray");
  check(box, "box");
  return box_detail::evaluate(ray.source, ray.direction, box, false, w).cast;
}

// The decision alone: the parameters are still needed (step 5), the outputs are not.
template <class F>
bool hit(const Segment<F>& seg, const Box<F>& box) {
  return cast(seg, box, 0).hit;
}

template <class F>
bool hit(const Ray<F>& ray, const Box<F>& box) {
  return cast(ray, box, 0).hit;
}

template <class F>
Decision decide(const Segment<F>& seg, const Box<F>& box) {
  check(seg, "segment");
  check(box, "box");
  return box_detail::evaluate(seg.source, seg.target, box, true, 0).decision;
}

template <class F>
Decision decide(const Ray<F>& ray, const Box<F>& box) {
  check(ray, "ray");
  check(box, "box");
  return box_detail::evaluate(ray.source, ray.direction, box, false, 0).decision;
}

}  // namespace cdref::robust
