// The damping that gives a target CoR (scenes/calibration.hpp), as `viscor
// calibrate` and viscor.calibrate report it: scaled (g -> gamma) or physical (the
// bead, speed and load -> gamma0 by the report's scaling).
//   method "solve" (default): root finding on solve_impact at the working precision.
//   method "surrogate": the inverse of the law's committed surrogate in double
//   (cor_surrogate::gamma_for): about a microsecond; refused for a law without a
//   surrogate, a load outside its domain, or a target outside 0.01 <= e < 1.
// Rendered by jobs/calibrate_render.hpp.
#pragma once

#include <viscor/core/working_number.hpp>
#include <viscor/jobs/physical_inputs.hpp>
#include <viscor/jobs/precision_used.hpp>

#include <viscor/core/contact_law.hpp>
#include <viscor/surrogate/cor_surrogate.hpp>

#include <optional>
#include <string>

namespace viscor::jobs {

/// A target e with a scaled load g, or with the physical inputs (no gamma0: it is the answer).
struct calibrate_request {
  contact_law law;
  physical_inputs physical;
  std::optional<std::string> target_e, g;
  std::string tolerance = "0";    ///< absolute tolerance on e (0: 1e5 x machine epsilon)
  std::string gamma_max = "100";  ///< largest scaled damping tried
  int digits = 15;                ///< working precision in decimal digits
  std::string method = "solve";   ///< "solve" or "surrogate"
};

/// What `viscor calibrate` found, in the working type (double for the surrogate).
struct calibrate_result {
  contact_law law;
  std::string target_e;  ///< as given
  bool by_surrogate = false;  ///< method "surrogate" (else "solve")
  std::optional<physical_inputs> physical;  ///< the inputs as given, in the physical mode
  /// The physical mode: the damping coefficient (SI) that gives the target and the time scale (s).
  std::optional<working_number> gamma0, time_scale;
  /// The physical mode, method solve: the bead and load the inputs give (kg, N/m^alpha, m/s, m/s^2, N).
  working_number m, k, v0, gravity, force;
  working_number gamma, g, e;  ///< the calibrated scaled damping, the scaled load and e there
  /// Method solve: |e - target| bound (miss plus 10 x the solver's estimate), the final bracket, the solves.
  working_number target_bound, gamma_lo, gamma_hi;
  std::size_t solves = 0;
  surrogate::surrogate_bound bound;  ///< method surrogate: the surrogate's stated bound
  precision_used precision;
  double seconds = 0;
};

/// The calibrated damping by the requested method.
calibrate_result run_calibrate(calibrate_request q);

}  // namespace viscor::jobs
