// The damping that gives a target CoR (scenes/calibration.hpp), as `viscor
// calibrate` and viscor.calibrate report it: scaled (g -> gamma) or physical (the
// bead, speed and load -> gamma0 by the report's scaling).
//   method "solve" (default): root finding on solve_impact at the working precision.
//   method "surrogate": the inverse of the law's committed surrogate in double
//   (cor_surrogate::gamma_for): about a microsecond; refused for a law without a
//   surrogate, a load outside its domain, or a target outside 0.01 <= e < 1.
#pragma once

#include <viscor/core/field_names.hpp>
#include <viscor/jobs/command_output.hpp>
#include <viscor/jobs/json_fields.hpp>
#include <viscor/jobs/physical_inputs.hpp>
#include <viscor/jobs/surrogate_files.hpp>

#include <viscor/core/contact_law.hpp>
#include <viscor/core/precision.hpp>
#include <viscor/core/real_io.hpp>
#include <viscor/core/scaling.hpp>
#include <viscor/scenes/calibration.hpp>

#include <chrono>
#include <optional>
#include <sstream>
#include <string>

namespace viscor::jobs {

/// A target e with a scaled load g, or with the physical inputs (no gamma0: it is the answer).
struct calibrate_request {
  contact_law law;
  physical_inputs physical;
  std::optional<std::string> target_e, g;
  std::string tolerance = "0";    ///< absolute tolerance on e (0: 1e5 x machine epsilon)
  std::string gamma_max = "100";  ///< largest scaled damping tried
  int digits = 15;                ///< working precision in decimal digits
  std::string method = "solve";   ///< "solve" or "surrogate"
};

namespace detail {

// gamma (and gamma0) from the committed surrogate's inverse, in double.
inline command_output calibrate_by_surrogate(const calibrate_request& q, bool is_physical) {
  const surrogate::cor_surrogate* s = find_surrogate(q.law);
  if (!s || !s->bound.verified())
    throw invalid_parameter("--method surrogate: no surrogate for " + q.law.describe() + " (looked in '" +
                            surrogate_directory() + "'; docs/surrogate.md)");
  const double target = parse_real<double>(*q.target_e, "target_e");
  if (!(target >= 0.01 && target < 1))
    throw invalid_parameter("--method surrogate: --target-e must be in [0.01, 1), got " + *q.target_e);
  double g_value = 0, factor = 0, time_scale_s = 0;
  command_output out;
  json& j = out.object;
  j["command"] = "calibrate";
  j[field::method] = "surrogate";
  j["law"] = law_json(q.law);
  j[field::target_e] = *q.target_e;
  if (is_physical) {
    const physical_parameters<double> in = q.physical.parameters<double>(q.law);
    physical_parameters<double> p = in;
    p.gamma0 = 1;  // gamma / gamma0 is the damping factor of the scaling
    const scaled_parameters<double> scaled = to_scaled(q.law, p);
    g_value = scaled.g, factor = scaled.gamma, time_scale_s = scaled.time_scale;
    j["physical"] = q.physical.echo();
  } else {
    g_value = q.g ? parse_real<double>(*q.g, "g") : 0.0;
  }
  if (!(g_value >= s->g_min && g_value <= s->g_max))
    throw invalid_parameter("--method surrogate: g = " + number(g_value) + " is outside the surrogate's domain (" +
                            number(s->g_min) + " <= g <= " + number(s->g_max) + ")");
  const auto start = std::chrono::steady_clock::now();
  const double gamma = s->gamma_for(target, g_value);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!(gamma == gamma))
    throw invalid_parameter("--method surrogate: no gamma in [0, " + number(s->gamma_max) + "] gives e = " +
                            *q.target_e + " at g = " + number(g_value) + " (the surrogate's domain)");
  const surrogate::surrogate_value v = (*s)(gamma, g_value);
  j["gamma"] = number(gamma);
  j["g"] = number(g_value);
  j[field::e] = number(v.e);
  j["error_bound"] = surrogate_bound_json(*s);
  j["precision"] = scalar_json<double>();
  j[field::seconds] = seconds;
  std::ostringstream text;
  text << "law        " << q.law.describe() << "\n"
       << "target e   " << *q.target_e << "\n";
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
  out.text = text.str();
  return out;
}

// Root finding on solve_impact at the working precision.
inline command_output calibrate_by_solving(const calibrate_request& q, bool is_physical) {
  command_output out;
  with_working_precision(q.digits, [&]<class Real>() {
    calibration_options<Real> options;
    options.tolerance = parse_real<Real>(q.tolerance, "tolerance");
    options.gamma_max = parse_real<Real>(q.gamma_max, "gamma_max");
    const Real target = parse_real<Real>(*q.target_e, "target_e");
    json& j = out.object;
    j["command"] = "calibrate";
    j["law"] = law_json(q.law);
    j[field::target_e] = *q.target_e;
    std::ostringstream text;
    text << "law        " << q.law.describe() << "\n"
         << "target e   " << *q.target_e << "\n";
    const auto start = std::chrono::steady_clock::now();
    calibration_result<Real> r;
    if (is_physical) {
      const physical_parameters<Real> in = q.physical.parameters<Real>(q.law);
      const physical_calibration<Real> p =
          calibrate_gamma0(q.law, in.m, in.k, in.v0, in.gravity, in.force, target, options);
      r = p.scaled;
      j["physical"] = q.physical.echo();
      j["gamma0"] = number(p.gamma0);
      j["time_scale_s"] = number(p.time_scale);
      text << "bead       m = " << number(in.m) << " kg, k = " << number(in.k) << ", v0 = " << number(in.v0)
           << " m/s, gravity = " << number(in.gravity) << " m/s^2, force = " << number(in.force) << " N\n"
           << "gamma0     " << number(p.gamma0) << "\n";
    } else {
      r = calibrate_gamma(q.law, q.g ? parse_real<Real>(*q.g, "g") : Real(0), target, options);
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    j["gamma"] = number(r.gamma);
    j["g"] = number(r.g);
    j[field::e] = number(r.e);
    j[field::target_bound] = number(r.target_bound);
    j[field::gamma_lo] = number(r.gamma_lo);
    j[field::gamma_hi] = number(r.gamma_hi);
    j[field::solves] = r.solves;
    j["precision"] = scalar_json<Real>(q.digits);
    j[field::seconds] = seconds;
    text << "gamma      " << number(r.gamma) << " (scaled)\n"
         << "g          " << number(r.g) << " (scaled load)\n"
         << "e          " << number(r.e) << " at gamma (solve_impact)\n"
         << "|e - tgt|  <= " << to_decimal_string(r.target_bound, 3) << " (miss plus 10 x the solver's estimate)\n"
         << "solves     " << r.solves << "\n"
         << "seconds    " << seconds << " s\n"
         << "digits     " << decimal_digits<Real>() << " (working precision)\n";
    out.text = text.str();
  });
  return out;
}

}  // namespace detail

/// The calibrated damping by the requested method.
inline command_output run_calibrate(calibrate_request q) {
  if (!q.target_e) throw invalid_parameter("calibrate needs --target-e, the CoR to reproduce");
  const bool is_physical = q.physical.given();
  if (is_physical && q.g)
    throw invalid_parameter("give either --g (scaled) or the physical inputs (" + q.physical.given_names() +
                            "), not both");
  if (is_physical) q.physical.check("calibrate");
  if (q.method == "surrogate") return detail::calibrate_by_surrogate(q, is_physical);
  if (q.method != "solve") throw invalid_parameter("--method must be solve or surrogate, got '" + q.method + "'");
  return detail::calibrate_by_solving(q, is_physical);
}

}  // namespace viscor::jobs
