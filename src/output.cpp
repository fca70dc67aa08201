// src/output.cpp - checked writes, temporary names and renames (output.hpp).
#include "output.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <iostream>
#include <cstdlib>
#include <streambuf>

namespace cdref::cli::io {

namespace {

// A stream buffer over a file descriptor that checks every write(2). The first failure is
// kept (its errno) and later output is dropped, so a command goes on computing and its other
// outputs are still written; the owner asks for the failure when it commits.
class FdBuf : public std::streambuf {
 public:
  explicit FdBuf(int fd, bool is_stdout = false) : fd_(fd), is_stdout_(is_stdout) { setp(buf_, buf_ + sizeof buf_); }
  ~FdBuf() override = default;
  int error() const { return err_; }
  bool pipe_closed() const { return pipe_closed_; }
  void set_fd(int fd) { fd_ = fd; }

 protected:
  int_type overflow(int_type c) override {
    if (!drain()) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override { return drain() ? 0 : -1; }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    if (n > epptr() - pptr()) {
      if (!drain()) return 0;
      if (n >= std::streamsize(sizeof buf_)) return put_all(s, std::size_t(n)) ? n : 0;
    }
    std::memcpy(pptr(), s, std::size_t(n));
    pbump(int(n));
    return n;
  }

 private:
  bool drain() {
    const std::size_t n = std::size_t(pptr() - pbase());
    setp(buf_, buf_ + sizeof buf_);
    return put_all(buf_, n);
  }
  bool put_all(const char* p, std::size_t n) {
    if (pipe_closed_) return true;  // the reader has gone: output is dropped, quietly
    if (err_) return false;
    while (n > 0) {
      const ssize_t w = ::write(fd_, p, n);
      if (w < 0) {
        if (errno == EINTR) continue;
        if (errno == EPIPE && is_stdout_) {
          pipe_closed_ = true;
          return true;
        }
        err_ = errno;
        return false;
      }
      p += w;
      n -= std::size_t(w);
    }
    return true;
  }
  int fd_;
  bool is_stdout_;
  int err_ = 0;
  bool pipe_closed_ = false;
  char buf_[1 << 16];
};

FdBuf* stdout_buf = nullptr;
bool stdout_reported = false;

std::string reason(int err) { return err ? std::strerror(err) : "unknown error"; }

}  // namespace

void init() {
  std::signal(SIGPIPE, SIG_IGN);
  // never destroyed: std::cout is flushed once more at exit, after static objects are gone
  static FdBuf* buf = new FdBuf(1, true);
  stdout_buf = buf;
  std::cout.flush();
  std::cout.rdbuf(buf);
}

bool stdout_closed() { return stdout_buf && stdout_buf->pipe_closed(); }

std::string finish_stdout() {
  if (!stdout_buf) {
    std::cout.flush();
    return std::cout ? "" : "standard output: write failed";
  }
  std::cout.flush();
  if (stdout_buf->error() && !stdout_reported) {
    stdout_reported = true;
    return "standard output: " + reason(stdout_buf->error());
  }
  return "";
}

struct Output::State {
  std::string path, what, tmp, target;  // target: the real path the temporary file replaces
  int fd = -1;
  bool to_stdout = false, committed = false;
  std::unique_ptr<FdBuf> buf;
  std::unique_ptr<std::ostream> os;

  [[noreturn]] void fail(const std::string& doing, int err) {
    const std::string msg = "cannot " + doing + " " + what + " " + path + ": " + reason(err);
    discard();
    throw write_error(msg);
  }
  void discard() {
    if (fd >= 0) ::close(fd);
    fd = -1;
    if (!tmp.empty()) ::unlink(tmp.c_str());
    tmp.clear();
  }
};

Output::Output(const std::string& path, const std::string& what) : s_(std::make_unique<State>()) {
  s_->path = path;
  s_->what = what;
  if (path == "-") {
    s_->to_stdout = true;
    return;
  }
  if (path.empty()) throw write_error(what + " needs a file name");
  struct stat st {};
  const bool exists = ::stat(path.c_str(), &st) == 0;  // (follows a symbolic link)
  if (exists && S_ISDIR(st.st_mode)) throw write_error("cannot write " + what + " " + path + ": it is a directory");
  if (exists && !S_ISREG(st.st_mode)) {
    // a device or a named pipe (standard output named as /dev/stdout among them): written in
    // place, since renaming over it would replace it
    s_->fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
    if (s_->fd < 0) s_->fail("write", errno);
  } else {
    // the file itself, not a symbolic link to it, is replaced: its real path names the
    // directory of the temporary file
    std::string real = path;
    if (exists) {
      char* r = ::realpath(path.c_str(), nullptr);
      if (r) real = r, std::free(r);
    }
    std::string t = real + ".tmp-XXXXXX";
    s_->fd = ::mkstemp(t.data());
    if (s_->fd >= 0) {
      s_->tmp = t;
      s_->target = real;
      // an existing file keeps its permissions; a new one gets those of an ordinary new file
      const mode_t mask = ::umask(0);
      ::umask(mask);
      ::fchmod(s_->fd, exists ? (st.st_mode & 07777) : (0666 & ~mask));
    } else if (exists && (errno == EACCES || errno == EROFS || errno == EPERM)) {
      // a file that may be written in a directory that may not: written in place (not atomic)
      s_->fd = ::open(path.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
      if (s_->fd < 0) s_->fail("write", errno);
    } else {
      s_->fail("write", errno);
    }
  }
  s_->buf = std::make_unique<FdBuf>(s_->fd);
  s_->os = std::make_unique<std::ostream>(s_->buf.get());
}

Output::Output(Output&&) noexcept = default;
Output& Output::operator=(Output&& o) noexcept {
  if (this != &o) {
    if (s_ && !s_->committed) s_->discard();  // the output replaced is abandoned, not left half
    s_ = std::move(o.s_);
  }
  return *this;
}

Output::~Output() {
  if (s_ && !s_->committed) s_->discard();
}

std::ostream& Output::stream() { return s_->to_stdout ? std::cout : *s_->os; }
const std::string& Output::path() const { return s_->path; }
bool Output::is_stdout() const { return s_->to_stdout; }

void Output::commit() {
  if (s_->committed) return;
  if (s_->to_stdout) {
    s_->committed = true;
    const std::string e = finish_stdout();
    if (!e.empty()) throw write_error("cannot write " + s_->what + " to " + e);
    return;
  }
  s_->os->flush();
  if (s_->buf->error()) s_->fail("write", s_->buf->error());
  if (!*s_->os) s_->fail("write", EIO);
  if (::close(s_->fd) != 0) {
    const int e = errno;
    s_->fd = -1;
    s_->fail("write", e);
  }
  s_->fd = -1;
  if (!s_->tmp.empty() && ::rename(s_->tmp.c_str(), s_->target.c_str()) != 0) s_->fail("rename into", errno);
  s_->tmp.clear();
  s_->committed = true;
}

void check_replaceable(const std::string& path, const std::string& what) {
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
    throw write_error("cannot write " + what + " " + path + ": it is not a regular file");
  std::string t = path + ".tmp-XXXXXX";
  const int fd = ::mkstemp(t.data());
  if (fd < 0) throw write_error("cannot write " + what + " " + path + ": " + reason(errno));
  ::close(fd);
  ::unlink(t.c_str());
}

void Outputs::finish() const {
  if (errors_.empty()) return;
  std::string all;
  for (const std::string& e : errors_) all += (all.empty() ? "" : "\n  and ") + e;
  throw write_error(all);
}

}  // namespace cdref::cli::io
