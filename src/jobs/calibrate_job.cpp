// `viscor calibrate` (include/viscor/jobs/calibrate_job.hpp), compiled once.
#include <viscor/jobs/calibrate_job.hpp>

#include <viscor/jobs/surrogate_files.hpp>
#include <viscor/core/precision.hpp>
#include <viscor/core/real_io.hpp>
#include <viscor/core/scaling.hpp>
#include <viscor/scenes/calibration.hpp>

#include <chrono>

namespace viscor::jobs {

namespace detail {

// gamma (and gamma0) from the committed surrogate's inverse, in double.
inline calibrate_result calibrate_by_surrogate(const calibrate_request& q, bool is_physical) {
  const surrogate::cor_surrogate* s = find_surrogate(q.law);
  if (!s || !s->bound.verified())
    throw invalid_parameter(VISCOR_FIELD("method")
                            " surrogate: no surrogate for " + q.law.describe() + " (looked in '" +
                            surrogate_directory() + "'; docs/surrogate.md)");
  const double target = parse_real<double>(*q.target_e, "target_e");
  if (!(target >= 0.01 && target < 1))
    throw invalid_parameter(VISCOR_FIELD("method") " surrogate: " VISCOR_FIELD("target_e")
                            " must be in [0.01, 1), got " + *q.target_e);
  double g_value = 0, factor = 0, time_scale_s = 0;
  if (is_physical) {
    const physical_parameters<double> in = q.physical.parameters<double>(q.law);
    physical_parameters<double> p = in;
    p.gamma0 = 1;  // gamma / gamma0 is the damping factor of the scaling
    const scaled_parameters<double> scaled = to_scaled(q.law, p);
    g_value = scaled.g, factor = scaled.gamma, time_scale_s = scaled.time_scale;
  } else {
    g_value = q.g ? parse_real<double>(*q.g, "g") : 0.0;
  }
  if (!(g_value >= s->g_min && g_value <= s->g_max))
    throw invalid_parameter(VISCOR_FIELD("method")
                            " surrogate: g = " + to_decimal_string(g_value) + " is outside the surrogate's domain (" +
                            to_decimal_string(s->g_min) + " <= g <= " + to_decimal_string(s->g_max) + ")");
  const auto start = std::chrono::steady_clock::now();
  const double gamma = s->gamma_for(target, g_value);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!(gamma == gamma))
    throw invalid_parameter(VISCOR_FIELD("method")
                            " surrogate: no gamma in [0, " + to_decimal_string(s->gamma_max) + "] gives e = " +
                            *q.target_e + " at g = " + to_decimal_string(g_value) + " (the surrogate's domain)");
  calibrate_result out;
  out.law = q.law;
  out.target_e = *q.target_e;
  out.by_surrogate = true;
  if (is_physical) {
    out.physical = q.physical;
    out.gamma0 = gamma / factor, out.time_scale = time_scale_s;
  }
  out.gamma = gamma, out.g = g_value, out.e = (*s)(gamma, g_value).e;
  out.bound = s->bound;
  out.precision = precision_used::of<double>();
  out.seconds = seconds;
  return out;
}

// Root finding on solve_impact at the working precision.
inline calibrate_result calibrate_by_solving(const calibrate_request& q, bool is_physical) {
  return with_working_precision(q.digits, [&]<class Real>() {
    calibration_options<Real> options;
    options.tolerance = parse_real<Real>(q.tolerance, "tolerance");
    options.gamma_max = parse_real<Real>(q.gamma_max, "gamma_max");
    const Real target = parse_real<Real>(*q.target_e, "target_e");
    calibrate_result out;
    out.law = q.law;
    out.target_e = *q.target_e;
    const auto start = std::chrono::steady_clock::now();
    calibration_result<Real> r;
    if (is_physical) {
      const physical_parameters<Real> in = q.physical.parameters<Real>(q.law);
      const physical_calibration<Real> p =
          calibrate_gamma0(q.law, in.m, in.k, in.v0, in.gravity, in.force, target, options);
      r = p.scaled;
      out.physical = q.physical;
      out.gamma0 = working_number::of(p.gamma0), out.time_scale = working_number::of(p.time_scale);
      out.m = working_number::of(in.m), out.k = working_number::of(in.k), out.v0 = working_number::of(in.v0);
      out.gravity = working_number::of(in.gravity), out.force = working_number::of(in.force);
    } else {
      r = calibrate_gamma(q.law, q.g ? parse_real<Real>(*q.g, "g") : Real(0), target, options);
    }
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    out.gamma = working_number::of(r.gamma), out.g = working_number::of(r.g), out.e = working_number::of(r.e);
    out.target_bound = working_number::of(r.target_bound);
    out.gamma_lo = working_number::of(r.gamma_lo), out.gamma_hi = working_number::of(r.gamma_hi);
    out.solves = r.solves;
    out.precision = precision_used::of<Real>(q.digits);
    return out;
  });
}

}  // namespace detail

calibrate_result run_calibrate(calibrate_request q) {
  if (!q.target_e) throw invalid_parameter("calibrate needs " VISCOR_FIELD("target_e") ", the CoR to reproduce");
  const bool is_physical = q.physical.given();
  if (is_physical && q.g)
    throw invalid_parameter("give either " VISCOR_FIELD("g")
                            " (scaled) or the physical inputs (" + q.physical.given_names() +
                            "), not both");
  if (is_physical) q.physical.check("calibrate");
  if (q.method == "surrogate") return detail::calibrate_by_surrogate(q, is_physical);
  if (q.method != "solve") throw invalid_parameter(VISCOR_FIELD("method")
                  " must be solve or surrogate, got '" + q.method + "'");
  return detail::calibrate_by_solving(q, is_physical);
}

}  // namespace viscor::jobs
