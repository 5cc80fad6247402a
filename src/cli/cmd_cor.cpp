// viscor cor: the coefficient of restitution of one impact (the cor job,
// jobs/cor_job.hpp), scaled (--gamma, --g) or physical (--m --k --gamma0 --v0
// --gravity [--force]); or many points from a file (--points, jobs/point_batch.hpp).
#include "cli_common.hpp"
#include "command_registry.hpp"
#include "physical_options.hpp"

#include <viscor/core/text_fields.hpp>
#include <viscor/jobs/cor_job.hpp>
#include <viscor/jobs/point_batch.hpp>
#include <viscor/jobs/cor_render.hpp>


namespace viscor::cli::cmd_cor {  // named: the subcommands share translation units (unity build)
namespace {

// The spelling before 0.2.0: "--physical m=2.05e-3,k=6.97e9,gamma0=0,v0=0.246,gravity=9.8,F=0".
// Still read, with a warning; its keys go to the same options as --m, --k, ...
void read_deprecated_physical(const std::string& text, physical_options& p) {
  deprecation_warning("--physical m=..,k=..", "--m .. --k .. --gamma0 .. --v0 .. --gravity .. [--force ..]");
  for (const std::string& item : split_fields(text)) {
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
  std::optional<int> certified_digits;
  bool digits_given = false;  // --digits on the command line (not its default)
  unsigned threads = 1;
  std::size_t max_steps = solve_options<double>{}.max_steps;
  bool certify = false, prove = false;

  void run() {
    if (certified_digits && digits_given)
      throw invalid_parameter("give either --digits (the working precision) or --certified-digits (the working "
                              "precision is then chosen), not both");
    if (points) return run_points();
    cor_request q;
    q.law = law.resolve();
    if (deprecated_physical) read_deprecated_physical(*deprecated_physical, physical);
    q.physical = physical;
    q.gamma = gamma, q.g = g;
    q.method = parse_integration_method(method);
    q.tolerance = tolerance, q.max_steps = max_steps, q.digits = digits;
    q.certify = certify, q.prove = prove;
    q.certified_digits = certified_digits;
    const cor_result r = run_cor(q);
    output.emit(render::cor_text(r), render::cor_json(r));
  }

  void run_points() const {
    if (gamma || g || physical.given() || deprecated_physical || !law.model.empty() || !law.alpha.empty() ||
        certify || prove || output.json || !output.path.empty())
      throw invalid_parameter("--points reads the law, gamma, g and digits of every point from its file; give only "
                              "--points, --threads, --method, --tolerance, --max-steps and --digits or "
                              "--certified-digits with it");
    if (threads < 1 || threads > 4096)
      throw invalid_parameter("--threads must be from 1 to 4096, got " + std::to_string(threads));
    point_options o;
    o.method = parse_integration_method(method);
    o.tolerance = tolerance;
    o.max_steps = max_steps;
    o.default_digits = digits;
    o.default_certified_digits = certified_digits;
    o.threads = threads;
    const std::size_t failed = solve_points(*points, o, std::cout);
    if (failed) throw invalid_parameter(std::to_string(failed) + " point(s) of " + *points + " were refused (see their "
                                        "\"error\" lines)");
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
      ->capture_default_str()
      ->each([cmd](const std::string&) { cmd->digits_given = true; });
  app.add_option("--certified-digits", cmd->certified_digits,
                 "at least this many certified digits of e, 1 - e, T_f and u_max: the working precision is chosen "
                 "and raised until they are certified (implies --certify; with --points: the default)");
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
