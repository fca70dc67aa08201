// cdref/bounded/eft.hpp - error-free transformations and a compensated dot product (namespace
// cdref::eft), for the double words with bounds (word_bounds.hpp), the filters' double-word
// stages and the robust float formulations (float, double, long double; never with -ffast-math).
//
//   two_sum(a, b) = (s, e) with s = fl(a + b) and a + b = s + e exactly (Knuth; 6 flops);
//   two_prod(a, b) = (p, e) with p = fl(a b) and a b = p + e exactly (one std::fma),
//     barring underflow;
//   dot2(x, y) = the dot product computed as if in twice the precision, then rounded
//     (Ogita, Rump and Oishi, "Accurate sum and dot product", 2005, Algorithm Dot2): its
//     error is at most u |x.y| + gamma_n^2 sum |x_i y_i| (u the unit roundoff, gamma_n =
//     n u / (1 - n u)), so a difference of nearly equal products such as |s|^2 - rho^2
//     keeps its digits as long as the cancellation is smaller than 1/u.
#pragma once

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>

namespace cdref::eft {

template <class F>
struct Pair {
  F hi, lo;
};

// exponent_of(x): std::ilogb(x), and exp2_of(k): 2^k (std::ldexp(F(1), k)), read off and
// written into the bits for normal floats and doubles (libm's are calls, and the robust tier
// scales by powers of two on every query); every other case, as libm gives it.
template <class F>
inline constexpr bool binary_bits = std::numeric_limits<F>::is_iec559 &&
                                    ((std::is_same_v<F, double> && sizeof(F) == 8) || (std::is_same_v<F, float> && sizeof(F) == 4));
template <class F>
int exponent_of(F x) {
  if constexpr (binary_bits<F>) {
    using U = std::conditional_t<sizeof(F) == 8, std::uint64_t, std::uint32_t>;
    constexpr int p = std::numeric_limits<F>::digits - 1, top = 2 * std::numeric_limits<F>::max_exponent - 1;
    const int biased = int((std::bit_cast<U>(x) >> p) & U(top));
    if (biased != 0 && biased != top) return biased - (std::numeric_limits<F>::max_exponent - 1);
  }
  return std::ilogb(x);
}
template <class F>
F exp2_of(int k) {
  if constexpr (binary_bits<F>) {
    using U = std::conditional_t<sizeof(F) == 8, std::uint64_t, std::uint32_t>;
    constexpr int p = std::numeric_limits<F>::digits - 1, bias = std::numeric_limits<F>::max_exponent - 1;
    if (k >= 1 - bias && k <= bias) return std::bit_cast<F>(U(unsigned(k + bias)) << p);
  }
  return std::ldexp(F(1), k);
}

template <class F>
Pair<F> two_sum(F a, F b) {
  const F s = a + b;
  const F bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}

template <class F>
Pair<F> two_prod(F a, F b) {
  const F p = a * b;
  return {p, std::fma(a, b, -p)};
}

template <class F, std::size_t N>
F dot2(const F (&x)[N], const F (&y)[N]) {
  Pair<F> acc = two_prod(x[0], y[0]);
  F err = acc.lo;
  for (std::size_t i = 1; i < N; ++i) {
    const Pair<F> p = two_prod(x[i], y[i]);
    const Pair<F> s = two_sum(acc.hi, p.hi);
    acc.hi = s.hi;
    err += p.lo + s.lo;
  }
  return acc.hi + err;
}

// sum_k(p, K): Ogita, Rump and Oishi's SumK (Algorithm 4.8 of the paper above): K - 1
// error-free cascades of two_sum over p (in place), then the plain sum. The result is as if
// computed in K-fold precision and rounded (their Proposition 4.10):
//   |res - s| <= (u + 3 gamma_{n-1}^2) |s| + gamma_{2n-2}^K sum |p_i|,
// so a sum that cancels by up to u^-(K-1) still comes out within about an ulp.
template <class F, std::size_t N>
F sum_k(F (&p)[N], int K) {
  for (int k = 1; k < K; ++k)
    for (std::size_t i = 1; i < N; ++i) {
      const Pair<F> t = two_sum(p[i], p[i - 1]);
      p[i] = t.hi;
      p[i - 1] = t.lo;
    }
  F s = p[0];
  for (std::size_t i = 1; i < N; ++i) s += p[i];
  return s;
}

// ---- Double-word helpers (additions for ray_sphere.hpp) ----
//
//   fast_two_sum(a, b) = (s, e), s = fl(a + b), a + b = s + e exactly when a = 0 or
//     exponent(a) >= exponent(b) (Dekker; 3 flops);
//   two_prod_split(a, b): two_prod without fma (Dekker's product over Veltkamp's split at
//     2^ceil(p/2) + 1): exact, barring overflow of the split (|a|, |b| below max / 2^(p/2+1))
//     and underflow. Built without -mfma, std::fma is a library call; this one stays inline;
//   mul_pair(x, y) = x y for double-word x, y: relative error at most 3u^2 (+ the lo x lo
//     term, below u^2 |x y|: 4u^2 in all);
//   div_pair(x, y) = x / y as a double-word (t, corr): t = fl(xh / yh), corr = the rounded
//     remainder (xh - t yh + xl - t yl) / yh; relative error at most 8u^2 (|xl| <= u|xh|,
//     |yl| <= u|yh|; the remainder xh - t yh is exact, three roundings of the u-sized
//     correction and the division by yh instead of y);
//   sqrt_pair(x) = sqrt(xh + xl) as (y, (xh - y^2 + xl) / (2y)), y = fl(sqrt xh): one Newton
//     step, relative error at most 4u^2;
//   recip_pair(y) = 1 / y as (t, fl(fl(e - t yl) t)), t = fl(1 / yh), e = 1 - t yh exactly (the
//     remainder of a rounded quotient is a double): 1/y = t + E/y with E = e - t yl, |E| <=
//     2.01u; E's two roundings err by 3.03u^2, E t against E/y by 2.01u |E| |1/y| (t and yh
//     against y), t E's rounding 2.1u^2: relative error at most 10u^2, one division.
// Each result is normalized (|lo| <= ulp(hi)/2) by a final fast_two_sum.

template <class F>
Pair<F> fast_two_sum(F a, F b) {
  const F s = a + b;
  return {s, b - (s - a)};
}

template <class F>
constexpr F split_factor() {
  constexpr int p = std::numeric_limits<F>::digits;
  return F((1ULL << ((p + 1) / 2)) + 1);
}

template <class F>
Pair<F> two_prod_split(F a, F b) {
  const F ca = split_factor<F>() * a, cb = split_factor<F>() * b;
  const F ah = ca - (ca - a), al = a - ah;
  const F bh = cb - (cb - b), bl = b - bh;
  const F p = a * b;
  return {p, ((ah * bh - p) + ah * bl + al * bh) + al * bl};
}

// The exact product as a policy, two ways with the same pair wherever the product is exact
// (operands far from overflow and from the subnormal range): Dekker's over Veltkamp's split
// (17 flops, inline on any CPU) or one fused multiply-add (a library call in a build without
// -mfma; an instruction in code compiled for the FMA extension: oracle/enter.hpp takes such a
// copy where the CPU has it).
struct SplitProduct {
  template <class F>
  static Pair<F> prod(F a, F b) { return two_prod_split(a, b); }
};
struct FusedProduct {
  template <class F>
  static Pair<F> prod(F a, F b) { return two_prod(a, b); }
};

// Whether a fused multiply-add is an instruction here. A build with -mfma (cdref's own build on
// a CPU with the extension, which says so with CDREF_FMA_REQUIRED: CMakeLists.txt; or for
// another architecture, whose compiler provides std::fma as it can) answers at compile time; an
// x86 build without it asks the CPU, and code that wants the instruction is compiled a second
// time with [[gnu::target("fma")]] (CDREF_FMA_CLONES) and that copy taken where the answer is yes.
#if defined(__FMA__) || (defined(CDREF_FMA_REQUIRED) && CDREF_FMA_REQUIRED)
#define CDREF_FMA_COMPILED 1
#else
#define CDREF_FMA_COMPILED 0
#endif
#if (defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))) && !CDREF_FMA_COMPILED
#define CDREF_FMA_CLONES 1
inline bool cpu_fma() { return __builtin_cpu_supports("fma"); }
#else
#define CDREF_FMA_CLONES 0
constexpr bool cpu_fma() {
#if CDREF_FMA_COMPILED
  return true;
#else
  return false;
#endif
}
#endif

// f(FusedProduct{}) in a copy compiled for the FMA extension (CDREF_FMA_CLONES: every call in
// it inlined, so that std::fma is the instruction there; otherwise as built), and
// with_products(f): that copy where the CPU has the instruction, f(SplitProduct{}) where it does
// not. f takes the policy by value (a generic lambda: [&](auto mul) { return g<decltype(mul)>(...); }).
//
// Flat: where the whole build is compiled for the extension, whether the fused path is still a
// function of its own with every call flattened into it, as the run-time copy is. Only the paths
// measured faster so ask for it: sphere-triangle's double-word certificates and its first look's
// classification, triangle-triangle's double-word decisions (filters/triangle_words.hpp), the
// HotWords formulations (words.hpp), the box casts' double-word classification
// (filters/box_cast_words.hpp: measured on the oriented box; the axis-aligned box's is flattened
// alike and was not measured apart), the sphere casts' double-word sigma
// (oracle/sphere_casts.hpp) and the oracle's first double on a hit (oracle/enter.hpp). Without it
// sphere-triangle's oracle took 1.4 times as long near touching, ray-obb-cast's grazing
// classification 1.23 times, the sphere casts' near-tangent classification 1.08 times and the fan
// and polygon casts' lambda_enter near edges 1.09-1.10 times (the last three against a build with
// the FMA copies flattened everywhere, each query group in a unit of its own: `cdref report`,
// three runs alternated, 2026-12-05). Elsewhere a flattened copy measured no faster, and it costs
// compile time and code.
#if CDREF_FMA_CLONES
template <class Fn>
[[gnu::target("fma"), gnu::flatten, gnu::noinline]] auto fused_call(const Fn& f) {
  return f(FusedProduct{});
}
#else
template <class Fn>
auto fused_call(const Fn& f) {
  return f(FusedProduct{});
}
#if defined(__GNUC__)
template <class Fn>
[[gnu::flatten, gnu::noinline]] auto flat_fused_call(const Fn& f) {
  return f(FusedProduct{});
}
#else
template <class Fn>
auto flat_fused_call(const Fn& f) {
  return f(FusedProduct{});
}
#endif
#endif
template <bool Flat = false, class Fn>
auto with_products(const Fn& f) {
#if CDREF_FMA_CLONES
  if (cpu_fma()) return fused_call(f);
  return f(SplitProduct{});
#else
  if constexpr (cpu_fma()) {  // known when compiling: one copy
    if constexpr (Flat)
      return flat_fused_call(f);
    else
      return fused_call(f);
  } else {
    return f(SplitProduct{});
  }
#endif
}

// f() in the copy compiled for the FMA extension where the CPU has it (std::fma an instruction
// there instead of a call into libm), else as built (Flat: as with_products). std::fma rounds
// once either way, so the values are the same; only the time differs.
template <bool Flat = false, class Fn>
auto with_fma(const Fn& f) {
#if CDREF_FMA_CLONES
  if (cpu_fma()) return fused_call([&](FusedProduct) { return f(); });
  return f();
#else
  if constexpr (Flat && cpu_fma())
    return flat_fused_call([&](FusedProduct) { return f(); });
  else
    return f();
#endif
}

// Double-word arithmetic (Mul: the exact product's policy above; Dekker's by default).
template <class Mul = SplitProduct, class F>
Pair<F> mul_pair(const Pair<F>& x, const Pair<F>& y) {
  const Pair<F> p = Mul::prod(x.hi, y.hi);
  return fast_two_sum(p.hi, F(p.lo + F(x.hi * y.lo + x.lo * y.hi)));
}

template <class Mul = SplitProduct, class F>
Pair<F> div_pair(const Pair<F>& x, const Pair<F>& y) {
  const F t = x.hi / y.hi;
  const Pair<F> p = Mul::prod(t, y.hi);
  const F rem = F(F(F(x.hi - p.hi) - p.lo) + x.lo) - t * y.lo;
  const F corr = rem / y.hi;
  if (!std::isfinite(corr)) return {t, F(0)};  // t itself at the edge of the range
  return fast_two_sum(t, corr);
}

template <class Mul = SplitProduct, class F>
Pair<F> recip_pair(const Pair<F>& y) {
  const F t = F(1) / y.hi;
  const Pair<F> p = Mul::prod(t, y.hi);
  const F e = F(F(1) - p.hi) - p.lo;
  return fast_two_sum(t, F(F(e - t * y.lo) * t));
}

template <class Mul = SplitProduct, class F>
Pair<F> sqrt_pair(const Pair<F>& x) {
  if (!(x.hi > F(0))) return {F(0), F(0)};
  const F y = std::sqrt(x.hi);
  const Pair<F> p = Mul::prod(y, y);
  const F e = F(F(x.hi - p.hi) - p.lo) + x.lo;
  return fast_two_sum(y, F(e / F(2 * y)));
}

}  // namespace cdref::eft
