// cdref/bounded/word_bounds.hpp - double words that carry a rigorous bound on their distance from
// an exact value, and the range in which the double-word stages take a pair of primitives.
// Shared by the oracle's correctly rounded lambda_enter (exact/cdref/oracle/enter_triangle.hpp,
// whose header derives cross_term, dot_words and the bounds' allowance for underflow), the
// filters' double-word stages (cdref/filters/box_cast_words.hpp, sat_words.hpp, triangle_words.hpp,
// obb_face.hpp) and the robust tier's first looks.
//
// A Word {v, e}: v = v.hi + v.lo, normalized (v.hi = fl(v.hi + v.lo)), and the exact value
// within e of it. Each operation below rounds a few low-order terms, each off by at most u of
// its computed magnitude (fl(x) = x / (1 + delta), |delta| <= u), and propagates its operands'
// bounds; the bound itself is computed from nonnegative terms and enlarged by (1 + 4u) or
// (1 + 8u) for its own roundings, and by a multiple of 2^-1022 for roundings that underflow
// (each off by at most 2^-1075).
//   add_words(x, y, s)  x + s y, s = +-1: the highs by Two-Sum, t = fl(x.lo + s y.lo) and
//                       r = fl(S.lo + t) rounded (u |t| + u |r|), renormalized exactly:
//                       e = x.e + y.e + 2u (|t| + |r|);
//   mul_words(x, y)     the highs' product exact (Mul), a = fl(x.hi y.lo), b = fl(x.lo y.hi),
//                       c = fl(a + b), l = fl(P.lo + c) rounded, x.lo y.lo dropped, and
//                       |XY - x^ y^| <= |x^| y.e + (|y^| + y.e) x.e:
//                       e = 2u (|a| + |b| + |c| + |l|) + |x.lo y.lo| + |x^| y.e + (|y^| + y.e) x.e;
//   scale_word(x, h)    x h for a double h: the highs' product exact, x.lo h rounded;
//   sign_of(x)          certain when magnitude_lo(x) > 0: |x.hi| - |x.lo| exceeds e (then the
//                       exact value has the sign of x.hi), `unknown` otherwise (an exact 0 too:
//                       every bound here is positive).
//
#pragma once

#include <algorithm>
#include <cdref/primitives.hpp>
#include <cdref/bounded/eft.hpp>
#include <cdref/bounded/scaling.hpp>
#include <cmath>

namespace cdref::word_bounds {

using eft::Pair;

// sign_of's answer where the sign is not certain: the filters' `unknown` (cdref/filters/).
inline constexpr int unknown = 2;

// The bounds' allowance for underflow, per product or quotient that may leave the normal
// range: the derivations need the smallest subnormal, 2^-1074, and take the smallest normal
// number instead (larger, so still a bound): an addition with a subnormal operand can cost a
// microcode assist on x86 (measured standalone, one run each: an oriented-box ray cast at
// 10^12, 462 -> 423 ns a call).
constexpr double under = 0x1p-1022;

constexpr double uu = 0x1p-53, eta = under;

// A double word v (v.hi = fl(v.hi + v.lo)) whose exact value lies within e of v.hi + v.lo.
struct Word {
  Pair<double> v;
  double e;
};

// The exact products as a policy (bounded/eft.hpp: Dekker's split, or one fused multiply-add;
// where the operands lie in [2^-600, 2^600] or one is zero, as in the oracle's enter paths, both
// give the same pair; the oriented-box casts' ObbWords has no lower range guard, and a product
// whose error term underflows may differ between the two by less than the 2^-1022 each bound
// allows for it). A build without -mfma has std::fma as a library call, so the paths built on
// these (oracle/enter_sphere.hpp, enter_obb.hpp and enter_triangle.hpp, about 7, 60 and 20
// products a call; the oriented-box casts' classification, filters/box_cast_words.hpp) are
// compiled twice and the fused copy is taken where the CPU has the instruction (eft::cpu_fma).
using eft::FusedProduct;
using eft::SplitProduct;

// a_j b_k - a_k b_j for exact pairs: the products of the high parts exact, the four cross
// terms and the lows in double (7 terms, 6 additions, 4 rounded products: 8u of their
// magnitudes), the lows' products dropped (<= 2u^2 (|a_j b_k| + |a_k b_j|)).
template <class Mul = SplitProduct>
inline Word cross_term(const Pair<double>& aj, const Pair<double>& bk, const Pair<double>& ak, const Pair<double>& bj) {
  using std::fabs;
  const Pair<double> P1 = Mul::prod(aj.hi, bk.hi), P2 = Mul::prod(ak.hi, bj.hi);
  const Pair<double> S = eft::two_sum(P1.hi, -P2.hi);
  const double a1 = aj.hi * bk.lo, b1 = aj.lo * bk.hi, a2 = ak.hi * bj.lo, b2 = ak.lo * bj.hi;
  const double lo = ((S.lo + P1.lo) - P2.lo) + ((a1 + b1) - (a2 + b2));
  const double M = fabs(P1.hi) + fabs(P2.hi);
  return {eft::two_sum(S.hi, lo),
          8 * uu * ((fabs(S.lo) + fabs(P1.lo) + fabs(P2.lo)) + ((fabs(a1) + fabs(b1)) + (fabs(a2) + fabs(b2)))) +
              2 * uu * uu * M * (1 + 4 * uu) + 16 * eta};
}
// a x b for doubles (an oriented box's axes): each component p - q of two exact products, its
// three low terms summed in double (2 additions: gamma_2 < 3u of their magnitudes; a product
// whose low term underflows is off by at most 2^-1075).
template <class Mul = SplitProduct>
inline void cross_of_doubles(const Vec3<double>& a, const Vec3<double>& b, Word (&n)[3]) {
  using std::fabs;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    const Pair<double> P1 = Mul::prod(a[j], b[k]), P2 = Mul::prod(a[k], b[j]);
    const Pair<double> S = eft::two_sum(P1.hi, -P2.hi);
    const double lo = (S.lo + P1.lo) - P2.lo;
    n[i] = {eft::two_sum(S.hi, lo), 3 * uu * ((fabs(S.lo) + fabs(P1.lo)) + fabs(P2.lo)) + 4 * eta};
  }
}
// x . y for doubles: the three products exact, summed by two_sum; their five low terms (the
// products' and the two sums') summed in double (4 additions: gamma_4 < 5u of their
// magnitudes; a product whose low term underflows is off by at most 2^-1075).
template <class Mul = SplitProduct>
inline Word dot_of_doubles(const double (&x)[3], const double (&y)[3]) {
  using std::fabs;
  const Pair<double> p0 = Mul::prod(x[0], y[0]), p1 = Mul::prod(x[1], y[1]), p2 = Mul::prod(x[2], y[2]);
  const Pair<double> s1 = eft::two_sum(p0.hi, p1.hi), s2 = eft::two_sum(s1.hi, p2.hi);
  const double lo = ((p0.lo + p1.lo) + (p2.lo + s1.lo)) + s2.lo;
  return {eft::two_sum(s2.hi, lo),
          5 * uu * (((fabs(p0.lo) + fabs(p1.lo)) + (fabs(p2.lo) + fabs(s1.lo))) + fabs(s2.lo)) + 4 * eta};
}
template <class Mul = SplitProduct>
inline void cross_words(const Pair<double> (&a)[3], const Pair<double> (&b)[3], Word (&n)[3]) {
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    n[i] = cross_term<Mul>(a[j], b[k], a[k], b[j]);
  }
}

// x . y for double words x_i (within ex_i of the exact) and y_i: the products of the high
// parts exact, summed by two_sum; the lows (11 terms: 10 additions, 6 rounded products) in
// double; the lows' products x.lo y.lo dropped; x^, y^ against the exact x, y propagated.
template <class Mul = SplitProduct>
inline Word dot_words(const Pair<double> (&x)[3], const double (&ex)[3], const Word (&y)[3]) {
  using std::fabs;
  const Pair<double> Q0 = Mul::prod(x[0].hi, y[0].v.hi), Q1 = Mul::prod(x[1].hi, y[1].v.hi),
                     Q2 = Mul::prod(x[2].hi, y[2].v.hi);
  const Pair<double> H1 = eft::two_sum(Q0.hi, Q1.hi), H2 = eft::two_sum(H1.hi, Q2.hi);
  double lows = (Q0.lo + Q1.lo) + (Q2.lo + (H1.lo + H2.lo));
  double lows_abs = fabs(Q0.lo) + fabs(Q1.lo) + fabs(Q2.lo) + fabs(H1.lo) + fabs(H2.lo);
  double prop = 0, dropped = 0;
  for (int i = 0; i < 3; ++i) {
    const double a = x[i].hi * y[i].v.lo, b = x[i].lo * y[i].v.hi;
    lows += a + b;
    lows_abs += fabs(a) + fabs(b);
    dropped += fabs(x[i].lo) * fabs(y[i].v.lo);
    prop += (fabs(x[i].hi) + fabs(x[i].lo)) * y[i].e + (fabs(y[i].v.hi) + fabs(y[i].v.lo) + y[i].e) * ex[i];
  }
  return {eft::two_sum(H2.hi, lows), (12 * uu * lows_abs + 1.01 * (dropped + prop)) * (1 + 8 * uu) + 64 * eta};
}

// A lower bound of |x| for the word x (0 when its sign is not certain), and its sign.
inline double magnitude_lo(const Word& x) {
  return std::max(0.0, ((std::fabs(x.v.hi) - std::fabs(x.v.lo)) * (1 - 2 * uu) - x.e) * (1 - 2 * uu));
}

template <class Mul = SplitProduct>
inline Word scale_word(const Word& x, double h) {
  using std::fabs;
  const Pair<double> P = Mul::prod(x.v.hi, h);
  const double hl = x.v.lo * h;
  return {eft::two_sum(P.hi, P.lo + hl), (x.e * fabs(h) + 2 * uu * (fabs(P.lo) + fabs(hl))) * (1 + 4 * uu) + 4 * eta};
}
inline Word add_words(const Word& x, const Word& y, double sg) {
  using std::fabs;
  const Pair<double> S = eft::two_sum(x.v.hi, sg * y.v.hi);
  const double t = x.v.lo + sg * y.v.lo, r = S.lo + t;
  return {eft::two_sum(S.hi, r), (x.e + y.e + 2 * uu * (fabs(t) + fabs(r))) * (1 + 4 * uu)};
}
template <class Mul = SplitProduct>
inline Word mul_words(const Word& x, const Word& y) {
  using std::fabs;
  const Pair<double> P = Mul::prod(x.v.hi, y.v.hi);
  const double a = x.v.hi * y.v.lo, b = x.v.lo * y.v.hi, c = a + b, l = P.lo + c;
  const double ax = fabs(x.v.hi) + fabs(x.v.lo), ay = fabs(y.v.hi) + fabs(y.v.lo);
  const double e = 2 * uu * (((fabs(a) + fabs(b)) + fabs(c)) + fabs(l)) + fabs(x.v.lo) * fabs(y.v.lo) + ax * y.e +
                   (ay + y.e) * x.e;
  return {eft::two_sum(P.hi, l), e * (1 + 8 * uu) + 8 * eta};
}
inline int sign_of(const Word& x) { return magnitude_lo(x) > 0 ? (x.v.hi > 0 ? 1 : -1) : unknown; }
inline Word negated(const Word& x) { return {{-x.v.hi, -x.v.lo}, x.e}; }
// The order of two normalized pairs by value (hi first, then lo).
inline bool pair_less(const Pair<double>& a, const Pair<double>& b) { return a.hi < b.hi || (a.hi == b.hi && a.lo < b.lo); }
// |x|, min and max need no decision: each is 1-Lipschitz, so the computed value with the larger
// bound encloses the exact result.
inline Word abs_word(const Word& w) { return pair_less(w.v, {0.0, 0.0}) ? negated(w) : w; }
inline Word min_word(const Word& a, const Word& b) { return {pair_less(b.v, a.v) ? b.v : a.v, std::max(a.e, b.e)}; }
inline Word max_word(const Word& a, const Word& b) { return {pair_less(a.v, b.v) ? b.v : a.v, std::max(a.e, b.e)}; }
// The pair of primitives as the double-word stages take it (sat_words.hpp, triangle_words.hpp):
// where the largest input (a length: points, centres, extents, radii; an oriented box's axes are
// not scaled) lies beyond [2^-100, 2^100], both scaled by the power of two that brings it to
// [1, 2) (bounded/scaling.hpp, scale_of: kept only where scaling back gives the inputs again, so
// the scaling is exact); false where an input is still beyond 2^100 after it, or not finite (an
// oriented box's axes included), and the stage then leaves the case to the next.
template <class A, class B>
bool in_word_range(const A& a, const B& b, A& as, B& bs) {
  double m = 0;
  scaling::largest(a, m);
  scaling::largest(b, m);
  double big = 0;
  if (m >= 0x1p-100 && m <= 0x1p100) {  // no scaling: the lengths are in range as they are
    as = a;
    bs = b;
    big = m;
  } else {
    const scaling::Scale sc = scaling::scale_of(a, b);
    as = scaling::scaled(a, sc);
    bs = scaling::scaled(b, sc);
    scaling::largest(as, big);
    scaling::largest(bs, big);
  }
  if constexpr (std::is_same_v<B, OrientedBox<double>>)
    for (int k = 0; k < 3; ++k) scaling::largest(bs.axis[k], big);
  if constexpr (std::is_same_v<A, OrientedBox<double>>)
    for (int k = 0; k < 3; ++k) scaling::largest(as.axis[k], big);
  return big <= 0x1p100;  // NaN and infinities fail
}

}  // namespace cdref::word_bounds
