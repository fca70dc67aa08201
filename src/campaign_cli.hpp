// src/campaign_cli.hpp - the options of `cdref campaign` (shared with cdref-mpi) and the
// campaign's outputs (text form, JSON, CSV, table), so that every runner prints the same bytes.
#pragma once

#include <cdref/fuzz/campaign.hpp>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "options.hpp"
#include "output.hpp"

namespace cdref::cli {

// A campaign as the command line asks for it.
struct CampaignCommand {
  fuzz::Spec spec;
  std::string out, json, csv;  // "" none, "-" standard output (json, csv)
  bool quiet = false;
  std::vector<std::string> query_names;
  std::string outputs = "all";
  std::string shard;  // "k/N"
  std::optional<std::uint64_t> threads;  // --threads (cdref-mpi shares the cores among ranks otherwise)
  bool mpi_flag = false;                 // --mpi given
  bool mpi = false;  // parsed for cdref-mpi (which runs across the ranks with or without --mpi)
};

// Adds the options of `cdref campaign` to `app` (`mpi`: cdref-mpi's, which names itself).
void add_campaign_options(Command& app, CampaignCommand& c, bool mpi);

// After parsing: fills the queries and implementations left open (`defaults`: the default
// campaign's n) and checks what CLI11 cannot (a name given twice, a family or a scale no chosen
// query has, --resume without --checkpoint). Throws std::invalid_argument naming the option.
void finish_campaign(CampaignCommand& c, bool defaults);

// The outputs of a campaign, opened before it runs (a path that cannot be written is refused
// before the work, with the option that named it).
struct CampaignOutputs {
  std::optional<io::Output> out, json, csv;
};
CampaignOutputs open_campaign_outputs(const CampaignCommand& c);

// Writes the campaign's outputs as the options ask: --out (the complete campaign's text form),
// --json, --csv, and the table on standard output unless --quiet. Every output is attempted;
// the failures are thrown together afterwards (io::write_error naming each).
void emit_campaign(const CampaignCommand& c, CampaignOutputs& o, const fuzz::Results& r);

// What the default campaign (`cdref` with no command) prints before it runs.
std::string default_campaign_banner(const fuzz::Spec& spec);

}  // namespace cdref::cli
