// src/report.hpp - campaign results as a table for people, JSON and CSV.
#pragma once

#include <cdref/fuzz/campaign.hpp>
#include <map>
#include <ostream>

namespace cdref::cli {

// A histogram by powers of two: key -1 for exact (0 ulps), j for [2^j, 2^(j+1)).
std::map<int, std::uint64_t> by_power_of_two(const fuzz::Histogram& h);

void print_table(std::ostream& o, const fuzz::Results& r, std::uint64_t seed, int worst_rows = 25);
void write_json(std::ostream& o, const fuzz::Results& r, std::uint64_t seed);
void write_csv(std::ostream& o, const fuzz::Results& r);

}  // namespace cdref::cli
