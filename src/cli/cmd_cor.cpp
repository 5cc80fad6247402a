// viscor cor: the coefficient of restitution of one impact, integrated to the
// working precision (solve_impact, Taylor method by default). Parameters are
// scaled (--gamma, --g) or physical (--physical m=..,k=..,gamma0=..,v0=..,gravity=..,F=..,
// converted by eq. (2)).
#include "certify_output.hpp"
#include "cli_common.hpp"
#include "command_registry.hpp"

#include <viscor/core/scaling.hpp>
#include <viscor/impact/solve_impact.hpp>

#include <chrono>
#include <map>
#include <sstream>

namespace viscor::cli {
namespace {

// "m=2.05e-3,k=6.97e9,gamma0=0,v0=0.246,gravity=9.8,F=0" -> key/value texts.
std::map<std::string, std::string> parse_assignments(const std::string& text) {
  static const char* const keys[] = {"m", "k", "gamma0", "v0", "gravity", "F"};
  std::map<std::string, std::string> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    const auto eq = item.find('=');
    if (eq == std::string::npos)
      throw invalid_parameter("--physical expects key=value pairs separated by commas, got '" + item + "'");
    const std::string key = item.substr(0, eq);
    bool known = false;
    for (const char* k : keys) known = known || key == k;
    if (!known)
      throw invalid_parameter("--physical: unknown key '" + key + "' (known: m, k, gamma0, v0, gravity, F)");
    if (out.count(key)) throw invalid_parameter("--physical: key '" + key + "' given twice");
    out[key] = item.substr(eq + 1);
  }
  for (const char* k : {"m", "k", "gamma0", "v0"})
    if (!out.count(k)) throw invalid_parameter(std::string("--physical: missing ") + k + "=...");
  return out;
}

struct cor_command {
  law_options law;
  output_options output;
  std::string gamma, g, physical, method = "taylor", tolerance = "0";
  int digits = 15;
  std::size_t max_steps = solve_options<double>{}.max_steps;
  bool certify = false;

  void run() const {
    const contact_law model = law.resolve();
    if (!physical.empty() && (!gamma.empty() || !g.empty()))
      throw invalid_parameter("give either --physical or --gamma/--g, not both");
    if (physical.empty() && gamma.empty())
      throw invalid_parameter("cor needs --gamma (and optionally --g), or --physical m=..,k=..,gamma0=..,v0=..");
    integration_method how;
    if (method == "taylor") {
      how = integration_method::taylor;
    } else if (method == "adaptive") {
      how = integration_method::adaptive;
    } else {
      throw invalid_parameter("parameter method must be 'taylor' or 'adaptive', got '" + method + "'");
    }
    with_working_precision(digits, [&]<class Real>() {
      json j;
      j["command"] = "cor";
      j["law"] = law_json(model);
      std::ostringstream text;
      text << "law        " << model.describe() << "\n";
      Real gamma_value, g_value;
      if (!physical.empty()) {
        const auto kv = parse_assignments(physical);
        auto get = [&](const char* key) {
          const auto it = kv.find(key);
          return it == kv.end() ? Real(0) : parse_real<Real>(it->second, key);
        };
        physical_parameters<Real> p;
        p.m = get("m"), p.k = get("k"), p.gamma0 = get("gamma0"), p.v0 = get("v0");
        p.gravity = get("gravity"), p.force = get("F");
        const scaled_parameters<Real> s = to_scaled(model, p);
        gamma_value = s.gamma, g_value = s.g;
        json phys;
        for (const auto& [key, value] : kv) phys[key] = value;
        j["physical"] = phys;
        j["time_scale"] = number(s.time_scale);
        j["length_scale"] = number(s.length_scale);
        text << "physical   " << physical << "\n";
      } else {
        gamma_value = parse_real<Real>(gamma, "gamma");
        g_value = g.empty() ? Real(0) : parse_real<Real>(g, "g");
      }
      solve_options<Real> options;
      options.method = how;
      options.tolerance = parse_real<Real>(tolerance, "tolerance");
      options.max_steps = max_steps;

      const auto start = std::chrono::steady_clock::now();
      const impact_result<Real> r = solve_impact(model, gamma_value, g_value, options);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

      j["gamma"] = number(gamma_value);
      j["g"] = number(g_value);
      j["precision"] = scalar_json<Real>();
      j["method"] = std::string(to_string(r.method));
      j["e"] = number(r.e);
      j["one_minus_e"] = number(r.one_minus_e);
      j["outcome"] = std::string(to_string(r.outcome));
      j["contact_time"] = number(r.contact_time);
      j["max_compression"] = number(r.max_compression);
      if (r.outcome == impact_outcome::stick) j["stop_overlap"] = number(r.stop_overlap);
      j["time_of_max_compression"] = number(r.time_of_max_compression);
      j["energy_residual"] = number(r.energy_residual);
      j["error_estimate"] = number(r.error_estimate);
      j["steps"] = r.steps;
      j["seconds"] = seconds;

      text << "gamma      " << number(gamma_value) << "\n"
           << "g          " << number(g_value) << "\n"
           << "outcome    " << to_string(r.outcome)
           << (r.outcome == impact_outcome::undecided
                   ? " (rebound or stick cannot be decided at this precision: e = 0 to within the error below)\n"
                   : " (contact ends at zero overlap u = 0)\n")
           << "e          " << number(r.e) << "\n"
           << "1 - e      " << number(r.one_minus_e) << "\n"
           << (r.outcome == impact_outcome::rebound ? "T_f        " : "T_stop     ")
           << (r.outcome == impact_outcome::undecided ? std::string("unknown") : number(r.contact_time)) << "\n"
           << "u_max      " << number(r.max_compression) << " at tau = " << number(r.time_of_max_compression) << "\n"
           << (r.outcome == impact_outcome::stick ? "u_stop     " + number(r.stop_overlap) + " (where u' returns to 0, or the rest position)\n" : std::string())
           << "error      " << to_decimal_string(r.error_estimate, 3) << " (estimated, absolute, on e)\n"
           << "energy     " << to_decimal_string(r.energy_residual, 3) << " (residual of identity (6))\n"
           << "steps      " << r.steps << " (" << to_string(r.method) << ")\n"
           << "time       " << seconds << " s\n"
           << "digits     " << decimal_digits<Real>() << " (working precision)\n";
      if (certify) certify_and_report<Real>(model, gamma_value, g_value, text, j);
      output.emit(text.str(), j);
    });
  }
};

void setup(CLI::App& app) {
  auto cmd = std::make_shared<cor_command>();
  cmd->law.add_to(app);
  cmd->output.add_to(app);
  app.add_option("--gamma", cmd->gamma, "scaled damping gamma >= 0");
  app.add_option("--g", cmd->g, "scaled load g (default 0)");
  app.add_option("--physical", cmd->physical,
                 "physical parameters instead of --gamma/--g: m=..,k=..,gamma0=..,v0=..[,gravity=..][,F=..] (SI)");
  app.add_option("--digits", cmd->digits, "working precision in decimal digits")->capture_default_str();
  app.add_option("--method", cmd->method, "integrator: taylor or adaptive")->capture_default_str();
  app.add_option("--tolerance", cmd->tolerance, "relative tolerance per step (0: working precision)")
      ->capture_default_str();
  app.add_option("--max-steps", cmd->max_steps, "step budget")->capture_default_str();
  app.add_flag("--certify", cmd->certify,
               "certify the digits: Taylor at two precisions and the independent adaptive method must agree");
  app.callback([cmd] { cmd->run(); });
}

const registration reg{"cor", "coefficient of restitution by integration to the working precision", setup};

}  // namespace
}  // namespace viscor::cli
