// The result vocabulary: the names of a result's fields as JSON objects and CSV
// headers spell them, in one place (docs/json-schema.md lists every JSON name and
// its meaning). The C++ result structs use the same words: `working_digits` (the
// precision a computation ran at), `certified_digits` (agreement of independent
// computations minus a margin, certify/), `proven_digits` (both ends of a proven
// enclosure round to the same decimal, enclose/); `error_estimate` (a solver's own
// estimate of its error) and `bound` (a stated bound, whose kind the result says:
// `empirical_bound`, `target_bound`). The per-quantity digits are the kind of digits
// followed by the quantity: `certified_digits_e`, `proven_digits_contact_time`.
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
inline constexpr char stop_overlap[] = "stop_overlap";                ///< scaled overlap where a stuck bead rests
inline constexpr char time_of_max_compression[] = "time_of_max_compression";  ///< scaled tau of u_max
inline constexpr char energy_residual[] = "energy_residual";          ///< residual of the energy identity (6)
inline constexpr char max_compression_m[] = "max_compression_m";      ///< u_max in metres

/// The three kinds of digits.
inline constexpr char working_digits[] = "working_digits";            ///< decimal digits a computation worked with
inline constexpr char certified_digits[] = "certified_digits";        ///< certified significant digits (certify/)
inline constexpr char proven_digits[] = "proven_digits";              ///< proven correctly rounded digits (enclose/)
/// The older name of certified digits: the CSV column of reference tables (committed
/// data), and the `certified` JSON object, which also writes `certified_digits`.
inline constexpr char certified_digits_column[] = "digits";

/// Certified digits per quantity (the agreement before the safety margin, in
/// `certified`; a computation's agreement with the reference, in `computations`).
inline constexpr char certified_digits_e[] = "certified_digits_e";
inline constexpr char certified_digits_one_minus_e[] = "certified_digits_one_minus_e";   ///< of 1 - e
inline constexpr char certified_digits_contact_time[] = "certified_digits_contact_time"; ///< of T_f
inline constexpr char certified_digits_max_compression[] = "certified_digits_max_compression";  ///< of u_max
/// Certified decimal places of e (absolute agreement, for e near 0).
inline constexpr char certified_absolute_digits_e[] = "certified_absolute_digits_e";
/// Proven digits per quantity (`proven_digits` itself is e's).
inline constexpr char proven_digits_one_minus_e[] = "proven_digits_one_minus_e";
inline constexpr char proven_digits_contact_time[] = "proven_digits_contact_time";        ///< of T_f
inline constexpr char proven_digits_max_compression[] = "proven_digits_max_compression";  ///< of u_max

/// The certification and the proof of one impact.
inline constexpr char certified[] = "certified";                      ///< the certified result, an object
inline constexpr char outcome_certified[] = "outcome_certified";      ///< whether all computations agree on it
inline constexpr char near_sticking[] = "near_sticking";              ///< e certified in absolute terms only
inline constexpr char safety_margin[] = "safety_margin";              ///< digits subtracted from the agreement
inline constexpr char computations[] = "computations";                ///< the computations behind a certified value
inline constexpr char source[] = "source";                            ///< what one computation is
inline constexpr char precision_digits[] = "precision_digits";        ///< decimal digits of one computation
inline constexpr char outcome_proven[] = "outcome_proven";            ///< the proven outcome
inline constexpr char proof[] = "proof";                              ///< the argument that decided it
/// Certified digits asked for (`--certified-digits`): the goal, and each run's working
/// and certified digits (objects of working_digits, certified_digits).
inline constexpr char certified_digits_goal[] = "certified_digits_goal";
inline constexpr char precision_runs[] = "precision_runs";

/// Errors and bounds.
inline constexpr char error_estimate[] = "error_estimate";            ///< a solver's estimate of its absolute error of e
inline constexpr char empirical_bound[] = "empirical_bound";          ///< evaluate's bound on |e - true e| (measured)
inline constexpr char empirical_bound_relative[] = "empirical_bound_relative";  ///< the same, relative on 1 - e
/// A calibration's stated bound on |e - target e| at the calibrated damping: a bound
/// (not a solver's estimate: it adds the miss of the target to ten estimates), on the
/// distance to the target, hence `target_bound`.
inline constexpr char target_bound[] = "target_bound";

/// A calibration (calibrate, scene, dem).
inline constexpr char target_e[] = "target_e";                        ///< the CoR to reproduce
inline constexpr char gamma_lo[] = "gamma_lo";                        ///< lower end of the bracket of gamma
inline constexpr char gamma_hi[] = "gamma_hi";                        ///< upper end of the bracket of gamma
inline constexpr char solves[] = "solves";                            ///< impact solves a calibration took

}  // namespace viscor::field
