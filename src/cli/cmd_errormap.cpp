// viscor errormap: builds the error map of one contact law (the errormap job,
// jobs/errormap_job.hpp) from certified tables or from references solved here.
#include "cli_common.hpp"
#include "command_registry.hpp"

#include <viscor/jobs/errormap_job.hpp>

#include <sstream>

namespace viscor::cli::cmd_errormap {  // named: the subcommands share translation units (unity build)
namespace {

struct errormap_command {
  law_options law;
  errormap_request request;

  void run() {
    request.law = law.resolve();
    request.command = "viscor errormap " + command_line();
    const errormap_summary s = make_error_map(request);
    std::cout << "law        " << request.law.describe() << "\nreference  " << s.reference << " (" << s.points
              << " points)\ncells      " << s.cells << " mapped of " << s.grid << " (" << s.mixed
              << " crossed by the sticking threshold, without bounds)\noutput     " << request.output
              << "\ntime       " << s.seconds << " s\n";
  }

  // The options as given, recorded in the map's metadata.
  std::string command_line() const {
    const errormap_request& q = request;
    std::string s = law.model.empty() ? "--alpha " + law.alpha + " --beta " + law.beta : "--model " + law.model;
    s += " --gamma-edges " + q.gamma_edges + " --g-edges " + q.g_edges;
    for (const auto& t : q.tables) s += " --table " + t;
    if (q.reference_digits)
      s += " --reference-digits " + std::to_string(q.reference_digits) + " --per-interval " +
           std::to_string(q.per_interval);
    std::ostringstream f;
    f << " --safety-factor " << q.safety_factor << " --floor " << q.floor << " -o " << q.output;
    return s + f.str();
  }
};

void setup(CLI::App& app) {
  auto cmd = std::make_shared<errormap_command>();
  errormap_request& q = cmd->request;
  cmd->law.add_to(app);
  app.add_option("--table", q.tables, "certified CoR table(s) with the reference values (reference_data/*.csv)");
  app.add_option("--reference-digits", q.reference_digits,
                 "instead of tables: reference by solve_impact at this many digits (>= 30)");
  app.add_option("--per-interval", q.per_interval, "with --reference-digits: samples per edge interval")
      ->capture_default_str();
  app.add_option("--gamma-edges", q.gamma_edges, "cell edges in gamma, comma-separated exact decimals")->required();
  app.add_option("--g-edges", q.g_edges, "cell edges in g, comma-separated exact decimals")->required();
  app.add_option("--safety-factor", q.safety_factor, "bound = factor x worst sampled error + floor")
      ->capture_default_str();
  app.add_option("--floor", q.floor, "added to every bound (rounding in double)")->capture_default_str();
  app.add_option("--min-samples", q.min_samples, "reference points a cell needs")->capture_default_str();
  app.add_option("-o,--output", q.output, "the map file to write")->check(output_options::regular_output_file());
  app.callback([cmd] { cmd->run(); });
}

const registration reg{"errormap", "build the error map of the approximations for one law", setup};

}  // namespace
}  // namespace viscor::cli::cmd_errormap
