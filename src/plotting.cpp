// src/plotting.cpp - gnuplot without a shell and without user text (plotting.hpp).
#include "plotting.hpp"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace cdref::cli {

std::string gp_string(const std::string& text) {
  std::string s = "'";
  for (char c : text) {
    if (c == '\'') s += "''";
    else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) s += ' ';
    else s += c;
  }
  return s + "'";
}

namespace {

// Reads a file descriptor to its end.
std::string read_all(int fd) {
  std::string out;
  char buf[1 << 16];
  for (;;) {
    const ssize_t r = ::read(fd, buf, sizeof buf);
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) break;
    out.append(buf, std::size_t(r));
  }
  return out;
}

struct Fd {
  int fd = -1;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

std::string gnuplot_svg(const std::string& script) {
  // the script: a temporary file of cdref's own naming, removed on the way out
  std::string path = (std::filesystem::temp_directory_path() / "cdref-plot-XXXXXX").string();
  Fd sf;
  sf.fd = ::mkstemp(path.data());
  if (sf.fd < 0) throw std::runtime_error(std::string("cannot write a gnuplot script: ") + std::strerror(errno));
  struct Remove {
    std::string p;
    ~Remove() { ::unlink(p.c_str()); }
  } remove{path};
  for (std::size_t done = 0; done < script.size();) {
    const ssize_t w = ::write(sf.fd, script.data() + done, script.size() - done);
    if (w < 0 && errno == EINTR) continue;
    if (w < 0) throw std::runtime_error(std::string("cannot write a gnuplot script: ") + std::strerror(errno));
    done += std::size_t(w);
  }
  // its messages go to a second temporary file (read after it ends: a pipe for them could fill
  // while cdref waits on the picture), the picture to a pipe
  std::string epath = (std::filesystem::temp_directory_path() / "cdref-plot-err-XXXXXX").string();
  Fd ef;
  ef.fd = ::mkstemp(epath.data());
  if (ef.fd < 0) throw std::runtime_error(std::string("cannot run gnuplot: ") + std::strerror(errno));
  Remove remove_err{epath};
  int out[2];
  if (::pipe2(out, O_CLOEXEC) != 0) throw std::runtime_error("cannot run gnuplot: no pipe");
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(out[0]), ::close(out[1]);
    throw std::runtime_error("cannot run gnuplot: fork failed");
  }
  if (pid == 0) {
    ::dup2(out[1], 1);
    ::dup2(ef.fd, 2);
    const int devnull = ::open("/dev/null", O_RDONLY);
    if (devnull >= 0) ::dup2(devnull, 0);
    char* argv[] = {const_cast<char*>("gnuplot"), path.data(), nullptr};
    ::execvp("gnuplot", argv);
    _exit(127);
  }
  ::close(out[1]);
  Fd o{out[0]};
  const std::string svg = read_all(o.fd);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  ::lseek(ef.fd, 0, SEEK_SET);
  const std::string messages = read_all(ef.fd);
  if (WIFEXITED(status) && WEXITSTATUS(status) == 127)
    throw std::runtime_error("cannot run gnuplot (apt-get install gnuplot-nox)");
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || svg.find("</svg>") == std::string::npos)
    throw std::runtime_error("gnuplot failed: " + messages.substr(0, 2000));
  return svg;
}

}  // namespace cdref::cli
