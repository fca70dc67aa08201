// cdref/oracle/rational.hpp - double inputs moved exactly to CGAL::Gmpq: the oracles' last,
// rational stage.
#pragma once

#include <cdref/exact/rationals.hpp>

namespace cdref::oracle {

// Double inputs moved exactly to a number type T that holds every double (CGAL::Gmpq,
// cdref::Bounded2): fields.hpp's rebind, for a point or any primitive over double.
template <class T, class P>
auto exactly(const P& p) {
  return rebind<T>(p);
}

namespace rational_inputs {

using Q = CGAL::Gmpq;
template <class P>
auto toq(const P& p) -> decltype(exactly<Q>(p)) {
  return exactly<Q>(p);
}

}  // namespace rational_inputs

}  // namespace cdref::oracle
