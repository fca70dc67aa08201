// cdref/exact/quadratic.hpp - exact values a + b sqrt(d) over an exact field T.
//
// Every quantity of Sections 3.1-3.2 that needs a square root needs just one per value:
// a distance sqrt(v.v), a hit parameter (-s.r - sqrt(sigma)) / |r|^2, a witness point
// c + rho v / sqrt(v.v). With a, b, d rational, such a value is an element of the
// quadratic field Q(sqrt(d)), closed under + - * / for a fixed d, with an exact sign:
//   sign(a + b sqrt d): if a and b sqrt d have the same sign (or one is zero) it is that
//   sign; otherwise compare a^2 with b^2 d.
// So a rational type without a square root (CGAL::Gmpq, CGAL::Epeck::FT) runs the
// chapter's algorithms unchanged with Quad<T> as its sqrt type, exactly, and no value
// ever passes through a double square root.
//
// Two values combine only when they share the radicand d (or one of them is rational);
// mixing fields is a logic error and throws std::logic_error.
#pragma once

#include <Eigen/Core>
#include <stdexcept>

namespace cdref {

template <class T>
class Quad {
 public:
  Quad() : a_(0), b_(0), d_(0) {}
  Quad(int x) : a_(x), b_(0), d_(0) {}  // NOLINT: implicit, like the field's own literals
  Quad(const T& x) : a_(x), b_(0), d_(0) {}  // NOLINT
  Quad(const T& a, const T& b, const T& d) : a_(a), b_(b), d_(d) {
    if (d_ < T(0)) throw std::domain_error("cdref::Quad: negative radicand");
    normalize();
  }

  // sqrt(d) for d >= 0.
  static Quad sqrt_of(const T& d) { return Quad(T(0), T(1), d); }

  const T& a() const { return a_; }
  const T& b() const { return b_; }
  const T& d() const { return d_; }
  bool is_rational() const { return b_ == T(0); }

  // The exact sign of a + b sqrt(d).
  int sign() const { return sign_of(a_, b_, d_); }

  // The exact sign of (this - t) for a rational t.
  int compare(const T& t) const { return sign_of(T(a_ - t), b_, d_); }

  Quad operator-() const { return raw(T(-a_), T(-b_), d_); }

  friend Quad operator+(const Quad& x, const Quad& y) {
    return raw(T(x.a_ + y.a_), T(x.b_ + y.b_), common(x, y));
  }
  friend Quad operator-(const Quad& x, const Quad& y) {
    return raw(T(x.a_ - y.a_), T(x.b_ - y.b_), common(x, y));
  }
  friend Quad operator*(const Quad& x, const Quad& y) {
    const T d = common(x, y);
    return raw(T(x.a_ * y.a_ + x.b_ * y.b_ * d), T(x.a_ * y.b_ + x.b_ * y.a_), d);
  }
  friend Quad operator/(const Quad& x, const Quad& y) {
    if (y.is_rational()) {
      if (y.a_ == T(0)) throw std::domain_error("cdref::Quad: division by zero");
      return raw(T(x.a_ / y.a_), T(x.b_ / y.a_), x.d_);
    }
    const T d = common(x, y);
    const T norm = y.a_ * y.a_ - y.b_ * y.b_ * d;  // (c + e sqrt d)(c - e sqrt d)
    if (norm == T(0)) {
      // d is a square and the conjugate c - e sqrt(d) vanishes: sqrt(d) = c / e, y = 2c.
      if (y.sign() == 0) throw std::domain_error("cdref::Quad: division by zero");
      const T root_d = y.a_ / y.b_;
      return Quad(T((x.a_ + x.b_ * root_d) / (y.a_ + y.a_)));
    }
    return raw(T((x.a_ * y.a_ - x.b_ * y.b_ * d) / norm), T((x.b_ * y.a_ - x.a_ * y.b_) / norm), d);
  }
  Quad& operator+=(const Quad& y) { return *this = *this + y; }
  Quad& operator-=(const Quad& y) { return *this = *this - y; }
  Quad& operator*=(const Quad& y) { return *this = *this * y; }
  Quad& operator/=(const Quad& y) { return *this = *this / y; }

  // The exact sign of x - y for values of any two quadratic fields (x = a + b sqrt p,
  // y = c + e sqrt q with p != q): with X = (a - c) + b sqrt p and Y = -e sqrt q, when X and
  // Y differ in sign the larger magnitude wins, and X^2 - Y^2 = ((a - c)^2 + b^2 p - e^2 q)
  // + 2 (a - c) b sqrt p is again a value of one field. Used where values of several
  // fields meet (the first of several hits, the deepest of several contacts).
  friend int compare_fields(const Quad& x, const Quad& y) {
    if (x.is_rational() || y.is_rational() || x.d_ == y.d_) return (x - y).sign();
    const T A = x.a_ - y.a_;
    const int sx = sign_of(A, x.b_, x.d_);
    const int sy = -sgn(y.b_);
    if (sx == 0) return sy;
    if (sy == 0 || sx == sy) return sx;
    const int z = sign_of(T(A * A + x.b_ * x.b_ * x.d_ - y.b_ * y.b_ * y.d_), T(T(2) * A * x.b_), x.d_);
    return sx > 0 ? z : -z;
  }

  friend bool operator<(const Quad& x, const Quad& y) { return (x - y).sign() < 0; }
  friend bool operator>(const Quad& x, const Quad& y) { return (x - y).sign() > 0; }
  friend bool operator<=(const Quad& x, const Quad& y) { return (x - y).sign() <= 0; }
  friend bool operator>=(const Quad& x, const Quad& y) { return (x - y).sign() >= 0; }
  friend bool operator==(const Quad& x, const Quad& y) { return (x - y).sign() == 0; }
  friend bool operator!=(const Quad& x, const Quad& y) { return (x - y).sign() != 0; }

 private:
  static Quad raw(const T& a, const T& b, const T& d) {
    Quad q;
    q.a_ = a;
    q.b_ = b;
    q.d_ = d;
    q.normalize();
    return q;
  }
  void normalize() {
    if (b_ == T(0) || d_ == T(0)) {
      b_ = T(0);
      d_ = T(0);
    }
  }
  static T common(const Quad& x, const Quad& y) {
    if (x.is_rational()) return y.d_;
    if (y.is_rational() || x.d_ == y.d_) return x.d_;
    throw std::logic_error("cdref::Quad: operands from different quadratic fields");
  }
  static int sgn(const T& x) { return x > T(0) ? 1 : (x < T(0) ? -1 : 0); }
  static int sign_of(const T& a, const T& b, const T& d) {
    const int sa = sgn(a);
    const int sb = (d == T(0)) ? 0 : sgn(b);
    if (sb == 0) return sa;
    if (sa == 0 || sa == sb) return sb;
    const T lhs = a * a;
    const T rhs = b * b * d;
    return lhs > rhs ? sa : (lhs < rhs ? sb : 0);
  }

  T a_, b_, d_;
};

}  // namespace cdref

namespace Eigen {
template <class T>
struct NumTraits<cdref::Quad<T>> {
  using Real = cdref::Quad<T>;
  using NonInteger = cdref::Quad<T>;
  using Nested = cdref::Quad<T>;
  using Literal = cdref::Quad<T>;
  static inline Real epsilon() { return Real(0); }
  static inline Real dummy_precision() { return Real(0); }
  static inline int digits10() { return 0; }
  enum {
    IsInteger = 0,
    IsSigned = 1,
    IsComplex = 0,
    RequireInitialization = 1,
    ReadCost = 20,
    AddCost = 300,
    MulCost = 500
  };
};
}  // namespace Eigen
