// viscor exact: the closed-form CoR where one exists (gamma = 0; linear law;
// beta = alpha + 1 at g = 0; Tsuji at g = 0).
#include "cli_common.hpp"
#include "command_registry.hpp"

#include <viscor/exact/exact_solutions.hpp>

#include <chrono>
#include <sstream>

namespace viscor::cli::cmd_exact {  // named: the subcommands share translation units (unity build)
namespace {

struct exact_command {
  law_options law;
  output_options output;
  std::string gamma = "0", g = "0";
  int digits = 15;

  void run() const {
    const contact_law model = law.resolve();
    with_working_precision(digits, [&]<class Real>() {
      const Real gamma_value = parse_real<Real>(gamma, "gamma");
      const Real g_value = parse_real<Real>(g, "g");
      const auto start = std::chrono::steady_clock::now();
      const std::optional<exact_result<Real>> r = exact_cor(model, gamma_value, g_value);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

      json j;
      j["command"] = "exact";
      j["law"] = law_json(model);
      j["gamma"] = number(gamma_value), j["g"] = number(g_value);
      j["precision"] = scalar_json<Real>();
      j["exists"] = r.has_value();
      std::ostringstream text;
      text << "law      " << model.describe() << "\ngamma    " << gamma << "\ng        " << g << "\n";
      if (!r) {
        text << "no exact solution is known for these parameters (exact: gamma = 0; alpha = beta = 1;\n"
                "beta = alpha + 1 with g = 0; alpha = 3/2, beta = 5/4 with g = 0). Use 'viscor cor'.\n";
        output.emit(text.str(), j);
        return;
      }
      j["formula"] = r->formula;
      j["e"] = number(r->e);
      j["one_minus_e"] = number(r->one_minus_e);
      j["outcome"] = std::string(to_string(r->outcome));
      if (r->contact_time) j["contact_time"] = number(*r->contact_time);
      if (r->max_compression) j["max_compression"] = number(*r->max_compression);
      if (r->time_of_max_compression) j["time_of_max_compression"] = number(*r->time_of_max_compression);
      j["seconds"] = seconds;
      text << "formula  " << r->formula << "\n"
           << "outcome  " << to_string(r->outcome) << " (contact ends at zero overlap u = 0)\n"
           << "e        " << number(r->e) << "\n"
           << "1 - e    " << number(r->one_minus_e) << "\n";
      if (r->contact_time) text << "T_f      " << number(*r->contact_time) << "\n";
      if (r->max_compression) text << "u_max    " << number(*r->max_compression) << "\n";
      text << "digits   " << decimal_digits<Real>() << " (working precision)\n"
           << "seconds  " << seconds << " s\n";
      output.emit(text.str(), j);
    });
  }
};

void setup(CLI::App& app) {
  auto cmd = std::make_shared<exact_command>();
  cmd->law.add_to(app);
  cmd->output.add_to(app);
  app.add_option("--gamma", cmd->gamma, "scaled damping gamma >= 0")->capture_default_str();
  app.add_option("--g", cmd->g, "scaled load g")->capture_default_str();
  app.add_option("--digits", cmd->digits, "working precision in decimal digits")->capture_default_str();
  app.callback([cmd] { cmd->run(); });
}

const registration reg{"exact", "closed-form CoR where one exists", setup};

}  // namespace
}  // namespace viscor::cli::cmd_exact
