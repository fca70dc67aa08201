// src/options.hpp - the one command line of cdref and cdref-mpi, on CLI11.
//
// Every subcommand is a CLI::App with its own --help; options take `--opt value` and
// `--opt=value`; an option given once takes one value (a repeat is refused by name), a list
// option (--query, --family, --scale, --impl, --precision, --compare) accumulates; numbers are
// range-checked by validators that name the option and what it wants; extra arguments are
// refused. Exit status: 0 all good, 1 the data says something is wrong, 2 the command could not
// run (a bad option, an unreadable file, a failed write).
//
// CLI11 is compiled in src/options.cpp alone (it is header-only and costs seconds of compile
// time in every translation unit that includes it): the commands declare their options through
// Command, whose members bind an option to a variable with cdref's validators.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace cdref::cli {

// "cdref 0.1.0 (commit abc1234)": the package version from CMake's project() and the commit
// the build was configured at.
std::string version_text();

// The default number of worker threads: the hardware's.
int default_threads();

// A subcommand (or the program itself) being declared: each member adds an option bound to a
// variable, which keeps its default when the option is not given. Names are "--name" for
// options and "NAME" for positional arguments.
class Command {
 public:
  explicit Command(CLI::App* app) : app_(app) {}
  CLI::App* app() const { return app_; }

  Command& text(const std::string& name, std::string& into, const std::string& help);
  // Repeatable: each use adds a value.
  Command& texts(const std::string& name, std::vector<std::string>& into, const std::string& help);
  // A whole number in [lo, hi], written in decimal digits (no sign, no 0x, no exponent).
  Command& whole(const std::string& name, std::uint64_t& into, std::uint64_t lo, std::uint64_t hi, const std::string& help);
  Command& whole(const std::string& name, int& into, int lo, int hi, const std::string& help);
  Command& whole(const std::string& name, std::optional<std::uint64_t>& into, std::uint64_t lo, std::uint64_t hi,
                 const std::string& help);
  Command& wholes(const std::string& name, std::vector<int>& into, int lo, int hi, const std::string& help);
  // A finite real number in [lo, hi].
  Command& real(const std::string& name, double& into, double lo, double hi, const std::string& help);
  Command& real(const std::string& name, std::optional<double>& into, double lo, double hi, const std::string& help);
  // One of `choices` (the message lists them); `choices` repeatable.
  Command& choice(const std::string& name, std::string& into, const std::vector<std::string>& choices,
                  const std::string& help);
  Command& choice(const std::string& name, int& into, const std::vector<int>& choices, const std::string& help);
  Command& choices(const std::string& name, std::vector<std::string>& into, const std::vector<std::string>& choices,
                   const std::string& help);
  // A query name (the list is generated from the query descriptors); `queries` repeatable.
  Command& query(const std::string& name, std::string& into, const std::string& help);
  Command& queries(const std::string& name, std::vector<std::string>& into, const std::string& help);
  Command& flag(const std::string& name, bool& into, const std::string& help);
  // A scale (a whole number) or "all", repeatable.
  Command& scales(const std::string& name, std::vector<std::string>& into, const std::string& help);
  // Positional arguments: one, or any number of existing files.
  Command& positional(const std::string& name, std::string& into, const std::string& help);
  Command& files(const std::string& name, std::vector<std::string>& into, const std::string& help);

  Command& required();  // the option declared last must be given
  // The option declared last refuses to be given with each of `others` (declared before it).
  Command& excludes(const std::vector<std::string>& others);
  // After parsing: whether the option was given.
  bool given(const std::string& name) const;
  // The command takes every argument after its name unparsed, --help included (a command that
  // another program answers); after parsing, rest() gives them in order.
  Command& pass_through();
  std::vector<std::string> rest() const;

 private:
  CLI::App* app_;
};

// The program's command line: the subcommands registered by each part of cdref; after parsing,
// the one that was given runs.
class Program {
 public:
  Program(const std::string& name, const std::string& description);
  ~Program();
  Command root();
  // Adds a subcommand; `run` runs it when it is the one given.
  Command add(const std::string& name, const std::string& description, std::function<int()> run);
  // Parses argv and runs the chosen subcommand (or `otherwise` when none is given), with the
  // exit statuses above: help and --version print and return 0, a parse error prints
  // "NAME: what is wrong" and returns 2, an exception from the command is reported the same
  // way, and a failed write to standard output turns a 0 or 1 into 2. `quiet` (another MPI
  // rank than 0) prints nothing of its own.
  int run(int argc, char** argv, const std::function<int()>& otherwise, bool quiet = false);
  // The help of the program, or of one of its subcommands.
  std::string help(const std::string& subcommand = "") const;
  std::vector<std::string> names() const;  // the subcommands, in order

 private:
  struct State;
  std::unique_ptr<State> s_;
};

// The subcommands of each part of the command line (each file registers its own).
void add_case_commands(Program& p);    // cases, oracle, score (src/casefiles.cpp)
void add_plot_command(Program& p);     // src/plot.cpp
void add_report_command(Program& p);   // src/costreport.cpp

}  // namespace cdref::cli
