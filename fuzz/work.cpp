// fuzz/work.cpp - sets of work items, a runner's checkpoint and its text form, atomic files.
// (Work itself is in engine.cpp, beside run().)
#include <cdref/fuzz/work.hpp>
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <charconv>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

namespace cdref::fuzz {

void ItemSet::add(std::uint64_t b, std::uint64_t e) {
  if (b >= e) return;
  // the first range that ends after b (one that ends at b is a neighbour before [b, e))
  auto it = std::lower_bound(r_.begin(), r_.end(), b, [](const Range& r, std::uint64_t x) { return r.second <= x; });
  if (it != r_.end() && it->first < e && b < it->second)
    throw std::runtime_error("items " + std::to_string(std::max(b, it->first)) + ".." +
                             std::to_string(std::min(e, it->second) - 1) + " counted twice");
  // [b, e) lies before *it and after its predecessor; join the neighbours it touches
  const bool join_next = it != r_.end() && it->first == e;
  const bool join_prev = it != r_.begin() && std::prev(it)->second == b;
  if (join_prev && join_next) {
    std::prev(it)->second = it->second;
    r_.erase(it);
  } else if (join_prev) {
    std::prev(it)->second = e;
  } else if (join_next) {
    it->first = b;
  } else {
    r_.insert(it, {b, e});
  }
}

void ItemSet::add(const ItemSet& o) {
  for (const Range& r : o.r_) add(r.first, r.second);
}

std::uint64_t ItemSet::count() const {
  std::uint64_t c = 0;
  for (const Range& r : r_) c += r.second - r.first;
  return c;
}

ItemSet ItemSet::complement(std::uint64_t n) const {
  ItemSet c;
  std::uint64_t at = 0;
  for (const Range& r : r_) {
    if (r.first >= n) break;
    if (at < r.first) c.r_.push_back({at, r.first});
    at = r.second;
  }
  if (at < n) c.r_.push_back({at, n});
  return c;
}

std::string ItemSet::text() const {
  std::string s;
  for (const Range& r : r_) {
    if (!s.empty()) s += ' ';
    s += std::to_string(r.first) + "-" + std::to_string(r.second);
  }
  return s;
}

ItemSet ItemSet::parse(const std::string& text) {
  ItemSet s;
  std::istringstream in(text);
  std::string tok;
  while (in >> tok) {
    const auto dash = tok.find('-');
    std::uint64_t b = 0, e = 0;
    const char* p = tok.data();
    const char* end = p + tok.size();
    const auto rb = std::from_chars(p, dash == std::string::npos ? end : p + dash, b);
    const auto re = dash == std::string::npos ? rb : std::from_chars(p + dash + 1, end, e);
    if (dash == std::string::npos || rb.ec != std::errc() || rb.ptr != p + dash || re.ec != std::errc() ||
        re.ptr != end || b >= e)
      throw std::runtime_error("malformed item range '" + tok + "' (wants first-end, first < end)");
    s.add(b, e);
  }
  return s;
}

void merge_into(Results& into, Results&& from) {
  while (!from.cells.empty()) {
    auto node = from.cells.extract(from.cells.begin());
    const auto ins = into.cells.insert(std::move(node));
    if (!ins.inserted) ins.position->second.merge(ins.node.mapped());
  }
}

std::string serialize(const PartCheckpoint& c) {
  std::ostringstream o;
  o << "cdref-part 1\n";
  o << "part " << c.part << " " << c.generation << "\n";
  o << "done " << c.done.text() << "\n";
  o << serialize(c.saved);
  return o.str();
}

PartCheckpoint deserialize_part(const std::string& text, const std::string& source) {
  PartCheckpoint c;
  std::istringstream in(text);
  std::string line[3];
  if (!std::getline(in, line[0]) || line[0].rfind("cdref-part 1", 0) != 0 ||
      line[0].find_first_not_of('\r', 12) != std::string::npos)
    throw std::runtime_error(source + ":1: not a cdref part checkpoint");
  for (int k = 1; k < 3; ++k)
    if (!std::getline(in, line[k])) throw std::runtime_error(source + ": truncated (no " + (k == 1 ? "part" : "done") + " record)");
  for (std::string& l : line)
    while (!l.empty() && l.back() == '\r') l.pop_back();  // a file that passed through CRLF line ends
  {
    std::istringstream ls(line[1]);
    std::string tag;
    if (!(ls >> tag >> c.part >> c.generation) || tag != "part" || c.part < 0)
      throw std::runtime_error(source + ":2: malformed part record");
  }
  if (line[2].rfind("done", 0) != 0) throw std::runtime_error(source + ":3: malformed done record");
  try {
    c.done = ItemSet::parse(line[2].substr(4));
  } catch (const std::exception& e) {
    throw std::runtime_error(source + ":3: " + e.what());
  }
  // the rest is the campaign's text form (its line numbers counted from its own start)
  std::stringstream rest;
  rest << in.rdbuf();
  c.saved = deserialize(rest.str(), source + " (after line 3)");
  if (c.saved.items_done != c.done.count())
    throw std::runtime_error(source + ": " + std::to_string(c.done.count()) + " items marked done, statistics of " +
                             std::to_string(c.saved.items_done));
  return c;
}

// The data reaches the disk before the rename, and the rename before the function returns
// (fsync of the file, then of its directory): a node that crashes leaves the old file or the
// new one, and a caller may remove what the new file replaces once this returns.
void write_file_atomically(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp";
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw std::runtime_error("cannot write checkpoint " + tmp + ": " + std::strerror(errno));
  // a failure leaves no temporary file behind (and the checkpoint as it was)
  auto fail = [&](const char* doing, int e, bool open) {
    if (open) ::close(fd);
    ::unlink(tmp.c_str());
    throw std::runtime_error(std::string("cannot ") + doing + " checkpoint " + path + ": " + std::strerror(e ? e : EIO));
  };
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t k = ::write(fd, text.data() + done, text.size() - done);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) fail("write", errno, true);
    done += std::size_t(k);
  }
  if (::fsync(fd) != 0) fail("write", errno, true);
  if (::close(fd) != 0) fail("write", errno, false);
  if (std::rename(tmp.c_str(), path.c_str()) != 0) fail("replace", errno, false);
  const auto slash = path.rfind('/');
  const std::string dir = slash == std::string::npos ? "." : (slash == 0 ? "/" : path.substr(0, slash));
  const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dfd >= 0) {  // (a file system that cannot sync a directory still renamed the file)
    ::fsync(dfd);
    ::close(dfd);
  }
}

std::string read_whole_file(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw std::runtime_error("cannot read " + path);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

}  // namespace cdref::fuzz
