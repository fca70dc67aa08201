// src/report.hpp - campaign results as a table for people, JSON and CSV.
#pragma once

#include <cdref/fuzz/campaign.hpp>
#include <ostream>

namespace cdref::cli {

void print_table(std::ostream& o, const fuzz::Results& r, std::uint64_t seed, int worst_rows = 25);
void write_json(std::ostream& o, const fuzz::Results& r, std::uint64_t seed);
void write_csv(std::ostream& o, const fuzz::Results& r);

}  // namespace cdref::cli
