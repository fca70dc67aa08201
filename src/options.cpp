// src/options.cpp - validators, conventions and the exit statuses of the command line.
#include "options.hpp"

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

const char* version() { return CDREF_VERSION; }
std::string version_text() { return std::string("cdref ") + CDREF_VERSION + " (commit " + CDREF_COMMIT + ")"; }

int default_threads() { return int(std::max(1u, std::thread::hardware_concurrency())); }

CLI::Validator whole_number(std::uint64_t lo, std::uint64_t hi) {
  const std::string range = std::to_string(lo) + " to " + std::to_string(hi);
  return CLI::Validator(
      [lo, hi, range](std::string& s) -> std::string {
        const std::string want = "wants a whole number from " + range + ", not '" + s + "'";
        if (s.empty() || s.size() > 20 || s.find_first_not_of("0123456789") != std::string::npos) return want;
        errno = 0;
        const unsigned long long x = std::strtoull(s.c_str(), nullptr, 10);
        if (errno == ERANGE || x < lo || x > hi) return want;
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
        if (end != s.c_str() + s.size() || errno == ERANGE || !std::isfinite(x) || x < lo || x > hi) return want;
        return "";
      },
      "in " + range);
}

CLI::Validator one_of(const std::vector<std::string>& choices) {
  std::string list;
  for (const auto& c : choices) list += (list.empty() ? "" : ", ") + c;
  return CLI::Validator(
      [choices, list](std::string& s) -> std::string {
        for (const auto& c : choices)
          if (s == c) return "";
        return "is one of " + list + ", not '" + s + "'";
      },
      "{" + list + "}");
}

CLI::Validator query_name() {
  std::vector<std::string> names;
  for (fuzz::Query q : fuzz::all_queries()) names.push_back(fuzz::info(q).name);
  CLI::Validator v = one_of(names);
  v.description("QUERY");  // the list is long: `cdref describe` and each command's help give it
  return v;
}

std::string parse_error_text(const CLI::ParseError& e) {
  // CLI11 says "--n: At Most 1 required but received 2" of an option given twice
  std::string w = e.what();
  const std::string at_most = ": At Most 1 required but received ";
  if (const auto k = w.find(at_most); k != std::string::npos)
    return w.substr(0, k) + " is given " + w.substr(k + at_most.size()) + " times; it takes one value";
  return w;
}

void conventions(CLI::App& app) {
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::Throw);
  app.allow_extras(false);
  app.positionals_at_end(false);
  app.get_formatter()->column_width(34);
}

int run_app(CLI::App& app, const Commands& commands, int argc, char** argv, const std::function<int()>& otherwise,
            const std::string& name) {
  int rc = 0;
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    rc = app.exit(e);
    const std::string out = io::finish_stdout();
    if (!out.empty()) std::fprintf(stderr, "%s: %s\n", name.c_str(), out.c_str());
    return out.empty() ? rc : 2;
  } catch (const CLI::CallForAllHelp& e) {
    app.exit(e);
    return io::finish_stdout().empty() ? 0 : 2;
  } catch (const CLI::CallForVersion& e) {
    app.exit(e);
    return io::finish_stdout().empty() ? 0 : 2;
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "%s: %s\n(see %s --help, or %s COMMAND --help)\n", name.c_str(), parse_error_text(e).c_str(),
                 name.c_str(), name.c_str());
    return 2;
  }
  try {
    const CLI::App* chosen = nullptr;
    for (const auto& c : commands.entries)
      if (c.app->parsed()) chosen = c.app;
    rc = 2;
    if (!chosen) {
      rc = otherwise();
    } else {
      for (const auto& c : commands.entries)
        if (c.app == chosen) rc = c.run();
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", name.c_str(), e.what());
    rc = 2;
  }
  const std::string out = io::finish_stdout();
  if (!out.empty()) {
    std::fprintf(stderr, "%s: %s\n", name.c_str(), out.c_str());
    rc = 2;
  }
  return rc;
}

}  // namespace cdref::cli
