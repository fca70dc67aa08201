// cdref/robust/segment_sphere.hpp - segment-sphere (Section 3.1.3, Algorithm 3.2) that keeps
// its accuracy where the book loses it, for F = float, double, long double. Same signatures
// and results as cdref::book (intersect, proximity) and decide_closest (decision.hpp). At
// F = float every entry point runs the double version on the same inputs and rounds each value
// once (decision.hpp, widened).
// u is the unit roundoff, eta the smallest subnormal.
//
// Formulation (local coordinates of the sphere, as the book: s = source - c, t = target - c,
// r = t - s, delta = -s.r; x the point of the segment closest to the centre):
//  1. Exact differences: s, t and r = target - source are each kept exactly as hi + lo
//     pairs (two_sum). Inputs are scaled by 2^-e1 (e1 > 0 only within 2^4 of overflow), the
//     pairs and rho then by one power of two bringing the largest hi (or rho) into [1,2).
//  2. The branch, as the book: delta <= 0 iff s.r >= 0; delta >= |r|^2 iff t.r <= 0 (since
//     t = s + r); both products by dot2 over the 12 exact products of the pairs.
//  3. Endpoint branches (x = s or x = t, exact pairs): the classification's Q = |x|^2 - rho^2
//     by dot2_cert over 10 exact products. The witness on the segment (and `closest`) is the
//     source or the target itself: exact.
//  4. Interior branch: the foot x = s + (delta/|r|^2) r = (r x (s x r)) / |r|^2. For the
//     classification, the cross product w = s x r is formed by dot2 over 8 exact products per
//     component, so |w^ - w| <= u|w| + gamma_8^2 2 sqrt3 (1+u)^2 max|s_i| |r|; then x_i =
//     (r x w^)_i / |r|^2 (dot2 over 4 products per component, |r|^2 by dot2): no term of the
//     size of |s| is subtracted, and normwise
//       |x^ - x| <= 4.02u |x| + 226 u^2 max|s_i|     (w: u|x|; r x w: u; |r|^2: u; division: u),
//     and Q^ = |x^|^2 - rho^2 by dot2 with the bound below (decide_closest).
//  5. The values, from double words (bounded/eft.hpp, sphere_sphere.hpp): x is the endpoint's exact
//     pair, or the foot l = s - f r, f = s.r / |r|^2, of ray_sphere.hpp's quantities(), each
//     l_i a double word. Its step A: l^ = s - f^ r + e, |e| <= 33u^2 |s|, and f^ r is off by
//     |f^ - f| |r| <= 51u^2 |s| + 60u^2 |f||r| <= 111u^2 |s| along r, so the foot's position
//     is within 144u^2 |s|; along r it moves |x| only to second order, so Q = |x|^2 - rho^2
//     (the foot's -D) is within u^2 (56 (rho^2 + |x|^2) + 66 |x| |s|); at an endpoint c_dw's
//     55u^2 (|x|^2 + rho^2).
//       closest = c + x, rounded once (plus_dw): within 144u^2 |s| + u^2 (|x| + |closest_i|)
//         before the rounding (endpoints: the endpoint itself, exact);
//       distance/depth = +-Q / (|x| + rho) by div_pair (|x|: norm_dw, 18u^2; the quotient
//         30u^2 in all): within u^2 (86 (|x| + rho) + 66 |s|) before the rounding. The 66u^2
//         |s| (from the foot's 33u^2 |s|) dominates at range near tangency; where it could
//         exceed u/16 of the distance (3168u max|x_i| max|s_i| >= |Q^|), each l_i is formed
//         again from the exact products, f taken as exact (foot_exactly: u^2 |l_i| + 3e4
//         u^3 (|s_i| + |f r_i|)), and Q from it: then within u^2 (88 (|x| + rho)) + 1.2e5
//         u^3 |s| + (111u^2 |s|)^2 / (|x| + rho). Either way within u^2 88 (|x| + rho) + u
//         d / 16 + 1.2e5 u^3 |s| (+ the u^4 term), about an ulp of d unless d is below
//         ~2^-46 of |x| + rho. Where it could be (|q^| <= 1408u (|x|_1 + rho)^2), the value
//         comes from |x|^2 exactly instead (seg_sph_xx: the endpoint's |s|^2 or the foot's
//         |s x r|^2 / |r|^2 on GMP rationals, then sphere_gap, rational.hpp): within an ulp
//         (the double words' value was 169 ulps off at 2^-52 of the radius from tangency).
//         (A sign other than the classification's, possible only where it is uncertain,
//         gives 0.)
//       the witness on the sphere c + rho x/|x| (unit_dw, then along_dw): x's direction within
//         27u^2 + 144u^2 |s| / |x|, then 4u^2 max(|on_b_i|, rho) before the rounding; where
//         144u^2 |s| could exceed u/16 of |x| (the centre within 2304u |s| of the line), the
//         direction is that of r x (s x r) formed from the exact products
//         (perpendicular_exactly, below): within 27u^2 + 3e4 u^3 |s| / |x|.
//     Each is within 1.5 ulps of the truth unless the truth is below 2/u times that error.
//     The previous formulation took the values from x^ in F (4.02u |x|): 3.5e14 ulps of
//     distance at 2^-48 from tangency and 288 ulps of witness at p99 (`cdref campaign --query
//     segment-sphere --impl robust-double`).
//     x = 0 exactly (the segment passes through the centre: s = 0, t = 0, or w = 0 exactly,
//     decided by an exact expansion sum when dot2 cannot tell): depth = rho exactly, n = y/|y|,
//     y = r x e_i with e_i the axis of the smallest |r_i| (compared exactly on the pairs; e_x
//     when r = 0), as in the book; y's components are r's pairs, so n has 27u^2.
//
// proximity(), where the casts' filter below decides: the branch of step 2 first from the high
// parts alone (seg_sph_branch), and step 2's certified solve only where that cannot tell. For
// pairs a, r (|al_i| <= u|a_i|, |rl_i| <= u|r_i|), a.r differs from the highs' sum of products
// by at most (2u + u^2) M, M = sum |a_i r_i|, and that sum rounded by gamma_3 M plus eta/2 a
// product below the normal range: the sign of the computed value v is a.r's where |v| > 8u m +
// 4 eta (m = M computed; 8u covers 5.01u M with m's own rounding). Likewise each component of
// s x r against 8u (|s_j r_k| + |s_k r_j|) + 4 eta: where one is certainly nonzero the foot is
// not the centre (x != 0, step 3's exact test skipped). The branch is then step 2's exact one,
// and the values below are those of the same branch: only the classification's work is saved
// (it is the filter's). The full query on 2,000 uniform cases (standalone loop, 2026-11-29):
// 514 ns a case, 348 in the FMA copy (bounded/eft.hpp, with_fma), 239 with this and the powers of two
// written into the bits (Pow2, exp2_of); at 10^12 radii 646, 437, 311. With every exact
// product of the double words one fused multiply-add in that copy (with_products, where
// Dekker's split had still run inside it): 197 ns, and 264 at 10^12 radii (2026-11-29).
// decide_closest(), intersect() and proximity() first try the sphere casts' filter
// (ray_sphere.hpp, cast_filter on the segment): the segment meets the closed ball exactly when Algorithm 3.1's
// segment cast hits, so where the filter decides, its answer is this query's exact answer too
// (and the double words below, u^2 accurate, give the same value).
// decide_closest() otherwise: the book's intersect() at an exact type decides the sign of |x|^2 - rho^2
// for the exact branch. It is certain iff the branch tests are certain (dot2_cert on s.r
// and t.r, ray_sphere.hpp; r = 0 exactly is branch s) and the final sign is -- or, when the
// branch is not certain, if an endpoint is certainly inside the sphere (then so is the
// segment) or the line's foot certainly outside (the segment is no closer than its line): endpoints by
// dot2_cert of Q; interior by |Q^| > 2 (E_Q + E_x (2 nx + E_x)), E_x = 4.1u nx + 512 u^2 +
// 16 eta, nx = ||x^||_1 >= |x^|, E_Q dot2_cert's bound. Where that leaves the sign open (a
// band about u |x|^2 wide near tangency), the sphere casts' certificate on double words
// decides (ray_sphere.hpp, decide_cast: the same exact answer, a band u^2 wide); intersect()
// and proximity() classify as decide_closest() does. (decide_closest() past the filter tries
// decide_cast first and the closest point only where that is uncertain: the same answers and
// certificates, the u-wide evaluation skipped where the u^2-wide one decides.) (decide(Segment, Sphere) in
// ray_sphere.hpp certifies the cast's formulation; the two classifications are the same
// exact answer, Algorithms 3.1 and 3.2 agreeing at exact types, but their float values
// may differ where neither is certain, hence two names.)
#pragma once

#include <algorithm>
#include <cdref/primitives.hpp>
#include <cdref/results.hpp>
#include <cmath>

#include "decision.hpp"
#include <cdref/bounded/eft.hpp>
#include "rational.hpp"
#include "ray_sphere.hpp"
#include "sphere_sphere.hpp"

namespace cdref::robust {

using namespace cdref::eft;  // the error-free transformations (bounded/eft.hpp)

namespace detail {

template <class F>
struct SegSphLocal {
  F s[3], sl[3], t[3], tl[3], r[3], rl[3], rho;
  int scale = 0;
  bool exact = true;
  bool r_zero = false;
};

template <class F>
SegSphLocal<F> seg_sph_local(const Segment<F>& seg, const Sphere<F>& sp) {
  SegSphLocal<F> L;
  F m = sp.radius;
  for (int i = 0; i < 3; ++i)
    m = std::max({m, std::fabs(seg.source[i]), std::fabs(seg.target[i]), std::fabs(sp.center[i])});
  const int e1 = overflow_guard(m);
  F top = scale_down(sp.radius, e1, L.exact);
  F rtop = 0;
  Pair<F> S[3], T[3], R[3];
  for (int i = 0; i < 3; ++i) {
    const F a = scale_down(seg.source[i], e1, L.exact);
    const F b = scale_down(seg.target[i], e1, L.exact);
    const F c = scale_down(sp.center[i], e1, L.exact);
    S[i] = two_sum(a, F(-c));
    T[i] = two_sum(b, F(-c));
    R[i] = two_sum(b, F(-a));
    top = std::max({top, std::fabs(S[i].hi), std::fabs(T[i].hi), std::fabs(R[i].hi)});
    rtop = std::max(rtop, std::fabs(R[i].hi));
  }
  L.r_zero = rtop == F(0);
  const int e2 = top > F(0) ? exponent_of(top) : 0;
  const Pow2<F> down(e2);  // x 2^-e2, as ldexp gives it
  for (int i = 0; i < 3; ++i) {
    L.s[i] = down(S[i].hi);
    L.sl[i] = down(S[i].lo);
    L.t[i] = down(T[i].hi);
    L.tl[i] = down(T[i].lo);
    L.r[i] = down(R[i].hi);
    L.rl[i] = down(R[i].lo);
  }
  L.rho = scale_down(scale_down(sp.radius, e1, L.exact), e2, L.exact);
  L.scale = e1 + e2;
  return L;
}

// The sign of a.r for pairs a, r from the high parts (header: proximity's branch), or 0 where
// it is not certain.
template <class F>
int dot_sign_of_highs(const F (&a)[3], const F (&r)[3]) {
  const F v = F(F(a[0] * r[0]) + F(a[1] * r[1])) + F(a[2] * r[2]);
  const F m = F(F(std::fabs(a[0] * r[0])) + std::fabs(a[1] * r[1])) + std::fabs(a[2] * r[2]);
  const F e = F(F(8) * unit_roundoff<F>()) * m + F(4) * std::numeric_limits<F>::denorm_min();
  return int(v > e) - int(v < -e);
}
// a.b for exact pairs a, b.
template <class F>
Bounded<F> dot_pairs(const F (&a)[3], const F (&al)[3], const F (&b)[3], const F (&bl)[3]) {
  return dot2_cert({a[0], a[0], al[0], al[0], a[1], a[1], al[1], al[1], a[2], a[2], al[2], al[2]},
                   {b[0], bl[0], b[0], bl[0], b[1], bl[1], b[1], bl[1], b[2], bl[2], b[2], bl[2]}, 96);
}

// |p|^2 - rho^2 for an exact pair p.
template <class F>
Bounded<F> q_pairs(const F (&v)[3], const F (&l)[3], F rho) {
  return dot2_cert({v[0], v[1], v[2], F(2 * l[0]), F(2 * l[1]), F(2 * l[2]), l[0], l[1], l[2], rho},
                   {v[0], v[1], v[2], v[0], v[1], v[2], l[0], l[1], l[2], F(-rho)}, 64);
}

enum class Branch { source, target, interior };

template <class F>
struct SegSphSolved {
  Branch branch = Branch::source;
  bool branch_certain = false;
  bool x_zero = false;  // interior foot exactly at the centre
  F x[3] = {0, 0, 0};   // interior foot (scaled)
  Bounded<F> q{0, 0};   // |x|^2 - rho^2 (scaled^2)
};

// Step 2's branch from the high parts where that is certain, and for the interior branch that the
// foot is not the centre (header); false where either is open.
template <class F>
bool seg_sph_branch(const SegSphLocal<F>& L, Branch& b) {
  if (L.r_zero) return b = Branch::source, true;
  const int sr = dot_sign_of_highs(L.s, L.r);
  if (sr > 0) return b = Branch::source, true;
  if (sr == 0) return false;
  const int tr = dot_sign_of_highs(L.t, L.r);
  if (tr == 0) return false;
  if (tr < 0) return b = Branch::target, true;
  b = Branch::interior;
  const F u8 = F(8) * unit_roundoff<F>(), e0 = F(4) * std::numeric_limits<F>::denorm_min();
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    const F p = L.s[j] * L.r[k], q = L.s[k] * L.r[j];
    if (std::fabs(F(p - q)) > u8 * F(std::fabs(p) + std::fabs(q)) + e0) return true;
  }
  return false;
}

template <class F>
SegSphSolved<F> seg_sph_solve(const SegSphLocal<F>& L) {
  SegSphSolved<F> out;
  if (L.r_zero) {
    out.branch = Branch::source;
    out.branch_certain = true;
  } else {
    const Bounded<F> sr = dot_pairs(L.s, L.sl, L.r, L.rl);
    if (sr.value >= F(0)) {
      out.branch = Branch::source;
      out.branch_certain = sr.sign() > 0;
    } else {
      const Bounded<F> tr = dot_pairs(L.t, L.tl, L.r, L.rl);
      out.branch = tr.value <= F(0) ? Branch::target : Branch::interior;
      out.branch_certain = sr.sign() < 0 && tr.sign() != 0;
    }
  }
  if (out.branch == Branch::source) {
    out.q = q_pairs(L.s, L.sl, L.rho);
    return out;
  }
  if (out.branch == Branch::target) {
    out.q = q_pairs(L.t, L.tl, L.rho);
    return out;
  }
  // interior: w = s x r, x = (r x w) / |r|^2
  const F *s = L.s, *sl = L.sl, *r = L.r, *rl = L.rl;
  F w[3];
  bool w_unknown = true;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    const Bounded<F> wi =
        dot2_cert({s[j], s[j], sl[j], sl[j], F(-s[k]), F(-s[k]), F(-sl[k]), F(-sl[k])},
                  {r[k], rl[k], r[k], rl[k], r[j], rl[j], r[j], rl[j]});
    w[i] = wi.value;
    if (wi.sign() != 0) w_unknown = false;
  }
  if (w_unknown) {  // every component within its bound of 0: is s x r exactly 0?
    bool zero = true;
    for (int i = 0; i < 3 && zero; ++i) {
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      const F a[4] = {s[j], s[j], sl[j], sl[j]}, b[4] = {r[k], rl[k], r[k], rl[k]};
      const F c[4] = {s[k], s[k], sl[k], sl[k]}, d[4] = {r[j], rl[j], r[j], rl[j]};
      F terms[16];
      for (int m = 0; m < 4; ++m) {
        const Pair<F> p = two_prod(a[m], b[m]);
        const Pair<F> q = two_prod(c[m], d[m]);
        terms[4 * m] = p.hi;
        terms[4 * m + 1] = p.lo;
        terms[4 * m + 2] = F(-q.hi);
        terms[4 * m + 3] = F(-q.lo);
      }
      zero = exact_sign_of_sum(terms) == 0;
    }
    if (zero) {
      out.x_zero = true;
      out.q = {F(-(L.rho * L.rho)), F(0)};  // exact up to one rounding: sign certain
      if (L.rho == F(0)) out.q = {F(0), F(0)};
      return out;
    }
  }
  const F rr = dot2({r[0], r[1], r[2], F(2 * rl[0]), F(2 * rl[1]), F(2 * rl[2]), rl[0], rl[1], rl[2]},
                    {r[0], r[1], r[2], r[0], r[1], r[2], rl[0], rl[1], rl[2]});
  F nx = 0;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    out.x[i] = dot2({r[j], rl[j], F(-r[k]), F(-rl[k])}, {w[k], w[k], w[j], w[j]}) / rr;
    nx += std::fabs(out.x[i]);
  }
  const Bounded<F> q = dot2_cert({out.x[0], out.x[1], out.x[2], L.rho}, {out.x[0], out.x[1], out.x[2], F(-L.rho)});
  const F u = unit_roundoff<F>();
  constexpr F eta16 = F(16) * std::numeric_limits<F>::denorm_min();  // constexpr: not loaded at run time
  const F ex = F(4.1) * u * nx + F(512) * u * u + eta16;
  out.q = {q.value, F(2) * (q.err + ex * (F(2) * nx + ex))};
  return out;
}

// s_i - f r_i for double words s_i, f, r_i, f taken as exact: the ten parts of the exact
// products and s_i summed as if in triple precision (sum_k, K = 3), then the residual the
// same way: a double word within u^2 |l_i| + 3e4 u^3 (|s_i| + |f r_i|) of it (two SumK
// bounds, the second on a residual of at most (u + 3 gamma_9^2)|l_i| + gamma_18^3 S).
// r x (s x r) for exact pairs s, r (x's direction: the foot times |r|^2, exactly
// perpendicular to r). Each component of w = s x r from the sixteen parts of its eight exact
// products summed as in triple precision, then the residual (as foot_exactly: within
// u^2 |w_i| + 3e4 u^3 |s||r|, however near the line the centre lies), then r x w on double
// words (no cancellation beyond u^2 |r||w|: r is perpendicular to w). Its direction is x's
// within 27u^2 + 3e4 u^3 |s| / |x|, where the foot's 144u^2 |s| / |x| is too coarse.
template <class Mul = SplitProduct, class F>
void perpendicular_exactly(const Pair<F> (&s)[3], const Pair<F> (&r)[3], Pair<F> (&y)[3]) {
  Pair<F> w[3];
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    F p[17], q[17];
    int n = 0;
    const auto add = [&](F a, F b, bool minus) {
      const Pair<F> t = Mul::prod(a, b);
      p[n++] = minus ? F(-t.hi) : t.hi;
      p[n++] = minus ? F(-t.lo) : t.lo;
    };
    add(s[j].hi, r[k].hi, false), add(s[j].hi, r[k].lo, false), add(s[j].lo, r[k].hi, false), add(s[j].lo, r[k].lo, false);
    add(s[k].hi, r[j].hi, true), add(s[k].hi, r[j].lo, true), add(s[k].lo, r[j].hi, true), add(s[k].lo, r[j].lo, true);
    p[16] = F(0);
    for (int m = 0; m < 17; ++m) q[m] = p[m];
    const F hi = sum_k(p, 3);
    q[16] = -hi;
    w[i] = two_sum(hi, sum_k(q, 3));
  }
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    const Pair<F> a = mul_pair<Mul>(r[j], w[k]), b = mul_pair<Mul>(r[k], w[j]);
    const Pair<F> t = two_sum(a.hi, F(-b.hi));
    y[i] = fast_two_sum(t.hi, F(t.lo + F(a.lo - b.lo)));
  }
}

// The witness direction through the centre: y = r x e_i, i the axis of the smallest |r_i|
// (exact comparison of the pairs; first on ties), e_x when r = 0.
template <class Mul = SplitProduct, class F>
void through_centre_direction(const SegSphLocal<F>& L, Pair<F> (&n)[3]) {
  if (L.r_zero) {
    n[0] = {F(1), F(0)}, n[1] = {F(0), F(0)}, n[2] = {F(0), F(0)};
    return;
  }
  auto abs_less = [&](int a, int b) {  // |r_a| < |r_b| exactly
    F ah = L.r[a], al = L.rl[a], bh = L.r[b], bl = L.rl[b];
    if (ah < F(0)) ah = -ah, al = -al;
    if (bh < F(0)) bh = -bh, bl = -bl;
    return ah < bh || (ah == bh && al < bl);
  };
  int best = 0;
  for (int i = 1; i < 3; ++i)
    if (abs_less(i, best)) best = i;
  const int j = (best + 1) % 3, k = (best + 2) % 3;
  // r x e_best: component j = r_k, component k = -r_j, component best = 0
  F h[3], l[3];
  h[best] = F(0), l[best] = F(0);
  h[j] = L.r[k], l[j] = L.rl[k];
  h[k] = F(-L.r[j]), l[k] = F(-L.rl[j]);
  unit_dw<Mul>(h, l, n);
}

}  // namespace detail

namespace detail {

// decide_closest() past the filter, from the solved branch (see the header). Where its bound
// in F leaves the sign open, the sphere casts' certificate on double words decides
// (ray_sphere.hpp, decide_cast: the segment meets the ball exactly when Algorithm 3.1's cast
// hits, and its band near tangency is u^2 wide where the foot in F leaves one u wide: at
// 2^-52 of the radius from tangency every case of the near-tangent family was uncertain).
template <class F>
Decision closest_decision(const Segment<F>& seg, const Sphere<F>& sp, const SegSphLocal<F>& L,
                          const SegSphSolved<F>& R) {
  const bool exact_zero = R.q.value == F(0) && R.q.err == F(0);
  bool certain = R.branch_certain && (exact_zero || R.q.sign() != 0);
  // An uncertain branch still decides when the answer does not depend on it: an endpoint
  // certainly inside the sphere means the segment meets it; the line's foot certainly
  // outside means the segment (farther from the centre than its line) does not.
  if (!R.branch_certain)
    certain = R.branch == Branch::interior ? R.q.sign() > 0 : (exact_zero || R.q.sign() < 0);
  const Decision own = within_range(Decision{R.q.value <= F(0), L.exact && certain}, seg, sp);
  if (own.certain) return own;
  Pair<F> s[3], r[3];
  diff_pairs(seg.source, sp.center, s);
  diff_pairs(seg.target, seg.source, r);
  const Decision words = within_range(decide_cast(s, r, sp, true), seg, sp);
  return words.certain ? words : own;
}

}  // namespace detail

// The book's intersect(Segment, Sphere) with its certificate (see the header).
template <class F>
[[gnu::noinline]] Decision decide_closest_checked(const Segment<F>& seg, const Sphere<F>& sp) {
  check(seg, "segment");
  check(sp, "sphere");
  // (at F = float every entry point runs at double on the same inputs: decision.hpp, widened)
  if constexpr (std::is_same_v<F, float>) return decide_closest_checked(detail::widened(seg), detail::widened(sp));
  if (const int f = detail::cast_filter(seg.source, seg.target, sp, true)) return Decision{f > 0, true};
  // The sphere casts' double words before the closest point: where they are certain their value
  // is the exact answer, which is what closest_decision() returns wherever it is certain itself,
  // so the answer and its certainty are unchanged; past the filter (near tangency, or out of its
  // range) they are nearly always certain, and the closest point's double words, whose band is
  // u wide, are then not computed. Standalone, 4000 cases each (2-core AMD EPYC, 2026-11-28):
  // 2^-52 from tangency 738 -> 278 ns a case, 10^12 radii within 1e-9 of tangency 495 -> 267
  // ns, every answer and certificate the same.
  Pair<F> s[3], r[3];
  detail::diff_pairs(seg.source, sp.center, s);
  detail::diff_pairs(seg.target, seg.source, r);
  if (const Decision words = within_range(detail::decide_cast(s, r, sp, true), seg, sp); words.certain) return words;
  const auto L = detail::seg_sph_local(seg, sp);
  return detail::closest_decision(seg, sp, L, detail::seg_sph_solve(L));
}
// (at double the filter before the input checks, as the casts' decide(): ray_sphere.hpp)
template <class F>
Decision decide_closest(const Segment<F>& seg, const Sphere<F>& sp) {
  if (const int f = detail::unchecked_filter(seg.source, seg.target, sp, true)) [[likely]]
    return Decision{f > 0, true};
  return decide_closest_checked(seg, sp);
}

// (the same answer as decide_closest(): the filter, the branch's sign in F, the double words)
template <class F>
bool intersect(const Segment<F>& seg, const Sphere<F>& sp) {
  return decide_closest(seg, sp).value;
}

namespace detail {
// |x|^2 exactly, x the closest point relative to the centre (scaled, step 5): the endpoint's
// |s|^2, or the foot's |s x r|^2 / |r|^2 (x = s - (s.r / |r|^2) r, so |x|^2 = |s|^2 - (s.r)^2 /
// |r|^2), from the exact pairs.
template <class F>
void seg_sph_xx(const LocalDW<F>& D, bool interior, Rational& xx) {
  RVec s, r;
  for (int i = 0; i < 3; ++i) {
    set_pair(s[i], D.s[i].hi, D.s[i].lo);
    set_pair(r[i], D.r[i].hi, D.r[i].lo);
  }
  if (!interior) return dot_vec(xx, s, s);
  RVec c;
  cross_vec(c, s, r);
  Rational rr;
  dot_vec(xx, c, c);
  dot_vec(rr, r, r);
  mpq_div(xx.q, xx.q, rr.q);
}
}  // namespace detail

namespace detail {
template <class Mul = SplitProduct, class F>
Proximity<F> proximity_dw(const Segment<F>& seg, const Sphere<F>& sp, unsigned w) {
  Proximity<F> res;
  const auto L = detail::seg_sph_local(seg, sp);
  // as decide_closest(); where the filter decides, the branch from the highs first (header)
  const int f = detail::cast_filter(seg.source, seg.target, sp, true);
  detail::SegSphSolved<F> R;
  if (f == 0 || !detail::seg_sph_branch(L, R.branch)) R = detail::seg_sph_solve(L);
  res.intersect = f != 0 ? f > 0 : detail::closest_decision(seg, sp, L, R).value;
  if (!(w & (want_closest | want_distance | want_depth | want_witnesses))) return res;
  // x, the closest point relative to the centre (scaled), as double words, and q = |x|^2 -
  // rho^2 (steps 3-5): an endpoint's exact pair and c_dw; the line's foot l and -D from
  // ray_sphere.hpp's quantities()
  const detail::Branch b = R.branch;
  detail::LocalDW<F> D{};
  for (int i = 0; i < 3; ++i) {
    D.s[i] = b == detail::Branch::target ? Pair<F>{L.t[i], L.tl[i]} : Pair<F>{L.s[i], L.sl[i]};
    D.r[i] = {L.r[i], L.rl[i]};
  }
  D.rho = L.rho;
  Pair<F> x[3];
  Pair<F> q{F(0), F(0)};
  bool near_line = false;
  if (R.x_zero) {
    for (auto& xi : x) xi = {F(0), F(0)};
  } else if (b == detail::Branch::interior) {
    const auto Q = detail::quantities<Mul>(D);
    for (int i = 0; i < 3; ++i) x[i] = Q.l[i];
    q = {F(-Q.D.hi), F(-Q.D.lo)};
    // the foot's rounding (33u^2 |s| per component) moves q by up to 66u^2 |x||s|: where
    // that could exceed u|q|/16 (at range, near tangency), the foot is formed again from the
    // exact products (foot_exactly) and q from it
    F sn = 0, xn = 0;
    for (int i = 0; i < 3; ++i) {
      sn = std::max(sn, std::fabs(D.s[i].hi));
      xn = std::max(xn, std::fabs(x[i].hi));
    }
    const F u = detail::unit_roundoff<F>();
    // where the centre lies so near the line that the foot's 144u^2 |s| could exceed u/16 of
    // |x| (|x| < 2304u |s|), the sphere's witness takes its direction from r x (s x r) instead
    near_line = xn < F(F(2304) * u) * sn;
    if (F(F(3168) * u) * F(xn * sn) >= std::fabs(q.hi)) {
      for (int i = 0; i < 3; ++i) x[i] = detail::foot_exactly<Mul>(D.s[i], Q.f, D.r[i]);
      const Pair<F> d2 = detail::rho2_minus_norm2<F, Mul>(D.rho, x);
      q = {F(-d2.hi), F(-d2.lo)};
    }
  } else {
    for (int i = 0; i < 3; ++i) x[i] = D.s[i];
    q = detail::c_dw<Mul>(D);
  }
  Vec3<F> xw;  // the closest point, world coordinates
  if (b == detail::Branch::source)
    xw = seg.source;
  else if (b == detail::Branch::target)
    xw = seg.target;
  else
    for (int i = 0; i < 3; ++i) xw[i] = R.x_zero ? sp.center[i] : detail::plus_dw(sp.center[i], x[i], L.scale);
  if (w & want_closest) res.closest = xw;
  if (!(w & (want_distance | want_depth | want_witnesses))) return res;

  const F xh[3] = {x[0].hi, x[1].hi, x[2].hi}, xl[3] = {x[0].lo, x[1].lo, x[2].lo};
  const bool x_zero = xh[0] == F(0) && xh[1] == F(0) && xh[2] == F(0);
  if (w & (want_distance | want_depth)) {
    if (x_zero) {  // the segment passes through the centre: depth rho, exactly
      if (w & want_depth) res.depth = sp.radius;
    } else {
      // +-q / (|x| + rho), the sign the classification's (a value of the other sign, where
      // the classification is uncertain, is 0)
      // where the double words' error could exceed u/16 of the value (|q| <= 1408u (|x| +
      // rho)^2, the u^2 88 (|x| + rho) term of step 5: the distance within 2^-42.5 of |x| +
      // rho), the value from |x|^2 exactly (seg_sph_xx, sphere_gap: within an ulp)
      const F u = detail::unit_roundoff<F>();
      const F reach = F(F(F(std::fabs(xh[0]) + std::fabs(xh[1])) + std::fabs(xh[2])) + L.rho);
      if (std::fabs(q.hi) <= F(F(1408) * u) * F(reach * reach)) {
        detail::Rational xx;
        detail::seg_sph_xx(D, b == detail::Branch::interior, xx);
        const F g = detail::sphere_gap(xx, L.rho);
        if (res.intersect ? g < F(0) : g > F(0))
          (res.intersect ? res.depth : res.distance) = std::ldexp(std::fabs(g), L.scale);
      } else {
        const Pair<F> len = detail::norm_dw<Mul>(xh, xl);
        const Pair<F> t = two_sum(len.hi, L.rho);
        const Pair<F> den = fast_two_sum(t.hi, F(t.lo + len.lo));
        const F num = res.intersect ? F(-q.hi) : q.hi;
        if (num > F(0)) {
          const Pair<F> v = div_pair<Mul>(res.intersect ? Pair<F>{F(-q.hi), F(-q.lo)} : q, den);
          (res.intersect ? res.depth : res.distance) = Pow2<F>(-L.scale)(F(v.hi + v.lo));
        }
      }
      if (!(w & want_distance)) res.distance = F(0);
      if (!(w & want_depth)) res.depth = F(0);
    }
  }
  if (w & want_witnesses) {
    Pair<F> n[3];
    if (x_zero) {
      detail::through_centre_direction<Mul>(L, n);
    } else if (near_line) {
      Pair<F> y[3];
      detail::perpendicular_exactly<Mul>(D.s, D.r, y);
      const F yh[3] = {y[0].hi, y[1].hi, y[2].hi}, yl[3] = {y[0].lo, y[1].lo, y[2].lo};
      detail::unit_dw<Mul>(yh, yl, n);
    } else {
      detail::unit_dw<Mul>(xh, xl, n);
    }
    res.on_a = xw;
    for (int i = 0; i < 3; ++i) res.on_b[i] = detail::along_dw(sp.center[i], sp.radius, n[i]);
  }
  return res;
}
}  // namespace detail

template <class F>
Proximity<F> proximity(const Segment<F>& seg, const Sphere<F>& sp, unsigned w = want_proximity) {
  check(seg, "segment");
  check(sp, "sphere");
  if constexpr (std::is_same_v<F, float>)
    return detail::rounded(proximity(detail::widened(seg), detail::widened(sp), w));
  else
    return with_products([&](auto mul) { return detail::proximity_dw<decltype(mul)>(seg, sp, w); });
}

}  // namespace cdref::robust
