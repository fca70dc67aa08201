// cdref/exact/staged.hpp - staged evaluation: one algorithm, written once as a template over
// its number type, answered exactly by running it on number types of growing precision.
//
// The derivation is cdref/robust/staged.hpp's (the bounded double, then the bounded double
// word: a comparison either certain or cdref::uncertain, a value rounded only where the
// rounding is certain); this header adds the third stage, the exact type E (CGAL::Gmpq by
// default, square roots kept as a + b sqrt d), which always answers. evaluate() is the oracle's
// form of the machinery, certify() (robust/staged.hpp) the robust tier's.
// A stage that cannot represent an input (a long double with more than 53 significant bits
// at stage 1) must throw cdref::uncertain from the make step: that is fn's business. An input
// the algorithm refuses may be refused at any stage; where the refusal itself depends on a
// comparison too close to call, the bounded stages throw uncertain and the exact stage decides
// it. A non-finite input makes every bounded comparison uncertain: fn must refuse those before
// the exact stage (GMP cannot hold them). Exceptions other than cdref::uncertain pass through.
#pragma once

#include <CGAL/Gmpq.h>
#include <cdref/robust/staged.hpp>
#include <optional>
#include <utility>

namespace cdref::staged {

// fn(at<T>{}) for T = cdref::Bounded, then cdref::Bounded2, then E: the first answer that is
// certain. `stage`, when given, receives the stage that answered. `First` skips the stages
// before it, and they are not compiled (Stage::word where the bounded double would seldom be
// certain: values rounded to double or long double, whose rounding needs a bound below half
// an ulp).
template <Stage First = Stage::bounded, class E = CGAL::Gmpq, class Fn>
auto evaluate(Fn&& fn, Stage* stage = nullptr) -> decltype(fn(at<E>{})) {
  if constexpr (First != Stage::exact)
    if (auto r = certify<First>(fn, stage)) return *std::move(r);
  if (stage) *stage = Stage::exact;
  return fn(at<E>{});
}

// fn at one stage alone: its answer, or nothing where that stage cannot decide (the
// exact stage always decides).
template <class E = CGAL::Gmpq, class Fn>
auto at_stage(Stage s, Fn&& fn) -> std::optional<decltype(fn(at<E>{}))> {
  try {
    if (s == Stage::bounded) return fn(at<cdref::Bounded>{});
    if (s == Stage::word) return fn(at<cdref::Bounded2>{});
  } catch (const cdref::uncertain&) {
    return std::nullopt;
  }
  return fn(at<E>{});
}

}  // namespace cdref::staged
