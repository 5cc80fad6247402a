// viscor scale: physical parameters <-> scaled (gamma, g), eq. (2) of the report.
#include "cli_common.hpp"
#include "command_registry.hpp"

#include <viscor/core/scaling.hpp>

#include <sstream>

namespace viscor::cli {
namespace {

struct scale_command {
  law_options law;
  output_options output;
  std::string m, k, v0, gamma0, gravity = "9.81", force = "0";  // forward
  std::string gamma, g;                                          // inverse
  int digits = 15;

  void run() const {
    const contact_law model = law.resolve();
    if (m.empty() || k.empty() || v0.empty())
      throw invalid_parameter("scale needs the bead: --m, --k and --v0");
    const bool inverse = !gamma.empty() || !g.empty();
    if (inverse && (gamma.empty() || g.empty()))
      throw invalid_parameter("scaled -> physical needs both --gamma and --g");
    if (inverse && !gamma0.empty())
      throw invalid_parameter("give either --gamma0 (physical -> scaled) or --gamma/--g (scaled -> physical)");
    with_working_precision(digits, [&]<class Real>() {
      const Real mass = parse_real<Real>(m, "m"), stiffness = parse_real<Real>(k, "k");
      const Real speed = parse_real<Real>(v0, "v0"), grav = parse_real<Real>(gravity, "gravity");
      json j;
      j["command"] = "scale";
      j["law"] = law_json(model);
      std::ostringstream text;
      text << "law      " << model.describe() << "\n";
      if (inverse) {
        const Real gamma_value = parse_real<Real>(gamma, "gamma"), g_value = parse_real<Real>(g, "g");
        const physical_parameters<Real> p = to_physical(model, gamma_value, g_value, mass, stiffness, speed, grav);
        j["direction"] = "scaled_to_physical";
        j["gamma0"] = number(p.gamma0);
        j["force"] = number(p.force);
        text << "gamma0   " << number(p.gamma0) << "\nF        " << number(p.force) << " N\n";
      } else {
        physical_parameters<Real> p;
        p.m = mass, p.k = stiffness, p.v0 = speed, p.gravity = grav;
        p.gamma0 = gamma0.empty() ? Real(0) : parse_real<Real>(gamma0, "gamma0");
        p.force = parse_real<Real>(force, "F");
        const scaled_parameters<Real> s = to_scaled(model, p);
        j["direction"] = "physical_to_scaled";
        j["gamma"] = number(s.gamma);
        j["g"] = number(s.g);
        j["time_scale"] = number(s.time_scale);
        j["length_scale"] = number(s.length_scale);
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
  app.add_option("--m", cmd->m, "mass, kg");
  app.add_option("--k", cmd->k, "contact stiffness, N/m^alpha");
  app.add_option("--v0", cmd->v0, "impact speed, m/s");
  app.add_option("--gamma0", cmd->gamma0, "physical damping coefficient (physical -> scaled)");
  app.add_option("--gravity", cmd->gravity, "gravitational acceleration towards the wall, m/s^2")->capture_default_str();
  app.add_option("--F", cmd->force, "external force, N (> 0 presses on the wall)")->capture_default_str();
  app.add_option("--gamma", cmd->gamma, "scaled damping (scaled -> physical)");
  app.add_option("--g", cmd->g, "scaled load (scaled -> physical)");
  app.add_option("--digits", cmd->digits, "working precision in decimal digits")->capture_default_str();
  app.callback([cmd] { cmd->run(); });
}

const registration reg{"scale", "convert physical parameters to scaled (gamma, g) and back (eq. 2)", setup};

}  // namespace
}  // namespace viscor::cli
