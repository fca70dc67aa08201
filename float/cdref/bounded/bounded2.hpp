// cdref/bounded/bounded2.hpp - a double-word number (an unevaluated sum hi + lo of two
// doubles) with a rigorous bound on its error: the second stage of the staged evaluation,
// the one that certifies the correct rounding of square roots and quotients.
//
// cdref::Bounded (bounded.hpp) carries a double and an error of a few ulps: enough to
// decide most signs, too wide to round a square root correctly (that needs the error
// below the distance to the nearest rounding midpoint, half an ulp or much less). A
// Bounded2 value (hi, lo, e) says: the exact value x of this quantity satisfies
// |x - (hi + lo)| <= e, and hi + lo is normalized (hi = fl(hi + lo)), so the error of an
// operation is of the order of u^2 times its operands (u = 2^-53) instead of u.
//
// Operations (u = 2^-53; every rounding error of one IEEE operation with result r is at
// most u |r| in round to nearest, plus eta = 2^-1074 for a product or quotient that
// underflows; a sum that underflows is exact):
//   a + b: (s, t) = two_sum(a.hi, b.hi) is exact; w1 = fl(t + a.lo), w = fl(w1 + b.lo)
//          round twice, and two_sum gives each rounding error r1, r2 exactly;
//          (hi, lo) = two_sum(s, w) is exact. So a + b = hi + lo + r1 + r2 exactly and
//          e' = ea + eb + |r1| + |r2| (0 when both roundings were exact: a sum of exact
//          values that fits in a double word stays exact, ties included).
//   a * b: exactly 0 when either factor is an exact 0. Otherwise, with a = ah + al, b = bh + bl: (p, pe) = two_prod(ah, bh) is exact when
//          |p| >= 2^-968 (then ah bh - p is a multiple of 2^-1073 below 2^53 of them),
//          else off by at most eta; c1 = fl(ah bl), c2 = fl(al bh), al bl left out;
//          w1 = fl(pe + c1), w = fl(w1 + c2); (hi, lo) = two_sum(p, w). The propagated
//          error of exact values x = a + da, y = b + db is |a db + b da + da db| <=
//          (|ah| + |al|) eb + (|bh| + |bl|) ea + ea eb (plus 3 eta: these three products of
//          the bound may underflow, and a bound that underflows to 0 would claim exactness), so
//          e' = that + |al| |bl| + u (|c1| + |c2| + |w1| + |w|) + 3 eta (c1, c2, al bl
//          may underflow), plus eta for pe when |p| < 2^-968. When exactly one of al, bl is
//          nonzero (a double word times a double y, the low part x): c = fl(x y) and its
//          error ce = fma(x, y, -c) (exact when |c| >= 2^-968, else off by at most eta), and
//          (w, we) = two_sum(pe, c), so that e' = that + |ce| + |we| (+ eta): 0 where both are
//          exact (a difference of doubles on a rounding midpoint, times 1, stays exact and
//          rounds to even rather than being left uncertain).
//   a / b: q = fl(fl(ah / bh) + correction) (one step of long division), then bounded
//          a posteriori: the residual R = a - q b is computed with the operations above
//          (q is an exact double), and with X, Y the exact values,
//          |X/Y - q| <= |X - q Y| / |Y| <= (|R| + eR + ea + |q| eb) / (|b| - eb),
//          requiring |b| > eb (else the divisor may be zero: uncertain).
//   sqrt a: y = sqrt(ah) refined by one Newton step y' = y + (a - y^2) / (2 y) in double
//          words, then bounded a posteriori the same way: with R = a - y'^2 (operations
//          above, y' an exact double word) and X the exact value,
//          |sqrt(X) - y'| = |X - y'^2| / (sqrt(X) + y') <= (|R| + eR + ea) / y'.
//          When a may be zero (a.hi <= 0, or the bound reaches zero) the value is
//          0 or sqrt(a.hi) with e' = sqrt(|a| + ea).
// The bound is itself computed in double: every bound expression is a sum of at most
// eight nonnegative terms, each rounded at most three times, so multiplying by
// grow = 1 + 16u covers its own rounding. A non-finite part makes every use uncertain.
//
// Signs: certain when |hi| > |lo| + e (then sign = sign(hi)), or when hi = lo = e = 0.
// Lenient signs (the robust tier's values only, robust/words.hpp): while a Bounded2::Lenient
// guard lives on the thread, a sign too close to call is answered by the double word's own
// sign (that of hi) instead of throwing. The flag is read on that path alone, so certain signs
// cost nothing more; the oracle never sets it, and its answers stay certain or uncertain.
// Rounding to double: hi is the double nearest to hi + lo; the exact value rounds to hi
// when [v - e, v + e] lies strictly inside hi's rounding interval (the midpoints to both
// neighbours), checked with the differences to the midpoints computed exactly; an exact
// value (e = 0) on a midpoint rounds to the even neighbour, as IEEE does. Rounding to float
// and to long double: the same test against the midpoints of the float or long double nearest
// hi + lo (exact doubles for a float, exact double words for an x87 long double); a value on
// a midpoint is uncertain there (left to the exact path).
#pragma once

#include <Eigen/Core>
#include <bit>
#include <cstdint>
#include <cdref/number_traits.hpp>
#include <cmath>
#include <limits>
#include <string>

#include "bounded.hpp"

namespace cdref {

/// A double word with a rigorous bound on its error (the derivation above).
class Bounded2 {
 public:
  static constexpr double u = 0x1p-53;
  static constexpr double eta = 0x1p-1074;
  static constexpr double grow = 1 + 16 * u;
  static constexpr double exact_product = 0x1p-968;  // two_prod is exact at and above

  Bounded2() = default;
  Bounded2(double x) : hi_(x) {}  // NOLINT: an exact input
  Bounded2(int x) : hi_(x) {}     // NOLINT
  // The exact value hi + lo, for hi = fl(hi + lo) (a long double split into two doubles).
  static Bounded2 exact_pair(double hi, double lo) { return make(hi, lo, 0); }
  // A value known to lie within e of hi + lo, for hi = fl(hi + lo) (a double word computed
  // elsewhere with its own bound, e >= 0).
  static Bounded2 within(double hi, double lo, double e) { return make(hi, lo, e); }

  double hi() const { return hi_; }
  double lo() const { return lo_; }
  double bound() const { return e_; }
  bool finite() const { return std::isfinite(hi_) && std::isfinite(lo_) && std::isfinite(e_); }

  [[gnu::always_inline]] friend Bounded2 operator-(const Bounded2& a) { return make(-a.hi_, -a.lo_, a.e_); }
  [[gnu::always_inline]] friend Bounded2 operator+(const Bounded2& a, const Bounded2& b) {
    double s, t, w1, r1, w, r2;
    two_sum(a.hi_, b.hi_, s, t);
    two_sum(t, a.lo_, w1, r1);  // the two roundings, each with its exact error
    two_sum(w1, b.lo_, w, r2);
    Bounded2 r;
    two_sum(s, w, r.hi_, r.lo_);
    const double err = a.e_ + b.e_ + std::fabs(r1) + std::fabs(r2);
    r.e_ = err == 0 ? 0 : err * grow;
    return r;
  }
  [[gnu::always_inline]] friend Bounded2 operator-(const Bounded2& a, const Bounded2& b) { return a + (-b); }
  [[gnu::always_inline]] friend Bounded2 operator*(const Bounded2& a, const Bounded2& b) {
    if (a.exact_zero() || b.exact_zero()) return Bounded2(0.0);  // exactly 0, whatever the other
    const double p = a.hi_ * b.hi_;
    const double pe = std::fma(a.hi_, b.hi_, -p);
    double err = (std::fabs(p) >= exact_product || (p == 0 && (a.hi_ == 0 || b.hi_ == 0))) ? 0 : eta;
    double w = pe;
    if ((a.lo_ == 0) != (b.lo_ == 0)) {
      // one factor is a double y, the other's low part x: x y = c + ce exactly (fma, above
      // the underflow of the error term) and pe + c = w + we exactly (two_sum), so only what
      // those leave is error: none where they are exact (a double word times 1 or 2^k, a
      // difference of doubles on a rounding midpoint times a unit axis)
      const double x = a.lo_ != 0 ? a.lo_ : b.lo_;
      const double y = a.lo_ != 0 ? b.hi_ : a.hi_;
      const double c = x * y;
      const double ce = std::fma(x, y, -c);
      double we;
      two_sum(pe, c, w, we);
      err += std::fabs(ce) + std::fabs(we) + (std::fabs(c) >= exact_product ? 0 : eta);
    } else if (a.lo_ != 0) {
      const double c1 = a.hi_ * b.lo_, c2 = a.lo_ * b.hi_;
      const double w1 = pe + c1;
      w = w1 + c2;
      err += std::fabs(a.lo_) * std::fabs(b.lo_) +
             u * (std::fabs(c1) + std::fabs(c2) + std::fabs(w1) + std::fabs(w)) + 3 * eta;
    }
    if (a.e_ != 0 || b.e_ != 0)
      err += (std::fabs(a.hi_) + std::fabs(a.lo_)) * b.e_ + (std::fabs(b.hi_) + std::fabs(b.lo_)) * a.e_ +
             a.e_ * b.e_ + 3 * eta;  // each of the three products may underflow
    Bounded2 r;
    two_sum(p, w, r.hi_, r.lo_);
    r.e_ = err == 0 ? 0 : err * grow;
    return r;
  }
  friend Bounded2 operator/(const Bounded2& a, const Bounded2& b) {
    if (!a.finite() || !b.finite()) throw uncertain();
    const double bmag = std::fabs(b.hi_) - std::fabs(b.lo_);  // |b| >= this, up to a rounding
    const double bmin = bmag * (1 - 2 * u) - b.e_ * grow;     // |exact divisor| >= bmin
    if (!(bmin > 0)) throw uncertain();
    // q = q1 + q2 as a double word: q1 = a.hi / b.hi, q2 from the remainder.
    const double q1 = a.hi_ / b.hi_;
    const Bounded2 rem1 = exact_part(a) - exact_part(b) * Bounded2(q1);
    const double q2 = rem1.hi_ / b.hi_;
    Bounded2 q;
    two_sum(q1, q2, q.hi_, q.lo_);
    // a posteriori: R = a - q b on the exact parts
    const Bounded2 R = exact_part(a) - exact_part(b) * q;
    const double qmag = std::fabs(q.hi_) + std::fabs(q.lo_);
    const double num = (std::fabs(R.hi_) + std::fabs(R.lo_) + R.e_ + a.e_ + qmag * b.e_ + (b.e_ != 0 ? eta : 0)) * grow;
    q.e_ = num == 0 ? 0 : (num / bmin) * grow + eta;
    if (!q.finite()) throw uncertain();
    return q;
  }
  Bounded2& operator+=(const Bounded2& b) { return *this = *this + b; }
  Bounded2& operator-=(const Bounded2& b) { return *this = *this - b; }
  Bounded2& operator*=(const Bounded2& b) { return *this = *this * b; }
  Bounded2& operator/=(const Bounded2& b) { return *this = *this / b; }

  friend Bounded2 sqrt(const Bounded2& a) { return root(a); }
  static Bounded2 root(const Bounded2& a) {
    if (!a.finite()) throw uncertain();
    if (a.hi_ == 0 && a.lo_ == 0 && a.e_ == 0) return Bounded2(0.0);
    const double amag = std::fabs(a.hi_) + std::fabs(a.lo_);
    if (!(a.hi_ > 0) || !(a.hi_ - std::fabs(a.lo_) > a.e_ * grow)) {  // a may be zero
      if ((a.hi_ + std::fabs(a.lo_) + a.e_ * grow) * grow < 0) throw uncertain();  // negative
      Bounded2 r(std::sqrt(std::max(a.hi_, 0.0)));
      r.e_ = std::sqrt((amag + a.e_) * grow) * grow;
      return r;
    }
    const double y = std::sqrt(a.hi_);
    const Bounded2 r1 = exact_part(a) - Bounded2(y) * Bounded2(y);
    const double corr = r1.hi_ / (2 * y);
    Bounded2 out;
    two_sum(y, corr, out.hi_, out.lo_);
    const Bounded2 R = exact_part(a) - out * out;
    const double num = (std::fabs(R.hi_) + std::fabs(R.lo_) + R.e_ + a.e_) * grow;
    const double ymin = (out.hi_ - std::fabs(out.lo_)) * (1 - 2 * u);
    if (!(ymin > 0)) throw uncertain();
    out.e_ = num == 0 ? 0 : (num / ymin) * grow + eta;
    return out;
  }

  // The sign of the exact value, or uncertain.
  int sign() const {
    const int s = sign_or_2(*this);
    if (s == 2) throw uncertain();
    return s;
  }
  // While one lives, signs too close to call take the double word's own sign (header).
  class Lenient {
   public:
    Lenient() : was_(lenient_flag()) { lenient_flag() = true; }
    ~Lenient() { lenient_flag() = was_; }
    Lenient(const Lenient&) = delete;
    Lenient& operator=(const Lenient&) = delete;

   private:
    bool was_;
  };
  friend bool operator<(const Bounded2& a, const Bounded2& b) { return (a - b).sign() < 0; }
  friend bool operator>(const Bounded2& a, const Bounded2& b) { return (a - b).sign() > 0; }
  friend bool operator<=(const Bounded2& a, const Bounded2& b) { return (a - b).sign() <= 0; }
  friend bool operator>=(const Bounded2& a, const Bounded2& b) { return (a - b).sign() >= 0; }
  friend bool operator==(const Bounded2& a, const Bounded2& b) { return (a - b).sign() == 0; }
  friend bool operator!=(const Bounded2& a, const Bounded2& b) { return !(a == b); }

  // |x|, min and max need no decision: each is 1-Lipschitz, so the computed operands' value
  // with the larger of their bounds bounds the exact result (a non-finite operand makes the
  // result non-finite: min and max of doubles would drop a NaN). Where the order is certain,
  // min and max return the operand itself, with its own bound (an exact 0 stays exact). (cdref's algorithms call abs_of,
  // min_of and max_of for them, found here by argument-dependent lookup). The values are
  // compared as the double words they are (hi first, then lo: both are normalized).
  // x > 0 where that is certain (book/common.hpp): never throwing, and never lenient.
  friend bool surely_positive(const Bounded2& x) {
    return x.finite() && x.hi_ > 0 && x.hi_ * (1 - 2 * u) > (std::fabs(x.lo_) + x.e_) * grow;
  }
  friend Bounded2 abs_of(const Bounded2& a) { return a.hi_ < 0 || (a.hi_ == 0 && a.lo_ < 0) ? -a : a; }
  friend Bounded2 max_of(const Bounded2& a, const Bounded2& b) {
    if (!a.finite() || !b.finite()) return not_finite();  // a NaN must not be dropped
    const int s = sign_or_2(a - b);  // the larger operand itself when certain
    if (s != 2) return s >= 0 ? a : b;
    Bounded2 r = word_less(a, b) ? b : a;
    r.e_ = std::max(a.e_, b.e_);
    return r;
  }
  friend Bounded2 min_of(const Bounded2& a, const Bounded2& b) {
    if (!a.finite() || !b.finite()) return not_finite();
    const int s = sign_or_2(a - b);
    if (s != 2) return s <= 0 ? a : b;
    Bounded2 r = word_less(a, b) ? a : b;
    r.e_ = std::max(a.e_, b.e_);
    return r;
  }

  // The exact value rounded to nearest double, or uncertain.
  double rounded() const {
    double r;
    if (!try_rounded(r)) throw uncertain();
    return r;
  }
  // The same without an exception (false: uncertain), for callers with another path.
  bool try_rounded(double& out) const {
    if (!finite()) return false;
    if (lo_ == 0 && e_ == 0) {
      out = hi_ + 0.0;  // an exact zero rounds to +0, never -0
      return true;
    }
    // Half-gaps are powers of two (exact). hi's rounding interval is
    // (hi - below, hi + above); the value lies in [hi + lo - e, hi + lo + e].
    double below, above;
    const double a = std::fabs(hi_);
    if (a >= 0x1p-1021 && a < std::numeric_limits<double>::max()) {
      // a normal number off the first binade and below the largest: its neighbours from
      // the bit pattern (no library call); the gaps are exact
      const std::uint64_t b = std::bit_cast<std::uint64_t>(a);
      const double gu = (std::bit_cast<double>(b + 1) - a) / 2, gd = (a - std::bit_cast<double>(b - 1)) / 2;
      above = hi_ > 0 ? gu : gd;
      below = hi_ > 0 ? gd : gu;
    } else {
      const double inf = std::numeric_limits<double>::infinity();
      const double dn = std::nextafter(hi_, -inf), up = std::nextafter(hi_, inf);
      below = std::isinf(dn) ? (up - hi_) / 2 : (hi_ - dn) / 2;
      above = std::isinf(up) ? (hi_ - dn) / 2 : (up - hi_) / 2;
    }
    // An exact value on a midpoint: ties to even (the neighbour with an even last bit).
    if (e_ == 0 && (lo_ == above || -lo_ == below) && above > 0 && below > 0) {
      const double inf = std::numeric_limits<double>::infinity();
      const double other = std::nextafter(hi_, lo_ > 0 ? inf : -inf);
      if (std::isinf(other)) return false;  // the overflow threshold: left to the exact path
      out = (std::bit_cast<std::uint64_t>(hi_) & 1) == 0 ? hi_ : other;
      return true;
    }
    // above - lo and below + lo: |lo| <= half an ulp of hi, so each is a sum of two
    // numbers within a factor 2^54 of one another, rounded once: shrink it by 2u.
    const double room = std::min(above - lo_, below + lo_) * (1 - 2 * u);
    if (!(e_ * grow < room)) return false;
    out = hi_;
    return true;
  }
  // The exact value rounded to nearest float, or uncertain.
  float rounded_float() const {
    if (!finite()) throw uncertain();
    if (hi_ == 0 && lo_ == 0 && e_ == 0) return 0.0f;  // +0, never -0
    const float f = static_cast<float>(hi_);
    if (!std::isfinite(f)) throw uncertain();
    // a value that rounds to a zero rounds to the zero of its own sign (hi's where that is certain)
    if (f == 0 && !((std::fabs(hi_) - std::fabs(lo_)) * (1 - 2 * u) > e_ * grow)) throw uncertain();
    const float inf = std::numeric_limits<float>::infinity();
    const float fdn = std::nextafter(f, -inf), fup = std::nextafter(f, inf);
    // the float rounding interval of f as doubles (a float midpoint has 25 bits: exact)
    const double mlo = std::isinf(fdn) ? double(f) - (double(fup) - double(f)) / 2 : (double(f) + double(fdn)) / 2;
    const double mhi = std::isinf(fup) ? double(f) + (double(f) - double(fdn)) / 2 : (double(f) + double(fup)) / 2;
    // The exact value X lies in [v - e, v + e], v = hi + lo. With D = v - mlo formed as a
    // double word on exact parts (its own bound dlo.e), X > mlo is certain when
    // D.hi - |D.lo| > D.e + e; likewise mhi - v. Both sides are compared with their
    // rounding covered: the left shrunk by 2u, the sum of nonnegative terms grown.
    const Bounded2 v = exact_part(*this);
    const Bounded2 dlo = v - Bounded2(mlo), dhi = Bounded2(mhi) - v;
    const bool inside_lo = (dlo.hi_ - std::fabs(dlo.lo_)) * (1 - 2 * u) > (dlo.e_ + e_) * grow;
    const bool inside_hi = (dhi.hi_ - std::fabs(dhi.lo_)) * (1 - 2 * u) > (dhi.e_ + e_) * grow;
    if (inside_lo && inside_hi) return f;
    throw uncertain();
  }
  // The exact value rounded to nearest long double, or uncertain. For the x87 extended format
  // (64 significant bits): f = fl(hi + lo) in long double is the long double nearest hi + lo
  // (one rounding of an exact sum). The ends of f's rounding interval, f - gd and f + gu (gd,
  // gu half the gaps to its neighbours, powers of two), have 65 bits: each is formed as a
  // double word from f's own exact split into the double nearest it and the rest (at most 11
  // bits, exact in a double), with the bound of that sum; then, as for a float, the exact
  // value's interval [v - e, v + e] must lie strictly inside. Kept well inside the range of
  // doubles (|hi| in [2^-900, 2^1000]) so that every part is a normal double; outside it,
  // and for a long double of another format than these two, uncertain.
  long double rounded_long_double() const {
    if constexpr (std::numeric_limits<long double>::digits == std::numeric_limits<double>::digits) {
      return rounded();
    } else {
      if (std::numeric_limits<long double>::digits != 64 || !finite()) throw uncertain();
      if (hi_ == 0 && lo_ == 0 && e_ == 0) return 0.0L;  // +0, never -0
      const double a = std::fabs(hi_);
      if (!(a >= 0x1p-900 && a <= 0x1p1000)) throw uncertain();
      const long double f = static_cast<long double>(hi_) + static_cast<long double>(lo_);
      const long double inf = std::numeric_limits<long double>::infinity();
      const double gd = static_cast<double>((f - std::nextafter(f, -inf)) / 2);
      const double gu = static_cast<double>((std::nextafter(f, inf) - f) / 2);
      const double fh = static_cast<double>(f);
      const double fl = static_cast<double>(f - static_cast<long double>(fh));
      const Bounded2 F = exact_pair(fh, fl);
      const Bounded2 v = exact_part(*this);
      const Bounded2 dlo = v - (F - Bounded2(gd)), dhi = (F + Bounded2(gu)) - v;
      const bool inside_lo = (dlo.hi_ - std::fabs(dlo.lo_)) * (1 - 2 * u) > (dlo.e_ + e_) * grow;
      const bool inside_hi = (dhi.hi_ - std::fabs(dhi.lo_)) * (1 - 2 * u) > (dhi.e_ + e_) * grow;
      if (inside_lo && inside_hi) return f;
      throw uncertain();
    }
  }

 private:
  bool exact_zero() const { return hi_ == 0 && lo_ == 0 && e_ == 0; }
  static bool& lenient_flag() {
    static thread_local bool on = false;
    return on;
  }
  // sign(), or 2 where it throws. Without an exception: min_of and max_of call it on every pair
  // they order, and on near-touching inputs (a box's projections on its own face axes, equal
  // in exact value, computed with different bounds) most of those pairs are too close to call;
  // throwing and catching there cost microseconds a query.
  static int sign_or_2(const Bounded2& x) {
    if (!x.finite()) return 2;
    if (x.hi_ == 0 && x.lo_ == 0 && x.e_ == 0) return 0;
    // |hi + lo| >= |hi| - |lo| exactly; the comparison is safe with a margin of 2u
    if (std::fabs(x.hi_) * (1 - 2 * u) > (std::fabs(x.lo_) + x.e_) * grow) return x.hi_ > 0 ? 1 : -1;
    if (lenient_flag()) return x.hi_ > 0 ? 1 : x.hi_ < 0 ? -1 : 0;  // (hi = 0 implies lo = 0)
    return 2;
  }
  static Bounded2 not_finite() {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return make(nan, nan, nan);
  }
  static bool word_less(const Bounded2& a, const Bounded2& b) { return a.hi_ < b.hi_ || (a.hi_ == b.hi_ && a.lo_ < b.lo_); }
  static void two_sum(double a, double b, double& s, double& t) {
    s = a + b;
    const double bb = s - a;
    t = (a - (s - bb)) + (b - bb);
  }
  static Bounded2 make(double hi, double lo, double e) {
    Bounded2 r;
    r.hi_ = hi;
    r.lo_ = lo;
    r.e_ = e;
    return r;
  }
  // hi + lo as an exact value (the error bound dropped).
  static Bounded2 exact_part(const Bounded2& a) { return make(a.hi_, a.lo_, 0); }

  double hi_ = 0, lo_ = 0, e_ = 0;
};

template <>
struct number_traits<Bounded2> {
  static constexpr bool is_exact = false;  // a filter: it answers or throws uncertain
  static constexpr sqrt_support sqrt_kind = sqrt_support::rounded;
  using sqrt_type = Bounded2;
  static Bounded2 sqrt(const Bounded2& x) { return Bounded2::root(x); }
  static bool is_finite(const Bounded2& x) { return x.finite(); }
  static double to_double(const Bounded2& x) { return x.rounded(); }
  static float to_float(const Bounded2& x) { return x.rounded_float(); }
  static std::string name() { return "Bounded2"; }
};
}  // namespace cdref

namespace Eigen {
template <>
struct NumTraits<cdref::Bounded2> {
  using Real = cdref::Bounded2;
  using NonInteger = cdref::Bounded2;
  using Nested = cdref::Bounded2;
  using Literal = cdref::Bounded2;
  static inline Real epsilon() { return Real(0); }
  static inline Real dummy_precision() { return Real(0); }
  static inline int digits10() { return 31; }
  enum { IsInteger = 0, IsSigned = 1, IsComplex = 0, RequireInitialization = 1, ReadCost = 3, AddCost = 20, MulCost = 20 };
};
}  // namespace Eigen
