// src/output.hpp - every byte cdref writes goes through here.
//
// Standard output is a checked stream: every write(2) is checked, a closed pipe (EPIPE, as
// after `cdref ... | head`) ends the output quietly (SIGPIPE is ignored, so no command dies of
// it) and the rest of the command still runs, so files it was asked for are still written; any
// other failure (a full disk, /dev/full) is remembered and turns the exit status into 2.
//
// A file output is opened before the work that fills it, so a path that cannot be written is
// refused in a second, not after a long campaign: a regular file is written to a temporary
// name in the same directory (mkstemp) and renamed over the path only when every write, the
// flush and the close succeeded; a failure removes the temporary file and leaves the path as
// it was. A path that exists and is not a regular file (a device, a named pipe) is written in
// place, each write checked. "-" names standard output.
#pragma once

#include <memory>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace cdref::cli::io {

// A write, flush, close or rename that failed; the message names the output and the reason.
struct write_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Installs the checked standard output (call first in main): SIGPIPE ignored, std::cout
// written through a checked buffer.
void init();

// Flushes standard output. Returns "" when everything written reached it or the reader closed
// the pipe, or the reason it failed ("standard output: No space left on device").
std::string finish_stdout();

// True once the reader of standard output has gone away (EPIPE): long outputs to it may stop.
bool stdout_closed();

// One output of a command, named for messages by what it is (`--json`, `the case file`).
class Output {
 public:
  // Opens `path` ("-" standard output) for writing now; throws write_error naming `what` and
  // the path when it cannot be written (a missing directory, no permission, a directory).
  Output(const std::string& path, const std::string& what);
  Output(Output&&) noexcept;
  Output& operator=(Output&&) noexcept;
  ~Output();  // an output never committed is removed (its temporary file), never left half

  // The stream to write to; its writes are checked (a failure is reported by commit()).
  std::ostream& stream();
  // Flushes, closes and renames into place; throws write_error naming the output on any
  // failure (and removes the temporary file). Standard output is flushed and checked.
  void commit();
  const std::string& path() const;
  bool is_stdout() const;

 private:
  struct State;
  std::unique_ptr<State> s_;
};

// Checks before a long run that `path` can be written as a file that is replaced atomically
// (a checkpoint): its directory exists and takes a new file, and the path is not a directory
// or a device. Throws write_error naming `what` and the path.
void check_replaceable(const std::string& path, const std::string& what);

// Several outputs of one command: each written even when another fails; the failures are
// collected and thrown together (write_error naming each) by finish().
class Outputs {
 public:
  // Runs `write` (which commits its outputs); a write_error is remembered, not thrown.
  template <class F>
  void attempt(F&& write) {
    try {
      write();
    } catch (const write_error& e) {
      errors_.push_back(e.what());
    }
  }
  void finish() const;  // throws write_error with every failure, one per line

 private:
  std::vector<std::string> errors_;
};

}  // namespace cdref::cli::io
