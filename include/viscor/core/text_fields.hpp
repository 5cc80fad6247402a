// The one reader of separated fields: a CSV line of a table, an error map or a values
// file, and a comma-separated list given as one option value. Every reader sees every
// field, empty ones included, so that it can refuse them by position; before, six hand
// splitters disagreed on "a,b," (two fields or three) and on an empty text.
#pragma once

#include <viscor/core/exceptions.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace viscor {

/// The fields of `text` between separators: n separators give n + 1 fields, empty ones
/// included ("a,,b," -> "a", "", "b", ""; "" -> one empty field). Nothing is trimmed.
inline std::vector<std::string> split_fields(std::string_view text, char separator = ',') {
  std::vector<std::string> fields;
  for (std::size_t start = 0;;) {
    const std::size_t end = text.find(separator, start);
    fields.emplace_back(text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
    if (end == std::string_view::npos) return fields;
    start = end + 1;
  }
}

/// split_fields with spaces, tabs and carriage returns trimmed from both ends of each field.
inline std::vector<std::string> split_trimmed_fields(std::string_view text, char separator = ',') {
  std::vector<std::string> fields = split_fields(text, separator);
  for (std::string& f : fields) {
    const std::size_t first = f.find_first_not_of(" \t\r");
    f = first == std::string::npos ? std::string() : f.substr(first, f.find_last_not_of(" \t\r") - first + 1);
  }
  return fields;
}

/// The comma-separated items of a list value named `name` (as the front end spells it);
/// an empty item ("0.1,,1", a leading or trailing comma, an empty value) is refused,
/// naming `name` and the value.
inline std::vector<std::string> split_list(std::string_view text, const std::string& name) {
  std::vector<std::string> items = split_fields(text);
  for (const std::string& item : items)
    if (item.empty())
      throw invalid_parameter(name + " has an empty entry in '" + std::string(text) +
                              "' (an item between every two commas)");
  return items;
}

}  // namespace viscor
