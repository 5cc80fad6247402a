// The rows of a table from a spec in SI (include/viscor/jobs/physical_table.hpp).
#include <viscor/jobs/physical_table.hpp>

#include <viscor/jobs/calibrate_job.hpp>
#include <viscor/jobs/cor_job.hpp>
#include <viscor/jobs/table_format.hpp>

#include <cstdlib>
#include <string>
#include <vector>

namespace viscor::jobs {

namespace {

// The row's inputs in the order of physical_columns() (empty: not given; gamma0 of a
// row with a target is its result, filled in by physical_row_line).
std::vector<std::string> input_fields(const physical_axes& axes, const physical_point& p) {
  const physical_inputs& in = p.inputs;
  const auto text = [](const std::optional<std::string>& v) { return v ? *v : std::string(); };
  return {axes.beads[p.bead].name,
          text(in.m),
          text(in.k),
          text(in.youngs_modulus),
          text(in.poisson_ratio),
          text(in.radius),
          text(in.density),
          axes.contact,
          axes.contact == "pair" ? std::string("none") : axes.walls[p.wall].name,
          text(in.wall_youngs_modulus),
          text(in.wall_poisson_ratio),
          text(in.other_youngs_modulus),
          text(in.other_poisson_ratio),
          text(in.other_radius),
          text(in.other_density),
          *in.v0,
          text(in.gamma0),
          text(p.target_e),
          *in.gravity,
          *in.force};
}

std::string joined(const std::vector<std::string>& fields) {
  std::string s;
  for (const auto& f : fields) s += (s.empty() ? "" : ",") + f;
  return s;
}

// "row 7 (tsuji, bead steel, wall rigid, gravity = 9.81, force = 0, gamma0 = 1e-3, v0 = 0.5)", for messages.
std::string describe(const physical_axes& axes, const physical_point& p) {
  const physical_inputs& in = p.inputs;
  return "row " + std::to_string(p.index) + " (" + p.law.describe() + ", bead " + axes.beads[p.bead].name +
         (axes.contact == "pair" ? std::string(", pair") : ", wall " + axes.walls[p.wall].name) +
         ", gravity = " + *in.gravity + ", force = " + *in.force +
         (p.target_e ? ", target_e = " + *p.target_e : ", gamma0 = " + *in.gamma0) + ", v0 = " + *in.v0 + ")";
}

// x rounded to the row's certified digits; empty when unknown or uncertified.
std::string certified_text(const std::optional<working_number>& x, int digits) {
  if (!x || digits < 1 || x->is_nan()) return "";
  return rounded_decimal(*x, digits);
}

}  // namespace

void check_physical_rows(const table_spec& table, const std::vector<physical_point>& points) {
  const physical_axes& axes = *table.physical;
  check_plausible_physical_units(axes, expand(axes), table.grid.source);
  for (const physical_point& p : points) {
    if (p.target_e) {  // the CoR a damping can give: 0 < e < 1
      const double target = std::strtod(p.target_e->c_str(), nullptr);
      if (!(target > 0 && target < 1))
        throw invalid_parameter(table.grid.source + ": field target_e: must be in (0, 1), got " + *p.target_e);
    }
    try {
      p.inputs.check_complete("table");
      require_gravity_towards_wall(p.inputs.gravity);
      p.inputs.require_double_range();
      (void)p.inputs.parameters<double>(p.law);  // the bead, wall and load accept these values
    } catch (const invalid_parameter& e) {
      throw invalid_parameter(table.grid.source + ": " + describe(axes, p) + ": " + e.marked());
    }
  }
}

std::string physical_key(const physical_axes& axes, const physical_point& p) {
  return p.law.name + "," + p.law.alpha.to_string() + "," + p.law.beta.to_string() + "," +
         joined(input_fields(axes, p));
}

std::string physical_row_line(const physical_axes& axes, const physical_point& p, const table_settings& settings) {
  cor_request q;
  q.law = p.law;
  q.physical = p.inputs;
  if (p.target_e) {  // the damping first, as viscor calibrate finds it at the working precision
    calibrate_request c;
    c.law = p.law;
    c.physical = p.inputs;
    c.target_e = p.target_e;
    c.digits = settings.digits;
    try {
      q.physical.gamma0 = run_calibrate(c).gamma0->decimal();
    } catch (const error& e) {
      throw certification_error(describe(axes, p) + ": " + e.marked());
    }
  }
  q.certify = true;
  if (settings.certified_digits > 0) q.certified_digits = settings.certified_digits;
  else q.digits = settings.digits;
  cor_result r;
  try {
    r = run_cor(q);
  } catch (const certified_digits_unreached& e) {
    throw certification_error(describe(axes, p) + ": " + e.marked());
  }
  const certified_result<working_number>& c = *r.certified;
  if (!c.outcome_certified)
    throw certification_error(describe(axes, p) + ": the methods disagree on the outcome (rebound or stick)");
  if (c.outcome == impact_outcome::rebound && (c.certified_digits < 1 || c.certified_digits < settings.min_digits))
    throw certification_error(describe(axes, p) + ": certified to " + std::to_string(c.certified_digits) +
                              " digits only (min_digits = " + std::to_string(settings.min_digits) +
                              "); raise the working digits");
  point_result<working_number> certified;
  certified.outcome = c.outcome;
  certified.e = c.e, certified.one_minus_e = c.one_minus_e;
  certified.contact_time = c.contact_time, certified.max_compression = c.max_compression;
  certified.certified_digits = c.certified_digits;
  certified.source = row_source::certified;
  // The scaled inputs in the digits that give back the working value: the row's point.
  const table_row row = make_row(grid_point{p.index, p.law, r.gamma.decimal(), r.g.decimal()}, certified);
  const physical_side& si = *r.physical;
  std::vector<std::string> inputs = input_fields(axes, p);
  inputs[physical_gamma0_column] = *q.physical.gamma0;
  return csv_line(row) + "," + joined(inputs) + "," +
         certified_text(si.certified_contact_time_s, c.certified_digits) + "," +
         certified_text(si.certified_max_compression_m, c.certified_digits);
}

}  // namespace viscor::jobs
