// cdref/robust/decision.hpp - a classification with its own certificate.
//
// Each robust query offers decide(...) beside its intersect/hit/cast/proximity. It returns
// the same classification those return, and says whether it is certain: certain == true
// is a promise, proven by the error bound derived in the query's header, that `value`
// equals the classification the book computes at an exact type on the same inputs (the
// F inputs taken exactly). certain == false says the decisive quantity lies within the
// stated error bound of the decision boundary, where the float answer may be wrong.
// Tests and campaigns count certain-but-wrong answers (there must be none) and report the
// share of uncertain ones: that is how "every misclassified case lies within the stated
// error bound of the decision boundary" is checked.
#pragma once

#include <cdref/fields.hpp>
#include <cdref/primitives.hpp>
#include <cdref/results.hpp>
#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

namespace cdref::robust {

struct Decision {
  bool value = false;
  bool certain = false;
};

// The certificates of the sphere queries are derived for inputs away from the ends of F's
// exponent range (their scaled squares and products neither overflow nor leave the normal
// range beyond the underflow terms the bounds carry). An input within 2^p of either end
// (p the precision: below 2^(emin + p) or above 2^(emax - p), for double 2^-968 and 2^971)
// makes decide() uncertain: the fuzz targets found certain-but-wrong answers of the double
// versions with inputs near 2^1009 and among subnormals.
namespace detail {
template <class F>
bool near_range_end(F x) {
  constexpr int p = std::numeric_limits<F>::digits;
  const F a = std::fabs(x);
  return a != F(0) && (a < std::ldexp(F(1), std::numeric_limits<F>::min_exponent + p) ||
                       a > std::ldexp(F(1), std::numeric_limits<F>::max_exponent - p));
}
template <class F>
bool near_range_end(const Vec3<F>& v) {
  return near_range_end(v[0]) || near_range_end(v[1]) || near_range_end(v[2]);
}
/// ... of any primitive: any of its coordinates (fields.hpp's for_each_value).
template <template <class> class P, class F>
bool near_range_end(const P<F>& p) {
  bool near = false;
  for_each_value(p, [&](const auto& x) { near = near || near_range_end(x); });
  return near;
}
// A primitive's number type (in unevaluated contexts).
template <template <class> class P, class F>
F scalar_of(const P<F>&);
}  // namespace detail

namespace detail {
// The largest and the smallest nonzero magnitude among the inputs, in three lanes (a vector's
// components each in its own, a scalar in the first) so that the comparisons do not wait on one
// another; NaN is passed over as before (max and min keep the lane's value, x > 0 is false).
template <class F>
struct Span {
  F hi[3] = {F(0), F(0), F(0)};
  F lo[3] = {std::numeric_limits<F>::infinity(), std::numeric_limits<F>::infinity(),
             std::numeric_limits<F>::infinity()};
  void add(F x, int k) {
    const F a = std::fabs(x);
    hi[k] = std::max(hi[k], a);
    lo[k] = std::min(lo[k], a > F(0) ? a : std::numeric_limits<F>::infinity());
  }
};
template <class F>
void span_of(F x, Span<F>& s) {
  s.add(x, 0);
}
template <class F>
void span_of(const Vec3<F>& v, Span<F>& s) {
  for (int i = 0; i < 3; ++i) s.add(v[i], i);
}
template <template <class> class P, class F>
void span_of(const P<F>& p, Span<F>& o) {
  for_each_value(p, [&](const auto& x) { span_of(x, o); });
}
}  // namespace detail

// d, made uncertain when an input lies near the ends of the exponent range, or when the
// inputs span more than a quarter of it (2^((emax - emin)/4): 2^511 for double): after
// scaling, squares of the smallest would leave the normal range (the fuzz targets found a
// certain-but-wrong double answer mixing 1 and 2^753).
namespace detail {
// 2^e as a constant expression (std::ldexp is a library call at run time).
template <class F>
constexpr F pow2c(int e) {
  F x(1);
  for (; e > 0; --e) x *= F(2);
  for (; e < 0; ++e) x /= F(2);
  return x;
}
}  // namespace detail

// Whether the inputs lie where the certificates are derived: no nonzero input within 2^p of
// either end of the exponent range, and the inputs spanning at most a quarter of it
// (2^((emax - emin)/4): 2^511 for double): after scaling, squares of the smallest would leave
// the normal range (the fuzz targets found a certain-but-wrong double answer mixing 1 and
// 2^753). The filters on the stable arithmetic (sphere-sphere, sphere-box, the sphere casts,
// Algorithm 3.2) are rigorous wherever their own range tests pass and need no such test: every
// entry point of those queries (the predicate, decide() and the full query) takes the filter's
// answer where it decides, so they classify alike everywhere (a fuzz target found the filter
// right and the double words wrong outside this range: decide() and the full query then
// disagreed, when only decide() took the filter).
template <class A, class B>
bool in_certified_range(const A& a, const B& b) {
  using F = std::decay_t<decltype(detail::scalar_of(a))>;
  detail::Span<F> sp;
  detail::span_of(a, sp);
  detail::span_of(b, sp);
  const F hi = std::max(std::max(sp.hi[0], sp.hi[1]), sp.hi[2]);
  const F lo = std::min(std::min(sp.lo[0], sp.lo[1]), sp.lo[2]);
  constexpr int p = std::numeric_limits<F>::digits;
  constexpr F low = detail::pow2c<F>(std::numeric_limits<F>::min_exponent + p);
  constexpr F high = detail::pow2c<F>(std::numeric_limits<F>::max_exponent - p);
  constexpr F quarter =
      detail::pow2c<F>((std::numeric_limits<F>::max_exponent - std::numeric_limits<F>::min_exponent) / 4);
  if (lo < low || hi > high) return false;  // (lo is infinite when every input is 0)
  return !(hi > F(0) && hi > lo * quarter);
}

// d, made uncertain outside in_certified_range.
template <class A, class B>
Decision within_range(Decision d, const A& a, const B& b) {
  if (!in_certified_range(a, b)) d.certain = false;
  return d;
}

// A float query evaluated at double (at F = float: the sphere and box casts, Algorithm 3.2,
// sphere-sphere and sphere-box): every
// float is a double, so the widened inputs are the same exact inputs, the double evaluation
// certifies the same exact classification, and each value is its double value rounded once to
// float. That value is within an ulp or two of double of the truth, so the float is the
// correctly rounded one unless the truth lies within those ulps of a midpoint between floats;
// the float formulation's own double words (pairs of floats, u^2 = 2^-48) carried thousands of
// float ulps of point, normal and witness at range and near tangency (`cdref campaign --query
// ray-sphere-cast --query segment-sphere-cast --query segment-sphere --impl robust-float`), and
// the box casts' entry point 1.3e4 at 10^8 box sizes.
namespace detail {
// a float primitive as the same primitive over double (exact)
template <class P>
auto widened(const P& p) {
  return rebind<double>(p);
}
// a double result with each value rounded to float
template <template <class> class R>
R<float> rounded(const R<double>& r) {
  return rounded_by<float>(r, [](double x) { return float(x); });
}
}  // namespace detail

}  // namespace cdref::robust
