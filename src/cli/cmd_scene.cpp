// viscor scene FILE.json: every impact of a scene (scene.hpp) to the scene's
// tolerance, one row per impact (CSV, or JSON with --json or -o OUT.json).
// Output goes to a file only when every impact succeeded (write then rename); the
// work is the scene job's (include/viscor/jobs/scene_job.hpp).
#include "cli_common.hpp"
#include "command_registry.hpp"
#include "physical_options.hpp"

#include <viscor/jobs/scene_file.hpp>
#include <viscor/jobs/scene_job.hpp>

namespace viscor::cli::cmd_scene {  // named: the subcommands share translation units (unity build)
namespace {

struct scene_command {
  output_options output;
  std::string path, maps;
  bool strict = false;

  void run() const {
    const scene_file file = read_scene_json(path);
    check_plausible_scene_units(file.scene, strict, [&](const std::string& field) { return file.locate(field); });
    const scene_result result = run_scene_file(file, path, maps, output.as_json());
    if (output.path.empty()) {
      std::cout << result.body << std::flush;
    } else {
      output_options::write_atomically(output.path, result.body);
      std::cout << result.summary << "output     " << output.path << (output.as_json() ? " (json)" : " (csv)") << "\n";
    }
  }
};

void setup(CLI::App& app) {
  auto cmd = std::make_shared<scene_command>();
  app.add_option("file", cmd->path, "scene file (JSON; format in docs/scenes.md)")->required();
  add_strict_flag(app, cmd->strict);
  cmd->output.add_to(app);
  app.add_option("--error-maps", cmd->maps,
                 "directory of error maps <law>.csv (default: the scene's error_maps, then $VISCOR_ERROR_MAPS, then "
                 "the data directory's error_maps)");
  app.callback([cmd] { cmd->run(); });
}

const registration reg{"scene", "evaluate every impact of a scene file to its tolerance", setup};

}  // namespace
}  // namespace viscor::cli::cmd_scene
