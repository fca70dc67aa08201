// cdref/exact/staged.hpp - staged evaluation: one algorithm, written once as a template over
// its number type, answered exactly by running it on number types of growing precision.
//
// The derivation. Let f be an algorithm written over a number type T (a book template: its
// decisions are comparisons of values computed with + - * / and sqrt from the inputs). Run
// at a type whose every comparison either returns the sign of the exact difference or throws
// oracle::uncertain, and whose values round to a float type only when the rounding is
// certain, f takes exactly the branches it takes at an exact type. So where it returns, its
// classification is the exact one and every value it rounds is the exact value rounded
// correctly: no error analysis per algorithm, the bound travels with each number
// (CGAL's Filtered_predicate rests on the same observation). Where it throws, the next type
// runs the same code again:
//   1. oracle::Bounded (float/cdref/oracle/bounded.hpp): a double with a running error bound,
//      a few ulps after each operation. Decides every comparison that is not close to a
//      tie; cannot round a value that is not exact to long double.
//   2. oracle::Bounded2 (bounded2.hpp): a double word with a bound of the order of 2^-106
//      relative. Decides the comparisons closer to a tie, rounds square roots and quotients
//      correctly to float, double and x87 long double.
//   3. the exact type E (CGAL::Gmpq by default, square roots kept as a + b sqrt d): always
//      answers.
// A stage that cannot represent an input (a long double with more than 53 significant bits
// at stage 1) must throw oracle::uncertain from the make step: that is fn's business.
//
// Boundary cases: an input the algorithm refuses (invalid_input: a zero direction, a
// degenerate shape) may be refused at any stage; where the refusal itself depends on a
// comparison too close to call, the bounded stages throw uncertain and the exact stage
// decides it. A non-finite input makes every bounded comparison uncertain: fn must refuse
// those before the exact stage (GMP cannot hold them). Exceptions other than
// oracle::uncertain pass through.
//
// certify() is the robust tier's form of the same machinery: the bounded stages alone,
// never the exact one, answering with whether a stage was certain.
#pragma once

#include <CGAL/Gmpq.h>
#include <cdref/oracle/bounded.hpp>
#include <cdref/oracle/bounded2.hpp>
#include <optional>
#include <utility>

namespace cdref::staged {

// The stage that answered: the bounded double, the bounded double word, the exact type.
enum class Stage { bounded = 0, word = 1, exact = 2 };

// A number type named as a value: fn(at<T>{}) runs the algorithm at T.
template <class T>
struct at {
  using type = T;
};

// fn(at<T>{}) for T = oracle::Bounded, then oracle::Bounded2, then E: the first answer that is
// certain. `stage`, when given, receives the stage that answered. `first` skips the stages
// before it (Stage::word where the bounded double would seldom be certain: values rounded
// to double or long double, whose rounding needs a bound below half an ulp).
template <class E = CGAL::Gmpq, class Fn>
auto evaluate(Fn&& fn, Stage* stage = nullptr, Stage first = Stage::bounded) {
  if (first == Stage::bounded) {
    try {
      auto r = fn(at<oracle::Bounded>{});
      if (stage) *stage = Stage::bounded;
      return r;
    } catch (const oracle::uncertain&) {
    }
  }
  if (first != Stage::exact) {
    try {
      auto r = fn(at<oracle::Bounded2>{});
      if (stage) *stage = Stage::word;
      return r;
    } catch (const oracle::uncertain&) {
    }
  }
  auto r = fn(at<E>{});
  if (stage) *stage = Stage::exact;
  return r;
}

// fn at one stage alone: its answer, or nothing where that stage cannot decide (the
// exact stage always decides).
template <class E = CGAL::Gmpq, class Fn>
auto at_stage(Stage s, Fn&& fn) -> std::optional<decltype(fn(at<E>{}))> {
  try {
    if (s == Stage::bounded) return fn(at<oracle::Bounded>{});
    if (s == Stage::word) return fn(at<oracle::Bounded2>{});
  } catch (const oracle::uncertain&) {
    return std::nullopt;
  }
  return fn(at<E>{});
}

// The bounded stages alone (the robust tier's certificate): their answer where one is
// certain, else nothing, and the caller answers in its own float type, uncertified.
template <class Fn>
auto certify(Fn&& fn, Stage* stage = nullptr) -> std::optional<decltype(fn(at<oracle::Bounded>{}))> {
  try {
    auto r = fn(at<oracle::Bounded>{});
    if (stage) *stage = Stage::bounded;
    return r;
  } catch (const oracle::uncertain&) {
  }
  try {
    auto r = fn(at<oracle::Bounded2>{});
    if (stage) *stage = Stage::word;
    return r;
  } catch (const oracle::uncertain&) {
  }
  return std::nullopt;
}

}  // namespace cdref::staged
