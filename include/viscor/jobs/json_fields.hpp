// JSON as viscor reads and writes it: one ordered object type, numbers as exact
// decimal strings at the working precision, the law and the scalar type described
// alike everywhere, and input text checked (UTF-8, nesting depth) before it is parsed.
// The command-line tool's --json, the Python module and the tables' sidecars all
// take their fields from here and from the jobs that use these helpers.
#pragma once

#include <viscor/core/field_names.hpp>
#include <viscor/core/contact_law.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/core/precision.hpp>
#include <viscor/core/real_io.hpp>
#include <viscor/core/real_types.hpp>
#include <viscor/core/warnings.hpp>
#include <viscor/jobs/files.hpp>
#include <viscor/jobs/precision_used.hpp>

#include <nlohmann/json.hpp>

#include <cstddef>
#include <optional>
#include <iostream>
#include <string>

namespace viscor::jobs {

using json = nlohmann::ordered_json;

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

/// An old spelling that still works (until 1.0): a warning naming the new one (core/warnings.hpp).
inline void deprecation_warning(const std::string& old_spelling, const std::string& new_spelling) {
  warn(old_spelling + " is deprecated; use " + new_spelling);
}

/// Reads and parses a JSON file (parse_json_text).
inline json read_json_file(const std::string& path) { return parse_json_text(read_file(path), path); }

/// A Real as a JSON string at full working precision.
template <class Real>
std::string number(const Real& x) {
  return to_decimal_string(x);
}

/// An optional quantity (a contact time) as number() writes it, "nan" when unknown:
/// the spelling docs/json-schema.md documents for an unknown contact time.
template <class Real>
std::string number(const std::optional<Real>& x) {
  return x ? number(*x) : std::string("nan");
}

/// Law description for JSON.
inline json law_json(const contact_law& law) {
  json j;
  j["name"] = law.name;
  j["alpha"] = law.alpha.to_string();
  j["beta"] = law.beta.to_string();
  return j;
}

/// The precision a computation ran at, as JSON: digits, binary_digits, arithmetic and,
/// when it left the type its requested digits chose, escalated_from.
inline json precision_json(const precision_used& p) {
  json j;
  j["digits"] = p.digits;
  j["binary_digits"] = p.binary_digits;
  j["arithmetic"] = to_string(p.arithmetic);
  if (p.escalated_from) j["escalated_from"] = to_string(*p.escalated_from);
  return j;
}

/// The precision and the arithmetic of the scalar type in use (precision_json); given
/// the digits that were asked for, also the arithmetic they chose when the
/// computation left it (with_working_precision reruns a double-double solve in
/// float128 or MPFR when a value leaves double's exponent range).
template <class Real>
json scalar_json(std::optional<int> requested_digits = std::nullopt) {
  return precision_json(precision_used::of<Real>(requested_digits));
}

}  // namespace viscor::jobs
