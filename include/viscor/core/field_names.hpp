// The result vocabulary: the names of a result's fields as JSON objects and CSV
// headers spell them, in one place (docs/json-schema.md lists every JSON name and
// its meaning). The C++ result structs use the same words: `working_digits` (the
// precision a computation ran at), `certified_digits` (agreement of independent
// computations minus a margin, certify/), `proven_digits` (both ends of a proven
// enclosure round to the same decimal, enclose/); `error_estimate` (a solver's own
// estimate of its error) and `bound` (a stated bound, whose kind the result says).
// Each name is a character array, so it reads wherever a string literal does.
#pragma once

namespace viscor::field {

// NOTE: arrays rather than std::string_view: nlohmann-json keys, std::string
// concatenation and std::tuple deduction take them exactly as the literals they replace.

/// The quantities of one impact.
inline constexpr char e[] = "e";
inline constexpr char one_minus_e[] = "one_minus_e";                  ///< 1 - e at full relative precision
inline constexpr char contact_time[] = "contact_time";                ///< scaled T_f
inline constexpr char contact_time_s[] = "contact_time_s";            ///< T_f in seconds
inline constexpr char max_compression[] = "max_compression";          ///< scaled u_max
inline constexpr char outcome[] = "outcome";                          ///< rebound, stick or undecided
inline constexpr char method[] = "method";                            ///< the method that produced the value
inline constexpr char steps[] = "steps";                              ///< integrator steps
inline constexpr char seconds[] = "seconds";                          ///< wall time

/// The three kinds of digits.
inline constexpr char working_digits[] = "working_digits";            ///< decimal digits a computation worked with
inline constexpr char certified_digits[] = "certified_digits";        ///< certified significant digits (certify/)
inline constexpr char proven_digits[] = "proven_digits";              ///< proven correctly rounded digits (enclose/)
/// The older name of certified digits: the CSV column of reference tables (committed
/// data), and the `certified` JSON object, which also writes `certified_digits`.
inline constexpr char certified_digits_column[] = "digits";

/// Errors and bounds.
inline constexpr char error_estimate[] = "error_estimate";            ///< a solver's estimate of its absolute error of e
inline constexpr char empirical_bound[] = "empirical_bound";          ///< evaluate's bound on |e - true e| (measured)
inline constexpr char empirical_bound_relative[] = "empirical_bound_relative";  ///< the same, relative on 1 - e

}  // namespace viscor::field
