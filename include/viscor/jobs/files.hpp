// Files as the jobs read and write them: a whole file read at once, and output
// written safely (only regular files, every write checked up to the close, the file
// replaced in one rename so that a failure leaves nothing behind, and its line in a
// checksum manifest beside it kept true: core/checksums.hpp).
#pragma once

#include <viscor/core/checksums.hpp>
#include <viscor/core/exceptions.hpp>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/file.h>
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
  update_checksum(path, body);  // a committed file viscor regenerates keeps a true manifest line
}

/// An exclusive lock on an output: the file `output + ".lock"`, held with flock(2)
/// while the job runs, so that a second viscor writing the same output stops at once
/// with a message instead of both appending to one partial file. The lock file is
/// removed when the holder finishes (a lock left by a killed run is free again: the
/// kernel drops flock locks with the process).
class output_lock {
 public:
  /// Takes the lock; throws viscor::error naming the output when another process holds it.
  explicit output_lock(const std::string& output) : m_path(output + ".lock") {
    refuse_unless_regular_or_absent(m_path);
    for (int attempt = 0; attempt < 100; ++attempt) {
      m_fd = ::open(m_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0666);
      if (m_fd < 0) throw error("cannot create the lock file '" + m_path + "': " + std::strerror(errno));
      if (::flock(m_fd, LOCK_EX | LOCK_NB) != 0) {
        const int e = errno;
        ::close(m_fd);
        if (e == EWOULDBLOCK)
          throw error("another viscor is writing '" + output + "' (it holds '" + m_path + "'): wait for it to "
                      "finish, or choose another output file");
        throw error("cannot lock '" + m_path + "': " + std::strerror(e));
      }
      // The holder before us may have removed the file between our open and flock: lock
      // only the file that is still at the path.
      struct stat held {}, at_path {};
      if (::fstat(m_fd, &held) == 0 && ::stat(m_path.c_str(), &at_path) == 0 && held.st_ino == at_path.st_ino &&
          held.st_dev == at_path.st_dev)
        return;
      ::close(m_fd);
    }
    throw error("cannot lock '" + m_path + "': it keeps being replaced");
  }
  output_lock(const output_lock&) = delete;
  output_lock& operator=(const output_lock&) = delete;
  ~output_lock() {
    ::unlink(m_path.c_str());  // before the unlock, so that a waiter re-checks the path
    ::close(m_fd);
  }

 private:
  std::string m_path;
  int m_fd = -1;
};

}  // namespace viscor::jobs
