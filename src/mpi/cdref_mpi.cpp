// src/mpi/cdref_mpi.cpp - cdref-mpi: `cdref campaign` across the ranks of an MPI job.
//
//   mpirun -np R cdref-mpi campaign [the options of cdref campaign]
//
// Rank 0 hands out chunks of work items (blocks of 256 cases of one cell; fuzz/cdref/fuzz/
// work.hpp) on request: a rank asks for its next chunk when it has finished the last, so fast
// and slow nodes finish together. Chunks shrink as the work runs out (a quarter of what is
// left, shared among the ranks, between T and 16 T items for a rank of T threads). Rank 0
// serves the requests from its main thread and works on its own chunks in another.
//
// The statistics are sums and maxima with deterministic tie-breaks, so the ranks' results,
// reduced along a binary tree with the campaign's exact merge, are exactly the single
// process's: rank 0 prints the same text form, JSON, CSV and table, byte for byte.
//
// Checkpoints (--checkpoint P). Each rank writes what it has finished, the items and their
// statistics together, to P.g<G>.r<rank> (atomically, every --checkpoint-every seconds,
// default 10, and when its work is done); P itself names the generation G and the number of
// ranks that wrote it. A job started with --resume (any number of ranks) reads generation G,
// refuses items counted twice, and writes the union as rank 0's file of generation G+1 before
// any rank starts; the items in it are never handed out again. A chunk finished but not yet
// in a checkpoint when its rank dies is run again after the resume, and counted once.
//
// Waiting for work and for results does not spin: OpenMPI's blocking calls poll in a loop,
// which on an oversubscribed node would take the core from a rank that works; those requests
// are tested every 200 us instead (the collectives at the start are brief and still block).
// A rank that dies ends the job through the launcher (mpirun ends a job that lost a rank).
#include <cdref/exact/gmp_pool.hpp>
#include <mpi.h>
#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <deque>
#include <exception>
#include <fstream>
#include <iostream>
#include <mutex>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <cdref/fuzz/work.hpp>

#include "../campaign_cli.hpp"

namespace {

using namespace cdref;
using namespace cdref::fuzz;
using Clock = std::chrono::steady_clock;

constexpr int tag_request = 1, tag_chunk = 2, tag_result = 3;

// `stop` (optional): give up waiting when it becomes true (rank 0's own worker failed).
bool wait_for(MPI_Request& r, MPI_Status* st = MPI_STATUS_IGNORE, const std::atomic<bool>* stop = nullptr) {
  for (int done = 0;;) {
    MPI_Test(&r, &done, st);
    if (done) return true;
    if (stop && stop->load()) return false;
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
}

void send_text(const std::string& text, int to) {
  if (text.size() > std::size_t(INT32_MAX)) throw std::runtime_error("a rank's results exceed 2 GiB");
  MPI_Request r;
  MPI_Isend(text.data(), int(text.size()), MPI_CHAR, to, tag_result, MPI_COMM_WORLD, &r);
  wait_for(r);
}

std::string recv_text(int from) {
  MPI_Status st;
  for (int flag = 0;;) {
    MPI_Iprobe(from, tag_result, MPI_COMM_WORLD, &flag, &st);
    if (flag) break;
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  int n = 0;
  MPI_Get_count(&st, MPI_CHAR, &n);
  std::string text(std::size_t(n), '\0');
  MPI_Recv(text.data(), n, MPI_CHAR, from, tag_result, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return text;
}

// Rank 0's queue of items not yet handed out.
class Dispenser {
 public:
  Dispenser(const ItemSet& todo, int ranks) : left_(todo.count()), ranks_(ranks) {
    for (const auto& r : todo.ranges()) q_.push_back(r);
  }
  // The next chunk for a rank of `threads` threads; empty (first == second) when none is left.
  ItemSet::Range take(int threads) {
    std::lock_guard<std::mutex> lock(m_);
    if (q_.empty()) return {0, 0};
    const std::uint64_t t = std::uint64_t(std::max(1, threads));
    const std::uint64_t want = std::clamp<std::uint64_t>(left_ / (4 * std::uint64_t(ranks_)), t, 16 * t);
    ItemSet::Range& front = q_.front();
    const ItemSet::Range c{front.first, std::min(front.second, front.first + want)};
    front.first = c.second;
    if (front.first == front.second) q_.pop_front();
    left_ -= c.second - c.first;
    return c;
  }

 private:
  std::mutex m_;
  std::deque<ItemSet::Range> q_;
  std::uint64_t left_;
  int ranks_;
};

struct Pointer {  // the file P of --checkpoint P
  std::uint64_t generation = 0;
  int ranks = 0;
  std::string fingerprint;
};

std::string part_path(const std::string& p, std::uint64_t g, int rank) {
  return p + ".g" + std::to_string(g) + ".r" + std::to_string(rank);
}

Pointer read_pointer(const std::string& p) {
  std::istringstream in(read_whole_file(p));
  Pointer ptr;
  std::string head, tag_g, tag_r, tag_f;
  std::getline(in, head);
  if (head != "cdref-mpi-checkpoint 1")
    throw std::runtime_error(p + " is not a cdref-mpi checkpoint (a single process's checkpoint resumes with cdref)");
  if (!(in >> tag_g >> ptr.generation >> tag_r >> ptr.ranks >> tag_f) || tag_g != "generation" || tag_r != "ranks" ||
      tag_f != "fingerprint" || ptr.ranks < 1)
    throw std::runtime_error(p + ": malformed cdref-mpi checkpoint");
  std::getline(in >> std::ws, ptr.fingerprint);
  return ptr;
}

bool exists(const std::string& path) { return access(path.c_str(), F_OK) == 0; }

// What this rank has finished, and its checkpoint.
struct Part {
  const Work& work;
  const std::string& fingerprint;
  std::string path;  // "" no checkpoint
  double every;
  PartCheckpoint c;
  Clock::time_point last = Clock::now();
  bool die_after_checkpoint = false;  // CDREF_MPI_TEST_KILL_RANKS (see main)

  void stamp() {  // the campaign's text form's header fields, for this part
    const Spec& s = work.spec();
    c.saved.fingerprint = fingerprint;
    c.saved.shard = s.shard;
    c.saved.shards = s.shards;
    c.saved.items_done = c.done.count();
    c.saved.items_total = work.items();
    c.saved.seed = s.seed;
  }
  void write() {
    if (path.empty()) return;
    stamp();
    write_file_atomically(path, serialize(c));
    last = Clock::now();
  }
  void run(ItemSet::Range r) {
    work.run(r.first, r.second, c.saved.results);
    c.done.add(r.first, r.second);
    if (std::chrono::duration<double>(Clock::now() - last).count() >= every) {
      write();
      if (die_after_checkpoint && !path.empty()) std::raise(SIGKILL);
    }
  }
  // The last checkpoint, when no work is left for this rank (a rank to die that no work
  // reached dies here: the job must still fail).
  void finish() {
    write();
    if (die_after_checkpoint && !path.empty()) std::raise(SIGKILL);
  }
};

// Rank 0 before any work: the generation of this run and what earlier ones finished.
// Throws with a message for the user (another campaign's checkpoint, items counted twice, ...).
PartCheckpoint start_generation(const Spec& spec, const Work& work, Pointer& old) {
  PartCheckpoint base;
  const std::string& p = spec.checkpoint;
  if (spec.resume) {
    if (!exists(p)) throw std::runtime_error("cannot resume: no checkpoint " + p);
    old = read_pointer(p);
    const std::string fp = spec.fingerprint() + ";shard=" + std::to_string(spec.shard) + "/" + std::to_string(spec.shards);
    if (old.fingerprint != fp)
      throw std::runtime_error("checkpoint " + p + " belongs to another campaign (" + old.fingerprint + ")");
    for (int r = 0; r < old.ranks; ++r) {
      const std::string f = part_path(p, old.generation, r);
      // rank 0's file holds all that earlier generations finished: it is always written before
      // P names its generation. Missing, the files are not where this rank 0 looks (P must be
      // on a file system every node sees) or were removed.
      if (r == 0 && !exists(f))
        throw std::runtime_error("cannot resume: " + f + " is missing (P and its rank files must be on a file system "
                                 "every rank sees, and stay together)");
      if (!exists(f)) continue;  // that rank died before its first checkpoint
      const PartCheckpoint c = deserialize_part(read_whole_file(f), f);
      if (c.saved.fingerprint != spec.fingerprint() || c.saved.shard != spec.shard || c.saved.shards != spec.shards)
        throw std::runtime_error(f + " belongs to another campaign (" + c.saved.fingerprint + ")");
      if (c.saved.items_total != work.items() ||
          (!c.done.empty() && c.done.ranges().back().second > work.items()))
        throw std::runtime_error(f + " has " + std::to_string(c.saved.items_total) + " work items, this campaign " +
                                 std::to_string(work.items()) + " (written by a cdref whose families differ)");
      work.check(c.saved.results, c.done.ranges(), f);  // its statistics are those of its items
      try {
        base.done.add(c.done);
      } catch (const std::exception& e) {
        throw std::runtime_error(f + ": " + e.what());
      }
      base.saved.results.merge(c.saved.results);
    }
  }
  else if (exists(p)) {  // a new campaign over an old checkpoint: its generation is left behind
    try {
      old = read_pointer(p);
    } catch (const std::exception&) {
      old = Pointer{};  // not a cdref-mpi checkpoint: replaced
    }
  }
  base.generation = old.generation + 1;
  return base;
}

// Rank 0 before any work: its file of the new generation (all that earlier ones finished),
// then P naming that generation, then the earlier generation's files removed.
void finish_generation(const Spec& spec, std::uint64_t generation, const Pointer& old, int ranks, Part& part0) {
  const std::string& p = spec.checkpoint;
  // files of the new generation left by another job (a campaign started over under the same
  // name) would be read on a resume: removed before P names the generation
  for (int r = 1; r < ranks; ++r) std::remove(part_path(p, generation, r).c_str());
  part0.write();
  std::ostringstream o;
  o << "cdref-mpi-checkpoint 1\ngeneration " << generation << "\nranks " << ranks << "\nfingerprint "
    << spec.fingerprint() << ";shard=" << spec.shard << "/" << spec.shards << "\n";
  write_file_atomically(p, o.str());
  for (int r = 0; r < old.ranks; ++r) std::remove(part_path(p, old.generation, r).c_str());
}

// The CPUs this rank may run on (mpirun binds a rank to one core when there are at most two
// ranks, and to a socket otherwise, unless told --bind-to none).
int cpus_of_this_rank() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) == 0) return std::max(1, CPU_COUNT(&set));
  return std::max(1, int(std::thread::hardware_concurrency()));
}

// The ranks on this rank's node.
int node_ranks() {
  MPI_Comm node;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
  int local = 1;
  MPI_Comm_size(node, &local);
  MPI_Comm_free(&node);
  return std::max(1, local);
}

int run_campaign(cli::CampaignCommand& cmd, bool defaults, int rank, int ranks) {
  std::optional<Work> checked;
  std::optional<cli::CampaignOutputs> outputs;
  std::string error;
  try {
    cli::finish_campaign(cmd, defaults);
    checked.emplace(cmd.spec);  // the cells and implementations exist
    if (rank == 0) outputs.emplace(cli::open_campaign_outputs(cmd));  // a path that cannot be written: now
    if (rank == 0 && !cmd.spec.checkpoint.empty()) cli::io::check_replaceable(cmd.spec.checkpoint, "--checkpoint");
  } catch (const std::exception& e) {
    error = e.what();
  }
  // every rank checks the same arguments and they fail alike; the outputs are rank 0's alone,
  // so its word decides
  int args_ok = error.empty(), all_ok = 0;
  MPI_Allreduce(&args_ok, &all_ok, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  if (!all_ok) {
    if (rank == 0) std::fprintf(stderr, "cdref-mpi: %s\n", error.c_str());
    return 2;
  }
  Spec& spec = cmd.spec;
  // a rank bound to fewer CPUs than its threads (they only take turns) or than its share of
  // the node (the rest stay idle): say so once, on rank 0
  const int cpus = cpus_of_this_rank();
  const int share = std::max(1, int(std::thread::hardware_concurrency()) / node_ranks());
  if (!cmd.threads) spec.threads = std::min(cpus, share);
  // (one CPU where the node has more is mpirun's binding of at most two ranks; a larger set
  // smaller than the node may be the job's allocation, which is as it should be)
  int bound[2] = {spec.threads > cpus || (cpus == 1 && share > 1), 0};
  MPI_Reduce(&bound[0], &bound[1], 1, MPI_INT, MPI_SUM, 0, MPI_COMM_WORLD);
  if (rank == 0 && bound[1] > 0)
    std::fprintf(stderr,
                 "cdref-mpi: %d of %d ranks are bound to fewer CPUs than their threads or their share of the node "
                 "(rank 0: %d threads, bound to %d of its share of %d CPUs); mpirun --bind-to none, or --map-by "
                 "...:PE=N, lets them use the node's cores\n",
                 bound[1], ranks, spec.threads, cpus, share);
  const Work work(spec);
  const std::string fingerprint = spec.fingerprint();

  // rank 0 reads earlier generations and opens this one (its own file holds all they
  // finished); the others wait for its word
  Part part{work, fingerprint, "", spec.checkpoint_every, {}};
  part.c.part = rank;
  PartCheckpoint base;
  int ok = 1;
  if (rank == 0 && !spec.checkpoint.empty()) {
    try {
      Pointer old;
      base = start_generation(spec, work, old);
      part.c.done = base.done;
      part.c.saved.results = base.saved.results;
      part.c.generation = base.generation;
      part.path = part_path(spec.checkpoint, base.generation, 0);
      finish_generation(spec, base.generation, old, ranks, part);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "cdref-mpi: %s\n", e.what());
      ok = 0;
    }
  }
  std::uint64_t generation = base.generation;
  MPI_Bcast(&ok, 1, MPI_INT, 0, MPI_COMM_WORLD);
  if (!ok) return 2;
  MPI_Bcast(&generation, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
  part.c.generation = generation;
  if (!spec.checkpoint.empty()) part.path = part_path(spec.checkpoint, generation, rank);
  // Fault injection for tests/mpi_test.sh: CDREF_MPI_TEST_KILL_RANKS=r[,r...] makes those ranks
  // kill themselves (SIGKILL) right after their first checkpoint written while working, so that
  // the resume tests lose a rank mid-run whatever the machine's speed (killing it from outside
  // raced with a rank that had already finished its share), or after their last one when no
  // work reached them (the other ranks finished it first: the job still fails).
  if (const char* kill = std::getenv("CDREF_MPI_TEST_KILL_RANKS")) {
    std::string list = std::string(",") + kill + ",";
    part.die_after_checkpoint = list.find("," + std::to_string(rank) + ",") != std::string::npos;
  }

  if (rank == 0 && defaults) std::cout << cli::default_campaign_banner(spec);

  const auto t0 = Clock::now();
  if (rank == 0) {
    Dispenser disp(base.done.complement(work.items()), ranks);
    std::exception_ptr failed;
    std::atomic<bool> stop{false};  // rank 0's worker failed: the job ends now, not at the end
    std::thread local([&] {
      try {
        for (ItemSet::Range r; (r = disp.take(spec.threads)).first < r.second;) part.run(r);
        part.finish();
      } catch (...) {
        failed = std::current_exception();
        stop = true;
      }
    });
    for (int finished = 0; finished < ranks - 1;) {
      int threads = 0;
      MPI_Request req;
      MPI_Status st;
      MPI_Irecv(&threads, 1, MPI_INT, MPI_ANY_SOURCE, tag_request, MPI_COMM_WORLD, &req);
      if (!wait_for(req, &st, &stop)) break;  // (MPI_Abort follows the rethrow below)
      const ItemSet::Range r = disp.take(threads);
      const std::uint64_t msg[2] = {r.first, r.second};
      MPI_Send(msg, 2, MPI_UINT64_T, st.MPI_SOURCE, tag_chunk, MPI_COMM_WORLD);
      finished += r.first == r.second;
    }
    local.join();
    if (failed) std::rethrow_exception(failed);
  } else {
    for (;;) {
      const int threads = spec.threads;
      std::uint64_t msg[2];
      MPI_Request req[2];
      MPI_Irecv(msg, 2, MPI_UINT64_T, 0, tag_chunk, MPI_COMM_WORLD, &req[1]);
      MPI_Isend(&threads, 1, MPI_INT, 0, tag_request, MPI_COMM_WORLD, &req[0]);
      wait_for(req[0]);
      wait_for(req[1]);
      if (msg[0] == msg[1]) break;
      part.run({msg[0], msg[1]});
    }
    part.finish();
  }
  const auto t_work = Clock::now();
  {  // every rank done: the reduction timed alone
    MPI_Request r;
    MPI_Ibarrier(MPI_COMM_WORLD, &r);
    wait_for(r);
  }
  const auto t1 = Clock::now();

  // the reduction: a binary tree of exact merges (log2 R steps), done sets included, so that
  // rank 0 can check that every item was counted exactly once
  std::uint64_t bytes = 0;
  for (int k = 1; k < ranks; k <<= 1) {
    if (rank & k) {
      part.stamp();
      send_text(serialize(part.c), rank - k);
      break;
    }
    if (rank + k < ranks) {
      const std::string text = recv_text(rank + k);
      bytes += text.size();
      PartCheckpoint other = deserialize_part(text, "rank " + std::to_string(rank + k));
      part.c.done.add(other.done);
      merge_into(part.c.saved.results, std::move(other.saved.results));
    }
  }
  const auto t2 = Clock::now();
  if (rank != 0) return 0;
  if (!(part.c.done.complement(work.items()).empty() && part.c.done.count() == work.items()))
    throw std::runtime_error("the ranks finished " + std::to_string(part.c.done.count()) + " of " +
                             std::to_string(work.items()) + " items");
  const Results& r = part.c.saved.results;
  cli::emit_campaign(cmd, *outputs, r);
  std::uint64_t cases = 0;
  for (const auto& [k, st] : r.cells) cases += st.n;
  auto ms = [](Clock::duration d) { return std::chrono::duration<double>(d).count() * 1e3; };
  if (!cmd.quiet)
    std::cout << "\n" << cases << " evaluations in " << std::chrono::duration<double>(t2 - t0).count() << " s on "
              << ranks << " ranks of " << spec.threads << " threads (rank 0 waited " << ms(t1 - t_work)
              << " ms for the last rank; the reduction of " << r.cells.size() << " cells took " << ms(t2 - t1)
              << " ms, " << bytes << " bytes received by rank 0).\n";
  return 0;
}

}  // namespace

int main(int argc, char* argv[]) {
  cdref::exact::use_gmp_pool();  // GMP's small blocks cached per thread (gmp_pool.hpp)
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  cdref::cli::io::init();
  cdref::cli::Program program(
      "cdref-mpi",
      "cdref-mpi: `cdref campaign` across the ranks of an MPI job (mpirun --bind-to none -np R cdref-mpi [campaign "
      "[options]]); no command: the default campaign. Rank 0 prints exactly what cdref campaign prints. With MPI, "
      "--checkpoint P means: every rank writes what it has finished to P.g<G>.r<rank>, P names the generation, and "
      "--resume continues from it with any number of ranks; --threads is per rank (default: the node's hardware "
      "threads shared among the ranks on that node).");
  cdref::cli::CampaignCommand cmd;
  // a failure after the work started: the other ranks cannot go on without this one
  auto guarded = [&](bool defaults) {
    try {
      if (provided < MPI_THREAD_FUNNELED) throw std::runtime_error("the MPI library gives no thread support");
      return run_campaign(cmd, defaults, rank, ranks);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "cdref-mpi: rank %d: %s\n", rank, e.what());
      if (ranks > 1) MPI_Abort(MPI_COMM_WORLD, 2);
      return 2;
    }
  };
  cdref::cli::Command campaign =
      program.add("campaign", "run a campaign across the ranks (the options of cdref campaign)", [&] { return guarded(false); });
  cdref::cli::add_campaign_options(campaign, cmd, true);
  program.add("help", "this help", [&] {
    if (rank == 0) std::cout << program.help();
    return 0;
  });
  // every rank parses the same arguments and fails alike; rank 0 says why
  const int rc = program.run(argc, argv, [&] { return guarded(true); }, rank != 0);
  MPI_Finalize();
  return rc;
}
