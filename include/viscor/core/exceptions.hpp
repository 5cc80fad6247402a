// Typed errors. Expected outcomes (a bead that sticks) are results, not errors.
// A message names the inputs it is about by their field names in the project's
// vocabulary (youngs_modulus, target_e), marked with VISCOR_FIELD, so that each
// front end spells them its own way: the command-line tool as its options
// (--youngs-modulus), what() and Python as the names themselves.
#pragma once

#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>

/// A field name marked in a message (a string literal, so it concatenates with the
/// literals around it): "dem needs " VISCOR_FIELD("youngs_modulus") " (Pa)".
#define VISCOR_FIELD(name) "\036" name "\037"

namespace viscor {

/// The marked field `name` for a message built at run time (VISCOR_FIELD for literals).
inline std::string field_ref(std::string_view name) { return "\036" + std::string(name) + "\037"; }

namespace detail {
/// `text` with every marked field written as spell(name); an unmatched mark stays as it is.
template <class Spell>
std::string spell_fields(std::string_view text, const Spell& spell) {
  std::string out;
  std::size_t at = 0;
  for (;;) {
    const std::size_t open = text.find('\036', at);
    const std::size_t close = open == std::string_view::npos ? open : text.find('\037', open + 1);
    if (close == std::string_view::npos) break;
    out.append(text.substr(at, open - at));
    out += spell(std::string(text.substr(open + 1, close - open - 1)));
    at = close + 1;
  }
  out.append(text.substr(at));
  return out;
}
/// `text` with its fields by name (what(), Python).
inline std::string plain_fields(std::string_view text) {
  return spell_fields(text, [](const std::string& name) { return name; });
}
}  // namespace detail

/// Base of every error viscor throws. what() names fields by their names; spelled()
/// lets a front end spell them (the CLI: as its options).
struct error : std::runtime_error {
  /// `message` names fields with VISCOR_FIELD or field_ref; what() shows their names.
  explicit error(const std::string& message)
      : std::runtime_error(detail::plain_fields(message)), m_marked(std::make_shared<const std::string>(message)) {}
  /// The message with each field written as spell(name).
  template <class Spell>
  std::string spelled(const Spell& spell) const {
    return detail::spell_fields(*m_marked, spell);
  }
  /// The message with its fields still marked (to pass on in another error).
  const std::string& marked() const noexcept { return *m_marked; }

 private:
  std::shared_ptr<const std::string> m_marked;  // shared: copying an exception must not throw
};

/// Bad input at the API boundary: the message names the parameter and its value.
struct invalid_parameter : error {
  using error::error;
};

/// A precision the build cannot provide (or a nonsensical digit count).
struct precision_unavailable : invalid_parameter {
  using invalid_parameter::invalid_parameter;
};

/// A value outside the exponent range in which the scalar type keeps its digits (a
/// double-double below 2^-939, a Taylor coefficient of a double or double-double solve
/// below the normal range where it matters): with_working_precision then runs the
/// computation again in a type with a wider range.
struct exponent_range_exceeded : precision_unavailable {
  using precision_unavailable::precision_unavailable;
};

/// An iteration (root finder, integrator step budget) did not converge.
struct convergence_error : error {
  using error::error;
};

/// Independent computations disagree: no digits can be certified.
struct certification_error : error {
  using error::error;
};

/// Malformed input file (table spec, scene, CSV): the message names file, line and field.
struct parse_error : invalid_parameter {
  using invalid_parameter::invalid_parameter;
};

}  // namespace viscor
