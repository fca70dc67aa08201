// src/casefiles.hpp - case files, so that an implementation in any language can be checked:
//   cdref cases   writes a query's inputs as CSV (hex-float, or decimal with 17 digits);
//   cdref oracle  reads such a file and writes the exact, correctly rounded answers;
//   cdref score   grades an answer file against the truth with the campaign's metrics.
#pragma once

#include <string>
#include <vector>

namespace cdref::cli {

int cases_command(std::vector<std::string> args);
int oracle_command(std::vector<std::string> args);
int score_command(std::vector<std::string> args);

}  // namespace cdref::cli
