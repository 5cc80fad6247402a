// viscor formula points|check: regression tests of an outside CoR formula against
// the certified tables (the formula job, jobs/formula_job.hpp; docs/formulas.md).
//   viscor formula points --model LAW [-o FILE]        the points to evaluate (CSV gamma,g)
//   viscor formula check --model LAW --values FILE --tolerance T [--gamma-min ...] [--json] [-o FILE]
// `check` exits 0 when every judged cell passes, 1 when one fails, 2 for bad input
// and when no cell could be judged.
#include "cli_common.hpp"
#include "command_registry.hpp"

#include <viscor/jobs/formula_job.hpp>

#include <sstream>

namespace viscor::cli::cmd_formula {  // named: the subcommands share translation units (unity build)
namespace {

struct points_command {
  law_options law;
  output_options output;
  std::string data;

  void run() const {
    const formula_reference r = committed_formula_reference(law.resolve(), data);
    std::ostringstream csv;
    csv << "# the points of the certified tables of " << r.law.name << " that `viscor formula check` compares at\n"
        << "gamma,g\n";
    json j{{"command", "formula points"}, {"law", law_json(r.law)}, {"points", json::array()}};
    for (const auto& [gamma, g] : distinct_points(r.points)) {
      csv << gamma << ',' << g << '\n';
      j["points"].push_back({{"gamma", gamma}, {"g", g}});
    }
    output.emit(csv.str(), j);
  }
};

struct check_command {
  law_options law;
  output_options output;
  std::string data, values, tolerance;
  std::string gamma_min, gamma_max, g_min, g_max;  // "" when not given: that side is unbounded

  void run() const {
    if (values.empty())
      throw invalid_parameter("formula check needs --values FILE (gamma,g,e or gamma,g,one_minus_e; - for stdin)");
    if (tolerance.empty()) throw invalid_parameter("formula check needs --tolerance, the largest |de| allowed");
    const double tol = formula_tolerance_of(tolerance);
    const formula_region region = formula_region_of(gamma_min, gamma_max, g_min, g_max);
    formula_reference r = committed_formula_reference(law.resolve(), data);
    const formula_values given = read_formula_values(values);
    const std::vector<double> at = values_at_reference(r, given);
    const formula_comparison c = compare_formula_values(r.points, at, given.quantity, r.grid, tol, region);
    // A check that judged nothing is refused as bad input, before any output is written.
    if (!c.judged_any())
      throw invalid_parameter("formula check judged no cell: " + formula_nothing_judged(c, r) + " (" +
                              formula_coverage_text(c) + ")");
    json j = formula_comparison_json(c, r, given.quantity);
    j["command"] = "formula check";
    output.emit(formula_comparison_text(c, r), j);
    if (!c.pass) throw failed_check{};
  }
};

void setup(CLI::App& app) {
  app.require_subcommand(1);
  auto points = std::make_shared<points_command>();
  CLI::App* p = app.add_subcommand("points", "the (gamma, g) points of the certified tables to evaluate a formula at");
  points->law.add_to(*p);
  points->output.add_to(*p);
  p->add_option("--data", points->data, "the data directory (default: as for report)");
  p->callback([points] { points->run(); });

  auto check = std::make_shared<check_command>();
  CLI::App* c = app.add_subcommand("check", "compare a formula's values with the certified e, cell by cell");
  check->law.add_to(*c);
  check->output.add_to(*c);
  c->add_option("--values", check->values, "CSV with the header gamma,g,e (or gamma,g,one_minus_e); - reads stdin");
  c->add_option("--tolerance", check->tolerance, "the largest |de| allowed in every cell, in [0, 1)");
  c->add_option("--gamma-min", check->gamma_min, "check only cells with gamma >= this");
  c->add_option("--gamma-max", check->gamma_max, "check only cells with gamma <= this");
  c->add_option("--g-min", check->g_min, "check only cells with g >= this");
  c->add_option("--g-max", check->g_max, "check only cells with g <= this");
  c->add_option("--data", check->data, "the data directory (default: as for report)");
  c->callback([check] { check->run(); });
}

const registration reg{"formula", "regression tests of your own CoR formula against the certified tables", setup};

}  // namespace
}  // namespace viscor::cli::cmd_formula
