// Physical parameters <-> scaled (gamma, g) by the report's scaling (core/scaling.hpp),
// as `viscor scale` and viscor.scale report it: forward from gamma0 (physical ->
// scaled), or inverse from gamma and g (scaled -> gamma0 and the force).
#pragma once

#include <viscor/jobs/command_output.hpp>
#include <viscor/jobs/json_fields.hpp>
#include <viscor/jobs/physical_inputs.hpp>

#include <viscor/core/contact_law.hpp>
#include <viscor/core/precision.hpp>
#include <viscor/core/real_io.hpp>
#include <viscor/core/scaling.hpp>

#include <optional>
#include <sstream>
#include <string>

namespace viscor::jobs {

/// The bead, speed and load always; gamma0 (forward) or gamma and g (inverse).
struct scale_request {
  contact_law law;
  physical_inputs physical;
  std::optional<std::string> gamma, g;  ///< the inverse direction: both, and no gamma0 or force
  int digits = 15;                      ///< working precision in decimal digits
};

/// The conversion in the direction the inputs ask for.
inline command_output run_scale(scale_request q) {
  const bool inverse = q.gamma || q.g;
  if (inverse && (!q.gamma || !q.g)) throw invalid_parameter("scaled -> physical needs both --gamma and --g");
  if (inverse && q.physical.gamma0)
    throw invalid_parameter("give either --gamma0 (physical -> scaled) or --gamma/--g (scaled -> physical)");
  if (inverse && q.physical.force) throw invalid_parameter("scaled -> physical computes --force from --g; do not give it");
  q.physical.check("scale");
  command_output out;
  with_working_precision(q.digits, [&]<class Real>() {
    json& j = out.object;
    j["command"] = "scale";
    j["law"] = law_json(q.law);
    j["physical"] = q.physical.echo();
    j["precision"] = scalar_json<Real>(q.digits);
    std::ostringstream text;
    text << "law      " << q.law.describe() << "\n";
    if (inverse) {
      const auto [mass, stiffness] = q.physical.bead<Real>(q.law);
      const Real speed = parse_real<Real>(*q.physical.v0, "v0");
      const Real grav = q.physical.acting_gravity<Real>();
      const Real gamma_value = parse_real<Real>(*q.gamma, "gamma"), g_value = parse_real<Real>(*q.g, "g");
      const physical_parameters<Real> p = to_physical(q.law, gamma_value, g_value, mass, stiffness, speed, grav);
      j["physical"].erase("force");
      j["direction"] = "scaled_to_physical";
      j["gamma"] = number(gamma_value);
      j["g"] = number(g_value);
      j["gamma0"] = number(p.gamma0);
      j["force"] = number(p.force);
      text << "gamma0   " << number(p.gamma0) << "\nforce    " << number(p.force) << " N\n";
    } else {
      const physical_parameters<Real> p = q.physical.parameters<Real>(q.law);
      const scaled_parameters<Real> s = to_scaled(q.law, p);
      j["direction"] = "physical_to_scaled";
      j["gamma"] = number(s.gamma);
      j["g"] = number(s.g);
      j["time_scale_s"] = number(s.time_scale);
      j["length_scale_m"] = number(s.length_scale);
      text << "gamma    " << number(s.gamma) << "\ng        " << number(s.g) << "\n"
           << "T        " << number(s.time_scale) << " s (time scale)\n"
           << "delta    " << number(s.length_scale) << " m (overlap scale)\n";
    }
    out.text = text.str();
  });
  return out;
}

}  // namespace viscor::jobs
