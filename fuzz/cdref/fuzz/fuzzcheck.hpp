// cdref/fuzz/fuzzcheck.hpp - what the coverage-guided fuzz targets check.
//
// check_query decodes bytes into the inputs of a query (each input either a small dyadic
// rational, so that exact touching and tangency are common, or raw IEEE bits: NaN,
// infinities and subnormals included), and runs:
//   - the book at float and double: any crash or undefined behaviour is a failure, and the
//     only error allowed is cdref::invalid_input for input outside the domain;
//   - the book at CGAL::Gmpq and at CGAL::Epeck::FT: both must refuse the same inputs, and
//     otherwise agree exactly, every output rounded correctly to double; and at exact types
//     the root- and division-free predicate must agree with the full query, and
//     Algorithm 3.1 with Algorithm 3.2 for segments and spheres;
//   - the oracle (filter first, then exact) must give exactly the Gmpq answer, rounded to
//     double and to long double.
// A violated check prints the inputs in hex-float and aborts.
// check_case_reader feeds bytes as a case file to the case-file parser; check_results_reader
// as a campaign's text form and as a cdref-mpi rank's checkpoint (read back after writing).
#pragma once

#include <cdref/fuzz/campaign.hpp>
#include <cstddef>
#include <cstdint>

namespace cdref::fuzz {

bool decode_inputs(Query q, const std::uint8_t* data, std::size_t size, Inputs& in);
void check_query(Query q, const std::uint8_t* data, std::size_t size);
void check_case_reader(const std::uint8_t* data, std::size_t size);
void check_results_reader(const std::uint8_t* data, std::size_t size);
// A scene file: refused with a scene_error, or (when small enough to run quickly) run at
// float, double and exact precision and compared, never anything else.
void check_scene_reader(const std::uint8_t* data, std::size_t size);

}  // namespace cdref::fuzz
