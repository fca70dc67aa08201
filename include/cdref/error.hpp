/// \file
/// cdref/error.hpp - the one exception cdref throws for bad input.
#pragma once

#include <stdexcept>
#include <string>

namespace cdref {

/// Thrown when an argument is outside a query's domain: a NaN or infinite
/// coordinate, a negative radius or extent, an inverted min-max box, a zero
/// direction for an infinite ray. The message names the argument and the value.
class invalid_input : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

}  // namespace cdref
