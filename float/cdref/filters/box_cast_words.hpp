// cdref/filters/box_cast_words.hpp - the second stage of the casts on a box: Algorithm 3.3's
// signs on double words with rigorous bounds (cdref/bounded/word_bounds.hpp), after the first
// stage's signs in double (box_cast_filter.hpp) leave a case undecided.
//
// On an oriented box, in face coordinates.
// The first stage (box_cast_filter.hpp, ObbFilter) decides the cast from the signs of the
// outcodes Y_i -+ H_i, a ray's d_i, and the pairs N_a d_j - N_b d_i in the box's face coordinates
// Y_i = n_i . (p - c), H_i = h_i |delta| (its header derives why Algorithm 3.3 on [-H, H] there is
// the solid's cast). Its bounds grow with the magnitudes: from 10^12 box sizes away a rounding of
// p - c alone is 10^-4 box sizes, and shots that pass a face, an edge or a corner closer than
// that are left undecided. Here the same quantities are double words: p - c and t - c exact
// pairs (Two-Sum), the normals n_i = a_{i+1} x a_{i+2} by cross_words, delta = a_0 . n_0 (its
// sign certain, n turned so that delta > 0: the box is then [-H, H] with H_i = delta h_i, as the
// sign of delta only swaps a symmetric box's planes), Y_i by dot_words, Y -+ H and d_i = Y_t -
// Y_s (segment) or n_i . r (ray) by add_words, the pairs by mul_words and add_words; each sign
// is sign_of, and hit_box_logic (box_cast_filter.hpp) decides from them exactly as stage 1
// does. Their bounds are of order u^2 of the magnitudes, so that only shots within about 10^-20
// box sizes of a face's plane at 10^12 are left to the next stage (the robust tier's double
// words on the solid's own cast, robust/separating_axes.hpp). Range: every input at most 2^100
// in magnitude (a pair is of degree 7 in them: no value overflows); below, the allowance for
// underflow only widens the bounds.
// On an axis-aligned box: AabbWords and AabbCastWords below.
#pragma once

#include <algorithm>
#include <cdref/bounded/word_bounds.hpp>
#include <cdref/filters/box_cast_filter.hpp>
#include <cdref/primitives.hpp>
#include <cdref/bounded/eft.hpp>
#include <cmath>

namespace cdref::filters::box_cast_words {

using namespace cdref::word_bounds;  // the double words' operations and their bounds
using staged::hit_box_logic;

// sign(lambda_a - lambda_b) for an entering plane a and an exiting plane b (planes 2i lower, 2i +
// 1 upper; hit_box_logic asks for no other pair), from the outcode words sL_i = Y_i + H_i, sU_i =
// Y_i - H_i at the source and the direction's d_i: lambda_a = N_a / d_i with N_a = -sL_i (lower)
// or -sU_i (upper), so lambda_a - lambda_b = (N_a d_j - N_b d_i) / (d_i d_j), and the signs of
// d_i and d_j are known from the planes: an entering lower plane has d_i > 0, an entering upper
// one d_i < 0, an exiting lower one d_j < 0, an exiting upper one d_j > 0 (sigma below).
template <class Mul>
int entering_order(const Word (&sL)[3], const Word (&sU)[3], const Word (&d)[3], int a, int b) {
  const int i = a / 2, j = b / 2;
  const Word Na = negated(a % 2 == 0 ? sL[i] : sU[i]), Nb = negated(b % 2 == 0 ? sL[j] : sU[j]);
  const int sigma = (a % 2 == 0 ? 1 : -1) * (b % 2 == 0 ? -1 : 1);
  const int r = sign_of(add_words(mul_words<Mul>(Na, d[j]), mul_words<Mul>(Nb, d[i]), -1));
  return r == unknown ? unknown : sigma * r;
}

// The plane pairs of Algorithm 3.3 on an axis-aligned box on double words: the oracle's second
// stage of the box casts tries them between the filter's signs and the expansions
// (exact/cdref/oracle/box_casts.hpp, BoxStaged). Y_i = s_i - c_i is an exact pair (Two-Sum), +-h_i
// added by add_words; d_i = t_i - s_i an exact pair (a segment) or the direction. Their bounds
// are of order u^2 of the magnitudes: only pairs within about that of a tie are left to the
// expansions. Range: every input at most 2^100 (BoxStaged runs on scaled inputs).
template <class Mul>
struct AabbWords {
  Word sL[3], sU[3], d[3];
  AabbWords(const Vec3<double>& src, const Vec3<double>& rt, const Box<double>& b, bool segment) {
    for (int i = 0; i < 3; ++i) {
      const Word y{eft::two_sum(src[i], -b.center[i]), 0.0}, h{{b.extent[i], 0.0}, 0.0};
      sL[i] = add_words(y, h, 1);
      sU[i] = add_words(y, h, -1);
      d[i] = segment ? Word{eft::two_sum(rt[i], -src[i]), 0.0} : Word{{rt[i], 0.0}, 0.0};
    }
  }
  int compare(int a, int b) const { return entering_order<Mul>(sL, sU, d, a, b); }
};

// Stage 2 of a cast on an oriented box (header): the signs of ObbFilter on double words.
template <class Mul>
struct ObbWords {
  Word sL[3], sU[3], tL[3], tU[3], d[3];
  bool bounded, ok = false;
  ObbWords(const Vec3<double>& src, const Vec3<double>& rt, const OrientedBox<double>& b, bool segment)
      : bounded(segment) {
    using std::fabs;
    double m = 0;
    for (int i = 0; i < 3; ++i) {
      m = std::max({m, fabs(src[i]), fabs(rt[i]), fabs(b.center[i]), fabs(b.extent[i])});
      for (int k = 0; k < 3; ++k) m = std::max(m, fabs(b.axis[k][i]));
    }
    if (!(m <= 0x1p100)) return;  // NaN and infinities too
    Pair<double> a[3][3], xs[3], xt[3];
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 3; ++i) a[k][i] = {b.axis[k][i], 0.0};
    Word n[3][3];
    for (int i = 0; i < 3; ++i) cross_words<Mul>(a[(i + 1) % 3], a[(i + 2) % 3], n[i]);
    const double zero[3] = {0, 0, 0};
    Word delta = dot_words<Mul>(a[0], zero, n[0]);
    if (!(magnitude_lo(delta) > 0)) return;  // degenerate axes, or too close to: the next stage
    if (delta.v.hi < 0) {
      delta = negated(delta);
      for (auto& ni : n)
        for (auto& c : ni) c = negated(c);
    }
    for (int c = 0; c < 3; ++c) {
      xs[c] = eft::two_sum(src[c], -b.center[c]);
      xt[c] = segment ? eft::two_sum(rt[c], -b.center[c]) : Pair<double>{rt[c], 0.0};
    }
    for (int i = 0; i < 3; ++i) {
      const Word H = scale_word<Mul>(delta, b.extent[i]);
      const Word ys = dot_words<Mul>(xs, zero, n[i]), yt = dot_words<Mul>(xt, zero, n[i]);
      sL[i] = add_words(ys, H, 1);
      sU[i] = add_words(ys, H, -1);
      if (segment) {
        tL[i] = add_words(yt, H, 1);
        tU[i] = add_words(yt, H, -1);
        d[i] = add_words(yt, ys, -1);
      } else {
        d[i] = yt;
      }
    }
    ok = true;
  }
  int src_lo(int i) const { return sign_of(sL[i]); }
  int src_hi(int i) const { return sign_of(sU[i]); }
  int tgt_lo(int i) const { return sign_of(tL[i]); }
  int tgt_hi(int i) const { return sign_of(tU[i]); }
  int dir_sign(int i) const { return sign_of(d[i]); }  // never a certain 0
  int compare(int a, int b) const { return entering_order<Mul>(sL, sU, d, a, b); }
};

template <class Mul>
int obb_cast(const Vec3<double>& src, const Vec3<double>& rt, const OrientedBox<double>& b, bool segment) {
  const ObbWords<Mul> w(src, rt, b, segment);
  return w.ok ? hit_box_logic(w) : unknown;
}
// 1 a hit, 0 a miss, unknown: the next stage.
[[gnu::noinline]] inline int obb_cast_any(const Vec3<double>& src, const Vec3<double>& rt,
                                          const OrientedBox<double>& b, bool segment) {
  return eft::with_products<true>([&](auto mul) { return obb_cast<decltype(mul)>(src, rt, b, segment); });
}
inline int obb_cast_words(const Segment<double>& s, const OrientedBox<double>& b) {
  return obb_cast_any(s.source, s.target, b, true);
}
inline int obb_cast_words(const Ray<double>& r, const OrientedBox<double>& b) {
  return obb_cast_any(r.source, r.direction, b, false);
}


// The casts on an axis-aligned box on double words alone: the outcodes Y_i -+ h_i (Y = p - c an
// exact pair, at the source and at a segment's target) by add_words, the direction's signs
// exactly (t - s an exact pair, or the ray's direction, an input) and AabbWords' plane pairs.
// Every sign is certain except an exact zero (a point on a face's plane, two planes crossed at the
// same parameter), which leaves the case to the next stage; hit_box_logic then decides from the
// signs exactly as the book does (box_cast_filter.hpp). The robust tier's certified decision
// (robust/ray_box.hpp) runs it between the oracle's first stage and its own certificate; the
// oracle's stage 2 (exact/cdref/oracle/box_casts.hpp, BoxStaged) takes the same plane pairs with
// the exact expansions behind them. Range: in_word_range (word_bounds.hpp: the scaling by a power
// of two changes no sign).
template <class Mul>
struct AabbCastWords {
  AabbWords<Mul> w;
  Word tL[3], tU[3];
  bool bounded;
  AabbCastWords(const Vec3<double>& src, const Vec3<double>& rt, const Box<double>& b, bool segment)
      : w(src, rt, b, segment), bounded(segment) {
    for (int i = 0; i < 3; ++i) {
      const Word y{segment ? eft::two_sum(rt[i], -b.center[i]) : Pair<double>{0.0, 0.0}, 0.0};
      const Word h{{b.extent[i], 0.0}, 0.0};
      tL[i] = add_words(y, h, 1);
      tU[i] = add_words(y, h, -1);
    }
  }
  int src_lo(int i) const { return sign_of(w.sL[i]); }
  int src_hi(int i) const { return sign_of(w.sU[i]); }
  int tgt_lo(int i) const { return sign_of(tL[i]); }
  int tgt_hi(int i) const { return sign_of(tU[i]); }
  int dir_sign(int i) const {  // the exact pair's high part has the exact value's sign (0 only for 0)
    const double d = w.d[i].v.hi;
    return d > 0 ? 1 : (d < 0 ? -1 : 0);
  }
  int compare(int a, int b) const { return w.compare(a, b); }
};

// 1 a hit, 0 a miss, unknown: the next stage.
template <class Shot>
int aabb_cast_words(const Shot& shot, const Box<double>& box) {
  Shot s;
  Box<double> b;
  if (!in_word_range(shot, box, s, b)) return unknown;
  constexpr bool segment = std::is_same_v<Shot, Segment<double>>;
  const Vec3<double>* rt;
  if constexpr (segment) rt = &s.target;
  else rt = &s.direction;
  return eft::with_products<true>(
      [&](auto mul) { return hit_box_logic(AabbCastWords<decltype(mul)>(s.source, *rt, b, segment)); });
}

}  // namespace cdref::filters::box_cast_words
