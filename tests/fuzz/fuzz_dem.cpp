// Fuzz target: DEM options (viscor dem CODE --damping D --contact C --radius ...):
// the library's readers and conversions behind src/cli/cmd_dem.cpp. One option a
// line: code, damping, contact, radius, density, youngs_modulus (or k),
// poisson_ratio, gravity, force, v0, gamma0. Runs find_dem_model,
// parse_contact_kind, parse_real, the bead's and the contact's checks
// (model_contact) and the scaling to viscor's (gamma, g) in double. Checks beyond
// "no crash": an accepted contact has a positive mass, radius and stiffness, and
// scaled parameters that come out are finite (a value viscor cannot represent must
// be refused, not passed on as inf or NaN).
#include "fuzz_support.hpp"

#include <viscor/core/scaling.hpp>
#include <viscor/dem/dem_calibration.hpp>
#include <viscor/dem/dem_model.hpp>

#include <cmath>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using viscor::fuzz::fuzz_require;
  if (size > 4096) return 0;
  auto lines = viscor::fuzz::lines_of(viscor::fuzz::text_of(data, size));
  lines.resize(12);
  viscor::fuzz::refusal_or_result([&] {
    namespace dem = viscor::dem;
    const dem::dem_model& model = dem::find_dem_model(lines[0], lines[1]);
    dem::dem_impact<double> impact;
    impact.kind = dem::parse_contact_kind(lines[2]);
    impact.bead.radius = viscor::parse_real<double>(lines[3], "radius");
    impact.bead.density = viscor::parse_real<double>(lines[4], "density");
    if (dem::takes_linear_stiffness(model)) {
      impact.stiffness = viscor::parse_real<double>(lines[5], "k");
    } else {
      impact.bead.youngs_modulus = viscor::parse_real<double>(lines[5], "youngs_modulus");
      impact.bead.poisson_ratio = viscor::parse_real<double>(lines[6], "poisson_ratio");
      impact.bead.validate();
    }
    impact.gravity = viscor::parse_real<double>(lines[7], "gravity");
    impact.force = viscor::parse_real<double>(lines[8], "force");
    impact.v0 = viscor::parse_real<double>(lines[9], "v0");
    const double gamma0 = viscor::parse_real<double>(lines[10], "gamma0");
    const auto c = dem::model_contact(model, impact);
    fuzz_require(c.effective_mass > 0 && c.effective_radius > 0 && c.stiffness > 0,
                 "an accepted contact has a mass, radius or stiffness that is not > 0");
    const auto p = dem::physical_impact(c, impact, gamma0);
    const auto s = viscor::to_scaled(dem::law_of(model), p);
    fuzz_require(std::isfinite(s.gamma) && std::isfinite(s.g) && std::isfinite(s.time_scale) &&
                     std::isfinite(s.length_scale),
                 "scaled parameters not finite: gamma = " + std::to_string(s.gamma) + ", g = " + std::to_string(s.g));
  });
  return 0;
}
