// The cor job from C++ (jobs/cor_job.hpp): a request in, a typed result out. The
// numbers are read as numbers (result.e is a double where one is wanted, its exact
// decimals are result.e.decimal()); cor_render.hpp makes the CLI's text and JSON.
// Checked against the closed form of the linear law without load,
// e = exp(-gamma pi / sqrt(4 - gamma^2)).
#include <viscor/viscor.hpp>

#include <cmath>
#include <iostream>
#include <numbers>

int main() {
  viscor::jobs::cor_request q;
  q.law = viscor::law_by_name("linear");
  q.gamma = "0.2", q.g = "0";
  q.certify = true;
  const viscor::jobs::cor_result r = viscor::jobs::run_cor(q);

  const double gamma = 0.2, closed_form = std::exp(-gamma * std::numbers::pi / std::sqrt(4 - gamma * gamma));
  std::cout << "e = " << r.e.decimal() << " (" << r.certified->certified_digits << " certified digits, "
            << r.steps << " steps)\nclosed form " << closed_form << ", 1 - e = " << r.one_minus_e * 1.0 << "\n";
  const bool agrees = std::abs(r.e - closed_form) < 1e-14 && r.outcome == viscor::impact_outcome::rebound &&
                      r.certified->certified_digits >= 12;

  // The same impact in SI: a 2 mm glass bead at 0.5 m/s on a rigid wall under gravity.
  viscor::jobs::cor_request s;
  s.law = viscor::law_by_name("hertz_linear_damping");
  s.physical.youngs_modulus = "70e9", s.physical.poisson_ratio = "0.22", s.physical.radius = "1e-3";
  s.physical.density = "2500", s.physical.gamma0 = "2e-10", s.physical.v0 = "0.5", s.physical.gravity = "9.81";
  const viscor::jobs::cor_result bead = viscor::jobs::run_cor(s);
  std::cout << "bead: e = " << bead.e << ", contact " << *bead.physical->contact_time_s * 1e6 << " us\n";
  const bool bead_ok = bead.e > 0 && bead.e < 1 && *bead.physical->contact_time_s > 0;
  return agrees && bead_ok ? 0 : 1;
}
