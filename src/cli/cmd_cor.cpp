// viscor cor: the coefficient of restitution of one impact, integrated to the
// working precision (solve_impact, Taylor method by default). Parameters are
// scaled (--gamma, --g) or physical (--m --k --gamma0 --v0 --gravity [--force],
// converted by eq. (2)); or many points from a file (--points, jobs/point_batch.hpp).
#include <viscor/jobs/certify_report.hpp>
#include "cli_common.hpp"
#include "command_registry.hpp"
#include <viscor/jobs/point_batch.hpp>
#include "physical_options.hpp"

#include <viscor/core/scaling.hpp>
#include <viscor/impact/solve_impact.hpp>

#if VISCOR_HAS_ARB
#include <viscor/jobs/proof_report.hpp>
#endif

#include <chrono>
#include <map>
#include <sstream>

namespace viscor::cli::cmd_cor {  // named: the subcommands share translation units (unity build)
namespace {

// The spelling before 0.2.0: "--physical m=2.05e-3,k=6.97e9,gamma0=0,v0=0.246,gravity=9.8,F=0".
// Still read, with a warning; its keys go to the same options as --m, --k, ...
void read_deprecated_physical(const std::string& text, physical_options& p) {
  deprecation_warning("--physical m=..,k=..", "--m .. --k .. --gamma0 .. --v0 .. --gravity .. [--force ..]");
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    const auto eq = item.find('=');
    if (eq == std::string::npos)
      throw invalid_parameter("--physical expects key=value pairs separated by commas, got '" + item + "'");
    const std::string key = item.substr(0, eq), value = item.substr(eq + 1);
    std::optional<std::string>* slot = key == "m"        ? &p.m
                                       : key == "k"      ? &p.k
                                       : key == "gamma0" ? &p.gamma0
                                       : key == "v0"     ? &p.v0
                                       : key == "gravity" ? &p.gravity
                                       : key == "F" || key == "force" ? &p.force
                                                                      : nullptr;
    if (!slot) throw invalid_parameter("--physical: unknown key '" + key + "' (known: m, k, gamma0, v0, gravity, force)");
    if (*slot) throw invalid_parameter("--physical: key '" + key + "' given twice (or also as --" + key + ")");
    *slot = value;
  }
}

struct cor_command {
  law_options law;
  output_options output;
  physical_options physical;
  std::optional<std::string> gamma, g, deprecated_physical, points;
  std::string method = "taylor", tolerance = "0";
  int digits = 15;
  unsigned threads = 1;
  std::size_t max_steps = solve_options<double>{}.max_steps;
  bool certify = false, prove = false;

  /// --prove needs exact decimal inputs and rational exponents: checked before any work.
  void check_provable(const contact_law& model, bool is_physical) const {
    if (is_physical)
      throw invalid_parameter("--prove needs the scaled --gamma and --g (exact decimals), not physical inputs");
    for (const auto& [name, x] : {std::pair<const char*, const exponent*>{"alpha", &model.alpha}, {"beta", &model.beta}})
      if (!x->is_rational())
        throw invalid_parameter("not provable: exponent " + std::string(name) + " = " + x->to_string() +
                                " is not rational (the proof needs u = s^Q at the end points)");
#if !VISCOR_HAS_ARB
    throw invalid_parameter("--prove: this viscor was built without Arb (apt-get install libflint-arb-dev)");
#endif
  }

  void run() {
    if (points) return run_points();
    const contact_law model = law.resolve();
    if (deprecated_physical) read_deprecated_physical(*deprecated_physical, physical);
    const bool is_physical = physical.given();
    if (is_physical && (gamma || g))
      throw invalid_parameter("give either the physical inputs (" + physical.given_names() +
                              ") or the scaled --gamma/--g, not both");
    if (!is_physical && !gamma)
      throw invalid_parameter("cor needs --gamma (and optionally --g), or the physical inputs --m --k --gamma0 --v0 "
                              "--gravity [--force], or --points FILE");
    if (is_physical) {
      physical.check("cor");
      if (!physical.gamma0) throw invalid_parameter("cor: physical mode needs --gamma0 (the damping coefficient, SI)");
    }
    if (prove) check_provable(model, is_physical);
    const integration_method how = parse_method(method);
    with_working_precision(digits, [&]<class Real>() {
      json j;
      j["command"] = "cor";
      j["law"] = law_json(model);
      std::ostringstream text;
      text << "law        " << model.describe() << "\n";
      Real gamma_value, g_value;
      std::optional<scaled_parameters<Real>> scales;
      if (is_physical) {
        const physical_parameters<Real> p = physical.parameters<Real>(model);
        scales = to_scaled(model, p);
        gamma_value = scales->gamma, g_value = scales->g;
        j["physical"] = physical.echo();
        j["time_scale_s"] = number(scales->time_scale);
        j["length_scale_m"] = number(scales->length_scale);
        text << "physical   " << physical.echo_text() << "\n";
        if (physical.has_material())  // the bead's mass and stiffness are computed, not typed
          text << "bead       m = " << to_decimal_string(p.m, 10) << " kg, k = " << to_decimal_string(p.k, 10)
               << " N/m^(3/2) (from the material)\n";
      } else {
        gamma_value = parse_real<Real>(*gamma, "gamma");
        g_value = g ? parse_real<Real>(*g, "g") : Real(0);
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
      add_result_json(j, r, seconds);
      if (scales) {
        j["contact_time_s"] = number(Real(r.contact_time * scales->time_scale));
        j["max_compression_m"] = number(Real(r.max_compression * scales->length_scale));
      }

      text << "gamma      " << number(gamma_value) << "\n"
           << "g          " << number(g_value) << "\n"
           << "outcome    " << to_string(r.outcome)
           << (r.outcome == impact_outcome::undecided
                   ? " (rebound or stick cannot be decided at this precision: e = 0 to within the error below)\n"
                   : " (contact ends at zero overlap u = 0)\n")
           << "e          " << number(r.e) << "\n"
           << "1 - e      " << number(r.one_minus_e) << "\n"
           << (r.outcome == impact_outcome::rebound ? "T_f        " : "T_stop     ")
           << (r.outcome == impact_outcome::undecided ? std::string("unknown") : number(r.contact_time))
           << " (scaled)\n";
      if (scales && r.outcome != impact_outcome::undecided)
        text << "time       " << number(Real(r.contact_time * scales->time_scale)) << " s (contact)\n";
      text << "u_max      " << number(r.max_compression) << " at tau = " << number(r.time_of_max_compression) << "\n"
           << (r.outcome == impact_outcome::stick ? "u_stop     " + number(r.stop_overlap) + " (where u' returns to 0, or the rest position)\n" : std::string())
           << "error      " << to_decimal_string(r.error_estimate, 3) << " (estimated, absolute, on e)\n"
           << "energy     " << to_decimal_string(r.energy_residual, 3) << " (residual of identity (6))\n"
           << "steps      " << r.steps << " (" << to_string(r.method) << ")\n"
           << "seconds    " << seconds << " s\n"
           << "digits     " << decimal_digits<Real>() << " (working precision)\n";
      if (certify) certify_and_report<Real>(model, gamma_value, g_value, text, j);
#if VISCOR_HAS_ARB
      if (prove) add_proof(model, *gamma, g ? *g : std::string("0"), digits, text, j);
#endif
      output.emit(text.str(), j);
    });
  }

  void run_points() const {
    if (gamma || g || physical.given() || deprecated_physical || !law.model.empty() || !law.alpha.empty() ||
        certify || prove || output.json || !output.path.empty())
      throw invalid_parameter("--points reads the law, gamma, g and digits of every point from its file; give only "
                              "--points, --threads, --method, --tolerance and --max-steps with it");
    if (threads < 1 || threads > 4096)
      throw invalid_parameter("--threads must be from 1 to 4096, got " + std::to_string(threads));
    point_options o;
    o.method = parse_method(method);
    o.tolerance = tolerance;
    o.max_steps = max_steps;
    o.default_digits = digits;
    o.threads = threads;
    const std::size_t failed = solve_points(*points, o, std::cout);
    if (failed) throw invalid_parameter(std::to_string(failed) + " point(s) of " + *points + " were refused (see their "
                                        "\"error\" lines)");
  }

  static integration_method parse_method(const std::string& method) {
    if (method == "taylor") return integration_method::taylor;
    if (method == "adaptive") return integration_method::adaptive;
    throw invalid_parameter("--method must be 'taylor' or 'adaptive', got '" + method + "'");
  }
};

void setup(CLI::App& app) {
  auto cmd = std::make_shared<cor_command>();
  cmd->law.add_to(app);
  cmd->output.add_to(app);
  app.add_option("--gamma", cmd->gamma, "scaled damping gamma >= 0");
  app.add_option("--g", cmd->g, "scaled load g (default 0)");
  cmd->physical.add_to(app);
  app.add_option("--physical", cmd->deprecated_physical, "deprecated: use --m --k --gamma0 --v0 --gravity --force")
      ->group("");
  app.add_option("--points", cmd->points,
                 "batch: one point per line of FILE (- for standard input), CSV with a header or JSON lines with "
                 "law (or alpha, beta), gamma, g and optional digits; one JSON result per line");
  app.add_option("--threads", cmd->threads, "with --points: worker threads")->capture_default_str();
  app.add_option("--digits", cmd->digits, "working precision in decimal digits (with --points: the default)")
      ->capture_default_str();
  app.add_option("--method", cmd->method, "integrator: taylor or adaptive")->capture_default_str();
  app.add_option("--tolerance", cmd->tolerance, "relative tolerance per step (0: working precision)")
      ->capture_default_str();
  app.add_option("--max-steps", cmd->max_steps, "step budget, >= 1")
      ->capture_default_str()
      ->check(CLI::Range(1.0, 1e12));
  app.add_flag("--certify", cmd->certify,
               "certify the digits: Taylor at two precisions and the independent adaptive method must agree "
               "(the linear law: its closed form at two precisions)");
  app.add_flag("--prove", cmd->prove,
               "also prove the digits: enclosures of e, 1 - e, T_f and u_max in ball arithmetic at --digits "
               "(rational exponents; docs/proofs.md)");
  app.callback([cmd] { cmd->run(); });
}

const registration reg{"cor", "coefficient of restitution by integration to the working precision", setup};

}  // namespace
}  // namespace viscor::cli::cmd_cor
