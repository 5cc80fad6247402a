// The closed-form CoR where one exists (gamma = 0; the linear law; beta = alpha + 1
// at g = 0; Tsuji at g = 0), as `viscor exact` and viscor.exact report it
// (rendered by jobs/exact_render.hpp).
#pragma once

#include <viscor/core/working_number.hpp>
#include <viscor/jobs/precision_used.hpp>

#include <viscor/core/contact_law.hpp>
#include <viscor/exact/exact_solutions.hpp>

#include <optional>
#include <string>

namespace viscor::jobs {

/// One closed-form evaluation: the law, scaled gamma and g as exact decimal text.
struct exact_request {
  contact_law law;
  std::string gamma = "0", g = "0";
  int digits = 15;  ///< working precision in decimal digits
};

/// What `viscor exact` found: the closed form in the working type, or none.
struct exact_job_result {
  contact_law law;
  std::string gamma_text, g_text;  ///< the inputs as given
  working_number gamma, g;         ///< as read in the working type
  precision_used precision;
  std::optional<exact_result<working_number>> exact;  ///< empty: no closed form is known here
  double seconds = 0;
};

namespace detail {
template <class Real>
exact_result<working_number> erased(const exact_result<Real>& r) {
  const auto optional_of = [](const std::optional<Real>& x) {
    return x ? std::optional<working_number>(working_number::of(*x)) : std::nullopt;
  };
  exact_result<working_number> out;
  out.e = working_number::of(r.e), out.one_minus_e = working_number::of(r.one_minus_e);
  out.outcome = r.outcome;
  out.contact_time = optional_of(r.contact_time);
  out.max_compression = optional_of(r.max_compression);
  out.time_of_max_compression = optional_of(r.time_of_max_compression);
  out.formula = r.formula;
  return out;
}
}  // namespace detail

/// The closed form at (gamma, g), or an empty `exact` when none is known.
exact_job_result run_exact(const exact_request& q);

}  // namespace viscor::jobs
