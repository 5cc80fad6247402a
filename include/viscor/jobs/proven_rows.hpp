// The proof's columns of one row of a table of method "proven" (table_format.hpp,
// docs/tables.md): viscor::enclose at the spec's digits on the row's exact decimal
// gamma and g, after the row has been certified as method "certify" does
// (compute_row). Needs Arb (VISCOR_HAS_ARB).
#pragma once

#include <viscor/core/field_names.hpp>
#include <viscor/jobs/table_format.hpp>

#include <viscor/core/detail/exact_decimal.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/enclose/enclose.hpp>
#include <viscor/tables/grid_spec.hpp>
#include <viscor/tables/reference_table.hpp>

#include <optional>
#include <string>
#include <tuple>

namespace viscor::jobs {

/// The proof's fields of one certified row: ",e_lower,e_upper,one_minus_e_lower,
/// one_minus_e_upper,proven_digits,outcome_proven", to append to the row's CSV line.
/// proven_digits is e's (as in `viscor prove --json`); an undecided proof gives empty
/// bounds and 0 digits. Throws certification_error (and no row is written) when the
/// proof contradicts the certified row: another outcome, or e or 1 - e outside the
/// enclosure by more than a unit of its last certified digit. `certified_e_shift`
/// is a test seam: a decimal added to the certified e before the check, so that
/// tests can show the check stops a run ("" in every release path).
inline std::string proven_fields(const grid_point& p, int digits, const table_row& row,
                                 const std::string& certified_e_shift = "") {
  using proofs::proven_outcome;
  const std::string where = "row " + std::to_string(p.index) + " (" + p.law.describe() + ", gamma = " + p.gamma +
                            ", g = " + p.g + ")";
  const proofs::cor_enclosure proof = [&] {
    try {
      return viscor::enclose(p.law, p.gamma, p.g, digits);
    } catch (const error& e) {  // say which row: the run stops here, keeping the rows done
      throw error(where + ": the proof failed: " + e.what());
    }
  }();
  if (proof.outcome == proven_outcome::undecided) return ",,,,,0,undecided";
  const bool proven_rebound = proof.outcome == proven_outcome::rebound;
  if (proven_rebound != (row.outcome == impact_outcome::rebound))
    throw certification_error(where + ": the proof gives " + std::string(proofs::to_string(proof.outcome)) +
                              " (" + proof.how + "), the certificate " + std::string(to_string(row.outcome)) +
                              "; one of the two is wrong: please report it");
  using viscor::detail::exact_decimal;
  const std::string& shift = certified_e_shift;
  const std::string e =
      shift.empty() ? row.e : (exact_decimal::parse(row.e, "e") + exact_decimal::parse(shift, "shift")).to_string();
  for (const auto& [name, value, bounds] : {std::tuple{field::e, &e, &proof.e},
                                            std::tuple{field::one_minus_e, &row.one_minus_e, &proof.one_minus_e}})
    if (!detail::within_last_digit(*value, row.certified_digits, bounds->lower, bounds->upper))
      throw certification_error(where + ": the certified " + std::string(name) + " = " + *value + " (" +
                                std::to_string(row.certified_digits) + " digits) is outside the proven enclosure [" +
                                bounds->lower + ", " + bounds->upper + "]; one of the two is wrong: please report it");
  return "," + proof.e.lower + "," + proof.e.upper + "," + proof.one_minus_e.lower + "," + proof.one_minus_e.upper +
         "," + std::to_string(proof.e.proven_digits) + "," + std::string(proofs::to_string(proof.outcome));
}

}  // namespace viscor::jobs
