// viscor scale: physical parameters <-> scaled (gamma, g) (the scale job, jobs/scale_job.hpp).
#include "cli_common.hpp"
#include "command_registry.hpp"
#include "physical_options.hpp"

#include <viscor/jobs/scale_job.hpp>
#include <viscor/jobs/scale_render.hpp>

namespace viscor::cli::cmd_scale {  // named: the subcommands share translation units (unity build)
namespace {

struct scale_command {
  law_options law;
  output_options output;
  physical_options physical;  // forward: gamma0 -> gamma; always the bead and the load
  scale_request request;

  void run() {
    request.law = law.resolve();
    request.physical = physical;
    const scale_result r = run_scale(request);
    output.emit(render::scale_text(r), render::scale_json(r));
  }
};

void setup(CLI::App& app) {
  auto cmd = std::make_shared<scale_command>();
  cmd->law.add_to(app);
  cmd->output.add_to(app);
  cmd->physical.add_to(app);
  app.add_option("--gamma", cmd->request.gamma, "scaled damping (scaled -> physical)");
  app.add_option("--g", cmd->request.g, "scaled load (scaled -> physical)");
  app.add_option("--digits", cmd->request.digits, "working precision in decimal digits")->capture_default_str();
  app.callback([cmd] { cmd->run(); });
}

const registration reg{"scale", "convert physical parameters to scaled (gamma, g) and back (eq. 2)", setup};

}  // namespace
}  // namespace viscor::cli::cmd_scale
