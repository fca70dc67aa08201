// cdref/robust/first_look.hpp - the first look at double shared by the sphere queries whose
// closest point lies on a feature of a polytope (sphere-triangle, item F of sphere_triangle.hpp;
// sphere-obb, sphere_obb.hpp; polygon-sphere through sphere-triangle's): the closest point's
// offset from the sphere's centre, v = x - c, in double words with a rigorous bound on each
// component's error, and every value of the query taken from it where its bound proves it.
//
// Each query certifies x's feature by its normal cone and computes v there in its own header;
// the pieces below are the ones they share:
//   dot_pairs            a dot product of vectors of exact normalized pairs, as a double word with
//                        a bound (word_bounds::dot_words, cdref/bounded/word_bounds.hpp);
//   first_look_edge      v = P + t E, t = -(P . E) / (E . E): the foot of the perpendicular from
//                        c on the line through the point P + c (P = its offset from c) along E;
//   first_look_face      v = n s / n.n, s = P . n: the foot on the plane through P + c normal
//                        to n;
//   first_look_values    steps 4-5 of sphere_triangle.hpp's item F: g = |v| -+ rho and the
//                        classification from its certain sign, the distance or the depth where
//                        its bound is below u |g| / 16, the witnesses and the closest point where
//                        each coordinate's bound is below u/4 of it (so within 3/4 of an ulp);
//                        or, for the oracle (Correct), each value where the interval of its
//                        double word and bound rounds to one double (then the truth rounded).
// P may carry its own error (Perr: an oriented box's vertex is a sum of products); each helper
// adds its effect: the foot on a line or a plane is a projection of P, so P's error moves t by
// at most (Perr . |E|) / E.E and s by Perr . |n|, and v by those through t E or n s / n.n plus
// Perr itself on the edge.
// A centre inside the solid (sphere_obb.hpp: the nearest face's foot, v from c to it) sets
// `inside`: then the depth is |v| + rho, the distance 0, the sphere's witness c - rho v / |v|
// and the closest point c itself, as solid/obb.hpp defines them.
#pragma once

#include <algorithm>
#include <cdref/bounded/bounded2.hpp>
#include <cdref/bounded/word_bounds.hpp>
#include <cdref/primitives.hpp>
#include <cdref/results.hpp>
#include <cmath>

#include <cdref/bounded/eft.hpp>
#include "sphere_sphere.hpp"

namespace cdref::robust::detail {

using namespace cdref::eft;  // the error-free transformations (bounded/eft.hpp)

// The unit roundoff; the allowance for a rounded product whose low part falls below the normal
// range (each off by at most 2^-1074); the factor that covers a bound's own roundings.
inline constexpr double first_look_u = 0x1p-53, first_look_tiny = 0x1p-800, first_look_grow = 1 + 64 * 0x1p-53;

// x . y for vectors of normalized pairs (x_i = xh_i + xl_i exactly, |xl_i| <= u |xh_i|; y
// alike): word_bounds::dot_words on exact operands (its derivation: the highs' products exact,
// the lows in double, the lows' products dropped).
template <class Mul>
word_bounds::Word dot_pairs(const double (&xh)[3], const double (&xl)[3], const double (&yh)[3], const double (&yl)[3]) {
  static constexpr double exact[3] = {0, 0, 0};
  const Pair<double> x[3] = {{xh[0], xl[0]}, {xh[1], xl[1]}, {xh[2], xl[2]}};
  const word_bounds::Word y[3] = {{{yh[0], yl[0]}, 0.0}, {{yh[1], yl[1]}, 0.0}, {{yh[2], yl[2]}, 0.0}};
  return word_bounds::dot_words<Mul>(x, exact, y);
}

// The closest point's offset from the centre, v = x - c, in units of 2^scale: pairs with a
// bound on each component's error.
struct FirstLookPoint {
  double h[3], l[3], err[3];
  int scale = 0;
  int vertex = -1;  // the closest point is this input vertex (v exact; a triangle's)
  int edge = -1;    // ... on the edge from vertex edge to the next (a triangle's)
  // in a face region, v's direction: sign * n, n = nh + nl within nerr (sign 0 elsewhere);
  // n / |n| does not carry the error of the factor s / n.n
  int sign = 0;
  double nh[3], nl[3], nerr[3];
  Pair<double> nn;      // |n~|^2 (norm2_dw)
  bool inside = false;  // the centre lies inside the solid, v to the nearest face's foot
};

// v = P + t E with t = -(P . E) / (E . E) (header): t from double-word dots (dot_pairs), div_pair
// (8u^2) and mul_pair (5u^2), the sum with P by two_sum (4u^2 of the terms); each component's
// bound follows every error through (the quotient's by (E_num + |t| E_den) / den_lo).
template <class Mul>
bool first_look_edge(const double (&Ph)[3], const double (&Pl)[3], const double (&Perr)[3], const double (&Eh)[3],
                     const double (&El)[3], FirstLookPoint& out) {
  constexpr double u = first_look_u, tiny = first_look_tiny, grow = first_look_grow;
  word_bounds::Word a = dot_pairs<Mul>(Ph, Pl, Eh, El), d = dot_pairs<Mul>(Eh, El, Eh, El);
  a.v = {-a.v.hi, -a.v.lo};
  a.e += ((Perr[0] * std::fabs(Eh[0]) + Perr[1] * std::fabs(Eh[1])) + Perr[2] * std::fabs(Eh[2])) * grow;
  const double den = d.v.hi * (1 - 2 * u) - d.e;
  if (!(den > 0)) return false;
  const Pair<double> tt = div_pair<Mul>(a.v, d.v);
  const double at = std::fabs(tt.hi) * (1 + u);
  const double Et = ((a.e + at * d.e) / den + 8 * u * u * at) * grow;
  for (int i = 0; i < 3; ++i) {
    const Pair<double> te = mul_pair<Mul>(tt, Pair<double>{Eh[i], El[i]});
    const Pair<double> s = two_sum(Ph[i], te.hi);
    const Pair<double> v = two_sum(s.hi, double(s.lo + double(Pl[i] + te.lo)));
    out.h[i] = v.hi, out.l[i] = v.lo;
    out.err[i] = (Perr[i] + Et * std::fabs(Eh[i]) + 10 * u * u * (std::fabs(Ph[i]) + std::fabs(te.hi))) * grow + tiny;
  }
  return true;
}

// v = n s / n.n with s = P . n (header), n = nh + nl within En: s by dot_pairs, n.n by norm2_dw,
// the quotient by div_pair and each component by mul_pair, every bound followed through. The
// direction's sign is set where s's sign is certain.
template <class Mul>
bool first_look_face(const double (&Ph)[3], const double (&Pl)[3], const double (&Perr)[3], const double (&nh)[3],
                     const double (&nl)[3], const double (&En)[3], FirstLookPoint& out) {
  constexpr double u = first_look_u, tiny = first_look_tiny, grow = first_look_grow;
  const word_bounds::Word s = dot_pairs<Mul>(Ph, Pl, nh, nl);
  double Es = s.e + (1 + 2 * u) * ((std::fabs(Ph[0]) * En[0] + std::fabs(Ph[1]) * En[1]) + std::fabs(Ph[2]) * En[2]);
  for (int i = 0; i < 3; ++i) Es += Perr[i] * ((std::fabs(nh[i]) * (1 + u) + En[i]) * (1 + 2 * u));
  Es *= grow;
  const Pair<double> nn = norm2_dw<Mul>(nh, nl);
  double Enn = 28 * u * u * nn.hi;
  for (int i = 0; i < 3; ++i) Enn += (2 * std::fabs(nh[i]) * (1 + u) + En[i]) * En[i];
  Enn = Enn * grow + tiny;
  const double den = nn.hi * (1 - 2 * u) - Enn;
  if (!(den > 0)) return false;
  if (s.v.hi > Es * (1 + 2 * u)) out.sign = 1;
  if (s.v.hi < -Es * (1 + 2 * u)) out.sign = -1;
  for (int i = 0; i < 3; ++i) out.nh[i] = nh[i], out.nl[i] = nl[i], out.nerr[i] = En[i];
  out.nn = nn;
  const Pair<double> kk = div_pair<Mul>(s.v, nn);
  const double ak = std::fabs(kk.hi) * (1 + u);
  const double Ek = ((Es + ak * Enn) / den + 8 * u * u * ak) * grow;
  for (int i = 0; i < 3; ++i) {
    const Pair<double> v = mul_pair<Mul>(Pair<double>{nh[i], nl[i]}, kk);
    out.h[i] = v.hi, out.l[i] = v.lo;
    out.err[i] = (5 * u * u * std::fabs(nh[i]) * ak + ak * En[i] + (std::fabs(nh[i]) * (1 + u) + En[i]) * Ek) * grow + tiny;
  }
  return true;
}

// A value whose last rounding gave v.hi (v the value before it, within err of the truth): kept
// where Correct says it is the truth rounded, else where v.hi lies within 3/4 of an ulp of the
// truth (err below u |v.hi| / 4 <= its ulp / 4); 2^-1070 for an underflowing low part.
template <bool Correct>
bool first_look_kept(const Pair<double>& v, double err) {
  if constexpr (Correct) {
    double r;
    return std::fabs(v.hi) >= 0x1p-960 && cdref::Bounded2::within(v.hi, v.lo, err + 0x1p-1070).try_rounded(r) &&
           r == v.hi;
  } else {
    return std::isfinite(v.hi) && err + 0x1p-1070 <= 0.25 * first_look_u * std::fabs(v.hi);
  }
}

// n / |n| for n = nh + nl within ne (per component), given |n| as a pair len within Elen (e.g.
// sqrt_pair(norm2_dw(n)): 18u^2 of it, plus the components' errors, whose l2 norm their sum
// bounds): each component as the pair out[i] within err[i] of the exact n_i / |n|, through
// recip_pair (10u^2) and mul_pair (5u^2), the errors of n and |n| followed through the quotient
// by (ne_i + |n_i / |n|| Elen) / len_lo. false where len_lo = |len| - Elen is not positive.
template <class Mul>
bool unit_words(const double* nh, const double* nl, const double* ne, const Pair<double>& len, double Elen,
                Pair<double> (&out)[3], double (&err)[3]) {
  constexpr double u = first_look_u, grow = first_look_grow;
  const double lo = len.hi * (1 - 2 * u) - Elen;
  if (!(lo > 0)) return false;
  const Pair<double> inv = recip_pair<Mul>(len);  // 10u^2
  const double rlo = 1 / lo;                       // (its rounding and the product's within grow)
  for (int i = 0; i < 3; ++i) {
    out[i] = mul_pair<Mul>(Pair<double>{nh[i], nl[i]}, inv);  // + 5u^2
    const double an = std::fabs(out[i].hi) * (1 + u);
    err[i] = ((ne[i] + an * Elen) * rlo + 16 * u * u * an) * grow;
  }
  return true;
}

// Steps 4-5 (header): the values from v where its bounds certify them; which of the asked values
// it set (want_distance | want_depth together, want_witnesses, want_closest). `point`: whether
// the query's first look found v (else only the classification, from first_stage()).
// cls: the classification (1 meets, 0 apart), or `unknown`: then g's sign where its bound makes
// it certain, else first_stage()'s, and the function sets it (unknown where neither tells:
// nothing set). key, where given and the distance and depth are set: |x - c| - rho as a double
// word (key[0] + key[1], before its last rounding) and a bound on its error (key[2]), for
// polygon.hpp to order a fan's triangles. exact(i, x): whether coordinate i of the closest point
// is known exactly (then x), as a triangle's vertex or a coordinate its feature's vertices share.
// Correct: each value kept only where it is the truth correctly rounded (its interval, the
// value before its last rounding and its bound, within the rounding interval of the double it
// rounds to: cdref::Bounded2::try_rounded), for the oracle's every-output path.
template <class Mul, bool Correct, class Stage, class Exact>
unsigned first_look_values(const Sphere<double>& sp, const FirstLookPoint& P, bool point, int& cls, int unknown,
                           unsigned w, Proximity<double>& res, double* key, Stage first_stage, Exact exact) {
  constexpr double u = first_look_u, grow = first_look_grow;
  // (scaled units: v far below the inputs' size, or 0, is left to the path below)
  const bool sized = point && std::max({std::fabs(P.h[0]), std::fabs(P.h[1]), std::fabs(P.h[2])}) >= 0x1p-400;
  const Pair<double> len = sized ? sqrt_pair<Mul>(norm2_dw<Mul>(P.h, P.l)) : Pair<double>{0, 0};  // |v~| (1 + 18u^2)
  const double Elen = sized ? (18 * u * u * len.hi + ((P.err[0] + P.err[1]) + P.err[2])) * grow : 0.0;
  const double lden = len.hi * (1 - 2 * u) - Elen;
  if (!sized || !(lden > 0)) {
    if (cls == unknown) cls = first_stage();
    return 0;
  }
  // g = |v| - rho (inside: |v| + rho, the depth) summed once (sphere_sphere.hpp,
  // first_look_gap): before that rounding within Eg = Elen + 2.1u^2 (|v| + rho) of the truth, so
  // its sign is certain where Eg (1 + 4u) < |g|
  const double rho = Pow2<double>(P.scale)(sp.radius);
  const Pair<double> d = two_sum(len.hi, P.inside ? rho : -rho);
  const Pair<double> gp = two_sum(d.hi, double(d.lo + len.lo));
  const double g = gp.hi;
  const double Eg = (Elen + 3 * u * u * (len.hi + rho)) * grow;
  if (cls == unknown) cls = Eg * (1 + 4 * u) < std::fabs(g) ? int(g < 0) : first_stage();
  if (cls == unknown) return 0;
  const auto kept = [](const Pair<double>& v, double err) { return first_look_kept<Correct>(v, err); };
  const Pow2<double> up(-P.scale);
  unsigned done = 0;
  if (w & (want_distance | want_depth)) {
    // the distance or the depth, where Eg is below u |g| / 16 (Correct: where |g| rounds surely)
    const bool sure = Correct ? kept(Pair<double>{up(gp.hi), up(gp.lo)}, up(Eg)) : 16 * Eg < u * std::fabs(g);
    if (sure && (P.inside || (g > 0) == (cls == 0))) {
      const double dv = up(std::fabs(g));
      if (w & want_distance) res.distance = g > 0 && !P.inside ? dv : 0.0;
      if (w & want_depth) res.depth = g < 0 || P.inside ? dv : 0.0;
      done |= want_distance | want_depth;
      // (the scaling exact but for an underflow, 2^-1074 at most)
      if (key) key[0] = up(gp.hi), key[1] = up(gp.lo), key[2] = up(Eg * grow) + 0x1p-1070;
    }
  }
  if (w & want_witnesses) {
    // the sphere's witness c + rho v / |v| (inside: c - rho v / |v|; sphere_sphere.hpp,
    // along_dw: before its rounding within u^2 |value| + 3u^2 rho |n_i| of c + rho n~_i); in a
    // face region v / |v| is sign(s) n / |n|
    const bool face = P.sign != 0;
    const double *dh = face ? P.nh : P.h, *dl = face ? P.nl : P.l, *de = face ? P.nerr : P.err;
    Pair<double> dlen = len;
    double Edlen = Elen;
    if (face) {
      dlen = sqrt_pair<Mul>(P.nn);
      Edlen = (18 * u * u * dlen.hi + ((P.nerr[0] + P.nerr[1]) + P.nerr[2])) * grow;
    }
    const double rho = (P.sign < 0) != P.inside ? -sp.radius : sp.radius;
    Pair<double> unit[3];
    double Eunit[3];
    bool ok = unit_words<Mul>(dh, dl, de, dlen, Edlen, unit, Eunit);
    for (int i = 0; i < 3 && ok; ++i) {
      const Pair<double>& n = unit[i];
      const double an = std::fabs(n.hi) * (1 + u), En = Eunit[i];
      // (along_dw, its last sum kept as a pair)
      const Pair<double> p = two_prod(rho, n.hi);
      const Pair<double> c = two_sum(sp.center[i], p.hi);
      const Pair<double> r = two_sum(c.hi, double(c.lo + double(p.lo + rho * n.lo)));
      ok = kept(r, (sp.radius * En + 4 * u * u * (std::fabs(r.hi) + sp.radius * an)) * grow);
      res.on_a[i] = r.hi;
    }
    if (ok) done |= want_witnesses;
  }
  if (P.inside && (w & want_closest)) {
    // the centre itself, which lies in the solid (+0 for -0, as the exact value rounds)
    for (int i = 0; i < 3; ++i) res.closest[i] = sp.center[i] + 0.0;
    done |= want_closest;
  }
  if ((w & want_witnesses) || (!P.inside && (w & want_closest))) {
    // the solid's point x = c + v 2^scale (plus_dw: before its rounding within u^2 (|x_i| +
    // |v_i|) of c + v~), or exactly where exact() knows it
    Vec3<double> x;
    bool ok = true;
    for (int i = 0; i < 3 && ok; ++i) {
      if (exact(i, x[i])) continue;
      // (plus_dw, its last sum kept as a pair)
      const Pair<double> c = two_sum(sp.center[i], up(P.h[i]));
      const Pair<double> r = two_sum(c.hi, double(c.lo + up(P.l[i])));
      x[i] = r.hi;
      ok = kept(r, (up(P.err[i]) + 2 * u * u * (std::fabs(x[i]) + up(std::fabs(P.h[i])))) * grow);
    }
    if (ok) {
      if (!P.inside && (w & want_closest)) res.closest = x, done |= want_closest;
      if (w & want_witnesses) res.on_b = x;
    } else {
      done &= ~want_witnesses;
    }
  }
  return done;
}

}  // namespace cdref::robust::detail
