// viscor bench: the speed-accuracy trade of every method, and the committed
// surrogates' evaluation times (the bench jobs, jobs/bench_job.hpp).
#include "cli_common.hpp"
#include "command_registry.hpp"

#include <viscor/jobs/bench_job.hpp>
#include <viscor/jobs/bench_render.hpp>

namespace viscor::cli::cmd_bench {  // named: the subcommands share translation units (unity build)
namespace {

struct bench_command {
  output_options output;
  bench_request request;
  bool surrogate_mode = false;

  void run() const {
    if (surrogate_mode) {
      const surrogate_bench_result r = run_surrogate_bench(request);
      output.emit(render::surrogate_bench_text(r), render::surrogate_bench_json(r));
      return;
    }
    const bench_result r = run_bench(request);
    output.emit(render::bench_text(r), render::bench_json(r));
  }
};

void setup(CLI::App& app) {
  auto cmd = std::make_shared<bench_command>();
  cmd->output.add_to(app);
  app.add_option("--laws", cmd->request.laws, "comma-separated named laws")->capture_default_str();
  app.add_option("--precisions", cmd->request.precisions, "MPFR digits to benchmark (e.g. 30,50,100,200,1000)")
      ->capture_default_str();
  app.add_flag("--certified", cmd->request.certified, "also benchmark certify (double and each MPFR precision)");
  app.add_option("--error-maps", cmd->request.error_maps, "directory of error maps for the evaluate rows");
  app.add_option("--table", cmd->request.table,
                 "certified CoR table holding the point set (default: cor_report_grid.csv of the data directory)");
  app.add_option("--min-time", cmd->request.min_time, "seconds of repetitions per point and method")->capture_default_str();
  app.add_flag("--surrogate", cmd->surrogate_mode,
               "time the committed surrogates per evaluation on random points (median, max, Taylor ratio) instead");
  app.add_option("--points", cmd->request.surrogate_points, "--surrogate: random points per law")->capture_default_str();
  app.add_option("--passes", cmd->request.surrogate_passes, "--surrogate: timings per point")->capture_default_str();
  app.add_option("--taylor-points", cmd->request.taylor_points, "--surrogate: points of each stream solved by Taylor in double")
      ->capture_default_str();
  app.callback([cmd] { cmd->run(); });
}

const registration reg{"bench", "median time per CoR and accuracy of every method", setup};

}  // namespace
}  // namespace viscor::cli::cmd_bench
