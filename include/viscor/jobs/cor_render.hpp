// The cor job's result (jobs/cor_result.hpp) as readable text and as JSON: the one
// place either form is made, for `viscor cor` (text and --json), each line of
// `viscor cor --points` and Python's viscor.cor. Field names are the project's
// vocabulary (core/field_names.hpp, docs/json-schema.md); numbers are the exact
// decimals of the working type.
#pragma once

#include <viscor/core/field_names.hpp>
#include <viscor/enclose/proven_bounds.hpp>
#include <viscor/jobs/cor_result.hpp>
#include <viscor/jobs/json_fields.hpp>

#include <ostream>
#include <sstream>
#include <string>

namespace viscor::render {

using jobs::json;
using jobs::number;

/// x rounded to `digits` significant digits ("uncertified" for 0 digits); e = 0 of a
/// certified stick and infinite times print exactly.
inline std::string rounded_to_certified(const working_number& x, int digits) {
  if (x.is_zero() || x.is_infinite()) return x.decimal();
  if (digits <= 0) return "uncertified";
  return x.decimal(digits);
}

/// The solver's fields of one impact (after law, gamma, g and precision).
template <class Real>
void add_impact_json(json& j, const impact_result<Real>& r, double seconds) {
  j[field::method] = std::string(to_string(r.method));
  j[field::e] = number(r.e);
  j[field::one_minus_e] = number(r.one_minus_e);
  j[field::outcome] = std::string(to_string(r.outcome));
  j[field::contact_time] = number(r.contact_time);
  j[field::max_compression] = number(r.max_compression);
  if (r.outcome == impact_outcome::stick) j[field::stop_overlap] = number(r.stop_overlap);
  j[field::time_of_max_compression] = number(r.time_of_max_compression);
  j[field::energy_residual] = number(r.energy_residual);
  j[field::error_estimate] = number(r.error_estimate);
  j[field::steps] = r.steps;
  j[field::seconds] = seconds;
}

/// The object "certified": the value rounded to its certified digits, the digits, and
/// every contributing computation at its own full precision, so a reader can audit
/// the claim. `digits` repeats certified_digits under its older name.
inline json certified_json(const certified_result<working_number>& c) {
  const bool stick = c.outcome == impact_outcome::stick;
  json out;
  out[field::outcome] = std::string(to_string(c.outcome));
  out[field::outcome_certified] = c.outcome_certified;
  out[field::certified_digits] = c.certified_digits;
  out[field::certified_digits_column] = c.certified_digits;  // the older name, still written
  out[field::e] = stick && c.outcome_certified ? std::string("0") : rounded_to_certified(c.e, c.certified_digits);
  out[field::one_minus_e] =
      stick && c.outcome_certified ? std::string("1") : rounded_to_certified(c.one_minus_e, c.certified_digits);
  out[field::contact_time] = c.contact_time ? rounded_to_certified(*c.contact_time, c.certified_digits)
                             : c.certified_digits <= 0 ? std::string("uncertified")
                                                       : std::string("nan");  // unknown
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
  return out;
}

/// The readable report of a certification (certified_json's content).
inline void write_certified_text(std::ostream& text, const certified_result<working_number>& c) {
  const json out = certified_json(c);
  const bool stick = c.outcome == impact_outcome::stick;
  text << "certified  " << (c.outcome_certified ? "" : "NO: the computations disagree on the outcome; ")
       << c.certified_digits << " significant digits (agreement of " << c.computations.size()
       << " computations minus a margin of " << c.safety_margin << ")\n"
       << "  outcome  " << to_string(c.outcome) << (c.outcome_certified ? " (all agree)" : " (reference)") << "\n"
       << "  e        " << out[field::e].get<std::string>() << "\n"
       << "  1 - e    " << out[field::one_minus_e].get<std::string>() << "\n"
       << (stick ? "  T_stop   " : "  T_f      ") << out[field::contact_time].get<std::string>() << "\n"
       << "  u_max    " << out[field::max_compression].get<std::string>() << "\n";
  if (c.near_sticking)
    text << "  near the sticking threshold: e is certified to " << c.certified_absolute_digits_e
         << " decimal places (absolute)\n";
  for (const auto& m : c.computations) {
    text << "  " << to_string(m.source) << " at " << m.precision_digits << " digits: " << to_string(m.outcome)
         << ", e = " << m.e_text << "\n"
         << "      1 - e = " << m.one_minus_e_text << ", T = " << m.contact_time_text << "\n"
         << "      agrees with the reference to " << m.certified_digits_e << " digits (e), "
         << m.certified_digits_one_minus_e << " (1 - e), " << m.certified_digits_contact_time << " (T); " << m.steps
         << " steps, " << m.seconds << " s\n";
  }
}

/// The certified digits asked for and the precision of each run made for them.
inline void add_goal_json(json& j, const certified_digits_goal& goal) {
  j[field::certified_digits_goal] = goal.certified_digits;
  json runs = json::array();
  for (const precision_run& r : goal.runs)
    runs.push_back(json{{field::working_digits, r.working_digits}, {field::certified_digits, r.certified_digits}});
  j[field::precision_runs] = runs;
}

/// The readable line of a goal of certified digits (add_goal_json's content).
inline void write_goal_text(std::ostream& text, const certified_digits_goal& goal) {
  text << "goal       " << goal.certified_digits << " certified digits: ";
  for (std::size_t i = 0; i < goal.runs.size(); ++i)
    text << (i ? ", then " : "") << goal.runs[i].certified_digits << " certified at " << goal.runs[i].working_digits
         << " working digits";
  text << "\n";
}

/// A proof's bounds, proven digits and outcome (`viscor prove`, `viscor cor --prove`).
inline void add_proof_json(json& j, const proofs::proven_decimals& p) {
  j[field::outcome_proven] = std::string(to_string(p.outcome));
  j[field::proof] = p.how;
  if (p.outcome == impact_outcome::undecided) {
    j[field::proven_digits] = 0;
    return;
  }
  const auto put = [&](const char* name, const proofs::proven_bounds& b, const char* digits) {
    j[std::string(name) + "_lower"] = b.lower;
    j[std::string(name) + "_upper"] = b.upper;
    j[digits] = b.proven_digits;
  };
  put(field::e, p.e, field::proven_digits);
  put(field::one_minus_e, p.one_minus_e, field::proven_digits_one_minus_e);
  if (p.contact_time) put(field::contact_time, *p.contact_time, field::proven_digits_contact_time);
  if (p.max_compression) put(field::max_compression, *p.max_compression, field::proven_digits_max_compression);
}

/// The readable lines of a proof (add_proof_json's content).
inline void write_proof_text(std::ostream& text, const proofs::proven_decimals& p) {
  text << "proven     " << to_string(p.outcome) << " (" << p.how << ")\n";
  if (p.outcome == impact_outcome::undecided) return;
  const auto show = [&](const char* label, const proofs::proven_bounds& b) {
    if (b.lower == b.upper) {  // an exact value (e = 0 of a stick, 1 - e = 0 at gamma = 0)
      text << label << b.lower << " (exact)\n";
      return;
    }
    text << label << "[" << b.lower << ", " << b.upper << "]\n           " << b.proven_digits
         << " proven correctly rounded digits" << (b.proven_digits > 0 ? ": " + b.rounded : std::string()) << "\n";
  };
  show("e in       ", p.e);
  show("1 - e in   ", p.one_minus_e);
  if (p.contact_time) show("T_f in     ", *p.contact_time);
  if (p.max_compression) show("u_max in   ", *p.max_compression);
}

/// The fields of one impact, in the order of `viscor cor --json` after "command"
/// (each line of `viscor cor --points` puts "line" before them).
inline void add_cor_fields(json& j, const jobs::cor_result& r) {
  j["law"] = jobs::law_json(r.law);
  if (r.physical) {
    j["physical"] = r.physical->inputs.echo();
    j["time_scale_s"] = number(r.physical->time_scale);
    j["length_scale_m"] = number(r.physical->length_scale);
  }
  j["gamma"] = number(r.gamma);
  j["g"] = number(r.g);
  j["precision"] = jobs::precision_json(r.precision);
  add_impact_json(j, r, r.seconds);
  if (r.physical) {
    j[field::contact_time_s] = number(r.physical->contact_time_s);
    j[field::max_compression_m] = number(r.physical->max_compression_m);
  }
  if (r.certified) j[field::certified] = certified_json(*r.certified);
  if (r.goal) add_goal_json(j, *r.goal);
  if (r.proof) add_proof_json(j, *r.proof);
}

/// The object of `viscor cor --json` (and of Python's viscor.cor).
inline json cor_json(const jobs::cor_result& r) {
  json j;
  j["command"] = "cor";
  add_cor_fields(j, r);
  return j;
}

/// The readable summary of `viscor cor`.
inline std::string cor_text(const jobs::cor_result& r) {
  std::ostringstream text;
  text << "law        " << r.law.describe() << "\n";
  if (r.physical) {
    const jobs::physical_inputs& in = r.physical->inputs;
    text << "physical   " << in.echo_text() << "\n";
    if (in.has_material())  // the bead's mass and stiffness are computed, not typed
      text << (in.is_pair() ? "pair       m* = " : "bead       m = ") << r.physical->m.decimal(10)
           << " kg, k = " << r.physical->k.decimal(10)
           << (in.is_pair() ? " N/m^(3/2) (the relative motion's reduced mass and stiffness, from the materials)\n"
                            : " N/m^(3/2) (from the material)\n");
  }
  const bool undecided = r.outcome == impact_outcome::undecided;
  text << "gamma      " << number(r.gamma) << "\n"
       << "g          " << number(r.g) << "\n"
       << "outcome    " << to_string(r.outcome)
       << (undecided ? " (rebound or stick cannot be decided at this precision: e = 0 to within the error below)\n"
                     : " (contact ends at zero overlap u = 0)\n")
       << "e          " << number(r.e) << "\n"
       << "1 - e      " << number(r.one_minus_e) << "\n"
       << (r.outcome == impact_outcome::rebound ? "T_f        " : "T_stop     ")
       << (undecided ? std::string("unknown") : number(r.contact_time)) << " (scaled)\n";
  if (r.physical && !undecided) text << "time       " << number(r.physical->contact_time_s) << " s (contact)\n";
  text << "u_max      " << number(r.max_compression) << " at tau = " << number(r.time_of_max_compression) << "\n"
       << (r.outcome == impact_outcome::stick
               ? "u_stop     " + number(r.stop_overlap) + " (where u' returns to 0, or the rest position)\n"
               : std::string())
       << "error      " << r.error_estimate.decimal(3) << " (estimated, absolute, on e)\n"
       << "energy     " << r.energy_residual.decimal(3) << " (residual of identity (6))\n"
       << "steps      " << r.steps << " (" << to_string(r.method) << ")\n"
       << "seconds    " << r.seconds << " s\n"
       << "digits     " << r.precision.digits << " (working precision)\n";
  if (r.certified) write_certified_text(text, *r.certified);
  if (r.goal) write_goal_text(text, *r.goal);
  if (r.proof) write_proof_text(text, *r.proof);
  return text.str();
}

}  // namespace viscor::render
