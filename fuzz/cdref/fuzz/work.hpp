// cdref/fuzz/work.hpp - a campaign as numbered work items, for runners that hand them out
// (cdref-mpi across the ranks of an MPI job).
//
// A campaign's work items are blocks of 256 consecutive cases of one cell, numbered
// 0 .. items()-1 in the order run() takes them. Every statistic is a sum or a maximum with a
// deterministic tie-break, so the results of any partition of the items, run anywhere in any
// order and merged, are exactly the results of run(spec): that is what lets a runner hand
// items out dynamically and still print byte for byte what one process prints.
#pragma once

#include <cdref/fuzz/campaign.hpp>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace cdref::fuzz {

class Work {
 public:
  // Checks the spec as run() does (shard numbering, cells, implementations); throws
  // std::invalid_argument naming the problem. spec.checkpoint and spec.resume are not used.
  explicit Work(const Spec& spec);
  const Spec& spec() const;
  std::uint64_t items() const;
  // Cases of items [begin, end) that belong to the spec's shard.
  std::uint64_t cases(std::uint64_t begin, std::uint64_t end) const;
  // Runs items [begin, end) on spec.threads threads and merges their statistics into `into`.
  void run(std::uint64_t begin, std::uint64_t end, Results& into) const;
  // Checks statistics read from a checkpoint or a shard against the items said to be done
  // (half-open ranges): every cell of those items present with exactly their cases, no other
  // cell, and counts within a cell that add up. Throws std::runtime_error naming `source`.
  void check(const Results& r, const std::vector<std::pair<std::uint64_t, std::uint64_t>>& done,
             const std::string& source) const;

 private:
  std::uint64_t cell_cases(std::uint64_t r) const;
  struct State;
  std::shared_ptr<const State> s_;
};

// A set of item numbers as sorted, disjoint, non-adjacent half-open ranges.
class ItemSet {
 public:
  using Range = std::pair<std::uint64_t, std::uint64_t>;  // [first, second)
  // Adds [b, e); throws std::runtime_error if any of it is already in the set (an item
  // counted twice).
  void add(std::uint64_t b, std::uint64_t e);
  void add(const ItemSet& o);
  std::uint64_t count() const;
  bool empty() const { return r_.empty(); }
  const std::vector<Range>& ranges() const { return r_; }
  // The items of [0, n) not in the set.
  ItemSet complement(std::uint64_t n) const;
  // "b-e b-e ..." (e exclusive), and back; parse throws std::runtime_error on malformed text.
  std::string text() const;
  static ItemSet parse(const std::string& text);
  bool operator==(const ItemSet&) const = default;

 private:
  std::vector<Range> r_;
};

// What one runner (an MPI rank) has finished: the items, and their statistics in the
// campaign's text form (items_done = done.count()). Written whole and replaced atomically, so
// a file on disk always holds items and statistics of the same moment.
struct PartCheckpoint {
  int part = 0;             // the rank that wrote it
  std::uint64_t generation = 0;  // the run (a resumed job is the next generation)
  ItemSet done;
  Saved saved;
};
std::string serialize(const PartCheckpoint& c);
// Throws std::runtime_error naming `source`, the line and the problem.
PartCheckpoint deserialize_part(const std::string& text, const std::string& source);

// Results::merge that moves the cells `into` does not have yet instead of copying them (a
// cell's statistics are some 60 KB, mostly histogram bins); `from` is left empty.
void merge_into(Results& into, Results&& from);

// Writes `text` to `path` through a temporary file and a rename (a reader sees the old file
// or the new one, never a part); throws std::runtime_error naming the file.
void write_file_atomically(const std::string& path, const std::string& text);
std::string read_whole_file(const std::string& path);  // throws std::runtime_error naming it

}  // namespace cdref::fuzz
