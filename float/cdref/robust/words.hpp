// cdref/robust/words.hpp - the robust versions' double-word evaluation: a formulation run on
// cdref::Bounded2 (double words hi + lo with a rigorous running bound on their error; its
// header derives every operation's bound) on the exact inputs, every length first scaled by a
// power of two. Each decisive comparison is certain when the double word's sign is, and the
// evaluation then completes; otherwise cdref::uncertain ends it and the caller falls back to
// the formulation in F, uncertain. Used by robust/separating_axes.hpp and
// robust/sphere_triangle.hpp.
//
// Inputs enter exactly: a float or a double is one double; a long double is hi + lo with
// hi = fl(x), lo = x - hi, exact while x lies within double's range (otherwise the double-word
// path is not taken). Every length (coordinates, extents, radii, a ray's direction) is scaled
// by 2^k so that the largest lies in [1, 2), an oriented box's axes left as they are: every
// decision is unchanged (the solids scale by 2^k; a ray's set does not depend on its
// direction's length), and so are parameters and unit normals, while points and distances
// scale by 2^k and are scaled back. The scaling keeps products of small inputs out of the
// underflow range, where the double word's bound loses its exactness; it is exact unless a
// scaled value leaves the normal range, and then k = 0.
#pragma once

#include <bit>
#include <cdref/bounded/bounded2.hpp>
#include <cdref/bounded/scaling.hpp>
#include <cstdint>
#include <cdref/primitives.hpp>
#include <cdref/results.hpp>
#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>
#include <utility>

#include "decision.hpp"
#include <cdref/bounded/eft.hpp>

namespace cdref::robust {

using namespace cdref::eft;  // the error-free transformations (bounded/eft.hpp)

namespace detail {

using W = cdref::Bounded2;

// x as an exact double word, or nothing.
template <class F>
std::optional<W> word(F x) {
  if constexpr (std::is_same_v<F, long double>) {
    const double hi = static_cast<double>(x);
    if (!std::isfinite(hi)) return std::nullopt;
    const double lo = static_cast<double>(x - static_cast<long double>(hi));
    if (static_cast<long double>(hi) + static_cast<long double>(lo) != x) return std::nullopt;
    return W::exact_pair(hi, lo);
  } else {
    return W(static_cast<double>(x));
  }
}
template <class F>
std::optional<Vec3<W>> word(const Vec3<F>& v) {
  Vec3<W> r;
  for (int i = 0; i < 3; ++i) {
    const auto w = word(v[i]);
    if (!w) return std::nullopt;
    r[i] = *w;
  }
  return r;
}

// Every primitive's fields as exact double words (all or nothing).
struct Words {
  bool ok = true;
  template <class F>
  Vec3<W> operator()(const Vec3<F>& v) {
    const auto w = word(v);
    if (!w) ok = false;
    return w ? *w : zero_vec<W>();
  }
  template <class F>
  W operator()(F x) {
    const auto w = word(x);
    if (!w) ok = false;
    return w ? *w : W(0.0);
  }
};
// A primitive as exact double words (fields.hpp's rebind_with: its description there).
template <class P>
auto lift_words(const P& p, Words& w) {
  return rebind_with<W>(p, w);
}
// Two triangles as one argument (a shot's entries into two triangles compared: ray_triangle.hpp).
template <class T>
struct TrianglePair {
  Triangle<T> a, b;
};
template <class T> auto members(TrianglePair<T>& t) { return std::tie(t.a, t.b); }
template <class T> auto members(const TrianglePair<T>& t) { return std::tie(t.a, t.b); }
template <class T> auto lengths(TrianglePair<T>& t) { return std::tuple_cat(lengths(t.a), lengths(t.b)); }
template <class T> auto lengths(const TrianglePair<T>& t) { return std::tuple_cat(lengths(t.a), lengths(t.b)); }

// A double word's value in F (hi + lo rounded to F).
template <class F>
F value(const W& x) {
  if constexpr (std::is_same_v<F, long double>)
    return static_cast<long double>(x.hi()) + static_cast<long double>(x.lo());
  else
    return static_cast<F>(x.hi() + x.lo());
}
template <class F>
Vec3<F> value(const Vec3<W>& v) {
  return Vec3<F>(value<F>(v[0]), value<F>(v[1]), value<F>(v[2]));
}

// Whether a double word's value is within a sixteenth of an ulp of F of its rounding to F
// (bound <= 2^-(p+4) |hi|, p F's precision): then hi + lo rounded is within one ulp of the
// exact value. An exact 0 carrying a residue is not sharp. (Scaling by 2^k changes neither side.)
template <class F = double>
bool sharp(const W& x) {
  constexpr double f = double(std::numeric_limits<F>::epsilon()) * 0x1p-5;  // 2^(1-p) 2^-5, exact
  return x.bound() <= std::fabs(x.hi()) * f;
}

// Every length scaled by 2^k (see the header; bounded/scaling.hpp).
using scaling::Scale;
using scaling::largest;
using scaling::scale_of;
using scaling::scaled;

// A formulation whose double words are its main path, not a fallback (the sphere queries'
// proximity at float and long double, which always ends there) derives from HotWords, and is a
// type of its own rather than a lambda inside a template over F, so that its double-word copy
// (whose operands are double words whatever F is) is compiled once for every F.
struct HotWords {};

// f(a, b) on the double words, a function of its own: a caller that flattens its calls into
// the copy compiled for the FMA extension (bounded/eft.hpp, fused_call) calls this one instead of
// taking the formulation at W into its body. (Taken in, each such caller of a sphere query held
// its formulation at W two or three times over, at float, double and long double: 1.2 MB of
// code each for sphere-triangle and sphere-obb, and two thirds of their groups' compile time.)
// Where the CPU has the FMA extension (CDREF_FMA_CLONES) a copy compiled for it runs, so that
// std::fma in the double-word products is the instruction: bounded/eft.hpp's with_fma (every call
// flattened into it, as inside the caller before) for a HotWords formulation, a copy with the
// compiler's usual inlining for the others. In a build compiled for the extension throughout
// (CDREF_FMA_COMPILED) a HotWords formulation keeps its flattened function (with_fma<true>);
// the others are called as built.
#if CDREF_FMA_CLONES
template <class Fn, class AW, class BW>
[[gnu::target("fma"), gnu::noinline]] auto words_call_fused(const Fn& f, const AW& a, const BW& b) {
  return f(a, b);
}
#endif
template <class Fn, class AW, class BW>
[[gnu::noinline]] auto words_call(const Fn& f, const AW& a, const BW& b) {
  if constexpr (std::is_base_of_v<HotWords, Fn>) {
    return with_fma<true>([&] { return f(a, b); });
  } else {
#if CDREF_FMA_CLONES
    if (cpu_fma()) return words_call_fused(f, a, b);
#endif
    return f(a, b);
  }
}

// Runs f on the primitives as double words (scaled as above); nothing when they are not
// representable or a decision is uncertain.
template <class A, class B, class Fn>
auto on_words(const A& a, const B& b, Fn f, Scale* used = nullptr)
    -> std::optional<decltype(f(lift_words(a, std::declval<Words&>()), lift_words(b, std::declval<Words&>())))> {
  const Scale sc = scale_of(a, b);
  if (used) *used = sc;
  Words w;
  const auto aw = lift_words(scaled(a, sc), w);
  const auto bw = lift_words(scaled(b, sc), w);
  if (!w.ok) return std::nullopt;
  try {
    return words_call(f, aw, bw);
  } catch (const cdref::uncertain&) {
    return std::nullopt;
  }
}

// on_words with lenient signs (bounded/bounded2.hpp): a decision too close to call takes the
// double word's own sign. For the values alone, where on_words did not complete: near such a
// boundary every formulation here is continuous (the closest point of a triangle or a box, a
// cast's entry point where the classification is known), so the branch taken moves the values
// by about the undecided quantity's error, u^2 of its size, instead of carrying F's rounding.
// Divisions by a divisor whose sign is not certain still end it (nothing then), and so does an
// input check inside the formulation (an oriented box's axes called dependent by a lenient sign:
// the inputs were checked already, exactly; the fuzz targets found subnormal axes refused here).
template <class A, class B, class Fn>
auto on_words_lenient(const A& a, const B& b, Fn f, Scale* used = nullptr) -> decltype(on_words(a, b, f, used)) {
  const W::Lenient lenient;
  try {
    return on_words(a, b, f, used);
  } catch (const invalid_input&) {
    return std::nullopt;
  }
}

// A value of the lenient double words (in units scaled by 2^k: k = 0 for parameters and unit
// normals), scaled back, or F's own value f of the same output where f lies within the double
// word's enclosure [hi + lo - e, hi + lo + e] (tested in long double, with a thousandth of e to
// spare: a choice between two values, not a bound): both are then within the enclosure's width of
// the value along the branch taken, and f keeps what F computes exactly (a coordinate of 0 at
// a vertex, where the double word carries a residue of u^2 that is an error of 10^18 ulps).
template <class F>
F word_or_enclosed(const W& w, F f, int k) {
  const long double fs = std::ldexp(static_cast<long double>(f), k);
  const long double v = static_cast<long double>(w.hi()) + static_cast<long double>(w.lo());
  if (std::isfinite(fs) && std::fabs(fs - v) <= static_cast<long double>(w.bound()) * 1.001L) return f;
  return std::ldexp(value<F>(w), -k);
}
template <class F>
Vec3<F> word_or_enclosed(const Vec3<W>& w, const Vec3<F>& f, int k) {
  return Vec3<F>(word_or_enclosed(w[0], f[0], k), word_or_enclosed(w[1], f[1], k), word_or_enclosed(w[2], f[2], k));
}
// A cast's values from the lenient double words (scaled by 2^k), field by field as above; the
// flags are the caller's.
template <class F, class CW, class CF>
void take_lenient_values(CF& out, const CW& w, int k) {
  out.lambda_enter = word_or_enclosed(w.lambda_enter, out.lambda_enter, 0);
  out.lambda_exit = word_or_enclosed(w.lambda_exit, out.lambda_exit, 0);
  out.point = word_or_enclosed(w.point, out.point, k);
  out.normal = word_or_enclosed(w.normal, out.normal, 0);
  if constexpr (std::is_same_v<CF, TriangleCast<F>>) {
    out.u = word_or_enclosed(w.u, out.u, 0);
    out.v = word_or_enclosed(w.v, out.v, 0);
  }
}

template <class F>
Cast<F> cast_value(const Cast<W>& c) {
  Cast<F> r;
  r.hit = c.hit;
  r.enters = c.enters;
  r.unbounded_exit = c.unbounded_exit;
  r.lambda_enter = value<F>(c.lambda_enter);
  r.lambda_exit = value<F>(c.lambda_exit);
  r.point = value<F>(c.point);
  r.normal = value<F>(c.normal);
  return r;
}
template <class F>
Proximity<F> proximity_value(const Proximity<W>& p) {
  Proximity<F> r;
  r.intersect = p.intersect;
  r.distance = value<F>(p.distance);
  r.depth = value<F>(p.depth);
  r.on_a = value<F>(p.on_a);
  r.on_b = value<F>(p.on_b);
  r.closest = value<F>(p.closest);
  return r;
}

// A sphere query's proximity on double words relative to the sphere's centre c: the other
// primitive moved by -c (translate(b, c): its points' differences from c, exact double words
// of exact inputs), the sphere to the origin, the witnesses moved back. A closest point 10^8
// radii from the origin then carries u^2 of its distance from c instead of u^2 of its
// coordinates, which is what the distance of a nearly touching pair is made of (the book's
// own formulation, every decision the same: translation changes no exact comparison). At
// other number types prox(s, b) as it is.
template <class S, class B, class Prox, class Translate>
auto about_centre(const S& s, const B& b, unsigned w, Prox prox, Translate translate) {
  if constexpr (std::is_same_v<std::decay_t<decltype(s.radius)>, W>) {
    S at_origin = s;
    at_origin.center = Vec3<W>(W(0.0), W(0.0), W(0.0));
    auto p = prox(at_origin, translate(b, s.center));
    if (w & want_witnesses) p.on_a = Vec3<W>(p.on_a + s.center), p.on_b = Vec3<W>(p.on_b + s.center);
    if (w & want_closest) p.closest = Vec3<W>(p.closest + s.center);
    return p;
  } else {
    return prox(s, b);
  }
}

// A proximity query and its certificate from one evaluation, so that they always classify
// alike: the double-word query (values scaled back); else the double-word classification with
// the query's values from the double words with lenient signs (on_words_lenient; F's own
// where it lies within their enclosure, word_or_enclosed), or in F where those do not
// complete either; else the classification in F too, uncertain. prox(a, b)
// and meet(a, b) are the formulation's proximity and intersection test, at any number type.
// The distance and the depth as the double words gave them (scaled back, hi + lo), for a
// caller that compares the values of several queries finer than F resolves (robust/polygon.hpp);
// words = false where the values came from elsewhere. bounded: the distance and the depth were
// taken from double words (those of the query, or with lenient signs), whose error bounds
// (scaled back) are distance_err and depth_err (rational.hpp, sharpen_gap).
struct WordValues {
  bool words = false;
  long double distance_hi = 0, depth_hi = 0;
  double distance_lo = 0, depth_lo = 0;
  bool bounded = false;
  long double distance_err = 0, depth_err = 0;
};
template <class A, class B, class Prox, class Meet>
auto proximity_on_words(const A& a, const B& b, Prox prox, Meet meet, WordValues* kept = nullptr) {
  using F = std::decay_t<decltype(scalar_of(a))>;
  const auto from_words = [](const Proximity<W>& r, const Scale& sc) {
    Proximity<F> p = proximity_value<F>(r);
    const Scale back{-sc.k};
    p.distance = back.len(p.distance), p.depth = back.len(p.depth);
    p.on_a = back.len(p.on_a), p.on_b = back.len(p.on_b), p.closest = back.len(p.closest);
    return p;
  };
  const auto values_of = [](const Proximity<W>& r, const Scale& sc, bool words) {
    // (x 2^-k in long double is exact for every double x and |k| of a double's exponent range)
    const long double back = std::ldexp(1.0L, -sc.k);
    return WordValues{words,
                      (long double)r.distance.hi() * back,
                      (long double)r.depth.hi() * back,
                      std::ldexp(r.distance.lo(), -sc.k),
                      std::ldexp(r.depth.lo(), -sc.k),
                      true,
                      (long double)r.distance.bound() * back,
                      (long double)r.depth.bound() * back};
  };
  Scale sc;
  if (const auto r = on_words(a, b, prox, &sc)) {
    if (kept) *kept = values_of(*r, sc, true);
    return std::pair<Proximity<F>, Decision>{from_words(*r, sc), {r->intersect, true}};
  }
  Proximity<F> p = prox(a, b);
  if (const auto lr = on_words_lenient(a, b, prox, &sc)) {
    if (kept) *kept = values_of(*lr, sc, false);
    p.distance = word_or_enclosed(lr->distance, p.distance, sc.k);
    p.depth = word_or_enclosed(lr->depth, p.depth, sc.k);
    p.on_a = word_or_enclosed(lr->on_a, p.on_a, sc.k);
    p.on_b = word_or_enclosed(lr->on_b, p.on_b, sc.k);
    p.closest = word_or_enclosed(lr->closest, p.closest, sc.k);
  }
  const auto h = on_words(a, b, meet);
  const Decision d = h ? Decision{*h, true} : Decision{meet(a, b), false};
  p.intersect = d.value;
  return std::pair<Proximity<F>, Decision>{p, d};
}

}  // namespace detail

}  // namespace cdref::robust
