// cdref/oracle/enter.hpp - the entry parameter of a cast, correctly rounded to double:
// oracle::enter(shot, solid) is round-to-nearest of the lambda_enter that the book's cast
// returns at an exact type (0 on a miss, and 0 when the source lies in the solid), for the
// casts on a sphere (Algorithm 3.1), on an axis-aligned box (Algorithm 3.3), on an oriented
// box (the solid's cast, solid/obb.hpp: the truth where the axes are not exactly orthonormal),
// on a triangle (Section 3.4, Moller-Trumbore) and on a union of triangles (a polygon's fan, a
// mesh's fan: enter_first, the smallest of the triangles' values). It is the one output a ray
// tracer takes from a cast, and `cdref report` prices it beside the oracle's classification and
// its every-output path.
//
// Each call: the input checks (for the sphere and box casts after the classification's
// filter, whose range tests refuse what they would: stages.hpp, staged::filter_first); the
// classification (oracle::classify: filter, double words, expansions, rationals; each query's
// own stages); on a hit a double path whose error is bounded rigorously, accepted when the
// exact value cannot lie on the other side of a rounding midpoint (Bounded2::try_rounded);
// otherwise the truth's formulation at cdref::Bounded2, then
// at CGAL::Gmpq.
//
// This file holds what the casts share: the exact path, the double paths' plumbing (the fused
// copy, the rounding, the classification's answer first) and the plane's parameter that the
// triangle's and the oriented box's paths both take (derived in enter_triangle.hpp's header).
// Each solid's double path is in its own file, with its derivation, its range and its
// enter() overloads: enter_sphere.hpp (Algorithm 3.1), enter_box.hpp (Algorithm 3.3),
// enter_triangle.hpp (a triangle, a polygon's fan, a union of triangles: enter_first, here),
// enter_obb.hpp (an oriented box). Include the one the cast needs.
//
// Measured (`cdref_bench`, ratios to that run's `bare`): docs/cost.md and docs/tiers.md.
#pragma once

#include <cdref/bounded/bounded2.hpp>
#include <cdref/cdref.hpp>
#include <cdref/bounded/word_bounds.hpp>
#include <cdref/filters/obb_face.hpp>
#include <cdref/oracle/rational.hpp>
#include <cdref/oracle/stage.hpp>
#include <cdref/bounded/eft.hpp>
#include <cdref/solid/obb.hpp>
#include <cmath>
#include <limits>
#include <optional>

namespace cdref::oracle {

namespace enter_detail {

using eft::Pair;

using namespace word_bounds;
using namespace cdref::filters::obb_face;  // an oriented box's faces (shot_pairs: every shot's pairs)

// w = x + l d for exact pairs x, d and a double l, as double words with their bounds.
template <class Mul = SplitProduct>
inline void affine_words(const Pair<double> (&x)[3], double l, const Pair<double> (&d)[3], Pair<double> (&w)[3],
                         double (&ew)[3]) {
  using std::fabs;
  for (int i = 0; i < 3; ++i) {
    const Pair<double> P = Mul::prod(l, d[i].hi);
    const Pair<double> T = eft::two_sum(x[i].hi, P.hi);
    const double zl = l * d[i].lo;
    w[i] = eft::two_sum(T.hi, ((T.lo + x[i].lo) + P.lo) + zl);
    ew[i] = 4 * uu * (((fabs(T.lo) + fabs(x[i].lo)) + fabs(P.lo)) + fabs(zl)) + 8 * eta;
  }
}

// The plane's parameter lambda* = l0 - g(l0) / D, g(l) = n . (x + l d) + off linear in l
// (off: a word, 0 for the triangle), D = n . d, l0 = -(N + off) / D in double with N = n . x
// (computed by the caller): the double word l0 + delta with its bound, rounded (nothing when
// the rounding is not certain).
template <class Mul = SplitProduct>
inline std::optional<double> plane_parameter(const Pair<double> (&x)[3], const Pair<double> (&d)[3], const Word (&n)[3],
                                             const Word& N, const Word& off) {
  using std::fabs;
  const double zero[3] = {0, 0, 0};
  const Word D = dot_words<Mul>(d, zero, n);
  const double D_lo = magnitude_lo(D);
  if (!(D_lo > 0)) return std::nullopt;  // nearly parallel, or in the plane: the exact path
  const double Dv = D.v.hi + D.v.lo;
  const double l0 = -((N.v.hi + off.v.hi) + (N.v.lo + off.v.lo)) / Dv;
  if (!std::isfinite(l0) || fabs(l0) > 0x1p250) return std::nullopt;
  Pair<double> w[3];
  double ew[3];
  affine_words<Mul>(x, l0, d, w, ew);
  const Word G = dot_words<Mul>(w, ew, n);
  // g = G + off: one two_sum of the highs, the rest in double
  const Pair<double> S = eft::two_sum(G.v.hi, off.v.hi);
  const double rest = S.lo + (G.v.lo + off.v.lo);
  const double g = S.hi + rest;
  const double eg = (G.e + off.e + 2 * uu * (fabs(rest) + fabs(g))) * (1 + 4 * uu);
  // delta = -g / D, off from -g_exact / D_exact by (eg + |g| eD / |D|) / D_lo + u |delta|
  const double delta = -g / Dv;
  const double err = 2 * ((eg + fabs(g) * D.e / fabs(Dv)) / D_lo + uu * fabs(delta)) + eta;
  const Pair<double> z = eft::two_sum(l0, delta);
  double v;
  if (!std::isfinite(err) || !Bounded2::within(z.hi, z.lo, err).try_rounded(v)) return std::nullopt;
  return v;
}

// The exact path: the truth's formulation (the book's cast; for an oriented box the solid's,
// solid/obb.hpp: the book's frame transform assumes orthonormal axes) at Bounded2 (certain,
// or it throws), then at CGAL::Gmpq.
template <class Shot, class Solid>
auto truth_cast(const Shot& x, const Solid& y) {
  return book::cast(x, y, want_lambda_enter);
}
template <class Shot, class T>
auto truth_cast(const Shot& x, const OrientedBox<T>& y) {
  return solid::cast(x, y, want_lambda_enter);
}
template <class Shot, class Solid>
double exact_enter(const Shot& x, const Solid& y) {
  try {
    const auto c = truth_cast(exactly<Bounded2>(x), exactly<Bounded2>(y));
    return c.hit ? c.lambda_enter.rounded() : 0.0;
  } catch (const uncertain&) {
  }
  const auto c = truth_cast(rational_inputs::toq(x), rational_inputs::toq(y));
  return c.hit ? round_to<double>(c.lambda_enter) : 0.0;
}

// A double path's answer rounded: the value, or nothing when the path could not tell.
inline std::optional<double> rounded(int st, const Bounded2& z) {
  if (st == 0) return 0.0;
  double v;
  if (st == 1 && z.try_rounded(v)) return v;
  return std::nullopt;
}

// Each solid's first double path, with the products of Mul (defined in its own file:
// enter_sphere.hpp, enter_triangle.hpp, enter_obb.hpp).
template <class Mul, class Shot>
std::optional<double> sphere_first(const Shot& x, const Sphere<double>& sp);
template <class Mul = SplitProduct, class Shot>
std::optional<double> triangle_double(const Shot& x, const Triangle<double>& tri);
template <class Mul = SplitProduct, class Shot>
std::optional<double> obb_double(const Shot& x, const OrientedBox<double>& b, const std::optional<ObbFace>& face);

// The first double path of a solid, with the products of Mul (an oriented box's: with the
// entering face, where the filter picked it).
template <class Mul, class Shot, class Solid, class... Face>
std::optional<double> first_double(const Shot& x, const Solid& y, const Face&... face) {
  if constexpr (std::is_same_v<Solid, Sphere<double>>)
    return sphere_first<Mul>(x, y);
  else if constexpr (std::is_same_v<Solid, Triangle<double>>)
    return triangle_double<Mul>(x, y);
  else
    return obb_double<Mul>(x, y, face...);
}

// The double path with fused products where the CPU has them (eft::with_products: on x86-64
// a copy compiled for the FMA extension, every call inside it inlined, chosen at run time; a
// build with -mfma or on another architecture: the split copy, or std::fma as the compiler
// provides it). fused_double is that copy alone (the tests compare it with the split one).
using eft::cpu_fma;
// The copy's answer crosses the call as one double, NaN for "cannot tell" (a value is finite):
// returned as std::optional<double>, g++ stored its flag byte and reloaded the pair as one
// word, a store the load could not take forwarded, and that stall was 9% of a hit's time
// (perf annotate, the ray cast's uniform hits, 2026-11-30).
inline double value_or_nan(const std::optional<double>& v) { return v ? *v : std::numeric_limits<double>::quiet_NaN(); }
inline std::optional<double> nan_to_none(double v) {
  if (std::isnan(v)) return std::nullopt;
  return v;
}
template <class Shot, class Solid, class... Face>
std::optional<double> fused_double(const Shot& x, const Solid& y, const Face&... face) {
  return nan_to_none(
      eft::fused_call([&](auto mul) { return value_or_nan(first_double<decltype(mul)>(x, y, face...)); }));
}
template <class Shot, class Solid, class... Face>
std::optional<double> solid_double(const Shot& x, const Solid& y, const Face&... face) {
  return nan_to_none(
      eft::with_products<true>([&](auto mul) { return value_or_nan(first_double<decltype(mul)>(x, y, face...)); }));
}

// The classification's answer, then on a hit the double path (a value, or nothing when it
// cannot tell), then the exact path.
template <class Shot, class Solid, class Path>
Entry entry_of(bool hit, const Shot& x, const Solid& y, bool* exact_used, Path double_path) {
  Entry out;
  if (exact_used) *exact_used = false;
  if (!hit) return out;
  out.hit = true;
  if (const std::optional<double> v = double_path()) {
    out.lambda_enter = *v;
    return out;
  }
  if (exact_used) *exact_used = true;
  out.lambda_enter = exact_enter(x, y);
  return out;
}

}  // namespace enter_detail

// oracle::enter(shot, solid, exact_used) -> oracle::Entry (stage.hpp), one overload per shot
// and solid in the solid's file: `exact_used` (optional) says whether the exact path answered.
// Inputs are checked as the book checks them (cdref::invalid_input naming what is wrong).
//
// A shot against a union of triangles (a polygon's fan, a mesh's fan): the book's cast takes the
// smallest lambda_enter over the triangles hit, and rounding is monotone, so the smallest of the
// triangles' correctly rounded values is the union's (each triangle's classification and double
// path as above; exact_used when any triangle took the exact path). `enter_k(k, bool*)` is
// triangle k's Entry, k < count.
template <class EnterK>
Entry enter_first(int count, EnterK enter_k, bool* exact_used = nullptr) {
  Entry out;
  if (exact_used) *exact_used = false;
  for (int k = 0; k < count; ++k) {
    bool e = false;
    const Entry t = enter_k(k, &e);
    if (exact_used) *exact_used = *exact_used || e;
    if (!t.hit) continue;
    if (!out.hit || t.lambda_enter < out.lambda_enter) out.lambda_enter = t.lambda_enter;
    out.hit = true;
  }
  return out;
}

}  // namespace cdref::oracle
