// cdref/robust/obb_cast.hpp - the first look of the casts on an oriented box at double
// (segment-obb-cast, ray-obb-cast): every value of robust::cast(shot, oriented box) from the
// two faces the shot enters and leaves by, each proven within 3/4 of an ulp of the truth (the
// solid's cast, solid/obb.hpp: Algorithm 3.3 in the parallelepiped's face coordinates), in
// place of the whole cast on double words (separating_axes.hpp, cast_eval), which took 1.2-1.4
// us a case.
//
//  0. Where steps 1-6 on the inputs as they are decline and the inputs lie far from 1 (a length
//     beyond 2^+-100: the magnitude families), they run again on the inputs scaled by a
//     power of two, exactly, so that the largest of the source, the target, the centre and the
//     extents lies in [1, 2) (a ray's direction by its own power; length_scale.hpp, whose
//     scaled filter the certified decisions take too): the filter's range and
//     face_parameter's hold there. A segment's parameters do not change, a ray's are multiplied
//     by 2^(k - j) (lengths scaled by 2^-k, its direction by 2^-j), the point by 2^k; where a
//     value scaled back leaves the normal range, or a scaled input would, the slower path.
//  1. The classification: the cast filter (filters/box_cast_filter.hpp, ObbFilter: Algorithm 3.3
//     in the box's unturned face coordinates with static bounds, tightened once). Where it
//     decides, it is the solid's classification at an exact type; a miss has no values (every
//     output 0, as the solid's cast leaves them). Undecided: the slower path.
//  2. The faces (filters/obb_face.hpp, crossed_face): the entering one from the source's certain
//     outcodes and the filter's certain order of the entering planes' parameters; the exiting
//     one likewise (a segment: from its target's outcodes; a ray: from its direction's signs).
//     None entered: the source lies in the box, lambda_enter = 0, the point is the source and the
//     normal 0 (enters = false). None left: a segment's target lies in the box, lambda_exit = 1.
//  3. Each face's parameter alone on double words (obb_face.hpp, face_parameter): lambda* within
//     err of a double word z.
//  4. The entry point s + lambda* d, component k: z.hi d_k.hi exact (Mul), its sum with s_k by
//     two_sum (exact), the lows (that two_sum's, the product's, z.hi d_k.lo, z.lo d_k.hi) summed
//     in double: 3 additions and 2 rounded products, within 5u of their magnitudes; z.lo d_k.lo
//     dropped (at most u^2 |z.hi d_k.hi|: both pairs normalized); lambda*'s own error moves it
//     by at most |d_k| err:
//         e_k = |d_k| err (1 + 2u) + 5u (the lows' magnitudes) + u^2 |z.hi d_k.hi| + 2^-1068
//     (the last for products whose low parts fall below the normal range, each off by at most
//     2^-1075). Exactly where the inputs give it: s_k where d_k = 0 exactly (a shot parallel to
//     the coordinate plane); c_k - tau a_i[k] rounded once (the face's plane passes through c -
//     tau a_i: obb_face.hpp) where both free axes of the face have an exact 0 in component k and
//     the product is exact (an axis-aligned box's face: c_k +- h_i, which often lies on a
//     rounding midpoint; the oracle's mode would refuse the double word's interval there).
//  5. The normal -+ n_i / |n_i| (plane 2i: -, 2i + 1: +; obb_face.hpp), n_i = a_{i+1} x a_{i+2}
//     by cross_of_doubles (3u of its low terms + 4 eta a component), |n_i| from norm2_dw and
//     sqrt_pair (18u^2, plus the components' errors, whose sum bounds their l2 norm), the
//     quotient by first_look.hpp's unit_words. A component whose two products each have a zero
//     factor is exactly 0.
//  6. Each value kept where its bound proves it within 3/4 of an ulp of the truth
//     (first_look.hpp, first_look_kept); in the oracle's mode (Correct: its every-output path,
//     cast_rounded below) where its interval rounds to one double, the truth rounded. A value
//     asked and not kept: the slower path answers the whole query.
// Range: obb_face.hpp's (every input at most 2^200, in_face_range) and the filter's own; the
// filter refuses NaN and infinities (its range tests fail), which the input checks name first.
#pragma once

#include <cdref/filters/box_cast_filter.hpp>
#include <cdref/filters/obb_face.hpp>
#include <cdref/primitives.hpp>
#include <cdref/results.hpp>
#include <cmath>

#include "first_look.hpp"
#include "length_scale.hpp"

namespace cdref::robust::detail {

// Steps 1-6 (header) at double, on inputs in range; true where every value asked was kept.
template <class Mul, bool Correct, class Shot>
bool obb_cast_first_look_in_range(const Shot& x, const OrientedBox<double>& b, int det, unsigned w, Cast<double>& out) {
  namespace st = filters::staged;
  namespace wb = filters::obb_face;
  constexpr double u = first_look_u;
  using std::fabs;
  // 1. the classification
  st::ObbFilter f = st::obb_filter(x, b);
  const int cls = st::filter(f);
  if (cls == st::unknown) return false;
  out = Cast<double>{};
  if (cls == 0) return true;
  out.hit = true;
  Pair<double> sc[3], d[3];
  wb::shot_pairs(x, b.center, sc, d);
  if (!wb::in_face_range(sc, d, b)) return false;
  // 2. the faces
  const std::optional<wb::ObbFace> enter = wb::crossed_face(f, det, false);
  if (!enter) return false;
  std::optional<wb::ObbFace> exit;
  if (w & want_lambda_exit) {
    exit = wb::crossed_face(f, det, true);
    if (!exit) return false;
  }
  // 3. the parameters
  out.enters = enter->plane >= 0;
  wb::FaceParameter z{{0, 0}, 0};  // lambda_enter's, 0 exactly without an entering face
  if (out.enters) {
    const auto p = wb::face_parameter<Mul>(sc, d, b, *enter);
    if (!p || ((w & want_lambda_enter) && !first_look_kept<Correct>(p->z, p->err))) return false;
    z = *p;
    out.lambda_enter = z.z.hi;
  }
  if (w & want_lambda_exit) {
    if (exit->plane >= 0) {
      const auto p = wb::face_parameter<Mul>(sc, d, b, *exit);
      if (!p || !first_look_kept<Correct>(p->z, p->err)) return false;
      out.lambda_exit = p->z.hi;
    } else if (f.bounded) {
      out.lambda_exit = 1.0;  // the target lies in the box
    } else {
      return false;  // (a ray always leaves through some plane: not reached)
    }
  }
  const Vec3<double>& s = x.source;
  // 4. the entry point
  if (w & want_point) {
    if (!out.enters) {
      for (int k = 0; k < 3; ++k) out.point[k] = s[k] + 0.0;  // (+0 for -0, as the exact value rounds)
    } else {
      const int i = enter->plane / 2;
      const double tau = (enter->plane % 2 == 0 ? det : -det) * b.extent[i];
      const Vec3<double>&aj = b.axis[(i + 1) % 3], &am = b.axis[(i + 2) % 3];
      for (int k = 0; k < 3; ++k) {
        if (d[k].hi == 0 && d[k].lo == 0) {
          out.point[k] = s[k] + 0.0;
          continue;
        }
        if (aj[k] == 0 && am[k] == 0) {
          const Pair<double> t = Mul::prod(-tau, b.axis[i][k]);
          if (t.lo == 0) {
            out.point[k] = (b.center[k] + t.hi) + 0.0;
            continue;
          }
        }
        const Pair<double> P = Mul::prod(z.z.hi, d[k].hi);
        const Pair<double> T = two_sum(s[k], P.hi);
        const double a = z.z.hi * d[k].lo, c = z.z.lo * d[k].hi;
        const double lows = ((T.lo + P.lo) + a) + c;
        const Pair<double> v = two_sum(T.hi, lows);
        const double e = (fabs(d[k].hi) + fabs(d[k].lo)) * z.err * (1 + 2 * u) +
                         5 * u * (((fabs(T.lo) + fabs(P.lo)) + fabs(a)) + fabs(c)) + u * u * fabs(P.hi) + 0x1p-1068;
        if (!first_look_kept<Correct>(v, e)) return false;
        out.point[k] = v.hi;
      }
    }
  }
  // 5. the normal
  if ((w & want_normal) && out.enters) {
    const int i = enter->plane / 2;
    const Vec3<double>&aj = b.axis[(i + 1) % 3], &am = b.axis[(i + 2) % 3];
    word_bounds::Word n[3];
    word_bounds::cross_of_doubles<Mul>(aj, am, n);
    double nh[3], nl[3], ne[3];
    for (int k = 0; k < 3; ++k) nh[k] = n[k].v.hi, nl[k] = n[k].v.lo, ne[k] = n[k].e;
    const Pair<double> len = sqrt_pair<Mul>(norm2_dw<Mul>(nh, nl));
    const double Elen = (18 * u * u * len.hi + ((ne[0] + ne[1]) + ne[2])) * first_look_grow;
    Pair<double> unit[3];
    double Eunit[3];
    if (!unit_words<Mul>(nh, nl, ne, len, Elen, unit, Eunit)) return false;
    const double sg = enter->plane % 2 == 0 ? -1.0 : 1.0;
    for (int k = 0; k < 3; ++k) {
      const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
      if ((aj[k1] == 0 || am[k2] == 0) && (aj[k2] == 0 || am[k1] == 0)) {
        out.normal[k] = 0.0;  // both products exactly 0
        continue;
      }
      if (!first_look_kept<Correct>(unit[k], Eunit[k])) return false;
      out.normal[k] = sg * unit[k].hi;
    }
  }
  return true;
}

// Steps 0-6 (header): true where every value asked was kept (then `out` is the whole answer),
// false where the slower path must answer. `det`: the sign of det[a0 a1 a2]
// (checked_orientation).
template <class Mul, bool Correct, class Shot>
bool obb_cast_first_look(const Shot& x, const OrientedBox<double>& b, int det, unsigned w, Cast<double>& out) {
  constexpr bool ray = std::is_same_v<Shot, Ray<double>>;
  // (the inputs as they are first: where they lie near 1 that is the whole first look, and the
  // lengths' magnitudes are looked at only where it declines)
  if (obb_cast_first_look_in_range<Mul, Correct>(x, b, det, w, out)) return true;
  LengthScale s;
  Shot xs;
  OrientedBox<double> bs;
  if (scale_lengths(x, b, s, xs, bs) != Scaling::scaled || !obb_cast_first_look_in_range<Mul, Correct>(xs, bs, det, w, out))
    return false;
  const int k = s.k, j = s.j;
  // back: the point by 2^k; a ray's parameters by 2^(k - j) (s + l d = 2^k (s' + l 2^(j - k)
  // d')), a segment's unchanged; exact where the result stays a normal number (else a second
  // rounding: the slower path)
  bool ok = true;
  const auto back = [&](double& v, int e) {
    v = std::ldexp(v, e);
    ok = ok && std::isfinite(v) && (v == 0 || std::fabs(v) >= 0x1p-1022);
  };
  if constexpr (ray) {
    back(out.lambda_enter, k - j);
    back(out.lambda_exit, k - j);
  }
  for (int i = 0; i < 3; ++i) back(out.point[i], k);
  return ok;
}

}  // namespace cdref::robust::detail
