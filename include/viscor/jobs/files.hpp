// Files as the jobs read and write them: a whole file read at once, and output
// written safely (only regular files, every write checked up to the close, the file
// replaced in one rename so that a failure leaves nothing behind; committed data, a
// file a checksum manifest lists, replaced only when asked and then its line kept
// true: core/checksums.hpp), files viscor may replace later sealed with their SHA-256,
// and one writer per output (output_lock).
#pragma once

#include <viscor/core/checksums.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/core/sha256.hpp>

#include <atomic>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fcntl.h>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

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

/// The last line of a file that viscor may replace later (a deck, a variable block, a C
/// export): the SHA-256 of everything before it. A name or a first line is no proof that
/// viscor wrote a file; a seal that matches is, and an edit breaks it. The line is a
/// comment of the file's language: `# ...` in decks, `/* ... */` in C.
struct seal_style {
  const char* prefix;
  const char* suffix;
};
inline constexpr seal_style hash_comment_seal{"# viscor sha256 ", ""};
inline constexpr seal_style c_comment_seal{"/* viscor sha256 ", " */"};
inline constexpr const char* seal_prefix = hash_comment_seal.prefix;

/// `body` with its seal as the last line (after a line end of its own, if `body` lacks one).
inline std::string sealed(std::string body, const seal_style& style = hash_comment_seal) {
  if (!body.empty() && body.back() != '\n') body += '\n';
  return body + style.prefix + sha256_hex(body) + style.suffix + "\n";
}

/// The largest file viscor takes for one it wrote (its decks and blocks are a few kB).
inline constexpr std::uintmax_t max_sealed_file_size = 1 << 20;

/// Whether `path` is a regular file (not followed through a symbolic link) that viscor
/// wrote and nobody changed since: it starts with `marker` and ends with the seal of
/// everything before the seal. Reads nothing from anything but a regular file of at
/// most `max_size` bytes.
inline bool is_unedited_viscor_file(const std::string& path, const std::string& marker,
                                    const seal_style& style = hash_comment_seal,
                                    std::uintmax_t max_size = max_sealed_file_size) {
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode) || static_cast<std::uintmax_t>(st.st_size) > max_size)
    return false;
  std::string text;
  try {
    text = read_file(path);
  } catch (const error&) {
    return false;
  }
  const std::size_t seal = text.rfind(style.prefix);
  if (text.rfind(marker, 0) != 0 || seal == std::string::npos || text.back() != '\n') return false;
  const std::string body = text.substr(0, seal);
  return text.compare(seal, std::string::npos, std::string(style.prefix) + sha256_hex(body) + style.suffix + "\n") == 0;
}

/// Refuses, before any work, an output (`option` names it in the message) that viscor
/// may write only over its own unedited file: absent, or is_unedited_viscor_file.
inline void refuse_unless_own_or_absent(const std::string& path, const std::string& marker, const std::string& option,
                                        const std::string& what, const seal_style& style = hash_comment_seal,
                                        std::uintmax_t max_size = max_sealed_file_size) {
  refuse_unless_regular_or_absent(path);
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0) return;
  if (!is_unedited_viscor_file(path, marker, style, max_size))
    throw invalid_parameter(option + " " + path + ": the file exists and is not " + what +
                            " viscor wrote (or it was edited since: its last line, the seal, no longer matches); "
                            "refusing to replace it (remove it or choose another name)");
}

/// Whether viscor may replace a file that the checksum manifest beside it lists (committed
/// data): not unless a front end says so for this process (the CLI's --update-committed).
inline std::atomic<bool>& replacing_committed_data_allowed() {
  static std::atomic<bool> allowed{false};
  return allowed;
}

/// Refuses to write over `path` when the manifest beside it lists it, unless replacing
/// committed data was asked for: an ordinary -o never rewrites certified tables or their
/// checksums.
inline void refuse_committed_unless_allowed(const std::string& path) {
  if (replacing_committed_data_allowed() || !listed_in_checksum_manifest(path)) return;
  throw invalid_parameter("output file '" + path + "' is committed data listed in " +
                          (std::filesystem::path(path).parent_path() / checksum_manifest_name).string() +
                          "; viscor replaces it only when asked to (viscor --update-committed ..., which also updates "
                          "its checksum line): write elsewhere");
}

/// One output of a command: where, and all of its content.
struct output_file {
  std::string path;
  std::string body;
};

namespace detail {

// A temporary file beside an output, created exclusively (never a file or a symbolic
// link planted at its name), written and closed with every step checked; removed when
// destroyed unless it was published (renamed over its output).
class staged_output {
 public:
  explicit staged_output(const output_file& file) : m_path(file.path), m_body(file.body) {
    m_temporary = file.path + ".tmp." + std::to_string(::getpid());
    const int fd = ::open(m_temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd < 0) throw error("cannot write output file '" + m_path + "': cannot create '" + m_temporary + "': " +
                            std::strerror(errno));
    const bool written = viscor::detail::write_all(fd, m_body) && ::fsync(fd) == 0;
    const int saved = errno;
    if (::close(fd) != 0 || !written) {
      const int e = written ? errno : saved;
      ::unlink(m_temporary.c_str());  // a constructor that throws has no destructor to do it
      throw error("writing output file '" + m_path + "' failed: " + std::strerror(e));
    }
    m_created = true;
  }
  staged_output(const staged_output&) = delete;
  staged_output& operator=(const staged_output&) = delete;
  ~staged_output() {
    if (m_created) ::unlink(m_temporary.c_str());
  }

  /// Renames the temporary over the output (checked again: the output may have become
  /// something else meanwhile), then keeps a manifest line that lists it true.
  void publish() {
    refuse_unless_regular_or_absent(m_path);
    if (::rename(m_temporary.c_str(), m_path.c_str()) != 0)
      throw error("cannot move output into '" + m_path + "': " + std::strerror(errno));
    m_created = false;
    update_checksum(m_path, m_body);  // a committed file viscor regenerates keeps a true manifest line
  }

 private:
  std::string m_path, m_temporary;
  const std::string& m_body;
  bool m_created = false;
};

}  // namespace detail

/// Writes the outputs of one command together: each is checked first (only regular
/// files are written: an existing output that is a device, a FIFO, a directory or a
/// symbolic link is refused and left alone, and so is a file a checksum manifest lists,
/// refuse_committed_unless_allowed), then each is written into a new temporary file
/// beside it (every write, the fsync and the close checked), and only when all are
/// written are they renamed over their outputs, in order. A failure before the renames
/// removes every temporary and replaces nothing.
inline void write_together(const std::vector<output_file>& files) {
  for (const output_file& f : files) {
    refuse_unless_regular_or_absent(f.path);
    refuse_committed_unless_allowed(f.path);
  }
  std::vector<std::unique_ptr<detail::staged_output>> staged;
  for (const output_file& f : files) staged.push_back(std::make_unique<detail::staged_output>(f));
  for (auto& s : staged) s->publish();
}

/// Writes one output as write_together does: a failure leaves nothing behind.
inline void write_atomically(const std::string& path, const std::string& body) {
  write_together({output_file{path, body}});
}

/// An exclusive lock on an output: the file `output + ".lock"`, held with flock(2)
/// while the job runs, so that a second viscor writing the same output stops at once
/// with a message instead of both appending to one partial file. The lock file is
/// removed when the holder that created it finishes; a lock file that was there before
/// (left by a killed run: free again, the kernel drops flock locks with the process) is
/// locked but left in place.
class output_lock {
 public:
  /// Takes the lock; throws viscor::error naming the output when another process holds it.
  explicit output_lock(const std::string& output) : m_path(output + ".lock") {
    refuse_unless_regular_or_absent(m_path);
    for (int attempt = 0; attempt < 100; ++attempt) {
      // Ours when we create it; an existing lock file (another run's, or left by a killed
      // one) is locked but never removed by us.
      m_fd = ::open(m_path.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0666);
      m_created = m_fd >= 0;
      if (!m_created && errno == EEXIST) {
        m_fd = ::open(m_path.c_str(), O_RDWR | O_CLOEXEC | O_NOFOLLOW);
        if (m_fd < 0 && errno == ENOENT) continue;  // its holder removed it meanwhile: try again
      }
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
    if (m_created) ::unlink(m_path.c_str());  // before the unlock, so that a waiter re-checks the path
    ::close(m_fd);
  }

 private:
  std::string m_path;
  int m_fd = -1;
  bool m_created = false;  ///< whether this lock made the file (only then is it removed)
};

}  // namespace viscor::jobs
