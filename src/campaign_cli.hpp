// src/campaign_cli.hpp - the options of `cdref campaign` (shared with cdref-mpi) and the
// campaign's outputs (text form, JSON, CSV, table), so that every runner prints the same bytes.
#pragma once

#include <cdref/fuzz/campaign.hpp>
#include <cstdint>
#include <string>
#include <vector>

namespace cdref::cli {

struct CampaignCommand {
  fuzz::Spec spec;
  std::string out, json, csv;  // "" none, "-" standard output (json, csv)
  bool quiet = false;
};

// Parses the options of `cdref campaign` (`defaults`: the default campaign's n); `mpi` names
// cdref-mpi in the messages. Fills the queries and implementations left open.
// Throws std::invalid_argument naming the option and what it wants.
CampaignCommand parse_campaign(const std::vector<std::string>& args, bool defaults, bool mpi);

// Writes the campaign's outputs as the options ask: --out (the complete campaign's text form),
// --json, --csv, and the table on standard output unless --quiet.
void emit_campaign(const CampaignCommand& c, const fuzz::Results& r);

// What the default campaign (`cdref` with no command) prints before it runs.
std::string default_campaign_banner(const fuzz::Spec& spec);

std::uint64_t to_u64(const std::string& s, const std::string& opt);  // throws std::invalid_argument
int to_int(const std::string& s, const std::string& opt);
void write_to(const std::string& path, const std::string& text);  // "-": standard output

}  // namespace cdref::cli
