// cdref/bounded/bounded.hpp - a double with a rigorous bound on its error: the first stage of
// the staged evaluation of any book template (cdref/robust/staged.hpp: the robust tier's
// certificates, and with the exact stage the oracle's generic path) and the number type of the
// oracle's hand filters. A number type like the others, in namespace cdref.
//
// A Bounded value (v, e) says: the exact value x of this quantity satisfies |x - v| <= e.
// Inputs are exact (e = 0). Each operation computes v in double, round to nearest, and a
// bound e' >= the propagated error plus the rounding error of v:
//   a + b:  |x - v| <= ea + eb + u |v| / (1 - u)
//   a * b:  exactly 0 when either factor is an exact 0; otherwise
//           |x - v| <= |a| eb + |b| ea + ea eb + u |v| / (1 - u) + eta
//   a / b:  needs |b| > eb;  <= (ea |b| + eb |a|) / (|b| (|b| - eb)) + u |v| / (1 - u) + eta
//   sqrt a: if a - ea > 0: <= ea / (sqrt(a - ea) + sqrt(a)) + u |v| / (1 - u)  (the root is
//           monotone, and its derivative at the lower end bounds the slope)
//           else (x may be 0): x lies in [0, sqrt(a + ea)], so |x - v| <= sqrt(a + ea)
// with u = 2^-53 and eta = 2^-1074 (the absolute error of an underflowing product or
// quotient). The bound itself is evaluated in double, so each is multiplied by (1 + 8u)
// (at most four nonnegative terms, each rounded once or twice: their relative error is
// below 6u) and its terms are nonnegative, so no cancellation can make it too small.
// A non-finite v or e makes every comparison uncertain.
//
// A comparison is certain when the sign of the difference is: d = a - b (a Bounded), and
// d.v - d.e > 0, d.v + d.e < 0, or d.v = d.e = 0 (both exact and equal). Otherwise it
// throws cdref::uncertain, and the caller runs the same code on an exact type. A value is
// known correctly rounded to double when e is below half the gap to both neighbours of v.
#pragma once

#include <Eigen/Core>
#include <cdref/number_traits.hpp>
#include <cmath>
#include <exception>
#include <limits>
#include <string>

namespace cdref {

/// Thrown by a comparison of bounded values (Bounded, Bounded2) whose sign the bound cannot
/// tell, and by a rounding it cannot certify: the caller runs the same code at the next stage.
struct uncertain : std::exception {
  const char* what() const noexcept override {
    return "cdref::uncertain: a bounded value cannot decide the comparison";
  }
};

/// A double with a rigorous bound on its error (the derivation above).
class Bounded {
 public:
  static constexpr double u = 0x1p-53;
  static constexpr double eta = 0x1p-1074;
  static constexpr double grow = 1 + 8 * u;

  Bounded() = default;
  Bounded(double x) : v_(x), e_(0) {}  // NOLINT: an exact input
  Bounded(int x) : v_(x), e_(0) {}     // NOLINT
  Bounded(double v, double e) : v_(v), e_(e) {}

  double value() const { return v_; }
  double bound() const { return e_; }
  bool finite() const { return std::isfinite(v_) && std::isfinite(e_); }

  friend Bounded operator-(const Bounded& a) { return {-a.v_, a.e_}; }
  friend Bounded operator+(const Bounded& a, const Bounded& b) {
    const double s = a.v_ + b.v_;
    return {s, (a.e_ + b.e_ + rounding(s)) * grow};
  }
  friend Bounded operator-(const Bounded& a, const Bounded& b) { return a + (-b); }
  friend Bounded operator*(const Bounded& a, const Bounded& b) {
    if (a.exact_zero() || b.exact_zero()) return Bounded(0.0);  // exactly 0, whatever the other
    const double p = a.v_ * b.v_;
    if (a.e_ == 0 && b.e_ == 0) return {p, (rounding(p) + eta) * grow};
    // the four products of the bound may underflow: one eta each, and one for p
    return {p, (std::fabs(a.v_) * b.e_ + std::fabs(b.v_) * a.e_ + a.e_ * b.e_ + rounding(p) + 5 * eta) * grow};
  }
  friend Bounded operator/(const Bounded& a, const Bounded& b) {
    const double ab = std::fabs(b.v_);
    if (!(ab > b.e_)) throw uncertain();  // the divisor may be zero
    if (a.exact_zero()) return Bounded(0.0);  // exactly 0 over a divisor that is not
    const double q = a.v_ / b.v_;
    // (ea |b| + eb |a|) / (|b| (|b| - eb)) = (ea + eb |a/b|) / (|b| - eb), with |a/b| <=
    // |q| (1 + u) / (1 - u) covered by grow, and eta for an underflowing eb |q|: written so
    // that no product of the bound underflows before the division by a small |b|
    const double prop = (a.e_ + b.e_ * std::fabs(q) * grow + (b.e_ != 0 ? eta : 0)) / ((ab - b.e_) * (1 - 2 * u));
    return {q, (prop * grow + rounding(q) + eta) * grow};
  }
  Bounded& operator+=(const Bounded& b) { return *this = *this + b; }
  Bounded& operator-=(const Bounded& b) { return *this = *this - b; }
  Bounded& operator*=(const Bounded& b) { return *this = *this * b; }
  Bounded& operator/=(const Bounded& b) { return *this = *this / b; }

  friend Bounded sqrt(const Bounded& a) { return root(a); }
  static Bounded root(const Bounded& a) {
    if (!a.finite()) throw uncertain();
    const double lo = a.v_ - a.e_;
    if (lo > 0) {
      const double r = std::sqrt(a.v_);
      // the lower end is computed with a rounding error: shrink it by a relative 2u
      const double prop = a.e_ / (std::sqrt(lo * (1 - 2 * u)) + r);
      return {r, (prop * grow + rounding(r)) * grow};
    }
    const double hi = (a.v_ + a.e_) * grow;
    if (hi < 0) throw uncertain();  // not a square root of a nonnegative quantity
    const double r = std::sqrt(std::max(a.v_, 0.0));
    return {r, std::sqrt(hi) * grow};
  }

  // The sign of the exact value, or uncertain.
  int sign() const {
    if (!finite()) throw uncertain();
    if (v_ - e_ > 0) return 1;
    if (v_ + e_ < 0) return -1;
    if (v_ == 0 && e_ == 0) return 0;
    throw uncertain();
  }
  friend bool operator<(const Bounded& a, const Bounded& b) { return (a - b).sign() < 0; }
  friend bool operator>(const Bounded& a, const Bounded& b) { return (a - b).sign() > 0; }
  friend bool operator<=(const Bounded& a, const Bounded& b) { return (a - b).sign() <= 0; }
  friend bool operator>=(const Bounded& a, const Bounded& b) { return (a - b).sign() >= 0; }
  friend bool operator==(const Bounded& a, const Bounded& b) {
    if (a.e_ == 0 && b.e_ == 0 && a.finite() && b.finite()) return a.v_ == b.v_;
    return (a - b).sign() == 0;
  }
  friend bool operator!=(const Bounded& a, const Bounded& b) { return !(a == b); }

  // x > 0 where that is certain (book/common.hpp's shortcuts): never throwing.
  friend bool surely_positive(const Bounded& x) { return x.finite() && x.v_ - x.e_ > 0; }

  // |x|, min and max need no decision: each is 1-Lipschitz, so the value of the computed
  // operands with the larger of their bounds bounds the exact result (cdref's algorithms call
  // abs_of, min_of and max_of for them, found here by argument-dependent lookup).
  friend Bounded abs_of(const Bounded& a) { return {std::fabs(a.v_), a.e_}; }
  // (a non-finite operand makes the result non-finite: std::max would drop a NaN)
  // (where the order is certain, the operand itself: an exact 0 stays exact)
  friend Bounded max_of(const Bounded& a, const Bounded& b) {
    if (!a.finite() || !b.finite()) return {std::numeric_limits<double>::quiet_NaN(), 0};
    const Bounded d = a - b;
    if (d.v_ - d.e_ >= 0) return a;
    if (d.v_ + d.e_ <= 0) return b;
    return {std::max(a.v_, b.v_), std::max(a.e_, b.e_)};
  }
  friend Bounded min_of(const Bounded& a, const Bounded& b) {
    if (!a.finite() || !b.finite()) return {std::numeric_limits<double>::quiet_NaN(), 0};
    const Bounded d = a - b;
    if (d.v_ - d.e_ >= 0) return b;
    if (d.v_ + d.e_ <= 0) return a;
    return {std::min(a.v_, b.v_), std::max(a.e_, b.e_)};
  }

  // The exact value rounded to nearest double, or uncertain.
  double rounded() const {
    if (!finite()) throw uncertain();
    if (e_ == 0) return v_ + 0.0;  // exact (an exact zero rounds to +0, never -0)
    const double inf = std::numeric_limits<double>::infinity();
    const double below = v_ - std::nextafter(v_, -inf), above = std::nextafter(v_, inf) - v_;
    if (e_ < 0.5 * std::min(below, above)) return v_;  // both gaps are powers of two: exact
    throw uncertain();
  }
  // The exact value rounded to nearest long double: an exact value is itself (every double
  // is a long double); any other is left to the next stage (its bound, a few ulps of a
  // double, is far wider than the long double's rounding interval).
  long double rounded_long_double() const {
    if (!finite() || e_ != 0) throw uncertain();
    return static_cast<long double>(v_ + 0.0);  // (+0 for an exact zero, never -0)
  }
  // The exact value rounded to nearest float, or uncertain.
  float rounded_float() const {
    if (!finite()) throw uncertain();
    if (v_ == 0 && e_ == 0) return 0.0f;  // +0, never -0
    const float f = static_cast<float>(v_);
    if (!std::isfinite(f)) throw uncertain();
    // a value that rounds to a zero rounds to the zero of its own sign: that sign must be certain
    if (f == 0 && !(std::fabs(v_) > e_)) throw uncertain();
    const float inf = std::numeric_limits<float>::infinity();
    // the float rounding interval of f, as doubles (a float midpoint has 25 bits: exact)
    // next to +-max the missing neighbour is max +- ulp: the overflow threshold
    const float dn = std::nextafter(f, -inf), up = std::nextafter(f, inf);
    const double lo = std::isinf(dn) ? double(f) - (double(up) - double(f)) / 2 : (double(f) + double(dn)) / 2;
    const double hi = std::isinf(up) ? double(f) + (double(f) - double(dn)) / 2 : (double(f) + double(up)) / 2;
    // v - lo and hi - v are differences of nearby doubles; shrink them by 2u to be safe
    const double room = std::min(v_ - lo, hi - v_) * (1 - 2 * u);
    if (e_ < room) return f;
    throw uncertain();
  }

 private:
  static double rounding(double v) { return std::fabs(v) * (u / (1 - u)); }
  bool exact_zero() const { return v_ == 0 && e_ == 0; }
  double v_ = 0, e_ = 0;
};

template <>
struct number_traits<Bounded> {
  static constexpr bool is_exact = false;  // a filter: it answers or throws uncertain
  static constexpr sqrt_support sqrt_kind = sqrt_support::rounded;
  using sqrt_type = Bounded;
  static Bounded sqrt(const Bounded& x) { return Bounded::root(x); }
  static bool is_finite(const Bounded& x) { return x.finite(); }
  static double to_double(const Bounded& x) { return x.rounded(); }
  static float to_float(const Bounded& x) { return x.rounded_float(); }
  static std::string name() { return "Bounded"; }
};
}  // namespace cdref

namespace Eigen {
template <>
struct NumTraits<cdref::Bounded> {
  using Real = cdref::Bounded;
  using NonInteger = cdref::Bounded;
  using Nested = cdref::Bounded;
  using Literal = cdref::Bounded;
  static inline Real epsilon() { return Real(0); }
  static inline Real dummy_precision() { return Real(0); }
  static inline int digits10() { return 15; }
  enum { IsInteger = 0, IsSigned = 1, IsComplex = 0, RequireInitialization = 1, ReadCost = 2, AddCost = 4, MulCost = 6 };
};
}  // namespace Eigen
