// viscor: certified coefficient of restitution of visco-elastic impacts under load.
// Umbrella header: includes the whole public API.
#pragma once

#include <viscor/impact/adaptive_impact.hpp>
#include <viscor/ode/adaptive_integrator.hpp>
#include <viscor/tables/approximation_errors.hpp>
#include <viscor/approx/approximations.hpp>
#include <viscor/scenes/calibration.hpp>
#include <viscor/certify/certification.hpp>
#include <viscor/approx/chebyshev_beta.hpp>
#include <viscor/approx/closed_form.hpp>
#include <viscor/core/contact_law.hpp>
#include <viscor/scenes/error_map.hpp>
#include <viscor/scenes/error_map_builder.hpp>
#include <viscor/scenes/evaluate.hpp>
#include <viscor/exact/exact_hunt_crossley.hpp>
#include <viscor/exact/exact_linear.hpp>
#include <viscor/exact/exact_result.hpp>
#include <viscor/exact/exact_solutions.hpp>
#include <viscor/exact/exact_tsuji.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/tables/grid_spec.hpp>
#include <viscor/core/impact_result.hpp>
#include <viscor/approx/integrals.hpp>
#include <viscor/core/outcome.hpp>
#include <viscor/core/parameters.hpp>
#include <viscor/core/precision.hpp>
#include <viscor/core/real_io.hpp>
#include <viscor/core/real_types.hpp>
#include <viscor/tables/reference_table.hpp>
#include <viscor/core/scaling.hpp>
#include <viscor/scenes/scene.hpp>
#include <viscor/impact/solve_impact.hpp>
#include <viscor/tables/sticking_threshold.hpp>
#include <viscor/tables/table_row.hpp>
#include <viscor/impact/taylor_impact.hpp>
#include <viscor/ode/taylor_integrator.hpp>
#include <viscor/approx/u_max.hpp>
#include <viscor/config.hpp>
#include <viscor/certify/extern_templates.hpp>

/// @namespace viscor
/// The coefficient of restitution of a bead hitting a wall under a constant load,
/// for visco-elastic contact laws: exact and approximate solutions, two independent
/// integrators, certification, reference tables, scenes and calibration.
/// docs/architecture.md maps the layers (one folder of include/viscor per layer).

/// @namespace viscor::dem
/// The DEM bridge: damping parameters in the conventions of LAMMPS and LIGGGHTS
/// (docs/dem.md).

/// @namespace viscor::surrogate
/// Fitted double-precision surrogates of e(gamma, g) per contact law, with measured
/// bounds (docs/surrogate.md).
