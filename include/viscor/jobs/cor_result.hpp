// What the cor job found (jobs/cor_job.hpp), as numbers and types: the solver's
// impact_result in the working type, the precision it ran at, the physical side
// when the inputs were SI, the certified digits and the proof when asked for.
// Rendered to text and JSON in one place (jobs/cor_render.hpp).
#pragma once

#include <viscor/core/contact_law.hpp>
#include <viscor/core/impact_result.hpp>
#include <viscor/core/working_number.hpp>
#include <viscor/enclose/proven_bounds.hpp>
#include <viscor/jobs/physical_inputs.hpp>
#include <viscor/jobs/precision_used.hpp>

#include <viscor/certify/certification.hpp>
#include <viscor/certify/certified_digits_goal.hpp>

#include <optional>
#include <utility>

namespace viscor::jobs {

/// An impact given in SI units: the inputs as given and what they scale to.
struct physical_side {
  physical_inputs inputs;                       ///< as given (exact decimal text)
  working_number m, k;                          ///< the bead's mass (kg) and stiffness (the pair's reduced ones)
  working_number time_scale, length_scale;      ///< s and m per scaled unit
  std::optional<working_number> contact_time_s;  ///< the contact time in seconds (empty: unknown)
  working_number max_compression_m;             ///< u_max in metres
  /// With certify: the certified T_f and u_max in seconds and metres (empty: unknown).
  std::optional<working_number> certified_contact_time_s, certified_max_compression_m;
};

/// One impact as the cor job found it: e, 1 - e, the outcome, the contact time and
/// the rest of impact_result in the working type (result.e reads as a double; its
/// exact decimals are result.e.decimal()), with the inputs and the precision.
struct cor_result : impact_result<working_number> {
  contact_law law;
  working_number gamma, g;  ///< the scaled inputs (converted from SI in the physical mode)
  precision_used precision;
  double seconds = 0;  ///< wall time of the solve
  std::optional<physical_side> physical;                   ///< SI inputs: their side
  std::optional<certified_result<working_number>> certified;  ///< with certify
  std::optional<certified_digits_goal> goal;                  ///< with certified_digits: the runs it took
  std::optional<proofs::proven_decimals> proof;             ///< with prove
};

namespace detail {

// A Real result as working numbers (the values keep their type).
template <class Real>
impact_result<working_number> erased(const impact_result<Real>& r) {
  impact_result<working_number> out;
  out.e = working_number::of(r.e), out.one_minus_e = working_number::of(r.one_minus_e);
  out.outcome = r.outcome;
  if (r.contact_time) out.contact_time = working_number::of(*r.contact_time);
  else out.contact_time = std::nullopt;
  out.max_compression = working_number::of(r.max_compression);
  out.stop_overlap = working_number::of(r.stop_overlap);
  out.time_of_max_compression = working_number::of(r.time_of_max_compression);
  out.energy_residual = working_number::of(r.energy_residual);
  out.steps = r.steps;
  out.error_estimate = working_number::of(r.error_estimate);
  out.method = r.method;
  return out;
}

template <class Real>
certified_computation<working_number> erased(const certified_computation<Real>& c) {
  certified_computation<working_number> out;
  out.source = c.source, out.precision_digits = c.precision_digits, out.outcome = c.outcome;
  out.e = working_number::of(c.e), out.one_minus_e = working_number::of(c.one_minus_e);
  out.max_compression = working_number::of(c.max_compression);
  if (c.contact_time) out.contact_time = working_number::of(*c.contact_time);
  else out.contact_time = std::nullopt;
  out.e_text = c.e_text, out.one_minus_e_text = c.one_minus_e_text, out.contact_time_text = c.contact_time_text;
  out.error_estimate = working_number::of(c.error_estimate);
  out.steps = c.steps, out.seconds = c.seconds;
  out.certified_digits_e = c.certified_digits_e, out.certified_digits_one_minus_e = c.certified_digits_one_minus_e;
  out.certified_digits_contact_time = c.certified_digits_contact_time;
  out.certified_digits_max_compression = c.certified_digits_max_compression;
  out.certified_absolute_digits_e = c.certified_absolute_digits_e;
  return out;
}

template <class Real>
certified_result<working_number> erased(const certified_result<Real>& c) {
  certified_result<working_number> out;
  out.outcome = c.outcome, out.outcome_certified = c.outcome_certified;
  out.e = working_number::of(c.e), out.one_minus_e = working_number::of(c.one_minus_e);
  out.max_compression = working_number::of(c.max_compression);
  if (c.contact_time) out.contact_time = working_number::of(*c.contact_time);
  else out.contact_time = std::nullopt;
  out.certified_digits = c.certified_digits;
  out.certified_digits_e = c.certified_digits_e, out.certified_digits_one_minus_e = c.certified_digits_one_minus_e;
  out.certified_digits_contact_time = c.certified_digits_contact_time;
  out.certified_digits_max_compression = c.certified_digits_max_compression;
  out.certified_absolute_digits_e = c.certified_absolute_digits_e;
  out.near_sticking = c.near_sticking, out.working_digits = c.working_digits, out.safety_margin = c.safety_margin;
  for (const auto& m : c.computations) out.computations.push_back(erased(m));
  return out;
}

}  // namespace detail
}  // namespace viscor::jobs
