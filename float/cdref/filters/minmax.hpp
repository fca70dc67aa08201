// cdref/filters/minmax.hpp - the minimum and the maximum of two doubles by value, for the filters'
// coordinate-plane tests. g++ compiles these to minsd and maxsd. std::min and std::max on
// elements of arrays return references, and g++ selected the address with a branch, which fresh
// cases mispredict about as often as the order of the two values changes (the triangle filters'
// coordinate-plane tests: README, "What changed since the run on 5288b05"). As std::min, a NaN in
// the second place is passed over; the filters' callers have checked their inputs, or test the
// values that follow for range.
#pragma once

namespace cdref::filters {

inline double min_value(double a, double b) { return b < a ? b : a; }
inline double max_value(double a, double b) { return b > a ? b : a; }

}  // namespace cdref::filters
