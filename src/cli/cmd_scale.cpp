// viscor scale: physical parameters <-> scaled (gamma, g), eq. (2) of the report.
#include "cli_common.hpp"
#include "command_registry.hpp"
#include "physical_options.hpp"

#include <viscor/core/scaling.hpp>

#include <sstream>

namespace viscor::cli::cmd_scale {  // named: the subcommands share translation units (unity build)
namespace {

struct scale_command {
  law_options law;
  output_options output;
  physical_options physical;              // forward: gamma0 -> gamma; always the bead and the load
  std::optional<std::string> gamma, g;    // inverse
  int digits = 15;

  void run() {
    const contact_law model = law.resolve();
    const bool inverse = gamma || g;
    if (inverse && (!gamma || !g)) throw invalid_parameter("scaled -> physical needs both --gamma and --g");
    if (inverse && physical.gamma0)
      throw invalid_parameter("give either --gamma0 (physical -> scaled) or --gamma/--g (scaled -> physical)");
    if (inverse && physical.force)
      throw invalid_parameter("scaled -> physical computes --force from --g; do not give it");
    physical.check("scale");
    with_working_precision(digits, [&]<class Real>() {
      json j;
      j["command"] = "scale";
      j["law"] = law_json(model);
      j["physical"] = physical.echo();
      j["precision"] = scalar_json<Real>();
      std::ostringstream text;
      text << "law      " << model.describe() << "\n";
      if (inverse) {
        const auto [mass, stiffness] = physical.bead<Real>(model);
        const Real speed = parse_real<Real>(*physical.v0, "v0"), grav = parse_real<Real>(*physical.gravity, "gravity");
        const Real gamma_value = parse_real<Real>(*gamma, "gamma"), g_value = parse_real<Real>(*g, "g");
        const physical_parameters<Real> p = to_physical(model, gamma_value, g_value, mass, stiffness, speed, grav);
        j["physical"].erase("force");
        j["direction"] = "scaled_to_physical";
        j["gamma"] = number(gamma_value);
        j["g"] = number(g_value);
        j["gamma0"] = number(p.gamma0);
        j["force"] = number(p.force);
        text << "gamma0   " << number(p.gamma0) << "\nforce    " << number(p.force) << " N\n";
      } else {
        const physical_parameters<Real> p = physical.parameters<Real>(model);
        const scaled_parameters<Real> s = to_scaled(model, p);
        j["direction"] = "physical_to_scaled";
        j["gamma"] = number(s.gamma);
        j["g"] = number(s.g);
        j["time_scale_s"] = number(s.time_scale);
        j["length_scale_m"] = number(s.length_scale);
        text << "gamma    " << number(s.gamma) << "\ng        " << number(s.g) << "\n"
             << "T        " << number(s.time_scale) << " s (time scale)\n"
             << "delta    " << number(s.length_scale) << " m (overlap scale)\n";
      }
      output.emit(text.str(), j);
    });
  }
};

void setup(CLI::App& app) {
  auto cmd = std::make_shared<scale_command>();
  cmd->law.add_to(app);
  cmd->output.add_to(app);
  cmd->physical.add_to(app);
  app.add_option("--gamma", cmd->gamma, "scaled damping (scaled -> physical)");
  app.add_option("--g", cmd->g, "scaled load (scaled -> physical)");
  app.add_option("--digits", cmd->digits, "working precision in decimal digits")->capture_default_str();
  app.callback([cmd] { cmd->run(); });
}

const registration reg{"scale", "convert physical parameters to scaled (gamma, g) and back (eq. 2)", setup};

}  // namespace
}  // namespace viscor::cli::cmd_scale
