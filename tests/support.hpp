// tests/support.hpp - what the templated tests share: the number-type lists, exact
// conversion of any value into CORE::Expr (so that results of every type are compared
// exactly with one another and with the expected answer), and ulp errors measured
// exactly.
#pragma once

#include <catch2/catch.hpp>
#include <cdref/exact.hpp>
#include <cdref/exact/long_double.hpp>
#include <cdref/float/mpfr.hpp>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

namespace cdref::test {

using Q = CGAL::Gmpq;
using QS = Quad<Q>;
using Lazy = CGAL::Epeck::FT;
using Expr = CORE::Expr;
using mpreal = mpfr::mpreal;

// The float types are run at these, the exact ones at these (tests list them by name in
// TEMPLATE_TEST_CASE, since Catch2's macros want the types spelled out).
#define CDREF_FLOAT_TYPES float, double, long double, mpfr::mpreal
#define CDREF_EXACT_TYPES CGAL::Gmpq, CGAL::Epeck::FT, CORE::Expr
#define CDREF_ALL_TYPES CDREF_FLOAT_TYPES, CDREF_EXACT_TYPES

inline Q q(const char* s) { return Q(std::string(s)); }

// ---- exact conversion to Gmpq of every float type (values are dyadic rationals) ----
inline Q exact_q(float x) { return Q(static_cast<double>(x)); }
inline Q exact_q(double x) { return Q(x); }
inline Q exact_q(long double x) {
  mpfr_t m;
  mpfr_init2(m, 64);
  mpfr_set_ld(m, x, MPFR_RNDN);  // exact: 64-bit significand
  Q r;
  mpfr_get_q(r.mpq(), m);
  mpfr_clear(m);
  return r;
}
inline Q exact_q(const mpreal& x) {
  Q r;
  mpfr_get_q(r.mpq(), x.mpfr_srcptr());
  return r;
}
inline Q exact_q(const Q& x) { return x; }
inline Q exact_q(const Lazy& x) {
  Q r;
  mpq_set(r.mpq(), exact::mpq_of(x));
  return r;
}

// ---- exact conversion to CORE::Expr of every value cdref produces ----
inline Expr to_expr(const Q& x) { return Expr(CORE::BigRat(x.mpq())); }
inline Expr to_expr(const Lazy& x) { return to_expr(exact_q(x)); }
inline Expr to_expr(const Expr& x) { return x; }
inline Expr to_expr(float x) { return Expr(static_cast<double>(x)); }
inline Expr to_expr(double x) { return Expr(x); }
inline Expr to_expr(long double x) { return to_expr(exact_q(x)); }
inline Expr to_expr(const mpreal& x) { return to_expr(exact_q(x)); }
template <class T>
Expr to_expr(const Quad<T>& x) {
  if (x.is_rational()) return to_expr(x.a());
  return to_expr(x.a()) + to_expr(x.b()) * CGAL::sqrt(to_expr(x.d()));
}

// An expected exact value a + b sqrt(d) with rational a, b, d.
struct X {
  Q a{0}, b{0}, d{0};
  X() = default;
  X(const Q& v) : a(v) {}                                       // NOLINT
  X(const char* v) : a(q(v)) {}                                 // NOLINT
  X(double v) : a(Q(v)) {}                                      // NOLINT
  X(int v) : a(Q(v)) {}                                         // NOLINT
  X(const Q& a_, const Q& b_, const Q& d_) : a(a_), b(b_), d(d_) {}
  Expr expr() const { return d == 0 || b == 0 ? to_expr(a) : to_expr(a) + to_expr(b) * CGAL::sqrt(to_expr(d)); }
};

template <class A, class B>
bool exact_equal(const A& x, const B& y) {
  return to_expr(x) == to_expr(y);
}

// ---- number-type facts for the tests ----
template <class T>
int precision_bits() {
  if constexpr (std::is_same_v<T, mpreal>)
    return static_cast<int>(mpreal::get_default_prec());
  else
    return std::numeric_limits<T>::digits;
}

template <class T>
T from_double(double x) {
  if constexpr (std::is_same_v<T, mpreal>)
    return mpreal(x);
  else
    return T(x);
}

template <class T>
Vec3<T> v3(double x, double y, double z) {
  return Vec3<T>(from_double<T>(x), from_double<T>(y), from_double<T>(z));
}

// ---- primitives written in doubles, moved to T (rounded) or to Gmpq (exactly): fields.hpp's
// rebind_with, so that every primitive it describes is covered ----
template <class T, class P>
auto convert_prim(const P& p) {
  return rebind_with<T>(p, [](double x) { return from_double<T>(x); });
}
template <class T>
Vec3<Q> exact_vec(const Vec3<T>& v) {
  return Vec3<Q>(exact_q(v[0]), exact_q(v[1]), exact_q(v[2]));
}
template <class P>
auto convert_prim_exact(const P& p) {
  return rebind_with<Q>(p, [](const auto& x) { return exact_q(x); });
}
template <class T>
bool finite_in(const Vec3<double>& v) {
  for (int i = 0; i < 3; ++i)
    if (!number_traits<T>::is_finite(from_double<T>(v[i]))) return false;
  return true;
}
// whether every coordinate of a primitive written in doubles is finite in T
template <class T, class P>
bool prim_finite(const P& p) {
  bool finite = true;
  for_each_value(p, [&](const auto& x) {
    if constexpr (requires { x.rows(); })
      finite = finite && finite_in<T>(x);
    else
      finite = finite && number_traits<T>::is_finite(from_double<T>(x));
  });
  return finite;
}

// A pair of primitives written in doubles, for the proximity checker.
template <class A, class B>
struct PairOf {
  A a;
  B b;
  template <class T>
  auto at() const {
    return std::pair{convert_prim<T>(a), convert_prim<T>(b)};
  }
  template <class T>
  bool finite() const {
    return prim_finite<T>(a) && prim_finite<T>(b);
  }
  template <class P>
  auto exact(const P& p) const {
    return std::pair{convert_prim_exact(p.first), convert_prim_exact(p.second)};
  }
};

// An exactly orthonormal rational frame from an integer quaternion q = (w, x, y, z), q != 0:
// the columns of R = M(q) / |q|^2.
inline std::array<Vec3<Q>, 3> rational_rotation(int w, int x, int y, int z) {
  const Q n = Q(w * w + x * x + y * y + z * z);
  const Q m[3][3] = {{Q(w * w + x * x - y * y - z * z), Q(2 * (x * y - w * z)), Q(2 * (x * z + w * y))},
                     {Q(2 * (x * y + w * z)), Q(w * w - x * x + y * y - z * z), Q(2 * (y * z - w * x))},
                     {Q(2 * (x * z - w * y)), Q(2 * (y * z + w * x)), Q(w * w - x * x - y * y + z * z)}};
  return {Vec3<Q>(m[0][0] / n, m[1][0] / n, m[2][0] / n), Vec3<Q>(m[0][1] / n, m[1][1] / n, m[2][1] / n),
          Vec3<Q>(m[0][2] / n, m[1][2] / n, m[2][2] / n)};
}

inline Q p2(int k) { return k >= 0 ? Q(std::ldexp(1.0, k)) : Q(1) / Q(std::ldexp(1.0, -k)); }

// 2^k exactly, for any k (split so that no factor leaves the double range).
inline Expr pow2(int k) {
  const int h = k / 2;
  return Expr(std::ldexp(1.0, h)) * Expr(std::ldexp(1.0, k - h));
}

// The error of a float-type value v against the exact value e, in ulps of v's own
// precision p at e: |v - e| / 2^(floor(log2 |e|) - p + 1). For e = 0 the unit is the ulp
// of `scale` instead. Non-finite v gives +infinity.
template <class T, class V>
double ulps(const V& v, const Expr& e, double scale = 1.0) {
  if (!number_traits<V>::is_finite(v)) return std::numeric_limits<double>::infinity();
  const Expr err = CGAL::abs(to_expr(v) - e);
  if (err == 0) return 0;
  const double mag = e == 0 ? scale : std::fabs(round_double(e));
  int ex = std::ilogb(mag);  // floor(log2 |e|), from the correctly rounded magnitude
  if (e != 0 && Expr(std::ldexp(1.0, ex)) > CGAL::abs(e)) --ex;  // |e| rounded up to a power of two
  const Expr ulp = pow2(ex - precision_bits<T>() + 1);
  const double r = round_double(Expr(err / ulp));
  return r;
}

}  // namespace cdref::test
