// viscor exact: the closed-form CoR where one exists (the exact job, jobs/exact_job.hpp).
#include "cli_common.hpp"
#include "command_registry.hpp"

#include <viscor/jobs/exact_job.hpp>
#include <viscor/jobs/exact_render.hpp>

namespace viscor::cli::cmd_exact {  // named: the subcommands share translation units (unity build)
namespace {

struct exact_command {
  law_options law;
  output_options output;
  exact_request request;

  void run() {
    request.law = law.resolve();
    const exact_job_result r = run_exact(request);
    output.emit(render::exact_text(r), render::exact_json(r));
  }
};

void setup(CLI::App& app) {
  auto cmd = std::make_shared<exact_command>();
  cmd->law.add_to(app);
  cmd->output.add_to(app);
  app.add_option("--gamma", cmd->request.gamma, "scaled damping gamma >= 0")->capture_default_str();
  app.add_option("--g", cmd->request.g, "scaled load g")->capture_default_str();
  app.add_option("--digits", cmd->request.digits, "working precision in decimal digits")->capture_default_str();
  app.callback([cmd] { cmd->run(); });
}

const registration reg{"exact", "closed-form CoR where one exists", setup};

}  // namespace
}  // namespace viscor::cli::cmd_exact
