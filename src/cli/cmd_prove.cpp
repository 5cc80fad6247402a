// viscor prove: a proven enclosure of e, 1 - e, T_f and u_max in ball arithmetic
// (docs/proofs.md); built when Arb is found (VISCOR_HAS_ARB).
#include "cli_common.hpp"
#include "command_registry.hpp"

#if VISCOR_HAS_ARB
#include <viscor/core/field_names.hpp>
#include <viscor/enclose/enclose.hpp>
#include <viscor/jobs/cor_render.hpp>

#include <algorithm>
#include <sstream>
#include <tuple>

namespace viscor::cli::cmd_prove {  // named: the subcommands share translation units (unity build)
namespace {

struct prove_command {
  law_options law;
  output_options output;
  std::string gamma, g;
  int digits = 30;

  void run() const {
    using namespace viscor::proofs;
    const contact_law model = law.resolve();
    if (gamma.empty()) throw invalid_parameter("--gamma is required");
    if (g.empty()) throw invalid_parameter("--g is required");
    json j;
    j["command"] = "prove";
    j["law"] = law_json(model);
    j["gamma"] = gamma, j["g"] = g;
    j["precision"] = {{"digits", digits}, {"binary_digits", working_bits(digits)}};
    std::ostringstream text;
    text << "law        " << model.describe() << "\ngamma      " << gamma << "\ng          " << g << "\n";
    const cor_enclosure proof = viscor::enclose(model, gamma, g, digits);
    render::add_proof_json(j, proof);
    render::write_proof_text(text, proof);
    const proven_impact& p = proof.balls;
    j[field::outcome] = std::string(to_string(p.outcome));
    j[field::steps] = p.steps;
    if (p.outcome == proven_outcome::rebound) {
      // The value fields hold only proven digits: the exact value correctly rounded
      // to its proven digits (null when none are proven). The ball's midpoint, with
      // more digits than are proven, is named as such (NAME_midpoint); the ball as
      // Arb prints it, with its relative digits + 2 (the printout's own rounding is
      // added to the printed radius, so fewer digits would hide proven ones).
      auto shown = [](const ball& x) { return std::max(10, proven_impact::relative_digits(x) + 2); };
      json enclosure;
      for (const auto& [name, value, bounds] :
           {std::tuple<const char*, const ball*, const proven_bounds*>{field::e, &p.e, &proof.e},
            {field::one_minus_e, &p.one_minus_e, &proof.one_minus_e},
            {field::contact_time, &p.contact_time, proof.contact_time ? &*proof.contact_time : nullptr}}) {
        j[name] = bounds && bounds->proven_digits > 0 ? json(bounds->rounded) : json(nullptr);
        j[std::string(name) + "_midpoint"] = value->mid_str(shown(*value));
        enclosure[name] = value->str(shown(*value));
      }
      j["enclosure"] = enclosure;
    } else if (p.outcome == proven_outcome::stick) {
      j[field::e] = "0", j[field::one_minus_e] = "1";
    }
    text << "steps      " << p.steps << "\n";
    output.emit(text.str(), j);
  }
};

void setup(CLI::App& app) {
  auto cmd = std::make_shared<prove_command>();
  cmd->law.add_to(app);
  cmd->output.add_to(app);
  app.add_option("--gamma", cmd->gamma, "scaled damping gamma >= 0 (an exact decimal)");
  app.add_option("--g", cmd->g, "scaled load g (an exact decimal)");
  app.add_option("--digits", cmd->digits, "decimal digits of the ball arithmetic")->capture_default_str();
  app.callback([cmd] { cmd->run(); });
}

const registration reg{"prove", "proven enclosure of e (ball arithmetic; rational exponents)", setup};

}  // namespace
}  // namespace viscor::cli::cmd_prove
#endif
