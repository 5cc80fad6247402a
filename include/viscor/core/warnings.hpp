// Warnings: an input that is probably a mistake but may be meant (a unit slip), a
// deprecated spelling. They name fields as errors do (VISCOR_FIELD, exceptions.hpp),
// and each front end chooses how to show them: by default one line on standard error
// with the fields by name; the command-line tool spells them as its options.
#pragma once

#include <viscor/core/exceptions.hpp>

#include <iostream>
#include <string>

namespace viscor {

/// Shows one warning; its fields are still marked (detail::spell_fields).
using warning_handler = void (*)(const std::string& marked_message);

/// This process's handler (nullptr: the default). Set it once, before any work.
inline warning_handler& current_warning_handler() {
  static warning_handler handler = nullptr;
  return handler;
}

/// Shows a warning through the current handler, or as "viscor: warning: MESSAGE" on stderr.
inline void warn(const std::string& marked_message) {
  if (const warning_handler handler = current_warning_handler())
    handler(marked_message);
  else
    std::cerr << "viscor: warning: " << detail::plain_fields(marked_message) << "\n";
}

}  // namespace viscor
