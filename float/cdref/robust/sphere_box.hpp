// cdref/robust/sphere_box.hpp - sphere-box (Section 3.2.2) that keeps its accuracy where the
// book loses it, for F = float, double, long double. Same signatures and results as
// cdref::book (intersect, proximity) and decide (decision.hpp). u is the unit roundoff,
// eta the smallest subnormal.
// At F = float every entry point runs the double version on the same inputs and rounds each
// value once (decision.hpp, widened).
//
// Formulation (the book's, in the box's local coordinates: c = sphere centre - box centre,
// x = clamp(c, -h, h), v = x - c):
//  1. c_i = ch_i + cl_i exactly (two_sum), after scaling the inputs by 2^-e1 (e1 > 0 only
//     within 2^4 of overflow).
//  2. The clamp exactly: c_i < -h_i iff ch_i < -h_i or (ch_i = -h_i and cl_i < 0), since
//     ch_i = fl(c_i) and rounding is monotone; likewise c_i > h_i.
//  3. A clamped coordinate v_i = +-h_i - ch_i - cl_i is kept exactly as a + b + e:
//     (p, e) = two_sum(+-h_i, -ch_i), (a, b) = two_sum(p, -cl_i). An unclamped one is 0.
//     These terms and rho are scaled by one power of two bringing the largest into [1,2).
//  4. Q = |v|^2 - rho^2 by dot2 over the 19 exact products of the expansions:
//     |Q^ - Q| <= u|Q| + gamma_19^2 S, S <= (|v| + 2 sum |b_i| + |e_i|)^2 + rho^2, about
//     |v|^2 + rho^2. intersect = Q^ <= 0.
//  5. Centre outside (some axis clamped): v is also rounded to pairs (two_sum(a, fl(b + e)),
//     off by at most 3u^2 |v_i|). distance/depth = +-Q/(|v| + rho) with Q within
//     (1 + 1/16)u of itself (dot2's where its bound is below 2.125u|Q^|, else Q summed as if
//     in triple precision, sph_box_q3: the gamma^2 S term was 362 u^2 S / |Q|, 117 ulps at
//     2^-52 of the radius from touching), |v| + rho as a double word (norm_dw, 18u^2 + the
//     pairs' 3u^2) and the quotient by div_pair (8u^2), rounded once: within about 1.6u of
//     the truth, 2 ulps, at any distance. Witness on the sphere c + rho n, n = v/|v| from the pairs (their
//     rounding 3u^2, unit_dw 27u^2 per component) and c_i + rho n_i rounded once (along_dw,
//     sphere_sphere.hpp): within one ulp unless it cancels to below ~64u rho |n_i| (fma with
//     n rounded to F was off by 3.5u rho |n_i|: 929 ulps on the near-touching family).
//     Witness on the box (and
//     `closest`): a clamped coordinate is fl(box centre_i +- h_i), half an ulp; an unclamped
//     one is the sphere's centre coordinate itself, exact.
//  6. Centre in the closed box (no axis clamped, v = 0 exactly): delta_i = h_i - |c_i| =
//     h_i - |ch_i| -+ cl_i, three floats; the smallest (first on ties, as the book's strict
//     `<`) is found by exact comparisons (the exact sign of a sum of six floats by an
//     expansion, exact_sign_of_sum). depth = delta + rho = h - |c| + rho as a sum of four
//     floats by dot2 (an error-free Sum2): error <= u depth + gamma_4^2 (h + |c| + rho).
//     Witnesses: on the box the face point, box centre_i + sign h_i (the book's
//     c + delta sign e_i equals it exactly): half an ulp; on the sphere c - rho sign e_i:
//     half an ulp. sign(0) = +1 as in the book.
//  7. First, for a centre outside where the filter below decides, as sphere_sphere.hpp's item
//     7: |v| as a double word alone from the pairs of item 5 (18u^2 + their 3u^2), g = |v| -
//     rho summed once; before that rounding g is within 26u^2 (|v| + rho) of the truth, so
//     where |g| > 520u fl(|v^| + rho) its sign is certain and g is within half an ulp plus
//     u|g|/16 of the distance or depth (item 4's dot2 and the quotient are skipped). The
//     sphere's witness from the same |v|: 1/|v| by recip_pair (31u^2 with |v|'s), n_i = v_i
//     (1/|v|) by mul_pair (39u^2 with the pairs' rounding), along_dw: within half an ulp plus
//     43u^2 max(|p_i|, rho |n_i|), one ulp unless it cancels to below 86u rho |n_i|. 244 -> 84
//     ns a case on 2,000 uniform cases (standalone loop, 2026-11-29).
//  8. Item 7 runs on the terms of item 3 without either scaling (e1 = e2 = 0), as
//     sphere_sphere.hpp's item 8: where the filter decides, W + rho^2 + C <= max / 4 bounds
//     every |v_i|^2, rho^2 and |c|^2, so nothing in item 7 overflows, and a clamped axis has
//     h_i < |c_i| (an extent beyond that range leaves the centre inside, where item 7 declines).
//     The clamps are exact comparisons either way. Only where item 7 declines are the scaled
//     terms formed.
//
// decide() and intersect() first try a filter on the stable tier's arithmetic (at double the
// oracle's first stage before it, filters/sphere_filter.hpp; this one where that leaves the
// case open; the book's, in F): c_i = fl(centre_i - box centre_i), v_i = fl(-+h_i - c_i) where c_i is clamped (else 0),
// q = fl(fl(v.v) - fl(rho^2)). With round to nearest c_i is off by at most u |c_i|, and the
// clamp's offset is 1-Lipschitz in c, so the exact v_i differs from the computed one by at
// most delta_i = u (|c_i| + |v_i|) (the rounding of v_i included; a coordinate clamped on one
// side of the face and not on the other counts too). Hence |Q - (v.v - rho^2)| <= sum_i
// (2 |v_i| delta_i + delta_i^2) + gamma_3 v.v + u rho^2 (+ eta/2 per product below the normal
// range) <= 5.02u W + 1.01u rho^2 + 1.01u^2 C, with W = sum_i |v_i| (|c_i| + |v_i|) and C =
// c.c. Where m = W + rho^2 + C lies in [2^emin / u, max / 4] the sign of q is the sign of Q
// whenever |q| > 8u (W + rho^2) + 16u^2 C (computed in F: the slack covers its roundings
// and the eta terms, 10u^2 m). Then the answer is certain without the expansions below; decide(),
// intersect() and proximity() all take it where it decides, so the three classify alike
// (the expansions' own value is certified only within in_certified_range, decision.hpp). At
// double, decide() and intersect() run it before the input checks: m fails its range test for
// every infinity or NaN among the centres and the radius (C and rho^2); the radius's sign and
// the extents, which it does not see (an infinite extent clamps to v_i = 0), are tested first;
// the rest takes the checks (the same messages) and the filter again, out of line.
// decide() otherwise: outside, the sign of Q by dot2_cert (ray_sphere.hpp), extra absolute 128 eta for
// low terms scaled below the normal range; inside, intersect = true exactly. Never certain
// when the first scaling lost bits (inputs 2^(emax+emin) apart). Where dot2's bound cannot
// tell Q's sign (an exact touch, Q = 0 with v != 0, among those cases), the exact sign of the
// 38 parts of its products (sph_box_q_sign): certain wherever every product's two_prod is exact
// (no factor pair underflows), and an exact touch then meets with distance and depth 0.
#pragma once

#include <algorithm>
#include <cdref/primitives.hpp>
#include <cdref/results.hpp>
#include <cmath>

#include <cdref/filters/sphere_filter.hpp>

#include "decision.hpp"
#include <cdref/bounded/eft.hpp>
#include "ray_sphere.hpp"
#include "sphere_sphere.hpp"

namespace cdref::robust {

using namespace cdref::eft;  // the error-free transformations (bounded/eft.hpp)

namespace detail {

template <class F>
struct SphBoxLocal {
  F ch[3], cl[3], h[3], rho1;  // scaled by 2^-e1
  int clamp[3] = {0, 0, 0};   // -1 below, +1 above, 0 inside
  bool outside = false;
  F a[3], b[3], e[3], rho;     // v = a + b + e, scaled by 2^-(e1 + e2)
  int e1 = 0, scale = 0;
  bool exact = true;
};

// (scaled = false: e1 = e2 = 0, item 8)
template <class F>
SphBoxLocal<F> sph_box_local(const Sphere<F>& sp, const Box<F>& box, bool scaled = true) {
  SphBoxLocal<F> L;
  if (scaled) {
    F m = sp.radius;
    for (int i = 0; i < 3; ++i)
      m = std::max({m, std::fabs(sp.center[i]), std::fabs(box.center[i]), box.extent[i]});
    L.e1 = overflow_guard(m);
  }
  L.rho1 = scale_down(sp.radius, L.e1, L.exact);
  F top = L.rho1;
  for (int i = 0; i < 3; ++i) {
    const Pair<F> c = two_sum(scale_down(sp.center[i], L.e1, L.exact), F(-scale_down(box.center[i], L.e1, L.exact)));
    L.ch[i] = c.hi;
    L.cl[i] = c.lo;
    const F h = L.h[i] = scale_down(box.extent[i], L.e1, L.exact);
    L.a[i] = L.b[i] = L.e[i] = F(0);
    if (c.hi < -h || (c.hi == -h && c.lo < F(0)))
      L.clamp[i] = -1;
    else if (c.hi > h || (c.hi == h && c.lo > F(0)))
      L.clamp[i] = 1;
    if (L.clamp[i] != 0) {
      L.outside = true;
      const Pair<F> p = two_sum(L.clamp[i] > 0 ? h : F(-h), F(-c.hi));
      const Pair<F> q = two_sum(p.hi, F(-c.lo));
      L.a[i] = q.hi;
      L.b[i] = q.lo;
      L.e[i] = p.lo;
      top = std::max({top, std::fabs(q.hi), std::fabs(q.lo), std::fabs(p.lo)});
    }
  }
  L.rho = L.rho1;
  if (!scaled) return L;
  const int e2 = top > F(0) ? exponent_of(top) : 0;
  const Pow2<F> down(e2);  // x 2^-e2, as ldexp gives it
  for (int i = 0; i < 3; ++i) {
    L.a[i] = down(L.a[i]);
    L.b[i] = down(L.b[i]);
    L.e[i] = down(L.e[i]);
  }
  L.rho = down(L.rho1);
  L.scale = L.e1 + e2;
  return L;
}

template <class F>
Bounded<F> sph_box_q(const SphBoxLocal<F>& L) {
  const F *a = L.a, *b = L.b, *e = L.e;
  return dot2_cert({a[0], b[0], e[0], F(2 * a[0]), F(2 * a[0]), F(2 * b[0]), a[1], b[1], e[1], F(2 * a[1]),
                    F(2 * a[1]), F(2 * b[1]), a[2], b[2], e[2], F(2 * a[2]), F(2 * a[2]), F(2 * b[2]), L.rho},
                   {a[0], b[0], e[0], b[0], e[0], e[0], a[1], b[1], e[1], b[1], e[1], e[1], a[2], b[2], e[2], b[2],
                    e[2], e[2], F(-L.rho)},
                   128);
}

// The 38 parts of Q's 19 exact products (two_prod's high and low parts, sph_box_q's terms);
// false where some product's low part may have underflowed. A product's low part is exact
// wherever the product is 0 by a zero factor or at least 2^(emin + p) in magnitude (then the
// lowest bits of its factors sum to at least emin - p + 1, the subnormals' spacing); 2 min / u
// stands for that with a factor 2 to spare.
template <class F>
bool sph_box_q_parts(const SphBoxLocal<F>& L, F (&p)[38]) {
  const F *a = L.a, *b = L.b, *e = L.e;
  int n = 0;
  bool exact = true;
  const auto put = [&](F x, F y) {
    const Pair<F> t = two_prod(x, y);
    exact = exact && (x == F(0) || y == F(0) || std::fabs(t.hi) >= F(2) * std::numeric_limits<F>::min() / unit_roundoff<F>());
    p[n++] = t.hi;
    p[n++] = t.lo;
  };
  for (int i = 0; i < 3; ++i) {
    put(a[i], a[i]), put(b[i], b[i]), put(e[i], e[i]);
    put(F(2 * a[i]), b[i]), put(F(2 * a[i]), e[i]), put(F(2 * b[i]), e[i]);
  }
  put(L.rho, F(-L.rho));
  return exact;
}

// Q as sph_box_q, summed as if in triple precision (sum_k, K = 3, over the 38 parts of the 19
// exact products): |Q^ - Q| <= (u + 3 gamma_37^2)|Q| + gamma_74^3 S (+ 38 eta for products
// below the normal range). Taken where dot2's bound is not within u|Q|/16 (item 5).
template <class F>
F sph_box_q3(const SphBoxLocal<F>& L) {
  F p[38];
  sph_box_q_parts(L, p);
  return sum_k(p, 3);
}

// Q's sign where dot2's bound cannot tell it (an exact touch, Q = 0, among such cases): the 38
// parts summed as an expansion (exact_sign_of_sum, sphere_sphere.hpp), exactly, wherever the
// first scaling lost nothing (L.exact) and every product's two_prod is exact. `certain` says
// whether the sign returned is Q's; where it is not, it is the sign of dot2's value.
template <class F>
int sph_box_q_sign(const SphBoxLocal<F>& L, const Bounded<F>& qb, bool& certain) {
  certain = true;
  if (const int s = qb.sign()) return s;
  const int rounded = int(qb.value > F(0)) - int(qb.value < F(0));
  certain = false;
  F p[38];
  if (!L.exact || !sph_box_q_parts(L, p)) return rounded;
  certain = true;
  return exact_sign_of_sum(p);
}

// The filter of the header: +1 (Q > 0: apart) or -1 (Q < 0: meeting) where the sign of Q is
// certain from the stable tier's arithmetic, 0 where it is not.
template <class F>
int sphere_box_filter_own(const Sphere<F>& sp, const Box<F>& box) {
  F vv(0), w(0), cc(0);
  for (int i = 0; i < 3; ++i) {
    const F c = sp.center[i] - box.center[i], h = box.extent[i];
    const F v = std::max(F(-h - c), F(0)) + std::min(F(h - c), F(0));  // the clamp's offset, branch-free
    const F ac = std::fabs(c), av = std::fabs(v);
    vv += v * v;
    w += av * (ac + av);
    cc += c * c;
  }
  const F ss = sp.radius * sp.radius;
  const F q = vv - ss, m = w + ss + cc;
  constexpr F u = unit_roundoff<F>();
  if (!(m <= std::numeric_limits<F>::max() / F(4) && m >= std::numeric_limits<F>::min() / u)) return 0;
  const F e = F(8) * u * (w + ss) + F(16) * u * u * cc;
  return int(q > e) - int(q < -e);
}

// The filter every entry point takes (header): at double the oracle's first stage
// (filters/sphere_filter.hpp: |v| from max(0, |c_i| - h_i), its bound from sum (|c_i| + h_i)^2),
// then the one above where that leaves the case open; at other types the one above.
template <class F>
int sphere_box_filter(const Sphere<F>& sp, const Box<F>& box) {
  if constexpr (std::is_same_v<F, double>) {
    const int o = filters::staged::filter(sp, box);
    if (o != filters::staged::unknown) [[likely]]
      return o ? -1 : 1;
  }
  return sphere_box_filter_own(sp, box);
}

}  // namespace detail

namespace detail {
// What the filter's range test does not see (header): the radius's sign, and the extents (an
// infinite extent clamps to an offset of 0).
template <class F>
bool sphere_box_unseen_valid(const Sphere<F>& sp, const Box<F>& box) {
  constexpr F big = std::numeric_limits<F>::max();
  return sp.radius >= F(0) && box.extent[0] >= F(0) && box.extent[0] <= big && box.extent[1] >= F(0) &&
         box.extent[1] <= big && box.extent[2] >= F(0) && box.extent[2] <= big;
}
// The filter as intersect() and decide() take it before their input checks: 0 where it does
// not decide or does not apply (at float; inputs it does not see valid).
template <class F>
int unchecked_filter(const Sphere<F>& sp, const Box<F>& box) {
  if constexpr (std::is_same_v<F, float>)
    return 0;
  else
    return sphere_box_unseen_valid(sp, box) ? sphere_box_filter(sp, box) : 0;
}
}  // namespace detail

template <class F>
[[gnu::noinline]] bool intersect_checked(const Sphere<F>& sp, const Box<F>& box) {
  check(sp, "sphere");
  check(box, "box");
  if constexpr (std::is_same_v<F, float>) return intersect_checked(detail::widened(sp), detail::widened(box));  // (decision.hpp, widened)
  if (const int f = detail::sphere_box_filter(sp, box)) return f < 0;
  const auto L = detail::sph_box_local(sp, box);
  bool certain;
  return !L.outside || detail::sph_box_q_sign(L, detail::sph_box_q(L), certain) <= 0;
}
// (intersect() and decide(): the filter before the input checks at double, header)
template <class F>
bool intersect(const Sphere<F>& sp, const Box<F>& box) {
  if (const int f = detail::unchecked_filter(sp, box)) [[likely]]
    return f < 0;
  return intersect_checked(sp, box);
}

template <class F>
[[gnu::noinline]] Decision decide_checked(const Sphere<F>& sp, const Box<F>& box) {
  check(sp, "sphere");
  check(box, "box");
  if constexpr (std::is_same_v<F, float>) return decide_checked(detail::widened(sp), detail::widened(box));  // (decision.hpp, widened)
  if (const int f = detail::sphere_box_filter(sp, box)) return Decision{f < 0, true};
  const auto L = detail::sph_box_local(sp, box);
  if (!L.outside) return within_range(Decision{true, L.exact}, sp, box);
  bool certain;
  const int q = detail::sph_box_q_sign(L, detail::sph_box_q(L), certain);
  return within_range(Decision{q <= 0, L.exact && certain}, sp, box);
}
template <class F>
Decision decide(const Sphere<F>& sp, const Box<F>& box) {
  if (const int f = detail::unchecked_filter(sp, box)) [[likely]]
    return Decision{f < 0, true};
  return decide_checked(sp, box);
}


namespace detail {

// v rounded to pairs (item 5): v_i = a_i + fl(b_i + e_i) as two_sum gives it.
template <class F>
void sph_box_pairs(const SphBoxLocal<F>& L, F (&vh)[3], F (&vl)[3]) {
  for (int i = 0; i < 3; ++i) {
    const Pair<F> p = two_sum(L.a[i], F(L.b[i] + L.e[i]));
    vh[i] = p.hi;
    vl[i] = p.lo;
  }
}

// A centre outside the box, where the filter decides: the values from |v| alone where that is
// accurate enough (sphere_sphere.hpp, item 7; v_i = a_i + (b_i + e_i) rounded once, within
// 2u^2 |v_i|). Returns which of the asked values it set.
template <class Mul, class F>
unsigned sph_box_fast(const SphBoxLocal<F>& L, const Sphere<F>& sp, int cls, unsigned w,
                      Proximity<F>& res) {
  if (cls == 0 || !L.exact || !L.outside) return 0;
  F vh[3], vl[3];
  sph_box_pairs(L, vh, vl);
  Pair<F> len;  // |v| (1 + 21u^2)
  if (!first_look_norm<Mul>(vh, vl, len)) return 0;
  unsigned done = 0;
  if ((w & (want_distance | want_depth)) && first_look_gap(len, L.rho, F(0), cls, L.scale, w, res))
    done |= want_distance | want_depth;
  if (w & want_witnesses) {
    const Pair<F> r = recip_pair<Mul>(len);  // 1 / |v| (1 + 31u^2)
    for (int i = 0; i < 3; ++i)
      res.on_a[i] = along_dw(sp.center[i], sp.radius, mul_pair<Mul>(Pair<F>{vh[i], vl[i]}, r));  // v_i / |v| (1 + 39u^2)
    done |= want_witnesses;
  }
  return done;
}

template <class F, class Mul = SplitProduct>
Proximity<F> proximity_dw(const Sphere<F>& sp, const Box<F>& box, unsigned w) {
  Proximity<F> res;
  const int cls = detail::sphere_box_filter(sp, box);
  const auto closest_point = [&](const SphBoxLocal<F>& L) {  // the box's point closest to the centre
    Vec3<F> x = sp.center;
    for (int i = 0; i < 3; ++i)
      if (L.clamp[i] != 0) x[i] = box.center[i] + (L.clamp[i] > 0 ? box.extent[i] : F(-box.extent[i]));
    return x;
  };
  unsigned done = 0;
  if (cls != 0) {
    // item 7 on the terms as they are (item 8); the clamps are the same either way
    const auto U = detail::sph_box_local(sp, box, false);
    const unsigned asked = w & (want_distance | want_depth | want_witnesses);
    done = asked ? sph_box_fast<Mul>(U, sp, cls, w, res) : 0u;
    if ((asked & ~done) == 0) {
      const Vec3<F> x = closest_point(U);
      if (done & want_witnesses) res.on_b = x;
      res.intersect = cls < 0;
      if (w & want_closest) res.closest = x;
      return res;
    }
    w &= ~done;
  }
  const auto L = detail::sph_box_local(sp, box);
  const Vec3<F> x = closest_point(L);
  if (done & want_witnesses) res.on_b = x;
  const detail::Bounded<F> qb = L.outside ? detail::sph_box_q(L) : detail::Bounded<F>{F(0), F(0)};
  const F q = qb.value;
  bool q_certain = false;  // Q's sign as decide() takes it (exact where dot2 cannot tell it)
  const int q_sign = L.outside ? detail::sph_box_q_sign(L, qb, q_certain) : 0;
  res.intersect = !L.outside || q_sign <= 0;
  if (cls != 0) res.intersect = cls < 0;  // as decide() and intersect()
  if (w & want_closest) res.closest = x;
  if (!(w & (want_distance | want_depth | want_witnesses))) return res;

  if (L.outside) {
    F vh[3], vl[3];
    detail::sph_box_pairs(L, vh, vl);
    // Q's sign: the exact one where it is certain (an exact touch, Q = 0 proven: distance and
    // depth stay 0), else the computed one's
    const int qs = q_certain ? q_sign : int(q > F(0)) - int(q < F(0));
    if ((w & (want_distance | want_depth)) && qs != 0) {
      // Q within (1 + 1/16)u of itself: dot2's where its bound says so (E <= 2.125u|Q^|), else
      // summed as if in triple precision; |v| + rho as a double word (norm_dw: 18u^2), the
      // quotient by div_pair, one rounding (as sphere_sphere.hpp)
      const F Q = qb.err <= F(2.125) * detail::unit_roundoff<F>() * std::fabs(q) ? q : detail::sph_box_q3(L);
      const Pair<F> len = detail::norm_dw<Mul>(vh, vl);
      const Pair<F> t = two_sum(len.hi, L.rho);
      const Pair<F> den = fast_two_sum(t.hi, F(t.lo + len.lo));
      if (den.hi > F(0) && (Q > F(0)) == (qs > 0)) {
        const Pair<F> d = div_pair<Mul>(Pair<F>{std::fabs(Q), F(0)}, den);
        const F dv = std::ldexp(F(d.hi + d.lo), L.scale);
        if ((w & want_distance) && qs > 0) res.distance = dv;
        if ((w & want_depth) && qs < 0) res.depth = dv;
      }
    }
    if (w & want_witnesses) {
      Pair<F> n[3];
      detail::unit_dw<Mul>(vh, vl, n);
      for (int i = 0; i < 3; ++i) res.on_a[i] = detail::along_dw(sp.center[i], sp.radius, n[i]);
      res.on_b = x;
    }
    return res;
  }
  // centre in the closed box: the axis of the smallest delta_i = h_i - |c_i|, exactly
  F ah[3], al[3];
  for (int i = 0; i < 3; ++i) {
    const bool neg = L.ch[i] < F(0);
    ah[i] = neg ? F(-L.ch[i]) : L.ch[i];
    al[i] = neg ? F(-L.cl[i]) : L.cl[i];
  }
  int axis = 0;
  for (int i = 1; i < 3; ++i) {
    const F d[6] = {L.h[i], F(-ah[i]), F(-al[i]), F(-L.h[axis]), ah[axis], al[axis]};
    if (detail::exact_sign_of_sum(d) < 0) axis = i;
  }
  const bool pos = !(L.ch[axis] < F(0));
  if (w & want_depth)
    res.depth = std::ldexp(dot2({L.h[axis], F(-ah[axis]), F(-al[axis]), L.rho1}, {F(1), F(1), F(1), F(1)}), L.e1);
  if (w & want_witnesses) {
    res.on_a = sp.center;
    res.on_a[axis] = pos ? F(sp.center[axis] - sp.radius) : F(sp.center[axis] + sp.radius);
    res.on_b = sp.center;
    res.on_b[axis] = pos ? F(box.center[axis] + box.extent[axis]) : F(box.center[axis] - box.extent[axis]);
  }
  return res;
}
}  // namespace detail

template <class F>
Proximity<F> proximity(const Sphere<F>& sp, const Box<F>& box, unsigned w = want_proximity) {
  check(sp, "sphere");
  check(box, "box");
  if constexpr (std::is_same_v<F, float>)
    return detail::rounded(proximity(detail::widened(sp), detail::widened(box), w));  // (decision.hpp, widened)
  else
    return with_products([&](auto mul) { return detail::proximity_dw<F, decltype(mul)>(sp, box, w); });
}

}  // namespace cdref::robust
