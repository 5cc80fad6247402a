// viscor calibrate: the damping that gives a target CoR (the calibrate job,
// jobs/calibrate_job.hpp), scaled (--g) or physical (--m, --k, --v0, --gravity[, --force]).
#include "cli_common.hpp"
#include "command_registry.hpp"
#include "physical_options.hpp"

#include <viscor/jobs/calibrate_job.hpp>
#include <viscor/jobs/calibrate_render.hpp>

namespace viscor::cli::cmd_calibrate {  // named: the subcommands share translation units (unity build)
namespace {

struct calibrate_command {
  law_options law;
  output_options output;
  physical_options physical;
  calibrate_request request;

  void run() {
    request.law = law.resolve();
    request.physical = physical;
    const calibrate_result r = run_calibrate(request);
    output.emit(render::calibrate_text(r), render::calibrate_json(r));
  }
};

void setup(CLI::App& app) {
  auto cmd = std::make_shared<calibrate_command>();
  calibrate_request& q = cmd->request;
  cmd->law.add_to(app);
  cmd->output.add_to(app);
  app.add_option("--target-e", q.target_e, "the CoR to reproduce, 0 < e <= 1");
  app.add_option("--g", q.g, "scaled load (scaled calibration; default 0)");
  cmd->physical.add_to(app, /*with_gamma0=*/false);
  app.add_option("--tolerance", q.tolerance, "absolute tolerance on e (0: 1e5 x machine epsilon)")
      ->capture_default_str();
  app.add_option("--gamma-max", q.gamma_max, "largest scaled damping tried")->capture_default_str();
  app.add_option("--digits", q.digits, "working precision in decimal digits")->capture_default_str();
  app.add_option("--method", q.method,
                 "solve (root finding on the Taylor solve) or surrogate (the committed surrogate's inverse, "
                 "double; docs/surrogate.md)")
      ->capture_default_str();
  app.callback([cmd] { cmd->run(); });
}

const registration reg{"calibrate", "damping (gamma or gamma0) that gives a target CoR", setup};

}  // namespace
}  // namespace viscor::cli::cmd_calibrate
