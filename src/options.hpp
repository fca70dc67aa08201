// src/options.hpp - the one command line of cdref and cdref-mpi, on CLI11.
//
// Every subcommand is a CLI::App with its own --help; options take `--opt value` and
// `--opt=value`; an option given once takes one value (a repeat is refused by name), a list
// option (--query, --family, --scale, --impl, --precision, --compare) accumulates; numbers are
// range-checked by validators that name the option and what it wants; extra arguments are
// refused. Exit status: 0 all good, 1 the data says something is wrong, 2 the command could not
// run (a bad option, an unreadable file, a failed write).
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace cdref::cli {

// "cdref 0.1.0 (commit abc1234)": the package version from CMake's project() and the commit
// the build was configured at.
std::string version_text();
const char* version();  // the package version alone: "0.1.0"

// A whole number in [lo, hi], written in decimal digits (no sign, no 0x, no exponent).
CLI::Validator whole_number(std::uint64_t lo, std::uint64_t hi);
// A finite real number in [lo, hi].
CLI::Validator real_number(double lo, double hi);
// One of `choices`; the message lists them.
CLI::Validator one_of(const std::vector<std::string>& choices);
// A query name (the list in the help is generated from the query descriptors).
CLI::Validator query_name();

// The subcommands registered by each part of the command line: after parsing, the one that was
// given runs.
struct Commands {
  struct Entry {
    CLI::App* app;
    std::function<int()> run;
  };
  std::vector<Entry> entries;
  void add(CLI::App* app, std::function<int()> run) { entries.push_back({app, std::move(run)}); }
};

// The default number of worker threads: the hardware's.
int default_threads();

// Parses argv with `app` and runs the chosen subcommand (or `otherwise` when none is given),
// with the exit statuses above: help and --version print and return 0, a parse error prints
// "NAME: what is wrong" and returns 2, an exception from the command is reported the same way,
// and a failed write to standard output turns a 0 or 1 into 2.
int run_app(CLI::App& app, const Commands& commands, int argc, char** argv, const std::function<int()>& otherwise,
            const std::string& name);

// The message of a parse error as cdref words it ("--n is given 2 times; it takes one value").
std::string parse_error_text(const CLI::ParseError& e);

// Applies cdref's option conventions to a new app (one value per single option, refusal of
// repeats, help for every subcommand, --help-all).
void conventions(CLI::App& app);

}  // namespace cdref::cli
