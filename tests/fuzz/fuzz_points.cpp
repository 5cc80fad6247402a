// Fuzz target: `viscor cor --points FILE` lines, CSV with a header or JSON lines
// (include/viscor/jobs/point_batch.hpp). Reads the input as solve_points does (UTF-8 check,
// comments, CSV header with known and distinct columns, fields per row, JSON
// objects through the spec reader), then checks each point's fields as
// solve_point does before it solves (law or exponents, digits, gamma and g in
// double). The solve itself is not run (seconds per point; tests/cli_points_test.cpp).
// Checks beyond "no crash": a CSV row's fields are the text between its commas,
// trimmed, and a JSON point keeps the exact text of its numbers (read back, the
// same decimal).
#include "fuzz_support.hpp"

#include <viscor/jobs/point_batch.hpp>

#include <viscor/core/detail/exact_decimal.hpp>

#include <algorithm>

namespace {

using viscor::fuzz::fuzz_require;

void check_point(const viscor::jobs::point_text& p) {
  if (!p.law.empty()) {
    (void)viscor::law_by_name(p.law);
  } else {
    viscor::make_law(viscor::exponent::parse(p.alpha, "alpha"), viscor::exponent::parse(p.beta, "beta"));
  }
  if (!p.digits.empty()) {
    if (p.digits.find_first_not_of("0123456789") != std::string::npos || p.digits.size() > 6 ||
        std::stoi(p.digits) < 1)
      throw viscor::invalid_parameter("digits");
  }
  const double gamma = viscor::parse_real<double>(p.gamma, "gamma");
  const double g = viscor::parse_real<double>(p.g, "g");
  // Both are exact decimals too (the tables read them so), with the same sign.
  using viscor::detail::exact_decimal;
  if (p.gamma.size() < 200 && p.g.size() < 200) {
    fuzz_require((exact_decimal::parse(p.gamma, "gamma").sign() > 0) == (gamma > 0), "gamma's sign differs: " + p.gamma);
    fuzz_require((exact_decimal::parse(p.g, "g").sign() > 0) == (g > 0), "g's sign differs: " + p.g);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace cli = viscor::jobs;
  if (size > 65536) return 0;
  const auto lines = viscor::fuzz::lines_of(viscor::fuzz::text_of(data, size));
  std::vector<std::string> header;
  bool decided = false, csv = false;
  for (std::size_t n = 0; n < lines.size(); ++n) {
    const std::string& line = lines[n];
    if (cli::first_invalid_utf8(line) != std::string::npos) return 0;  // refused as a whole (exit 2)
    if (line.find_first_not_of(" \t\r") == std::string::npos || line[line.find_first_not_of(" \t")] == '#') continue;
    if (!decided) {
      decided = true;
      csv = line[line.find_first_not_of(" \t")] != '{';
      if (csv) {
        header = viscor::split_trimmed_fields(line);
        cli::point_text probe;
        for (std::size_t c = 0; c < header.size(); ++c)
          if (!cli::detail::point_field(probe, header[c]) ||
              std::find(header.begin(), header.begin() + static_cast<long>(c), header[c]) != header.begin() + static_cast<long>(c))
            return 0;  // refused as a whole (exit 2)
        continue;
      }
    }
    viscor::fuzz::refusal_or_result([&] {
      cli::point_text p;
      if (csv) {
        const auto fields = viscor::split_trimmed_fields(line);
        fuzz_require(fields.size() == static_cast<std::size_t>(std::count(line.begin(), line.end(), ',')) + 1 ||
                         line.empty(),
                     "a CSV row splits into a number of fields other than its commas + 1: '" + line + "'");
        for (const auto& f : fields)
          fuzz_require(f.find(',') == std::string::npos && (f.empty() || (f.front() != ' ' && f.back() != ' ')),
                       "a CSV field is not trimmed text between commas: '" + f + "'");
        if (fields.size() != header.size()) return;  // that point is refused
        for (std::size_t c = 0; c < header.size(); ++c)
          if (!fields[c].empty()) *cli::detail::point_field(p, header[c]) = fields[c];
      } else {
        p = cli::detail::parse_json_point(line, "points:" + std::to_string(n + 1), n + 1);
      }
      check_point(p);
    });
  }
  return 0;
}
