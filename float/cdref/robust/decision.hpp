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

namespace cdref::robust {

struct Decision {
  bool value = false;
  bool certain = false;
};

}  // namespace cdref::robust
