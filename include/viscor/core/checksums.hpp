// Checksums of data files: a directory may hold a manifest SHA256SUMS (the format
// of `sha256sum`: 64 hex digits, two spaces, the file name) listing the files in it
// that viscor committed. A reader checks a listed file against its line before it
// trusts a single value in it, because a changed digit in a surrogate coefficient or
// a table's e leaves the file well formed and nothing else would tell. Files not
// listed (a user's own tables and surrogates) are read as before. viscor's writers
// keep the line of a file they write into such a directory up to date.
#pragma once

#include <viscor/core/exceptions.hpp>
#include <viscor/core/sha256.hpp>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <fcntl.h>
#include <unistd.h>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace viscor {

namespace detail {

/// Writes all of `body` to `fd`, retrying short writes; false on an error.
inline bool write_all(int fd, std::string_view body) {
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

/// The manifest's file name in a data directory.
inline constexpr const char* checksum_manifest_name = "SHA256SUMS";

/// One line of a manifest.
struct checksum_entry {
  std::string sha256;  ///< 64 lowercase hex digits
  std::string name;    ///< the file's name in the manifest's directory
};

/// The entries of a manifest's text (`manifest` names it in messages). Reads what
/// sha256sum writes, on any platform: CRLF line ends, the binary-mode mark ("<sha256> *<name>") and names
/// given as "./name" (the same file). Throws parse_error naming the manifest and the
/// line when a line is not "<64 hex digits>  <name>", when a name is not a file of the
/// manifest's own directory (a path, empty, or holding a control character such as a
/// stray CR), and when a name is listed twice: a
/// line that cannot be read is refused, never ignored.
inline std::vector<checksum_entry> parse_checksum_manifest(const std::string& text, const std::string& manifest) {
  std::vector<checksum_entry> entries;
  std::istringstream in(text);
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    const std::string where = manifest + ":" + std::to_string(number) + ": ";
    const bool hex = line.size() > 66 && line.find_first_not_of("0123456789abcdef") == 64 &&
                     (line.compare(64, 2, "  ") == 0 || line.compare(64, 2, " *") == 0);
    if (!hex) throw parse_error(where + "not a checksum line ('<sha256>  <name>')");
    std::string name = line.substr(66);
    if (name.rfind("./", 0) == 0) name.erase(0, 2);
    const bool control = std::any_of(name.begin(), name.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; });
    if (name.empty() || name.find('/') != std::string::npos || name == "." || name == ".." || control)
      throw parse_error(where + "'" + name.substr(0, 80) + "' is not the name of a file in the manifest's directory");
    for (const checksum_entry& e : entries)
      if (e.name == name) throw parse_error(where + "'" + name + "' is listed twice");
    entries.push_back({line.substr(0, 64), name});
  }
  return entries;
}

/// The manifest beside `file` (empty when there is none), read and parsed
/// (parse_checksum_manifest, whose rules it follows).
inline std::vector<checksum_entry> read_checksum_manifest(const std::filesystem::path& file) {
  const std::filesystem::path manifest = file.parent_path() / checksum_manifest_name;
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(manifest, ec);
  if (status.type() == std::filesystem::file_type::not_found) return {};
  if (ec) throw parse_error("cannot read the checksum manifest '" + manifest.string() + "': " + ec.message());
  if (status.type() != std::filesystem::file_type::regular)  // a FIFO would hang the read
    throw parse_error("the checksum manifest '" + manifest.string() + "' is not a regular file");
  std::ifstream in(manifest, std::ios::binary);
  if (!in) throw parse_error("cannot read the checksum manifest '" + manifest.string() + "'");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw parse_error("reading the checksum manifest '" + manifest.string() + "' failed");
  return parse_checksum_manifest(text.str(), manifest.string());
}

/// Whether the manifest beside `file` lists it: a file of committed data.
inline bool listed_in_checksum_manifest(const std::filesystem::path& file) {
  const std::string name = file.filename().string();
  for (const checksum_entry& e : read_checksum_manifest(file))
    if (e.name == name) return true;
  return false;
}

/// Throws parse_error when `content`, read from `path`, is listed in the manifest
/// beside it with another SHA-256: the file was changed or damaged after viscor wrote it.
inline void verify_checksum(const std::string& path, std::string_view content) {
  const std::filesystem::path file(path);
  const std::string name = file.filename().string();
  for (const checksum_entry& e : read_checksum_manifest(file)) {
    if (e.name != name) continue;
    if (sha256_hex(content) == e.sha256) return;
    throw parse_error(path + ": content does not match its SHA-256 in " +
                      (file.parent_path() / checksum_manifest_name).string() +
                      ": the file was changed or damaged after viscor wrote it; regenerate it (reference_data/README.md), "
                      "or restore it from the repository");
  }
}

/// The whole file, checked against the manifest beside it (verify_checksum);
/// throws `Error` naming the file when it cannot be read.
template <class Error = parse_error>
std::string read_checked_file(const std::string& path, const std::string& what) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("cannot open " + what + " '" + path + "'");
  std::ostringstream s;
  s << in.rdbuf();
  if (in.bad()) throw Error("reading " + what + " '" + path + "' failed");
  const std::string content = s.str();
  verify_checksum(path, content);
  return content;
}

/// After viscor wrote `content` to `path`: if a manifest beside it lists the file, its
/// line is set to the new SHA-256 (the manifest is rewritten through a temporary file
/// and a rename). A directory without a manifest is left alone; a file not listed is
/// not added (the manifest lists what was committed). Throws viscor::error when the
/// manifest cannot be rewritten.
inline void update_checksum(const std::string& path, std::string_view content) {
  const std::filesystem::path file(path);
  std::vector<checksum_entry> entries = read_checksum_manifest(file);
  const std::string name = file.filename().string(), digest = sha256_hex(content);
  bool changed = false;
  for (checksum_entry& e : entries)
    if (e.name == name && e.sha256 != digest) e.sha256 = digest, changed = true;
  if (!changed) return;
  const std::filesystem::path manifest = file.parent_path() / checksum_manifest_name;
  std::string body;
  for (const checksum_entry& e : entries) body += e.sha256 + "  " + e.name + "\n";
  // A new file of our own (O_EXCL: never a file or a symbolic link planted at the name),
  // every write checked to the close, then renamed over the manifest.
  const std::string temporary = manifest.string() + ".tmp." + std::to_string(::getpid());
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
  if (fd < 0)
    throw error("cannot rewrite the checksum manifest '" + manifest.string() + "': cannot create '" + temporary +
                "': " + std::strerror(errno));
  const bool written = detail::write_all(fd, body) && ::fsync(fd) == 0;
  if (::close(fd) != 0 || !written) {
    ::unlink(temporary.c_str());
    throw error("cannot rewrite the checksum manifest '" + manifest.string() + "'");
  }
  if (std::rename(temporary.c_str(), manifest.c_str()) != 0) {
    const int e = errno;
    ::unlink(temporary.c_str());
    throw error("cannot replace '" + manifest.string() + "': " + std::strerror(e));
  }
}

}  // namespace viscor
