// cdref/filters/obb_face.hpp - the face through which a shot enters (or leaves) an oriented box,
// and that face's crossing parameter alone on double words, at double. The oracle's correctly
// rounded lambda_enter takes the entering face (oracle/enter_obb.hpp, "An oriented box"); the robust
// casts' first look takes both faces, with the entry point and the normal (robust/obb_cast.hpp).
//
// The faces. The cast filter (box_cast_filter.hpp, ObbFilter: Algorithm 3.3 in the box's
// unturned face coordinates Y_i = n_i . (p - c), n_i = a_{i+1} x a_{i+2}, the slab |Y_i| <= H_i =
// |delta| h_i) gives the outcodes with certain signs and, for two planes a, b crossed with known
// direction signs, the sign of lambda_a - lambda_b = (N_a d_j - N_b d_i) / (d_i d_j) against
// the bound it derives for its pairs (N = -(Y_i(s) -+ H_i), d_i = n_i . d). On a shot that hits
// each entering plane and each exiting plane is crossed, so d_i has the sign of its role: an
// entering lower plane d_i > 0, an entering upper one d_i < 0, an exiting lower one d_i < 0, an
// exiting upper one d_i > 0. The sign of (d_i d_j) is then the same product of the planes' sides
// for two entering planes as for two exiting ones, and compare_entering serves both.
//   entering   the planes the source lies outside of (src_lo < 0: the lower, src_hi > 0: the
//              upper); the largest parameter; none: the source is in the box (lambda_enter = 0).
//   exiting    a segment's: the planes its target lies outside of (tgt_lo < 0, tgt_hi > 0); none:
//              the target is in the box (lambda_exit = 1). A ray's: on an axis the source lies
//              outside of, the opposite plane of the one it enters (its d_i's sign is the
//              entering role's); on an axis it lies between, the plane d_i points to, where the
//              sign of d_i is certain (dir_sign; d_i = 0 exactly, a shot parallel to the slab,
//              is never certain, and the case goes on to the slower paths); the smallest.
// Any sign or order too close to call: nothing (the caller takes its slower path). Where the
// filter's static bounds leave one open, its tightened bounds are tried once.
//
// The parameter (face_parameter). The face's plane is the one through c - tau a_i (tau = h_i
// sign(delta) for the lower plane, -h_i sign(delta) for the upper: Y_i(c - tau a_i) = -tau delta
// = -+H_i; sign(delta) = det3_sign of the axes, exact, which the input check decides:
// checked_orientation), so g(l) = n_i . w(l), w = (s - c) + l d + tau a_i, with no H_i to form,
// and g is linear in l: lambda* = l0 - g(l0) / D exactly for any l0. w's components are three
// exact high terms (s - c's pair, two exact products) and six low ones summed in double (5
// additions and the rounded l0 d.lo: 7u of their magnitudes); n_i is a cross product of doubles
// (cross_of_doubles: two exact products a component, 3u of its low terms); g is one dot_words.
// l0 = -N / D from the filter's own N and D = n_i . d (in double: l0 needs no bound). D itself
// again on double words (dot_words of d and n_i: |D~ - D| <= eD of order u^2 of its terms, where
// the filter's d_bound is 8u of them; D_lo = |D~| - eD > 0): its error reaches lambda* through
// |g| eD / |D|, of order u^2 |lambda*| at long range (g is the residual of l0, about u |N|), and
// the robust tier's entry point multiplies lambda*'s error by |d|, which at 10^12 made the
// filter's first-order bound refuse a point coordinate of 2^-8 on one case in 20. Then delta =
// fl(-g^ / D~) is off from -g / D by (eg + |g^| eD / |D~|) / D_lo + u |delta| (eg: g's word
// bound and its low part), and lambda* lies within err of the double word l0 + delta (two_sum),
// the bound doubled for its own rounding. About 18 exact products instead of some 60 for three
// faces.
// Range: every input at most 2^200 (in_face_range) and |l0| at most 2^250 (every product below
// 2^860, no split overflows); it needs no in_certified_range: a product or a sum that
// underflows is off by at most 2^-1075, which the eta terms of every bound above cover (the
// words' 4, 8 and 64 eta, the last + eta), and the filter's values hold within its own range
// (ObbFilter::ok).
// The outward unit normal of plane 2i is -n_i / |n_i|, of plane 2i + 1 +n_i / |n_i| (in the
// unturned frame Y_i grows outward through the upper plane).
#pragma once

#include <cdref/filters/box_cast_filter.hpp>
#include <cdref/bounded/word_bounds.hpp>
#include <cdref/primitives.hpp>
#include <cmath>
#include <optional>

namespace cdref::filters::obb_face {

using namespace cdref::word_bounds;  // the double words' operations and their bounds

// s - o and the shot's direction (target - source, or the direction) as exact pairs.
template <class Shot>
void shot_pairs(const Shot& x, const Vec3<double>& o, Pair<double> (&so)[3], Pair<double> (&d)[3]) {
  for (int i = 0; i < 3; ++i) {
    so[i] = eft::two_sum(x.source[i], -o[i]);
    if constexpr (std::is_same_v<Shot, Segment<double>>)
      d[i] = eft::two_sum(x.target[i], -x.source[i]);
    else
      d[i] = {x.direction[i], 0.0};
  }
}
inline double largest(const Pair<double> (&a)[3]) {
  return std::max({std::fabs(a[0].hi), std::fabs(a[1].hi), std::fabs(a[2].hi)});
}
// face_parameter's range (header): s - c, d, the axes and the extents at most 2^200.
inline bool in_face_range(const Pair<double> (&sc)[3], const Pair<double> (&d)[3], const OrientedBox<double>& b) {
  double m = std::max(largest(sc), largest(d));
  for (int k = 0; k < 3; ++k)
    m = std::max({m, std::fabs(b.axis[k][0]), std::fabs(b.axis[k][1]), std::fabs(b.axis[k][2]), std::fabs(b.extent[k])});
  return m <= 0x1p200;
}

// A face crossed (header): the plane (2i lower, 2i + 1 upper, in the filter's unturned frame;
// -1: none), the filter's values of its offset at the source (N = Y_i(s) -+ H_i), of D = n_i .
// d and D's bound; `det` the sign of det[a0 a1 a2] (checked_orientation, primitives.hpp).
struct ObbFace {
  int plane;
  double N = 0, D = 0, eD = 0;
  int det = 0;
};
// The entering face (exiting = false) or the exiting one, on a shot that hits (the caller runs
// after the classification: the signs of d follow from the planes' roles only there); nothing
// where the filter cannot tell. `f` is the classification's own filter (tightened there or here
// where its static bounds leave a sign open).
inline std::optional<ObbFace> crossed_face(staged::ObbFilter& f, int det, bool exiting) {
  if (!f.ok) return std::nullopt;
  for (int pass = 0; pass < 2; ++pass) {
    int best = -1, count = 0;
    bool open = false;
    for (int i = 0; i < 3 && !open; ++i) {
      const int lo = f.src_lo(i), hi = f.src_hi(i);
      if (lo == staged::unknown || hi == staged::unknown) {
        open = true;
        continue;
      }
      int plane = -1;
      if (!exiting) {
        plane = lo < 0 ? 2 * i : hi > 0 ? 2 * i + 1 : -1;
      } else if (f.bounded) {
        const int tl = f.tgt_lo(i), th = f.tgt_hi(i);
        if (tl == staged::unknown || th == staged::unknown) {
          open = true;
          continue;
        }
        plane = tl < 0 ? 2 * i : th > 0 ? 2 * i + 1 : -1;
      } else if (lo < 0 || hi > 0) {
        plane = lo < 0 ? 2 * i + 1 : 2 * i;  // out through the opposite plane
      } else {
        const int ds = f.dir_sign(i);
        if (ds == staged::unknown) {
          open = true;
          continue;
        }
        plane = ds > 0 ? 2 * i + 1 : 2 * i;
      }
      if (plane < 0) continue;
      ++count;
      if (best < 0) {
        best = plane;
        continue;
      }
      const int c = f.compare_entering(plane, best);
      if (c == staged::unknown) open = true;
      else if (exiting ? c < 0 : c > 0) best = plane;
    }
    if (!open) {
      if (count == 0) return ObbFace{-1};
      const int i = best / 2;
      return ObbFace{best, best % 2 == 0 ? f.sL[i] : f.sU[i], f.d[i], f.d_bound(i), det};
    }
    if (f.tight) break;
    f.tighten();
  }
  return std::nullopt;
}

// The crossing parameter of a face's plane (header): lambda* within err of z.hi + z.lo.
struct FaceParameter {
  Pair<double> z;
  double err;
};
template <class Mul>
std::optional<FaceParameter> face_parameter(const Pair<double> (&sc)[3], const Pair<double> (&d)[3],
                                            const OrientedBox<double>& b, const ObbFace& e) {
  using std::fabs;
  const int i = e.plane / 2;
  if (!(fabs(e.D) > e.eD)) return std::nullopt;
  const double l0 = -e.N / e.D;
  if (!std::isfinite(l0) || fabs(l0) > 0x1p250) return std::nullopt;
  if (e.det == 0) return std::nullopt;  // (delta = det[a0 a1 a2] != 0 once the box is checked)
  const Vec3<double>& ai = b.axis[i];
  const double tau = (e.plane % 2 == 0 ? e.det : -e.det) * b.extent[i];
  Word n[3];
  cross_of_doubles<Mul>(b.axis[(i + 1) % 3], b.axis[(i + 2) % 3], n);
  // D = n_i . d again on double words (dot_words: within u^2 of its terms, where the filter's
  // bound is 8u of them; its error reaches lambda* through |g| eD / |D|, which the entry point
  // multiplies by |d|)
  const double zero[3] = {0, 0, 0};
  const Word Dw = dot_words<Mul>(d, zero, n);
  const double D = Dw.v.hi, eD = Dw.e + fabs(Dw.v.lo);
  const double D_lo = (fabs(D) - eD) * (1 - 2 * uu);
  if (!(D_lo > 0)) return std::nullopt;
  // w = s - c + l0 d + tau a_i: three exact high terms (two exact products), six low ones in
  // double (5 additions and l0 d.lo rounded: 7u of their magnitudes)
  Pair<double> w[3];
  double ew[3];
  for (int k = 0; k < 3; ++k) {
    const Pair<double> P = Mul::prod(l0, d[k].hi), Q = Mul::prod(tau, ai[k]);
    const Pair<double> T1 = eft::two_sum(sc[k].hi, P.hi), T2 = eft::two_sum(T1.hi, Q.hi);
    const double zl = l0 * d[k].lo;
    const double lows = ((T1.lo + T2.lo) + sc[k].lo) + ((P.lo + Q.lo) + zl);
    w[k] = eft::two_sum(T2.hi, lows);
    ew[k] = 7 * uu * ((fabs(T1.lo) + fabs(T2.lo)) + fabs(sc[k].lo) + ((fabs(P.lo) + fabs(Q.lo)) + fabs(zl))) +
            8 * eta;
  }
  const Word G = dot_words<Mul>(w, ew, n);
  const double g = G.v.hi, eg = G.e + fabs(G.v.lo);
  // lambda* = l0 - g_exact / D_exact; delta = fl(-g / D) is off by (eg + |g| eD / |D|) / D_lo + u |delta|
  const double delta = -g / D;
  const double err = 2 * ((eg + fabs(g) * eD / fabs(D)) / D_lo + uu * fabs(delta)) + eta;
  if (!std::isfinite(err)) return std::nullopt;
  return FaceParameter{eft::two_sum(l0, delta), err};
}

}  // namespace cdref::filters::obb_face
