// src/peers/rapier.hpp - Rapier's shape queries in `cdref peers`: parry's geometry as Rapier's
// WebAssembly build (npm's @dimforge/rapier3d-compat, f32) runs it under node. The queries run in
// one node process (scripts/rapier/peer.mjs), started at the first case, asked a case at a time
// on a socket pair: the case's columns rounded to float, written as decimals that read back
// exactly (%.9g), and its answer read back the same way (node prints the shortest decimal of a
// double, here a float widened). The process is started without a shell, its argument list fixed;
// a socket, not a pipe, so that a process gone away is an error of the call (MSG_NOSIGNAL), not a
// SIGPIPE. A reply that does not come within kWait is a refused case, named, and the process is
// started again for the next one.
//
// Built where node and the package are: scripts/deps.sh installs the package into
// scripts/rapier/node_modules with npm (`npm ci`), and CMake then defines CDREF_RAPIER_NODE,
// CDREF_RAPIER_SCRIPT and CDREF_RAPIER_VERSION.
#pragma once

#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cdref/error.hpp>
#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "adapter.hpp"

extern char** environ;

namespace cdref::peers::rapier {

/// The longest a case may take before it is refused and the process started again.
inline constexpr int kWait = 20000;  // milliseconds

/// The node process running peer.mjs, one request at a time.
class Node {
 public:
  Node() = default;
  ~Node() { stop(); }
  Node(const Node&) = delete;
  Node& operator=(const Node&) = delete;

  /// The reply's numbers to a request (an operation and the case's values at float).
  std::vector<double> ask(const std::string& op, const std::vector<float>& args) {
    const std::lock_guard<std::mutex> one(m_);
    if (fd_ < 0) start();
    send_all(request(op, args));
    return parse(read_line());
  }
  /// The replies to many requests of one operation, sent together and read back in order: each
  /// the reply's numbers, or the message of a refused case (in `refused`, empty when answered).
  std::vector<std::vector<double>> ask_many(const std::string& op, const std::vector<std::vector<float>>& args,
                                            std::vector<std::string>& refused) {
    const std::lock_guard<std::mutex> one(m_);
    std::vector<std::vector<double>> out(args.size());
    refused.assign(args.size(), "");
    constexpr std::size_t chunk = 128;  // requests in flight: their replies fit the socket's buffer
    for (std::size_t first = 0; first < args.size();) {
      if (fd_ < 0) start();
      const std::size_t last = std::min(args.size(), first + chunk);
      std::string lines;
      for (std::size_t k = first; k < last; ++k) lines += request(op, args[k]);
      send_all(lines);
      std::size_t k = first;
      while (k < last) {
        try {
          out[k] = parse(read_line());
          ++k;
        } catch (const invalid_input& e) {
          refused[k++] = e.what();
          // no answer in time: the process was stopped; the rest of the chunk is asked again of
          // a new one
          if (fd_ < 0) break;
        }
      }
      first = k;
    }
    return out;
  }
  /// Rapier's version, as the package reports it.
  std::string version() {
    const std::lock_guard<std::mutex> one(m_);
    if (fd_ < 0) start();
    static const char ask[] = "version\n";
    if (::send(fd_, ask, sizeof ask - 1, MSG_NOSIGNAL) != ssize_t(sizeof ask - 1)) {
      stop();
      throw std::runtime_error("Rapier's node process (" CDREF_RAPIER_SCRIPT ") went away");
    }
    const std::string reply = read_line();
    if (reply.rfind("ok ", 0) != 0) throw std::runtime_error("Rapier's node process answered '" + reply + "'");
    return reply.substr(3);
  }

 private:
  static std::string request(const std::string& op, const std::vector<float>& args) {
    std::string line = op;
    char num[32];
    for (float x : args) {
      std::snprintf(num, sizeof num, " %.9g", double(x));
      line += num;
    }
    line += '\n';
    return line;
  }
  void send_all(const std::string& line) {
    for (std::size_t done = 0; done < line.size();) {
      const ssize_t k = ::send(fd_, line.data() + done, line.size() - done, MSG_NOSIGNAL);
      if (k < 0 && errno == EINTR) continue;
      if (k <= 0) {
        stop();
        throw std::runtime_error("Rapier's node process (" CDREF_RAPIER_SCRIPT ") went away");
      }
      done += std::size_t(k);
    }
  }
  // A reply's numbers; a refused case throws invalid_input with Rapier's message.
  static std::vector<double> parse(const std::string& reply) {
    std::istringstream in(reply);
    std::string status;
    in >> status;
    if (status == "error") {
      std::string why;
      std::getline(in, why);
      throw invalid_input("Rapier refused the case:" + why);
    }
    if (status != "ok") throw std::runtime_error("Rapier's node process answered '" + reply + "'");
    std::vector<double> out;
    std::string tok;
    while (in >> tok) {
      char* end = nullptr;
      const double x = std::strtod(tok.c_str(), &end);
      if (end == tok.c_str() || *end) throw std::runtime_error("Rapier's node process answered '" + reply + "'");
      out.push_back(x);
    }
    return out;
  }
  void start() {
    int sv[2];
    if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sv) != 0)
      throw std::runtime_error(std::string("socketpair: ") + std::strerror(errno));
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_adddup2(&fa, sv[1], 0);
    posix_spawn_file_actions_adddup2(&fa, sv[1], 1);
    std::string node = CDREF_RAPIER_NODE, script = CDREF_RAPIER_SCRIPT;
    char* argv[] = {node.data(), script.data(), nullptr};
    const int rc = posix_spawn(&pid_, node.c_str(), &fa, nullptr, argv, environ);
    posix_spawn_file_actions_destroy(&fa);
    ::close(sv[1]);
    if (rc != 0) {
      ::close(sv[0]);
      pid_ = -1;
      throw std::runtime_error("cannot run " + node + ": " + std::strerror(rc));
    }
    fd_ = sv[0];
    buf_.clear();
  }
  void stop() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
    if (pid_ > 0) {
      ::kill(pid_, SIGKILL);
      int status = 0;
      while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
      }
    }
    pid_ = -1;
  }
  // One line of the reply; a process that does not answer within kWait is stopped.
  std::string read_line() {
    for (;;) {
      const std::size_t nl = buf_.find('\n');
      if (nl != std::string::npos) {
        std::string line = buf_.substr(0, nl);
        buf_.erase(0, nl + 1);
        return line;
      }
      pollfd p{fd_, POLLIN, 0};
      const int r = ::poll(&p, 1, kWait);
      if (r < 0 && errno == EINTR) continue;
      if (r == 0) {
        stop();
        throw invalid_input("Rapier did not answer within " + std::to_string(kWait / 1000) +
                            " s: the case is refused (its process is started again)");
      }
      char chunk[4096];
      const ssize_t k = ::recv(fd_, chunk, sizeof chunk, 0);
      if (k < 0 && errno == EINTR) continue;
      if (k <= 0) {
        stop();
        throw std::runtime_error("Rapier's node process (" CDREF_RAPIER_SCRIPT ") ended; is its package installed "
                                 "(scripts/deps.sh runs npm ci in scripts/rapier)?");
      }
      buf_.append(chunk, std::size_t(k));
    }
  }
  std::mutex m_;
  pid_t pid_ = -1;
  int fd_ = -1;
  std::string buf_;
};

/// The process all of Rapier's rows share.
inline Node& node() {
  static Node n;
  return n;
}

/// The case's columns [from, from + n) at float.
inline std::vector<float> floats(const Inputs& in, int from, int n) {
  std::vector<float> out;
  for (int i = from; i < from + n; ++i) out.push_back(float(in[i]));
  return out;
}

/// A cast's answer from its reply: hit, lambda_enter (the time of impact) and the normal.
inline Answer cast_answer(Query q, const std::vector<double>& r) {
  if (r.size() != 5) throw std::runtime_error("Rapier's cast answered " + std::to_string(r.size()) + " numbers");
  Out o(q, r[0] != 0);
  if (r[0] != 0) o.set("lambda_enter", {r[1]}).set("normal", {r[2], r[3], r[4]});
  return o.a;
}
/// A proximity's answer: intersect, distance and depth from contactShape's signed distance.
inline Answer contact_answer(Query q, const std::vector<double>& r) {
  if (r.size() != 2) throw std::runtime_error("Rapier's contact answered " + std::to_string(r.size()) + " numbers");
  Out o(q, r[0] != 0);
  return o.set("distance", {r[1] > 0 ? r[1] : 0.0}).set("depth", {r[1] < 0 ? -r[1] : 0.0}).a;
}
/// An intersection test's answer.
inline Answer test_answer(Query q, const std::vector<double>& r) {
  if (r.size() != 1) throw std::runtime_error("Rapier's test answered " + std::to_string(r.size()) + " numbers");
  return Out(q, r[0] != 0).a;
}

/// One of Rapier's rows: its operation, the columns it takes and how its reply reads. Its cases
/// are asked a block at a time (prefetch), the answers kept per engine thread in the block's
/// order, and run() takes a case's answer from there (asking alone for a case not told).
struct Row {
  Query q;
  std::string op;
  int width;
  Answer (*answer)(Query, const std::vector<double>&);
  struct Told {
    Inputs in;
    Answer a;
    std::string refused;
  };
  static std::vector<Told>& told() {
    thread_local std::vector<Told> t;
    return t;
  }
  static std::size_t& cursor() {
    thread_local std::size_t c = 0;
    return c;
  }
  bool same(const Inputs& a, const Inputs& b) const {
    for (int i = 0; i < width; ++i)
      if (a[i] != b[i]) return false;
    return true;
  }
  void prefetch(const Inputs* in, std::size_t n) const {
    std::vector<std::vector<float>> args;
    for (std::size_t k = 0; k < n; ++k) args.push_back(floats(in[k], 0, width));
    std::vector<std::string> refused;
    const std::vector<std::vector<double>> r = node().ask_many(op, args, refused);
    std::vector<Told>& t = told();
    t.assign(n, Told{});
    for (std::size_t k = 0; k < n; ++k) {
      t[k].in = in[k];
      t[k].refused = refused[k];
      if (refused[k].empty()) t[k].a = answer(q, r[k]);
    }
    cursor() = 0;
  }
  Answer run(const Inputs& in) const {
    std::vector<Told>& t = told();
    for (std::size_t& c = cursor(); c < t.size(); ++c)
      if (same(t[c].in, in)) {
        const Told& got = t[c++];
        if (!got.refused.empty()) throw invalid_input(got.refused);
        return got.a;
      }
    return answer(q, node().ask(op, floats(in, 0, width)));
  }
};

/// Rapier's adapters (each at f32, precision 24).
inline std::vector<Adapter> adapters() {
  const std::string lib = "Rapier " CDREF_RAPIER_VERSION " (f32, WebAssembly)";
  auto none = [](const Inputs&, const Answer&) { return false; };
  std::vector<Adapter> out;
  auto add = [&](const char* function, const char* query, const char* convention, std::vector<std::string> graded,
                 std::function<bool(const Inputs&, const Answer&)> differs, const char* op, int width,
                 Answer (*answer)(Query, const std::vector<double>&)) {
    const Row row{fuzz::query_by_name(query), op, width, answer};
    Adapter a{lib, function, query, convention, std::move(graded), std::move(differs),
              [row](const Inputs& in) { return row.run(in); }, 24};
    a.prefetch = [row](const Inputs* in, std::size_t n) { row.prefetch(in, n); };
    out.push_back(std::move(a));
  };
  add("Ball::castRayAndGetNormal (solid)", "ray-sphere-cast",
      "a source inside or on the sphere: a solid cast hits at 0, as in cdref, but with the normal pointing from the "
      "source to the centre (NaN at the centre; cdref: a zero normal): those cases are set apart",
      {"lambda_enter", "normal"}, [](const Inputs& in, const Answer&) { return source_inside(in); }, "rs", 10,
      cast_answer);
  add("Cuboid::castRayAndGetNormal (solid)", "ray-box-cast",
      "none: a solid cast from inside hits at 0 with a zero normal, as in cdref",
      {"lambda_enter", "normal"}, none, "rb", 12, cast_answer);
  add("Triangle::castRayAndGetNormal", "ray-triangle-cast",
      "a ray in the triangle's plane: those cases are set apart (parry casts on the plane's crossing)",
      {"lambda_enter"}, [](const Inputs& in, const Answer&) { return in_plane(in); }, "rt", 15, cast_answer);
  add("Ball::intersectsShape and contactShape (Ball)", "sphere-sphere",
      "none: contactShape's negative distance is the depth", {"distance", "depth"}, none, "ss", 8, contact_answer);
  add("Ball::intersectsShape and contactShape (Cuboid)", "sphere-box",
      "none: contactShape's negative distance is the depth", {"distance", "depth"}, none, "sb", 10, contact_answer);
  add("Ball::intersectsShape and contactShape (Triangle)", "sphere-triangle",
      "none: contactShape's negative distance is the depth", {"distance", "depth"}, none, "st", 13, contact_answer);
  add("Cuboid::intersectsShape (Cuboid)", "box-box", "none", {}, none, "bb", 12, test_answer);
  add("Triangle::intersectsShape (Cuboid)", "triangle-box", "none", {}, none, "tb", 15, test_answer);
  add("Triangle::intersectsShape (Triangle)", "triangle-triangle", "none", {}, none, "tt", 18, test_answer);
  return out;
}

}  // namespace cdref::peers::rapier
