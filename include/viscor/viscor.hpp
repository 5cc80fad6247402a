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
#include <viscor/core/field_names.hpp>
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
#include <viscor/core/text_fields.hpp>
#include <viscor/scenes/scene.hpp>
#include <viscor/impact/solve_impact.hpp>
#include <viscor/tables/sticking_threshold.hpp>
#include <viscor/tables/table_row.hpp>
#include <viscor/impact/taylor_impact.hpp>
#include <viscor/ode/taylor_integrator.hpp>
#include <viscor/approx/u_max.hpp>
#include <viscor/core/plausible_units.hpp>
#include <viscor/dem/builtin_conversions.hpp>
#include <viscor/dem/deck_convention.hpp>
#include <viscor/dem/deck_entries.hpp>
#include <viscor/dem/deck_snippet.hpp>
#include <viscor/dem/drop_deck.hpp>
#include <viscor/dem/dem_calibration.hpp>
#include <viscor/dem/dem_model.hpp>
#include <viscor/dem/hertz_contact.hpp>
#include <viscor/dem/variable_block.hpp>
#include <viscor/surrogate/chebyshev.hpp>
#include <viscor/surrogate/cor_surrogate.hpp>
#include <viscor/surrogate/surrogate_fit.hpp>
#include <viscor/surrogate/surrogate_source.hpp>
#include <viscor/surrogate/surrogate_timing.hpp>
#include <viscor/surrogate/surrogate_verify.hpp>
#include <viscor/config.hpp>
#include <viscor/certify/extern_templates.hpp>

// The proofs need Arb: they are part of the umbrella where the target viscor::enclose
// (which defines VISCOR_WITH_ENCLOSE and carries Arb's include path) is linked.
#if defined(VISCOR_WITH_ENCLOSE)
#include <viscor/enclose/enclose.hpp>
#endif

// The jobs need nlohmann-json: they are part of the umbrella where the target
// viscor::jobs (which defines VISCOR_WITH_JOBS) is linked.
#if defined(VISCOR_WITH_JOBS)
#include <viscor/jobs/approx_job.hpp>
#include <viscor/jobs/calibrate_job.hpp>
#include <viscor/jobs/cor_job.hpp>
#include <viscor/jobs/data_directory.hpp>
#include <viscor/jobs/dem_job.hpp>
#include <viscor/jobs/errormap_job.hpp>
#include <viscor/jobs/exact_job.hpp>
#include <viscor/jobs/physical_inputs.hpp>
#include <viscor/jobs/point_batch.hpp>
#include <viscor/jobs/report_job.hpp>
#include <viscor/jobs/scale_job.hpp>
#include <viscor/jobs/scene_file.hpp>
#include <viscor/jobs/scene_job.hpp>
#include <viscor/jobs/surrogate_build.hpp>
#include <viscor/jobs/surrogate_export.hpp>
#include <viscor/jobs/surrogate_files.hpp>
#include <viscor/jobs/table_jobs.hpp>
#include <viscor/jobs/approx_render.hpp>
#include <viscor/jobs/bench_job.hpp>
#include <viscor/jobs/bench_render.hpp>
#include <viscor/jobs/calibrate_render.hpp>
#include <viscor/jobs/cor_render.hpp>
#include <viscor/jobs/dem_render.hpp>
#include <viscor/jobs/exact_render.hpp>
#include <viscor/jobs/scale_render.hpp>
#endif

/// @namespace viscor
/// The coefficient of restitution of a bead hitting a wall under a constant load,
/// for visco-elastic contact laws: exact and approximate solutions, two independent
/// integrators, certification, reference tables, scenes and calibration.
/// docs/architecture.md maps the layers (one folder of include/viscor per layer).

/// @namespace viscor::dem
/// The DEM bridge: damping parameters in the conventions of LAMMPS, LIGGGHTS and YADE
/// (docs/dem.md).

/// @namespace viscor::jobs
/// The jobs as the command-line tool and the Python module run them, for C++
/// programs: tables with shards, threads, progress and resume; point batches;
/// scene files; the data directory; the file formats and JSON fields of all of them.

/// @namespace viscor::surrogate
/// Fitted double-precision surrogates of e(gamma, g) per contact law, with measured
/// bounds (docs/surrogate.md).
