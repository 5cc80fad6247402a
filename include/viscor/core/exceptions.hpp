// Typed errors. Expected outcomes (a bead that sticks) are results, not errors.
#pragma once

#include <stdexcept>
#include <string>

namespace viscor {

/// Base of every error viscor throws.
struct error : std::runtime_error {
  using std::runtime_error::runtime_error;
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
