// viscor errormap: builds the error map of one contact law (error_map_builder.hpp)
// from certified reference tables (--table, reference_table.hpp format), or from
// references computed here by solve_impact (--reference-digits, for laws or
// regions without tables; the map records which).
#include "cli_common.hpp"
#include "command_registry.hpp"

#include <viscor/scenes/error_map_builder.hpp>
#include <viscor/tables/reference_table.hpp>

#include <chrono>
#include <ctime>
#include <sstream>

namespace viscor::cli::cmd_errormap {  // named: the subcommands share translation units (unity build)
namespace {

std::vector<std::string> split_list(const std::string& text, const std::string& name) {
  std::vector<std::string> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) out.push_back(item);
  if (out.size() < 2) throw invalid_parameter("--" + name + " needs at least two comma-separated edges, got '" + text + "'");
  return out;
}

struct errormap_command {
  law_options law;
  std::vector<std::string> tables;
  std::string output, gamma_edges, g_edges;
  int reference_digits = 0, per_interval = 2, min_samples = 4;
  double safety_factor = 4, floor = 1e-14;

  /// The integer options within what their help text promises.
  void refuse_out_of_range() const {
    if (reference_digits != 0 && (reference_digits < 30 || reference_digits > max_working_digits))
      throw invalid_parameter("--reference-digits must be from 30 to " + std::to_string(max_working_digits) +
                              ", got " + std::to_string(reference_digits));
    if (per_interval < 1)
      throw invalid_parameter("--per-interval must be >= 1, got " + std::to_string(per_interval));
    if (min_samples < 1)
      throw invalid_parameter("--min-samples must be >= 1, got " + std::to_string(min_samples));
  }

  void run() const {
    const contact_law model = law.resolve();
    if (output.empty()) throw invalid_parameter("errormap needs -o FILE (e.g. reference_data/error_maps/" +
                                                (model.name.empty() ? std::string("LAW") : model.name) + ".csv)");
    if (tables.empty() == (reference_digits == 0))
      throw invalid_parameter("errormap needs either --table FILE... (certified tables) or --reference-digits N");
    refuse_out_of_range();
    error_map_spec spec;
    spec.gamma_edges = split_list(gamma_edges, "gamma-edges");
    spec.g_edges = split_list(g_edges, "g-edges");
    spec.safety_factor = safety_factor, spec.floor = floor, spec.min_samples = min_samples;

    const auto start = std::chrono::steady_clock::now();
    std::vector<reference_point> points;
    std::string reference;
    if (!tables.empty()) {
      for (const auto& path : tables) {
        const csv_table t = read_table(path);
        if (t.kind != table_kind::cor) throw invalid_parameter("--table " + path + " is not a CoR table");
        const auto& cols = table_columns(table_kind::cor);
        auto col = [&](const char* name) {
          return static_cast<std::size_t>(std::find(cols.begin(), cols.end(), name) - cols.begin());
        };
        for (const auto& row : t.rows) {
          if (row.fields[col("alpha")] != model.alpha.to_string() || row.fields[col("beta")] != model.beta.to_string())
            continue;
          const std::string& e = row.fields[col("e")];
          if (e.empty()) continue;
          reference_point p;
          p.gamma = row.fields[col("gamma")], p.g = row.fields[col("g")], p.e = e;
          p.outcome = row.fields[col("outcome")] == "stick" ? impact_outcome::stick : impact_outcome::rebound;
          points.push_back(p);
        }
        reference += (reference.empty() ? "" : " ") + path;
      }
      reference = "certified tables " + reference;
    } else {
      points = reference_by_solve(model, grid_nodes(spec.gamma_edges, per_interval), grid_nodes(spec.g_edges, per_interval),
                                  reference_digits);
      reference = "solve_impact (Taylor) at " + std::to_string(reference_digits) + " digits on the cell edges with " +
                  std::to_string(per_interval) + " samples per edge interval (not certified)";
    }
    spec.metadata = {{"reference", reference},
                     {"command", "viscor errormap " + command_line()},
                     {"viscor", std::string(VISCOR_VERSION) + " (" + git_commit() + ")"}};
    const error_map map = build_error_map(model, points, spec);
    output_options::write_atomically(output, error_map_text(map));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::size_t mixed = 0;
    for (const auto& c : map.cells()) mixed += c.outcome == cell_outcome::mixed;
    std::cout << "law        " << model.describe() << "\nreference  " << reference << " (" << points.size()
              << " points)\ncells      " << map.cells().size() << " mapped of "
              << (spec.gamma_edges.size() - 1) * (spec.g_edges.size() - 1) << " (" << mixed
              << " crossed by the sticking threshold, without bounds)\noutput     " << output << "\ntime       "
              << seconds << " s\n";
  }

  std::string command_line() const {
    std::string s = law.model.empty() ? "--alpha " + law.alpha + " --beta " + law.beta : "--model " + law.model;
    s += " --gamma-edges " + gamma_edges + " --g-edges " + g_edges;
    for (const auto& t : tables) s += " --table " + t;
    if (reference_digits) s += " --reference-digits " + std::to_string(reference_digits) + " --per-interval " + std::to_string(per_interval);
    std::ostringstream f;
    f << " --safety-factor " << safety_factor << " --floor " << floor << " -o " << output;
    return s + f.str();
  }
};

void setup(CLI::App& app) {
  auto cmd = std::make_shared<errormap_command>();
  cmd->law.add_to(app);
  app.add_option("--table", cmd->tables, "certified CoR table(s) with the reference values (reference_data/*.csv)");
  app.add_option("--reference-digits", cmd->reference_digits,
                 "instead of tables: reference by solve_impact at this many digits (>= 30)");
  app.add_option("--per-interval", cmd->per_interval, "with --reference-digits: samples per edge interval")
      ->capture_default_str();
  app.add_option("--gamma-edges", cmd->gamma_edges, "cell edges in gamma, comma-separated exact decimals")->required();
  app.add_option("--g-edges", cmd->g_edges, "cell edges in g, comma-separated exact decimals")->required();
  app.add_option("--safety-factor", cmd->safety_factor, "bound = factor x worst sampled error + floor")
      ->capture_default_str();
  app.add_option("--floor", cmd->floor, "added to every bound (rounding in double)")->capture_default_str();
  app.add_option("--min-samples", cmd->min_samples, "reference points a cell needs")->capture_default_str();
  app.add_option("-o,--output", cmd->output, "the map file to write")
      ->check(output_options::regular_output_file());
  app.callback([cmd] { cmd->run(); });
}

const registration reg{"errormap", "build the error map of the approximations for one law", setup};

}  // namespace
}  // namespace viscor::cli::cmd_errormap
