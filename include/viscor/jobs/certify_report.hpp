// `viscor cor ... --certify`: the certified result (viscor::certify) as text and
// JSON. The value is printed rounded to its certified digits, then the digits, then
// every contributing computation at its own full precision, so a reader can audit
// the claim. JSON field names are those of certified_result / certified_computation
// (core/field_names.hpp); `digits` repeats certified_digits under its older name.
#pragma once

#include <viscor/core/field_names.hpp>
#include <viscor/jobs/json_fields.hpp>
#include <viscor/jobs/files.hpp>

#include <viscor/certify/certification.hpp>

#include <boost/math/special_functions/fpclassify.hpp>

#include <sstream>
#include <string>

namespace viscor::jobs {

/// x rounded to `digits` significant digits ("uncertified" for 0 digits); e = 0 of a
/// certified stick and infinite times print exactly.
template <class Real>
std::string rounded_to_certified(const Real& x, int digits) {
  using boost::math::isinf;
  if (x == 0 || isinf(x)) return to_decimal_string(x);
  if (digits <= 0) return "uncertified";
  return to_decimal_string(x, digits);
}

/// Runs viscor::certify at (law, gamma, g) in the working type Real and appends the
/// readable report to `text` and the object "certified" to `j`.
template <class Real>
void certify_and_report(const contact_law& law, const Real& gamma, const Real& g, std::ostringstream& text, json& j) {
  const certified_result<Real> c = certify<Real>(law, gamma, g);
  const bool stick = c.outcome == impact_outcome::stick;
  json out;
  out[field::outcome] = std::string(to_string(c.outcome));
  out[field::outcome_certified] = c.outcome_certified;
  out[field::certified_digits] = c.certified_digits;
  out[field::certified_digits_column] = c.certified_digits;  // the older name, still written
  out[field::e] = stick && c.outcome_certified ? std::string("0") : rounded_to_certified(c.e, c.certified_digits);
  out[field::one_minus_e] =
      stick && c.outcome_certified ? std::string("1") : rounded_to_certified(c.one_minus_e, c.certified_digits);
  out[field::contact_time] = rounded_to_certified(viscor::detail::or_nan(c.contact_time), c.certified_digits);  // unknown: nan
  out[field::max_compression] = rounded_to_certified(c.max_compression, c.certified_digits);
  out[field::certified_digits_e] = c.certified_digits_e;
  out[field::certified_digits_one_minus_e] = c.certified_digits_one_minus_e;
  out[field::certified_digits_contact_time] = c.certified_digits_contact_time;
  out[field::certified_digits_max_compression] = c.certified_digits_max_compression;
  out[field::certified_absolute_digits_e] = c.certified_absolute_digits_e;
  out[field::near_sticking] = c.near_sticking;
  out[field::working_digits] = c.working_digits;
  out[field::safety_margin] = c.safety_margin;
  json list = json::array();
  for (const auto& m : c.computations) {
    json k;
    k[field::source] = std::string(to_string(m.source));
    k[field::precision_digits] = m.precision_digits;
    k[field::outcome] = std::string(to_string(m.outcome));
    k[field::e] = m.e_text;
    k[field::one_minus_e] = m.one_minus_e_text;
    k[field::contact_time] = m.contact_time_text;
    k[field::max_compression] = number(m.max_compression);
    k[field::error_estimate] = to_decimal_string(m.error_estimate, 3);
    k[field::steps] = m.steps;
    k[field::seconds] = m.seconds;
    k[field::certified_digits_e] = m.certified_digits_e;
    k[field::certified_digits_one_minus_e] = m.certified_digits_one_minus_e;
    k[field::certified_digits_contact_time] = m.certified_digits_contact_time;
    k[field::certified_absolute_digits_e] = m.certified_absolute_digits_e;
    list.push_back(k);
  }
  out[field::computations] = list;
  j[field::certified] = out;

  text << "certified  " << (c.outcome_certified ? "" : "NO: the computations disagree on the outcome; ")
       << c.certified_digits << " significant digits (agreement of " << c.computations.size() << " computations minus a margin of "
       << c.safety_margin << ")\n"
       << "  outcome  " << to_string(c.outcome) << (c.outcome_certified ? " (all agree)" : " (reference)") << "\n"
       << "  e        " << out[field::e].get<std::string>() << "\n"
       << "  1 - e    " << out[field::one_minus_e].get<std::string>() << "\n"
       << (stick ? "  T_stop   " : "  T_f      ") << out[field::contact_time].get<std::string>() << "\n"
       << "  u_max    " << out[field::max_compression].get<std::string>() << "\n";
  if (c.near_sticking)
    text << "  near the sticking threshold: e is certified to " << c.certified_absolute_digits_e << " decimal places (absolute)\n";
  for (const auto& m : c.computations) {
    text << "  " << to_string(m.source) << " at " << m.precision_digits << " digits: " << to_string(m.outcome)
         << ", e = " << m.e_text << "\n"
         << "      1 - e = " << m.one_minus_e_text << ", T = " << m.contact_time_text << "\n"
         << "      agrees with the reference to " << m.certified_digits_e << " digits (e), " << m.certified_digits_one_minus_e
         << " (1 - e), " << m.certified_digits_contact_time << " (T); " << m.steps << " steps, " << m.seconds << " s\n";
  }
}

}  // namespace viscor::jobs
