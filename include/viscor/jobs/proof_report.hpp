// The proven enclosure of one impact in the output of `viscor prove` and
// `viscor cor --prove` (docs/proofs.md): the same JSON names in both (docs/json-schema.md).
#pragma once

#include <viscor/core/field_names.hpp>
#include <viscor/jobs/json_fields.hpp>
#include <viscor/jobs/files.hpp>

#include <viscor/enclose/enclose.hpp>

#include <sstream>
#include <string>

namespace viscor::jobs {

/// Proves the impact of `law` at the exact decimals (gamma, g) with viscor::enclose
/// and adds the bounds, proven digits and proven outcome to `j` and `text`.
/// Throws invalid_parameter ("not provable: ...") for non-rational exponents.
inline proofs::cor_enclosure add_proof(const contact_law& law, const std::string& gamma, const std::string& g,
                                       int digits, std::ostringstream& text, json& j) {
  const proofs::cor_enclosure p = viscor::enclose(law, gamma, g, digits);
  j[field::outcome_proven] = std::string(proofs::to_string(p.outcome));
  j[field::proof] = p.how;
  text << "proven     " << proofs::to_string(p.outcome) << " (" << p.how << ")\n";
  if (p.outcome == proofs::proven_outcome::undecided) {
    j[field::proven_digits] = 0;
    return p;
  }
  const auto show = [&](const char* name, const char* label, const proofs::proven_bounds& b, const char* digits) {
    j[std::string(name) + "_lower"] = b.lower;
    j[std::string(name) + "_upper"] = b.upper;
    j[digits] = b.proven_digits;
    if (b.lower == b.upper) {  // an exact value (e = 0 of a stick, 1 - e = 0 at gamma = 0)
      text << label << b.lower << " (exact)\n";
      return;
    }
    text << label << "[" << b.lower << ", " << b.upper << "]\n           " << b.proven_digits
         << " proven correctly rounded digits" << (b.proven_digits > 0 ? ": " + b.rounded : std::string()) << "\n";
  };
  show(field::e, "e in       ", p.e, field::proven_digits);
  show(field::one_minus_e, "1 - e in   ", p.one_minus_e, field::proven_digits_one_minus_e);
  if (p.contact_time) show(field::contact_time, "T_f in     ", *p.contact_time, field::proven_digits_contact_time);
  if (p.max_compression) show(field::max_compression, "u_max in   ", *p.max_compression, field::proven_digits_max_compression);
  return p;
}

}  // namespace viscor::jobs
