// Options and output shared by the subcommands: the contact law, the working
// precision, and the two output forms (readable text, or one JSON object whose
// field names match the API, numbers as full-precision decimal strings).
#pragma once

// First, before anything can use them: the solvers, certification and closed forms
// are compiled once in libviscor (src/instantiation.cpp.in). Without these extern
// declarations every subcommand compiled its own copy of the whole solver stack
// for every scalar type (about half of each object file, and of the build time).
#include <viscor/certify/extern_templates.hpp>

#include <viscor/core/contact_law.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/core/precision.hpp>
#include <viscor/core/real_io.hpp>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

namespace viscor::cli {

using json = nlohmann::ordered_json;

inline bool ends_with(const std::string& text, const std::string& tail) {
  return text.size() >= tail.size() && text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
}

/// An old spelling that still works (until 1.0): one line on stderr naming the new one.
inline void deprecation_warning(const std::string& old_spelling, const std::string& new_spelling) {
  std::cerr << "viscor: warning: " << old_spelling << " is deprecated; use " << new_spelling << "\n";
}

/// --model NAME | --alpha A --beta B (exponents accept fractions: --alpha 3/2).
struct law_options {
  std::string model, alpha, beta;

  void add_to(CLI::App& app) {
    app.add_option("--model", model, "named contact law: linear, hertz_linear_damping, tsuji, kuwabara_kono, hunt_crossley");
    app.add_option("--alpha", alpha, "stiffness exponent alpha >= 1 (decimal or fraction p/q)");
    app.add_option("--beta", beta, "damping exponent beta >= 1 (decimal or fraction p/q)");
  }

  contact_law resolve() const {
    if (!model.empty()) {
      if (!alpha.empty() || !beta.empty())
        throw invalid_parameter("give either --model or --alpha/--beta, not both (got --model " + model + ")");
      return law_by_name(model);
    }
    if (alpha.empty() || beta.empty())
      throw invalid_parameter("the contact law needs --model NAME, or both --alpha and --beta");
    return make_law(exponent::parse(alpha, "alpha"), exponent::parse(beta, "beta"));
  }
};

/// --json and --output FILE. Output goes to the file only once the command has
/// succeeded (written to a temporary and renamed), so a failed run leaves none.
struct output_options {
  bool json = false;
  std::string path;

  void add_to(CLI::App& app) {
    app.add_flag("--json", json, "print one JSON object instead of the readable summary");
    app.add_option("-o,--output", path, "write the output to FILE instead of standard output")
        ->check(regular_output_file());
  }

  /// JSON when asked with --json or when the output file ends in .json.
  bool as_json() const { return json || ends_with(path, ".json"); }

  void emit(const std::string& text, const cli::json& object) const {
    const std::string body = as_json() ? object.dump(2) + "\n" : text;
    if (path.empty()) {
      std::cout << body << std::flush;
      return;
    }
    write_atomically(path, body);
    say_written(path, body);
  }

  /// One line on stderr naming the file written: -o leaves standard output empty,
  /// and a user should not have to guess whether (and where) anything was written.
  static void say_written(const std::string& path, const std::string& body) {
    std::cerr << "viscor: wrote " << path << " (" << body.size() << " bytes)\n";
  }

  /// Writes `body` to `path`: into a new temporary file beside it (every write,
  /// the fsync and the close checked), then renamed over `path`. Only regular files
  /// are written: an existing `path` that is not a regular file (a device, a FIFO, a
  /// directory, a symbolic link) is refused and left alone. Any failure removes the
  /// temporary and throws, so nothing is left behind.
  static void write_atomically(const std::string& path, const std::string& body) {
    refuse_unless_regular_or_absent(path);
    const std::string temporary = path + ".tmp." + std::to_string(::getpid());
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) throw error("cannot write output file '" + path + "': " + std::strerror(errno));
    const bool written = write_all(fd, body) && ::fsync(fd) == 0;
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

  /// A CLI11 check of an output option: refuses, before any work, a path that
  /// exists and is not a regular file (write_atomically checks again when writing).
  static CLI::Validator regular_output_file() {
    return CLI::Validator(
        [](std::string& value) {
          try {
            refuse_unless_regular_or_absent(value);
          } catch (const error& e) {
            return std::string(e.what());
          }
          return std::string();
        },
        "FILE", "REGULAR_OUTPUT_FILE");
  }

  /// Throws invalid_parameter naming `path` when it exists and is not a regular file
  /// (checked without following a symbolic link).
  static void refuse_unless_regular_or_absent(const std::string& path) {
    struct stat st {};
    if (::lstat(path.c_str(), &st) != 0) return;  // absent (or unreachable: the open says why)
    if (S_ISREG(st.st_mode)) return;
    const char* kind = S_ISLNK(st.st_mode) ? "a symbolic link" : S_ISDIR(st.st_mode) ? "a directory"
                       : S_ISFIFO(st.st_mode) ? "a FIFO" : S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode) ? "a device"
                                                                                                    : "not a regular file";
    throw invalid_parameter("output file '" + path + "' exists and is " + kind +
                            "; viscor writes only regular files (name a new or regular file)");
  }

 private:
  static bool write_all(int fd, const std::string& body) {
    std::size_t done = 0;
    while (done < body.size()) {
      const ssize_t n = ::write(fd, body.data() + done, body.size() - done);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) return false;
      done += static_cast<std::size_t>(n);
    }
    return true;
  }
};

/// The offset of the first byte of `text` that is not part of valid UTF-8
/// (std::string::npos if there is none): input files are UTF-8 text.
inline std::size_t first_invalid_utf8(const std::string& text) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  for (std::size_t i = 0; i < text.size();) {
    const unsigned char c = byte(i);
    std::size_t length = 0;
    unsigned char low = 0x80, high = 0xBF;  // allowed range of the second byte
    if (c < 0x80) length = 1;
    else if (c >= 0xC2 && c <= 0xDF) length = 2;
    else if (c >= 0xE0 && c <= 0xEF) length = 3, low = c == 0xE0 ? 0xA0 : 0x80, high = c == 0xED ? 0x9F : 0xBF;
    else if (c >= 0xF0 && c <= 0xF4) length = 4, low = c == 0xF0 ? 0x90 : 0x80, high = c == 0xF4 ? 0x8F : 0xBF;
    else return i;
    if (i + length > text.size()) return i;
    for (std::size_t k = 1; k < length; ++k) {
      const unsigned char b = byte(i + k);
      if (b < (k == 1 ? low : 0x80) || b > (k == 1 ? high : 0xBF)) return i;
    }
    i += length;
  }
  return std::string::npos;
}

/// The deepest nesting of JSON objects and arrays viscor reads (its own files nest
/// 4 levels at most): deeper input is refused before it costs time or stack.
inline constexpr std::size_t max_json_depth = 64;

/// Parses JSON text read from `where` (a file name, for errors); refuses nesting
/// deeper than max_json_depth. Throws parse_error naming `where`.
inline json parse_json_text(const std::string& text, const std::string& where) {
  try {
    return json::parse(text, [&where](int depth, json::parse_event_t, json&) {
      if (static_cast<std::size_t>(depth) > max_json_depth)
        throw parse_error(where + ": JSON nested deeper than " + std::to_string(max_json_depth) + " levels");
      return true;
    });
  } catch (const json::exception& e) {
    throw parse_error(where + ": invalid JSON: " + e.what());
  }
}

/// A Real as a JSON string at full working precision.
template <class Real>
std::string number(const Real& x) {
  return to_decimal_string(x);
}

/// Law description for JSON.
inline json law_json(const contact_law& law) {
  json j;
  j["name"] = law.name;
  j["alpha"] = law.alpha.to_string();
  j["beta"] = law.beta.to_string();
  return j;
}

/// The name and precision of the scalar type in use.
template <class Real>
json scalar_json() {
  json j;
  j["digits"] = decimal_digits<Real>();
  j["binary_digits"] = binary_digits<Real>();
  return j;
}

}  // namespace viscor::cli
