// Files as the jobs read and write them: a whole file read at once, and output
// written safely (only regular files, every write checked up to the close, the file
// replaced in one rename so that a failure leaves nothing behind).
#pragma once

#include <viscor/core/exceptions.hpp>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

namespace viscor::jobs {

/// The whole content of a file; throws viscor::error naming it if it cannot be read.
inline std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw error("cannot read '" + path + "'");
  std::stringstream s;
  s << in.rdbuf();
  if (in.bad()) throw error("reading '" + path + "' failed");
  return s.str();
}

/// Throws invalid_parameter naming `path` when it exists and is not a regular file
/// (checked without following a symbolic link).
inline void refuse_unless_regular_or_absent(const std::string& path) {
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0) return;  // absent (or unreachable: the open says why)
  if (S_ISREG(st.st_mode)) return;
  const char* kind = S_ISLNK(st.st_mode) ? "a symbolic link" : S_ISDIR(st.st_mode) ? "a directory"
                     : S_ISFIFO(st.st_mode) ? "a FIFO" : S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode) ? "a device"
                                                                                                  : "not a regular file";
  throw invalid_parameter("output file '" + path + "' exists and is " + kind +
                          "; viscor writes only regular files (name a new or regular file)");
}

/// Whether the file at `path` begins with `prefix` (false if it cannot be read):
/// how viscor recognises a file it wrote before replacing it.
inline bool file_starts_with(const std::string& path, const std::string& prefix) {
  std::ifstream in(path, std::ios::binary);
  std::string head(prefix.size(), '\0');
  return in.read(head.data(), static_cast<std::streamsize>(head.size())) && head == prefix;
}

namespace detail {

inline bool write_all(int fd, const std::string& body) {
  std::size_t done = 0;
  while (done < body.size()) {
    const ssize_t n = ::write(fd, body.data() + done, body.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace detail

/// Writes `body` to `path`: into a new temporary file beside it (every write,
/// the fsync and the close checked), then renamed over `path`. Only regular files
/// are written: an existing `path` that is not a regular file (a device, a FIFO, a
/// directory, a symbolic link) is refused and left alone. Any failure removes the
/// temporary and throws, so nothing is left behind.
inline void write_atomically(const std::string& path, const std::string& body) {
  refuse_unless_regular_or_absent(path);
  const std::string temporary = path + ".tmp." + std::to_string(::getpid());
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) throw error("cannot write output file '" + path + "': " + std::strerror(errno));
  const bool written = detail::write_all(fd, body) && ::fsync(fd) == 0;
  const int saved = errno;
  if (::close(fd) != 0 || !written) {
    ::unlink(temporary.c_str());
    throw error("writing output file '" + path + "' failed: " + std::strerror(written ? errno : saved));
  }
  try {
    refuse_unless_regular_or_absent(path);  // again: it may have appeared meanwhile
  } catch (...) {
    ::unlink(temporary.c_str());
    throw;
  }
  if (::rename(temporary.c_str(), path.c_str()) != 0) {
    const int e = errno;
    ::unlink(temporary.c_str());
    throw error("cannot move output into '" + path + "': " + std::strerror(e));
  }
}

}  // namespace viscor::jobs
