// src/options.cpp - validators, conventions and the exit statuses of the command line.
#include "options.hpp"

#include <CLI/CLI.hpp>
#include <cerrno>
#include <stdexcept>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <thread>

#include <cdref/fuzz/campaign.hpp>

#include "output.hpp"

#ifndef CDREF_VERSION
#error "CDREF_VERSION comes from CMake's project(VERSION)"
#endif
#ifndef CDREF_COMMIT
#define CDREF_COMMIT "unknown"
#endif

namespace cdref::cli {

std::string version_text() { return std::string("cdref ") + CDREF_VERSION + " (commit " + CDREF_COMMIT + ")"; }

int default_threads() { return int(std::max(1u, std::thread::hardware_concurrency())); }

namespace {

// Whole numbers are decimal: the validator writes the value back in canonical form, so that
// CLI11's own conversion (which reads a leading 0 as octal) sees no leading zero.
CLI::Validator whole_number(std::uint64_t lo, std::uint64_t hi) {
  const std::string range = std::to_string(lo) + " to " + std::to_string(hi);
  return CLI::Validator(
      [lo, hi, range](std::string& s) -> std::string {
        const std::string want = "wants a whole number from " + range + ", not '" + s + "'";
        if (s.empty() || s.size() > 20 || s.find_first_not_of("0123456789") != std::string::npos) return want;
        errno = 0;
        const unsigned long long x = std::strtoull(s.c_str(), nullptr, 10);
        if (errno == ERANGE || x < lo || x > hi) return want;
        s = std::to_string(x);
        return "";
      },
      "in " + range);
}

// A signed whole number in [lo, hi] (a family's scale may be negative), decimal, canonical.
CLI::Validator signed_number(long lo, long hi) {
  const std::string range = std::to_string(lo) + " to " + std::to_string(hi);
  return CLI::Validator(
      [lo, hi, range](std::string& s) -> std::string {
        const std::string want = "wants a whole number from " + range + ", not '" + s + "'";
        const std::size_t digits = s.size() - (!s.empty() && s[0] == '-');
        if (digits == 0 || digits > 18 || s.find_first_not_of("0123456789", s.size() - digits) != std::string::npos)
          return want;
        const long x = std::strtol(s.c_str(), nullptr, 10);
        if (x < lo || x > hi) return want;
        s = std::to_string(x);
        return "";
      },
      "in " + range);
}

CLI::Validator real_number(double lo, double hi) {
  char b[96];
  std::snprintf(b, sizeof b, "%g to %g", lo, hi);
  const std::string range = b;
  return CLI::Validator(
      [lo, hi, range](std::string& s) -> std::string {
        const std::string want = "wants a number from " + range + ", not '" + s + "'";
        if (s.empty()) return want;
        char* end = nullptr;
        errno = 0;
        const double x = std::strtod(s.c_str(), &end);
        // (ERANGE also marks a subnormal result, which is a number; not one that reads as 0)
        if (end != s.c_str() + s.size() || (errno == ERANGE && (x == 0 || !std::isfinite(x))) || !std::isfinite(x) ||
            x < lo || x > hi)
          return want;
        return "";
      },
      "in " + range);
}

CLI::Validator one_of(const std::vector<std::string>& choices, const std::string& shown = "") {
  std::string list;
  for (const auto& c : choices) list += (list.empty() ? "" : ", ") + c;
  return CLI::Validator(
      [choices, list](std::string& s) -> std::string {
        for (const auto& c : choices)
          if (s == c) return "";
        return "is one of " + list + ", not '" + s + "'";
      },
      shown.empty() ? "{" + list + "}" : shown);
}

std::vector<std::string> query_names() {
  std::vector<std::string> names;
  for (fuzz::Query q : fuzz::all_queries()) names.push_back(fuzz::info(q).name);
  return names;
}

// The message of a parse error as cdref words it ("--n is given 2 times; it takes one value").
std::string parse_error_text(const CLI::ParseError& e) {
  // CLI11 says "--n: At Most 1 required but received 2" of an option given twice
  std::string w = e.what();
  const std::string at_most = ": At Most 1 required but received ";
  if (const auto k = w.find(at_most); k != std::string::npos)
    return w.substr(0, k) + " is given " + w.substr(k + at_most.size()) + " times; it takes one value";
  return w;
}

// cdref's option conventions on a new app: one value per single option (a repeat refused),
// extras refused.
void conventions(CLI::App& app) {
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::Throw);
  app.allow_extras(false);
  app.positionals_at_end(false);
  app.get_formatter()->column_width(34);
}

CLI::Option* last_option(CLI::App* app) {
  const auto all = app->get_options();
  if (all.empty()) throw std::logic_error("no option declared yet");
  return const_cast<CLI::Option*>(all.back());
}

}  // namespace

// ---- Command ----
Command& Command::text(const std::string& name, std::string& into, const std::string& help) {
  app_->add_option(name, into, help);
  return *this;
}
Command& Command::texts(const std::string& name, std::vector<std::string>& into, const std::string& help) {
  app_->add_option(name, into, help)->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  return *this;
}
Command& Command::whole(const std::string& name, std::uint64_t& into, std::uint64_t lo, std::uint64_t hi,
                        const std::string& help) {
  app_->add_option(name, into, help)->transform(whole_number(lo, hi));
  return *this;
}
Command& Command::whole(const std::string& name, int& into, int lo, int hi, const std::string& help) {
  app_->add_option(name, into, help)->transform(signed_number(lo, hi));
  return *this;
}
Command& Command::whole(const std::string& name, std::optional<std::uint64_t>& into, std::uint64_t lo,
                        std::uint64_t hi, const std::string& help) {
  app_->add_option_function<std::uint64_t>(name, [&into](const std::uint64_t& x) { into = x; }, help)
      ->transform(whole_number(lo, hi));
  return *this;
}
Command& Command::wholes(const std::string& name, std::vector<int>& into, int lo, int hi, const std::string& help) {
  app_->add_option(name, into, help)
      ->transform(signed_number(lo, hi))
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  return *this;
}
Command& Command::real(const std::string& name, double& into, double lo, double hi, const std::string& help) {
  app_->add_option(name, into, help)->check(real_number(lo, hi));
  return *this;
}
Command& Command::real(const std::string& name, std::optional<double>& into, double lo, double hi,
                       const std::string& help) {
  app_->add_option_function<double>(name, [&into](const double& x) { into = x; }, help)->check(real_number(lo, hi));
  return *this;
}
Command& Command::choice(const std::string& name, std::string& into, const std::vector<std::string>& choices,
                         const std::string& help) {
  app_->add_option(name, into, help)->check(one_of(choices));
  return *this;
}
Command& Command::choice(const std::string& name, int& into, const std::vector<int>& choices, const std::string& help) {
  std::vector<std::string> text;
  for (int c : choices) text.push_back(std::to_string(c));
  app_->add_option(name, into, help)->check(one_of(text));
  return *this;
}
Command& Command::choices(const std::string& name, std::vector<std::string>& into,
                          const std::vector<std::string>& choices, const std::string& help) {
  app_->add_option(name, into, help)->check(one_of(choices))->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  return *this;
}
Command& Command::query(const std::string& name, std::string& into, const std::string& help) {
  app_->add_option(name, into, help)->check(one_of(query_names(), "QUERY"));
  return *this;
}
Command& Command::queries(const std::string& name, std::vector<std::string>& into, const std::string& help) {
  app_->add_option(name, into, help)
      ->check(one_of(query_names(), "QUERY"))
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  return *this;
}
Command& Command::pass_through() {
  app_->set_help_flag();  // (--help is the other program's)
  app_->allow_extras();
  app_->prefix_command();
  return *this;
}
std::vector<std::string> Command::rest() const { return app_->remaining(); }
Command& Command::flag(const std::string& name, bool& into, const std::string& help) {
  app_->add_flag(name, into, help);
  return *this;
}
Command& Command::scales(const std::string& name, std::vector<std::string>& into, const std::string& help) {
  app_->add_option(name, into, help)
      ->transform(CLI::Validator(
          [](std::string& v) -> std::string {
            if (v == "all") return "";
            const std::size_t digits = v.size() - (!v.empty() && v[0] == '-');
            if (digits == 0 || digits > 9 || v.find_first_not_of("0123456789", v.size() - digits) != std::string::npos)
              return "wants a scale (a whole number) or all, not '" + v + "'";
            v = std::to_string(std::stol(v));
            return "";
          },
          "SCALE or all"))
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  return *this;
}
Command& Command::positional(const std::string& name, std::string& into, const std::string& help) {
  app_->add_option(name, into, help);
  return *this;
}
Command& Command::files(const std::string& name, std::vector<std::string>& into, const std::string& help) {
  app_->add_option(name, into, help)->check(CLI::ExistingFile);
  return *this;
}
Command& Command::required() {
  last_option(app_)->required();
  return *this;
}
Command& Command::excludes(const std::vector<std::string>& others) {
  CLI::Option* o = last_option(app_);
  for (const std::string& other : others) o->excludes(app_->get_option(other));
  return *this;
}
bool Command::given(const std::string& name) const { return app_->get_option(name)->count() > 0; }

// ---- Program ----
struct Program::State {
  std::string name;
  CLI::App app;
  std::vector<std::pair<CLI::App*, std::function<int()>>> commands;
  State(const std::string& n, const std::string& description) : name(n), app(description, n) {}
};

Program::Program(const std::string& name, const std::string& description)
    : s_(std::make_unique<State>(name, description)) {
  conventions(s_->app);
  s_->app.set_version_flag("--version", version_text(), "print the version and the commit, then exit");
  s_->app.require_subcommand(0, 1);
}
Program::~Program() = default;

Command Program::root() { return Command(&s_->app); }

Command Program::add(const std::string& name, const std::string& description, std::function<int()> run) {
  CLI::App* sub = s_->app.add_subcommand(name, description);
  conventions(*sub);
  s_->commands.push_back({sub, std::move(run)});
  return Command(sub);
}

std::vector<std::string> Program::names() const {
  std::vector<std::string> out;
  for (const auto& [app, run] : s_->commands) out.push_back(app->get_name());
  return out;
}

std::string Program::help(const std::string& subcommand) const {
  // (App::help prints the help of the subcommand given on the command line, as `help` itself)
  const CLI::App* of = subcommand.empty() ? &s_->app : s_->app.get_subcommand(subcommand);
  return s_->app.get_formatter()->make_help(of, subcommand.empty() ? s_->name : s_->name + " " + subcommand,
                                            CLI::AppFormatMode::Normal);
}

int Program::run(int argc, char** argv, const std::function<int()>& otherwise, bool quiet) {
  const char* name = s_->name.c_str();
  CLI::App& app = s_->app;
  int rc = 0;
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) {  // --help, --help-all, --version
      if (!quiet) app.exit(e);
      const std::string out = io::finish_stdout();
      if (!out.empty() && !quiet) std::fprintf(stderr, "%s: %s\n", name, out.c_str());
      return out.empty() ? 0 : 2;
    }
    if (!quiet)
      std::fprintf(stderr, "%s: %s\n(see %s --help, or %s COMMAND --help)\n", name, parse_error_text(e).c_str(), name,
                   name);
    return 2;
  }
  try {
    rc = 2;
    const std::function<int()>* chosen = &otherwise;
    for (const auto& [sub, run] : s_->commands)
      if (sub->parsed()) chosen = &run;
    rc = (*chosen)();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", name, e.what());
    rc = 2;
  }
  if (!quiet) {
    const std::string out = io::finish_stdout();
    if (!out.empty()) {
      std::fprintf(stderr, "%s: %s\n", name, out.c_str());
      rc = 2;
    }
  }
  return rc;
}

}  // namespace cdref::cli
