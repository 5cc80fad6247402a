// The report's approximate CoR formulas (approx/approximations.hpp) at one (law,
// gamma, g), as `viscor approx` and viscor.approx report them: small g (22), large
// g (23), Schwager-Poschel (25)+(30), and Proposition 2 (36) with its branches
// (89), (90), each with its coefficients I(g), Q(g) from the closed forms at g = 0,
// tanh-sinh quadrature, or the Chebyshev-Beta approximation; or the committed
// surrogate in double (never silently outside its domain or for a law without one).
// Rendered by jobs/approx_render.hpp.
#pragma once

#include <viscor/core/working_number.hpp>
#include <viscor/jobs/precision_used.hpp>

#include <viscor/approx/approximations.hpp>
#include <viscor/core/contact_law.hpp>
#include <viscor/surrogate/cor_surrogate.hpp>

#include <optional>
#include <string>
#include <vector>

namespace viscor::jobs {

/// One (law, gamma, g) and the formulas to evaluate.
struct approx_request {
  contact_law law;
  std::string gamma;            ///< scaled damping, exact decimal text (required)
  std::string g = "0";          ///< scaled load
  std::string formula = "all";  ///< all, small_g, large_g, schwager_poschel, prop2, prop2_squared, prop2_linearized, surrogate
  std::string source = "all";   ///< Prop. 2 coefficients: all, exact_at_zero, numeric, chebyshev_beta
  int digits = 15;              ///< working precision in decimal digits
  int order = 21;               ///< odd order of the Chebyshev-Beta approximation, 1 to 999
};

/// Proposition 2 with one source of its coefficients I(g), Q(g).
struct prop2_value {
  coefficient_source source = coefficient_source::exact_at_zero;
  working_number I, Q, e_squared;
  std::optional<working_number> theta;         ///< chebyshev_beta: the Beta argument theta(g)
  std::optional<working_number> e;             ///< (36) min(e_+, e_s), when asked for
  std::optional<working_number> e_plus;        ///< (89), when asked for
  std::optional<working_number> e_linearized;  ///< (90), when asked for
};

/// What `viscor approx` found: the report's formulas in the working type, or the
/// committed surrogate's value in double (`by_surrogate`).
struct approx_result {
  contact_law law;
  std::string gamma_text, g_text;  ///< the inputs as given
  bool by_surrogate = false;
  // --formula surrogate:
  working_number e, one_minus_e;
  impact_outcome outcome = impact_outcome::rebound;
  surrogate::surrogate_bound bound;
  // the formulas:
  working_number gamma, g;
  precision_used precision;
  int chebyshev_order = 0;
  /// The closed forms at g = 0 behind the formulas (closed_form_coefficients: eqs. 19, 22, 23, 39, 40).
  struct closed_forms {
    working_number I0, Q0, dI_dg0, C0, C1, C, p, C2;
  } closed;
  std::optional<working_number> critical_g;      ///< gamma > 0: the sticking threshold g_c(gamma) (24)
  std::optional<working_number> critical_gamma;  ///< g > 0: the damping that sticks at this g
  std::optional<working_number> small_g, large_g, schwager_poschel;  ///< those asked for and applicable
  bool prop2_asked = false;
  std::vector<prop2_value> prop2;           ///< per coefficient source, in order
  std::vector<std::string> not_applicable;  ///< why a formula of "all" was left out
};

/// The requested formulas at (gamma, g).
approx_result run_approx(const approx_request& q);

}  // namespace viscor::jobs
