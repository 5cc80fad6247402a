// viscor approx: the report's approximate CoR formulas (the approx job, jobs/approx_job.hpp).
#include "cli_common.hpp"
#include "command_registry.hpp"

#include <viscor/jobs/approx_job.hpp>
#include <viscor/jobs/approx_render.hpp>

namespace viscor::cli::cmd_approx {  // named: the subcommands share translation units (unity build)
namespace {

struct approx_command {
  law_options law;
  output_options output;
  approx_request request;

  void run() {
    request.law = law.resolve();
    const approx_result r = run_approx(request);
    output.emit(render::approx_text(r), render::approx_json(r));
  }
};

void setup(CLI::App& app) {
  auto cmd = std::make_shared<approx_command>();
  cmd->law.add_to(app);
  cmd->output.add_to(app);
  app.add_option("--gamma", cmd->request.gamma, "scaled damping gamma >= 0")->required();
  app.add_option("--g", cmd->request.g, "scaled load g")->capture_default_str();
  app.add_option("--formula", cmd->request.formula,
                 "all, small_g, large_g, schwager_poschel, prop2, prop2_squared, prop2_linearized, or surrogate (double; docs/surrogate.md)")
      ->capture_default_str();
  app.add_option("--source", cmd->request.source, "Prop. 2 coefficients: all, exact_at_zero, numeric or chebyshev_beta")
      ->capture_default_str();
  app.add_option("--order", cmd->request.order, "odd order n of the Chebyshev-Beta approximation, 1 to 999")
      ->capture_default_str()
      ->check(CLI::Range(1, 999));
  app.add_option("--digits", cmd->request.digits, "working precision in decimal digits")->capture_default_str();
  app.callback([cmd] { cmd->run(); });
}

const registration reg{"approx", "the report's approximate CoR formulas (small g, large g, Schwager-Poschel, Prop. 2)",
                       setup};

}  // namespace
}  // namespace viscor::cli::cmd_approx
