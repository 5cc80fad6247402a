// Physical parameters <-> scaled (gamma, g) by the report's scaling (core/scaling.hpp),
// as `viscor scale` and viscor.scale report it: forward from gamma0 (physical ->
// scaled), or inverse from gamma and g (scaled -> gamma0 and the force); rendered by
// jobs/scale_render.hpp.
#pragma once

#include <viscor/core/working_number.hpp>
#include <viscor/jobs/physical_inputs.hpp>
#include <viscor/jobs/precision_used.hpp>

#include <viscor/core/contact_law.hpp>

#include <optional>
#include <string>

namespace viscor::jobs {

/// The bead, speed and load always; gamma0 (forward) or gamma and g (inverse).
struct scale_request {
  contact_law law;
  physical_inputs physical;
  std::optional<std::string> gamma, g;  ///< the inverse direction: both, and no gamma0 or force
  int digits = 15;                      ///< working precision in decimal digits
};

/// What `viscor scale` found, in the working type.
struct scale_result {
  contact_law law;
  physical_inputs physical;  ///< the inputs as given
  precision_used precision;
  bool scaled_to_physical = false;  ///< the inverse direction (gamma, g given)
  working_number gamma, g;          ///< given (inverse) or computed (forward)
  working_number gamma0, force;     ///< inverse: the damping coefficient (SI) and the force (N) that give gamma, g
  working_number time_scale, length_scale;  ///< forward: s and m per scaled unit
};

/// The conversion in the direction the inputs ask for.
scale_result run_scale(scale_request q);

}  // namespace viscor::jobs
