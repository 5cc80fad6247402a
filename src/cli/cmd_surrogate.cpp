// viscor surrogate build SPEC.json -o FILE [--threads N] [--resume] [--shard i/N] [--quiet]
// viscor surrogate export --language c -o DIR [--law NAME|all]
//
// Fits, verifies and writes a CoR surrogate (the surrogate build job,
// jobs/surrogate_build.hpp), or writes the committed ones as C99 (the export job,
// jobs/surrogate_export.hpp); docs/surrogate.md has the details.
#include "cli_common.hpp"
#include "command_registry.hpp"
#include "test_hooks.hpp"

#include <viscor/jobs/surrogate_build.hpp>
#include <viscor/jobs/surrogate_export.hpp>
#include <viscor/jobs/surrogate_files.hpp>

namespace viscor::cli::cmd_surrogate {  // named: the subcommands share translation units (unity build)
namespace {

struct build_command {
  surrogate_build_request request;

  void run() {
    request.handle_signals = true;
    request.stop_after_rows = test_hooks::table_stop_after_rows();
    build_surrogate(request);
  }
};

// Parses the options and calls jobs::export_surrogates (the files are written there).
struct export_command {
  std::string language = "c", law = "all", output;
  bool quiet = false;

  void run() const {
    jobs::surrogate_export_options o;
    o.language = language;
    o.laws = {law};
    o.surrogate_directory = jobs::surrogate_directory();
    o.output_directory = output;
    for (const auto& path : jobs::export_surrogates(o))
      if (!quiet) std::cout << path << "\n";
  }
};

void setup(CLI::App& app) {
  app.require_subcommand(1);
  auto build = std::make_shared<build_command>();
  CLI::App* b = app.add_subcommand("build", "fit a CoR surrogate, verify it on certified points, write it");
  b->add_option("spec", build->request.spec_path, "surrogate spec, JSON (docs/surrogate.md)");
  b->add_option("-o,--output", build->request.output, "the surrogate file (with FILE.json and FILE.verification.csv)");
  b->add_flag("--resume", build->request.resume, "continue an interrupted verification table");
  b->add_option("--shard", build->request.shard, "compute only shard i of N of the verification table");
  b->add_option("--threads", build->request.threads, "threads for the verification table")->capture_default_str();
  b->add_flag("--quiet", build->request.quiet, "no progress output");
  b->callback([build] { build->run(); });

  auto exporter = std::make_shared<export_command>();
  CLI::App* x = app.add_subcommand("export", "write the committed surrogates as self-contained C99 (a .h and a .c)");
  x->add_option("--language", exporter->language, "the language of the export (c)")->capture_default_str();
  x->add_option("-o,--output", exporter->output, "the directory to write into (created if absent)")->required();
  x->add_option("--law", exporter->law, "one law's name, or all (one pair for every committed law)")->capture_default_str();
  x->add_flag("--quiet", exporter->quiet, "do not print the paths written");
  x->callback([exporter] { exporter->run(); });
}

const registration reg{"surrogate", "fast certified-by-verification surrogates of e(gamma, g) (docs/surrogate.md)", setup};

}  // namespace
}  // namespace viscor::cli::cmd_surrogate
