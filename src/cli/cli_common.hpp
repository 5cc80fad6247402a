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
#include <viscor/jobs/json_fields.hpp>
#include <viscor/jobs/files.hpp>

#include "option_spelling.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <iostream>
#include <string>

namespace viscor::cli {

// The subcommands are front ends of the jobs (include/viscor/jobs/): they use its
// names unqualified.
using namespace viscor::jobs;
using json = jobs::json;

inline bool ends_with(const std::string& text, const std::string& tail) {
  return text.size() >= tail.size() && text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
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

  /// The library's safe write (jobs/files.hpp).
  static void write_atomically(const std::string& path, const std::string& body) {
    jobs::write_atomically(path, body);
  }

  /// A CLI11 check of an output option: refuses, before any work, a path that
  /// exists and is not a regular file, and committed data unless --update-committed
  /// (write_atomically checks both again when writing).
  static CLI::Validator regular_output_file() {
    return CLI::Validator(
        [](std::string& value) {
          try {
            refuse_unless_regular_or_absent(value);
            jobs::refuse_committed_unless_allowed(value);  // viscor --update-committed comes before the subcommand
          } catch (const error& e) {
            return spelled(e);
          }
          return std::string();
        },
        "FILE", "REGULAR_OUTPUT_FILE");
  }

  static void refuse_unless_regular_or_absent(const std::string& path) {
    jobs::refuse_unless_regular_or_absent(path);
  }
};

}  // namespace viscor::cli
