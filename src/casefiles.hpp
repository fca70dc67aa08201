// src/casefiles.hpp - case files, so that an implementation in any language can be checked:
//   cdref cases   writes a query's inputs as CSV (hex-float, or decimal with 17 digits);
//   cdref oracle  reads such a file and writes the exact, correctly rounded answers;
//   cdref score   grades an answer file against the truth with the campaign's metrics.
#pragma once

#include <cdref/fuzz/campaign.hpp>
#include <istream>
#include <string>
#include <vector>


namespace cdref::cli {


struct CaseRow {
  std::uint64_t id;
  fuzz::Inputs in{};
  std::string refusal;  // why no exact answer exists (a non-finite input, by column), or ""
};

// Reads a case file of query q. Malformed lines (a field count that differs from the header's,
// a case id that is not a whole number below 2^64 or that an earlier line has, a number with a
// blank inside or one that underflows to 0, a NUL byte) are reported on standard error with
// `source` and their line number, counted in `bad`, and skipped; a header without the query's
// columns, or naming a column twice, throws std::runtime_error. A UTF-8 byte-order mark is
// skipped. A well-formed line whose numbers are not finite
// (nan, inf, or a literal beyond double's range such as 1e400) is kept with its `refusal`:
// `oracle` and `score` refuse that case by name and answer the rest.
// `skipped` (optional) receives the ids of the malformed lines whose id could be read, so that an
// answer to such a case is known to answer a case that exists.
std::vector<CaseRow> parse_cases(fuzz::Query q, std::istream& in, const std::string& source, int& bad,
                                 std::vector<std::uint64_t>* skipped = nullptr);

// The exact answer to a case at the precision (24: for the inputs rounded to float, as a float
// implementation receives them), as `cdref oracle` writes it; with values false the
// classification alone (the classification oracle). Throws cdref::invalid_input naming the
// problem for a case outside the query's domain, non-finite inputs included (they are refused
// by column before any exact conversion).
fuzz::Answer answer_case(fuzz::Query q, const CaseRow& r, int precision, bool values = true);

}  // namespace cdref::cli
