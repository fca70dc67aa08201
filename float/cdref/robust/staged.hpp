// cdref/robust/staged.hpp - the robust tier of any book template: the same algorithm run on
// number types that carry a rigorous error bound, answering with a certificate. No CGAL: the
// exact stage is added by cdref/exact/staged.hpp (the oracle's form of the same machinery).
//
// The derivation. Let f be an algorithm written over a number type T (a book template: its
// decisions are comparisons of values computed with + - * / and sqrt from the inputs). Run at
// a type whose every comparison either returns the sign of the exact difference or throws
// cdref::uncertain, and whose values round to a float type only when the rounding is certain,
// f takes exactly the branches it takes at an exact type. So where it returns, its
// classification is the exact one and every value it rounds is the exact value rounded
// correctly: no error analysis per algorithm, the bound travels with each number (CGAL's
// Filtered_predicate rests on the same observation). The stages:
//   1. cdref::Bounded (cdref/bounded/bounded.hpp): a double with a running error bound, a few
//      ulps after each operation. Decides every comparison that is not close to a tie; seldom
//      rounds a value that is not exact correctly to double, never to long double.
//   2. cdref::Bounded2 (bounded2.hpp): a double word with a bound of the order of 2^-106
//      relative. Decides the comparisons closer to a tie, rounds square roots and quotients
//      correctly to float, double and x87 long double.
// certify() runs them in turn and answers with the first that is certain, or with nothing:
// the robust tier then answers in its own float type F, uncertified (decide()'s certain =
// false). The oracle adds a third stage, the exact rationals, that always answers.
//
// Boundary cases. The inputs must be doubles exactly (float's are; a long double with more
// than 53 significant bits is not, and decide() and rounded() answer in F uncertified for it).
// An input the algorithm refuses (invalid_input: not finite, a zero direction, a degenerate
// shape) is refused at the first stage as in F: exceptions other than cdref::uncertain pass
// through. Overflow and underflow are in the bounds (a non-finite value or bound makes every
// comparison uncertain; an underflowing product or quotient adds 2^-1074), so near the ends
// of the exponent range the stages are uncertain, not wrong.
#pragma once

#include <cdref/fields.hpp>
#include <cdref/bounded/bounded.hpp>
#include <cdref/bounded/bounded2.hpp>
#include <cdref/robust/decision.hpp>
#include <optional>
#include <tuple>
#include <utility>
#include <type_traits>

namespace cdref::staged {

/// The stage that answered: the bounded double, the bounded double word, the exact type.
enum class Stage { bounded = 0, word = 1, exact = 2 };

/// A number type named as a value: fn(at<T>{}) runs the algorithm at T.
template <class T>
struct at {
  using type = T;
};

/// The bounded stages alone, from First on (the earlier ones are not compiled): fn(at<T>{})'s
/// answer at the first stage that is certain, else nothing. `stage`, when given, receives the
/// stage that answered.
template <Stage First = Stage::bounded, class Fn>
auto certify(Fn&& fn, Stage* stage = nullptr) -> std::optional<decltype(fn(at<cdref::Bounded2>{}))> {
  if constexpr (First == Stage::bounded) {
    try {
      auto r = fn(at<cdref::Bounded>{});
      if (stage) *stage = Stage::bounded;
      return r;
    } catch (const cdref::uncertain&) {
    }
  }
  try {
    auto r = fn(at<cdref::Bounded2>{});
    if (stage) *stage = Stage::word;
    return r;
  } catch (const cdref::uncertain&) {
  }
  return std::nullopt;
}

/// Whether every coordinate of a primitive (or a point) over F is a double exactly: the bounded
/// stages' inputs. Always for float and double; a long double primitive is compared with its
/// round trip through double (rebind, which leaves a polygon's or a fan's unused slots zero).
template <class F, class P>
bool fits_double(const P& p) {
  if constexpr (!std::is_same_v<F, long double>) {
    return true;
  } else {
    const P back = rebind<F>(rebind<double>(p));
    const P orig = rebind<F>(p);
    if constexpr (requires { p.rows(); })
      return same_value(back, orig);
    else
      return same_members(back, orig);
  }
}

/// A bounded value rounded correctly to F, or cdref::uncertain where the bound cannot tell.
template <class F, class B>
F rounded_value(const B& x) {
  if constexpr (std::is_same_v<F, float>)
    return x.rounded_float();
  else if constexpr (std::is_same_v<F, double>)
    return x.rounded();
  else
    return x.rounded_long_double();
}

/// A result over a bounded type, each field rounded correctly to F (fields.hpp's rounded_by), or
/// cdref::uncertain where one cannot be; a bool is its own.
template <class F, template <class> class R, class B>
R<F> rounded(const R<B>& r) {
  return rounded_by<F>(r, [](const auto& x) { return rounded_value<F>(x); });
}
template <class F>
bool rounded(bool r) {
  return r;
}

/// The robust tier's decide() for a classification fn(a, b) written over its number type: the
/// bounded stages' answer, certain, where one decides; else fn at F, uncertain.
template <class F, class Fn, class A, class B>
robust::Decision decide(Fn&& fn, const A& a, const B& b) {
  if (fits_double<F>(a) && fits_double<F>(b)) {
    const auto x = rebind<double>(a);
    const auto y = rebind<double>(b);
    if (const auto r = certify([&]<class T>(at<T>) { return bool(fn(rebind<T>(x), rebind<T>(y))); }))
      return {*r, true};
  }
  return {bool(fn(a, b)), false};
}

/// A result's classification as a reference: the first field fields.hpp's zip_fields visits
/// (hit for a cast, intersect otherwise); a bool is its own.
template <class R>
bool& classification_ref(R& r) {
  if constexpr (std::is_same_v<R, bool>) {
    return r;
  } else {
    bool* p = nullptr;
    zip_fields(r, r, [&p](const char*, const auto&, auto& y) {
      if constexpr (std::is_same_v<std::remove_cvref_t<decltype(y)>, bool>)
        if (!p) p = &y;
    });
    return *p;
  }
}

/// The robust tier's full result for a query fn(a, b) written over its number type, with the
/// classification cls(a, b) of decide() (the two classify alike everywhere, as every robust
/// tier's do): every value from the double word, rounded correctly to F, where it is certain
/// (the bounded double too at float; at double and long double it seldom rounds a value that
/// is not exact correctly); else fn at F.
template <class F, class Cls, class Fn, class A, class B>
auto result(Cls&& cls, Fn&& fn, const A& a, const B& b) -> decltype(fn(a, b)) {
  const robust::Decision d = decide<F>(cls, a, b);
  decltype(fn(a, b)) out;
  bool values = false;
  if (fits_double<F>(a) && fits_double<F>(b)) {
    const auto x = rebind<double>(a);
    const auto y = rebind<double>(b);
    if (auto r = certify<std::is_same_v<F, float> ? Stage::bounded : Stage::word>(
            [&]<class T>(at<T>) { return rounded<F>(fn(rebind<T>(x), rebind<T>(y))); })) {
      out = *r;
      values = true;
    }
  }
  if (!values) out = fn(a, b);
  classification_ref(out) = d.value;
  return out;
}

}  // namespace cdref::staged
