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
};

// Reads a case file of query q. Malformed lines are reported on standard error with
// `source` and their line number, counted in `bad`, and skipped; a header without the
// query's columns throws std::runtime_error.
std::vector<CaseRow> parse_cases(fuzz::Query q, std::istream& in, const std::string& source, int& bad);

int cases_command(std::vector<std::string> args);
int oracle_command(std::vector<std::string> args);
int score_command(std::vector<std::string> args);
int plot_command(std::vector<std::string> args);
int report_command(std::vector<std::string> args);

}  // namespace cdref::cli
