// viscor calibrate: the damping that gives a target CoR (calibration.hpp), scaled
// (--g) or physical (--m, --k, --v0, --gravity[, --force] -> gamma0 by eq. 2).
// --method solve (default): root finding on solve_impact at --digits.
// --method surrogate: the inverse of the law's committed surrogate in double
// (cor_surrogate::gamma_for, docs/surrogate.md): about a microsecond; exit 2 for a law
// without a surrogate, a load outside its domain, or a target outside 0.01 <= e < 1.
#include "cli_common.hpp"
#include "command_registry.hpp"
#include "physical_options.hpp"
#include <viscor/jobs/surrogate_files.hpp>

#include <viscor/core/scaling.hpp>
#include <viscor/scenes/calibration.hpp>

#include <chrono>
#include <sstream>

namespace viscor::cli::cmd_calibrate {  // named: the subcommands share translation units (unity build)
namespace {

struct calibrate_command {
  law_options law;
  output_options output;
  physical_options physical;
  std::optional<std::string> target_e, g;
  std::string tolerance = "0", gamma_max = "100";
  int digits = 15;
  std::string method = "solve";

  void run() {
    const contact_law model = law.resolve();
    if (!target_e) throw invalid_parameter("calibrate needs --target-e, the CoR to reproduce");
    const bool is_physical = physical.given();
    if (is_physical && g)
      throw invalid_parameter("give either --g (scaled) or the physical inputs (" + physical.given_names() +
                              "), not both");
    if (is_physical) physical.check("calibrate");
    if (method == "surrogate") return run_surrogate(model, is_physical);
    if (method != "solve") throw invalid_parameter("--method must be solve or surrogate, got '" + method + "'");
    with_working_precision(digits, [&]<class Real>() {
      calibration_options<Real> options;
      options.tolerance = parse_real<Real>(tolerance, "tolerance");
      options.gamma_max = parse_real<Real>(gamma_max, "gamma_max");
      const Real target = parse_real<Real>(*target_e, "target_e");
      json j;
      j["command"] = "calibrate";
      j["law"] = law_json(model);
      j["target_e"] = *target_e;
      std::ostringstream text;
      text << "law        " << model.describe() << "\n"
           << "target e   " << *target_e << "\n";
      const auto start = std::chrono::steady_clock::now();
      calibration_result<Real> r;
      if (is_physical) {
        const physical_parameters<Real> in = physical.parameters<Real>(model);
        const physical_calibration<Real> p =
            calibrate_gamma0(model, in.m, in.k, in.v0, in.gravity, in.force, target, options);
        r = p.scaled;
        j["physical"] = physical.echo();
        j["gamma0"] = number(p.gamma0);
        j["time_scale_s"] = number(p.time_scale);
        text << "bead       m = " << number(in.m) << " kg, k = " << number(in.k) << ", v0 = " << number(in.v0)
             << " m/s, gravity = " << number(in.gravity) << " m/s^2, force = " << number(in.force) << " N\n"
             << "gamma0     " << number(p.gamma0) << "\n";
      } else {
        r = calibrate_gamma(model, g ? parse_real<Real>(*g, "g") : Real(0), target, options);
      }
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      j["gamma"] = number(r.gamma);
      j["g"] = number(r.g);
      j["e"] = number(r.e);
      j["e_error"] = number(r.e_error);
      j["gamma_lo"] = number(r.gamma_lo);
      j["gamma_hi"] = number(r.gamma_hi);
      j["solves"] = r.solves;
      j["precision"] = scalar_json<Real>();
      j["seconds"] = seconds;
      text << "gamma      " << number(r.gamma) << " (scaled)\n"
           << "g          " << number(r.g) << " (scaled load)\n"
           << "e          " << number(r.e) << " at gamma (solve_impact)\n"
           << "|e - tgt|  <= " << to_decimal_string(r.e_error, 3) << " (miss plus 10 x the solver's estimate)\n"
           << "solves     " << r.solves << "\n"
           << "seconds    " << seconds << " s\n"
           << "digits     " << decimal_digits<Real>() << " (working precision)\n";
      output.emit(text.str(), j);
    });
  }

  // gamma (and gamma0) from the committed surrogate's inverse, in double.
  void run_surrogate(const contact_law& model, bool is_physical) {
    const surrogate::cor_surrogate* s = find_surrogate(model);
    if (!s || !s->bound.verified())
      throw invalid_parameter("--method surrogate: no surrogate for " + model.describe() + " (looked in '" +
                              surrogate_directory() + "'; docs/surrogate.md)");
    const double target = parse_real<double>(*target_e, "target_e");
    if (!(target >= 0.01 && target < 1))
      throw invalid_parameter("--method surrogate: --target-e must be in [0.01, 1), got " + *target_e);
    double g_value = 0, factor = 0, time_scale_s = 0;
    json j;
    j["command"] = "calibrate";
    j["method"] = "surrogate";
    j["law"] = law_json(model);
    j["target_e"] = *target_e;
    if (is_physical) {
      const physical_parameters<double> in = physical.parameters<double>(model);
      physical_parameters<double> p = in;
      p.gamma0 = 1;  // gamma / gamma0 is the damping factor of eq. 2
      const scaled_parameters<double> scaled = to_scaled(model, p);
      g_value = scaled.g, factor = scaled.gamma, time_scale_s = scaled.time_scale;
      j["physical"] = physical.echo();
    } else {
      g_value = g ? parse_real<double>(*g, "g") : 0.0;
    }
    if (!(g_value >= s->g_min && g_value <= s->g_max))
      throw invalid_parameter("--method surrogate: g = " + number(g_value) + " is outside the surrogate's domain (" +
                              number(s->g_min) + " <= g <= " + number(s->g_max) + ")");
    const auto start = std::chrono::steady_clock::now();
    const double gamma = s->gamma_for(target, g_value);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!(gamma == gamma))
      throw invalid_parameter("--method surrogate: no gamma in [0, " + number(s->gamma_max) + "] gives e = " +
                              *target_e + " at g = " + number(g_value) + " (the surrogate's domain)");
    const surrogate::surrogate_value v = (*s)(gamma, g_value);
    j["gamma"] = number(gamma);
    j["g"] = number(g_value);
    j["e"] = number(v.e);
    j["error_bound"] = surrogate_bound_json(*s);
    j["precision"] = scalar_json<double>();
    j["seconds"] = seconds;
    std::ostringstream text;
    text << "law        " << model.describe() << "\n"
         << "target e   " << *target_e << "\n";
    if (is_physical) {
      j["gamma0"] = number(gamma / factor);
      j["time_scale_s"] = number(time_scale_s);
      text << "gamma0     " << number(gamma / factor) << "\n";
    }
    text << "gamma      " << number(gamma) << " (scaled; the surrogate's inverse)\n"
         << "g          " << number(g_value) << " (scaled load)\n"
         << "e          " << number(v.e) << " at gamma (surrogate)\n"
         << "bound      |de| <= " << number(s->bound.abs_e) << " where e >= 1e-2 (measured maximum x "
         << number(s->bound.safety_factor) << ", docs/surrogate.md)\n"
         << "seconds    " << seconds << " s\n";
    output.emit(text.str(), j);
  }
};

void setup(CLI::App& app) {
  auto cmd = std::make_shared<calibrate_command>();
  cmd->law.add_to(app);
  cmd->output.add_to(app);
  app.add_option("--target-e", cmd->target_e, "the CoR to reproduce, 0 < e <= 1");
  app.add_option("--g", cmd->g, "scaled load (scaled calibration; default 0)");
  cmd->physical.add_to(app, /*with_gamma0=*/false);
  app.add_option("--tolerance", cmd->tolerance, "absolute tolerance on e (0: 1e5 x machine epsilon)")
      ->capture_default_str();
  app.add_option("--gamma-max", cmd->gamma_max, "largest scaled damping tried")->capture_default_str();
  app.add_option("--digits", cmd->digits, "working precision in decimal digits")->capture_default_str();
  app.add_option("--method", cmd->method,
                 "solve (root finding on the Taylor solve) or surrogate (the committed surrogate's inverse, "
                 "double; docs/surrogate.md)")
      ->capture_default_str();
  app.callback([cmd] { cmd->run(); });
}

const registration reg{"calibrate", "damping (gamma or gamma0) that gives a target CoR", setup};

}  // namespace
}  // namespace viscor::cli::cmd_calibrate
