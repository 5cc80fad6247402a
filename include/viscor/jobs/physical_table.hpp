// The rows of a table from a spec in SI (physical_grid.hpp, docs/tables.md "Physical
// specs"): each row is `viscor cor` with the row's physical inputs, certified (run_cor
// of cor_job.hpp, so the scaling is the library's one scaling), written as a CoR row
// over the scaled gamma and g it maps to, followed by the inputs and the contact time
// and maximal compression in SI (table_format.hpp, physical_columns). Defined in
// src/jobs/physical_table.cpp; make_cor_table (table_jobs.hpp) runs them.
#pragma once

#include <viscor/jobs/physical_grid.hpp>
#include <viscor/jobs/table_spec.hpp>

#include <viscor/tables/table_row.hpp>

#include <string>
#include <vector>

namespace viscor::jobs {

/// Checks every row's inputs before any work: complete, within double's range,
/// gravity towards the wall, and values the bead, wall and load accept (a Hertz bead
/// of a material only with alpha = 3/2); errors name the spec and the row. Warns once
/// per value about implausible units.
void check_physical_rows(const table_spec& table, const std::vector<physical_point>& points);

/// The row's law and inputs as table_format::key reads them from the row.
std::string physical_key(const physical_axes& axes, const physical_point& p);

/// The CSV line of one row (without '\n'), computed as `viscor cor` computes the same
/// inputs with certify (and settings.certified_digits when given). Throws
/// certification_error for an uncertified outcome or a rebound certified to fewer
/// than settings.min_digits digits, as compute_row does.
std::string physical_row_line(const physical_axes& axes, const physical_point& p, const table_settings& settings);

}  // namespace viscor::jobs
