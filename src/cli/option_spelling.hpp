// The library names inputs by their field names (core/exceptions.hpp, VISCOR_FIELD);
// this tool spells them as its options in every error and warning it prints.
#pragma once

#include <viscor/core/exceptions.hpp>
#include <viscor/core/warnings.hpp>

#include <iostream>
#include <string>

namespace viscor::cli {

/// A field of the library's messages as this tool's option: youngs_modulus ->
/// --youngs-modulus (the code of `viscor dem` is its first word, CODE).
inline std::string option_spelling(const std::string& field) {
  if (field == "code") return "CODE";
  std::string option = "--" + field;
  for (char& c : option)
    if (c == '_') c = '-';
  return option;
}

/// A library message with its fields spelled as this tool's options.
inline std::string spelled(const error& e) { return e.spelled(option_spelling); }

/// The library's warnings, their fields spelled as options (core/warnings.hpp).
inline void print_warning(const std::string& marked_message) {
  std::cerr << "viscor: warning: " << detail::spell_fields(marked_message, option_spelling) << "\n";
}

}  // namespace viscor::cli
