// Verifying a surrogate against certified values it was not fitted to:
//   draw_verification_points: fixed-seed random points in five strata (bulk,
//     small gamma, near the sticking threshold, large g, g < 0), drawn after the
//     fit (the near-threshold stratum is placed with the fitted gamma_c(g));
//   compare_with_reference: the errors of the targets, overall and per
//     region, and the worst points.
// The certified values come from viscor::certify (via the table machinery of the
// CLI); this header only compares numbers, so it needs no multiprecision.
#pragma once

#include <viscor/core/outcome.hpp>
#include <viscor/surrogate/cor_surrogate.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

namespace viscor::surrogate {

/// A point at which the fit is checked against a certified value.
struct verification_point {
  double gamma = 0, g = 0;
};

/// The shortest decimal text that reads back as exactly x (%.17g).
inline std::string exact_text(double x) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

/// `count` points, a fifth from each stratum, reproducible from `seed` (std::mt19937_64
/// is fully specified by the standard, and the uniform variates are built here from its bits).
inline std::vector<verification_point> draw_verification_points(const cor_surrogate& s, std::size_t count,
                                                                 std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  auto uniform = [&](double a, double b) { return a + (b - a) * static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  auto log_uniform = [&](double a, double b) { return std::exp(uniform(std::log(a), std::log(b))); };
  std::vector<verification_point> points;
  points.reserve(count);
  const double g_top = s.g_max, g_low = std::max(1e-3, s.g_split);
  for (std::size_t i = 0; i < count; ++i) {
    verification_point p;
    switch (i % 5) {
      case 0:  // bulk
        p.gamma = uniform(0, s.gamma_max);
        p.g = uniform(0, 1) < 0.5 ? uniform(s.g_min, 10) : log_uniform(1e-3, g_top);
        break;
      case 1:  // small damping
        p.gamma = log_uniform(1e-12, 1e-2);
        p.g = uniform(0, 1) < 0.2 ? uniform(s.g_min, 0) : log_uniform(1e-3, g_top);
        break;
      case 2:  // near the threshold: relative distance 1e-9 .. 1e-1, three quarters on the rebound side
        for (;;) {
          p.g = log_uniform(g_low, g_top);
          if (p.g <= s.g_split) continue;
          const double d = std::pow(10.0, uniform(-9, -1));
          p.gamma = s.critical_gamma(p.g) * (uniform(0, 1) < 0.75 ? 1 - d : 1 + d);
          if (p.gamma <= s.gamma_max) break;
        }
        break;
      case 3:  // large loads
        p.g = log_uniform(std::min(100.0, g_top / 10), g_top);  // stays inside a smaller domain too
        p.gamma = log_uniform(1e-10, s.gamma_max);
        break;
      default:  // pulling loads
        p.g = uniform(s.g_min, 0);
        p.gamma = uniform(0, s.gamma_max);
        break;
    }
    // Round to the decimal that will be written, so both sides see the same point.
    p.gamma = std::strtod(exact_text(p.gamma).c_str(), nullptr);
    p.g = std::strtod(exact_text(p.g).c_str(), nullptr);
    points.push_back(p);
  }
  return points;
}

/// A certified reference value (from a CoR table row).
struct reference_value {
  double gamma = 0, g = 0;
  impact_outcome outcome = impact_outcome::rebound;
  long double e = 0, one_minus_e = 1;
  int certified_digits = 0;  ///< the row's certified significant digits
};

/// Worst errors over one region.
struct region_errors {
  std::string name;
  std::size_t points = 0;
  double abs_e = 0;             ///< max |e_s - e| over rebounds with e >= 1e-2
  double abs_e_squared = 0;     ///< max |e_s^2 - e^2| (e = 0 for a certified stick)
  double rel_one_minus_e = 0;   ///< max relative error of 1 - e, gamma <= small_gamma and e >= 1e-2
  std::size_t wrong_outcomes = 0;  ///< outside the exempt band around the threshold
  std::size_t exempt = 0;          ///< within relative 1e-10 (in g) of the threshold
  std::size_t outside_domain = 0;
  std::size_t judged_by_absolute_digits = 0;  ///< rebounds below min_certified_digits, still precise enough
  std::size_t left_out = 0;  ///< rebounds whose certified digits cannot decide any check
  reference_value worst_e, worst_e_squared, worst_rel;
};

/// Regions of the README table: all, small gamma, near threshold, large g, g < 0.
inline constexpr std::array<const char*, 5> region_names{"all", "small_gamma", "near_threshold", "large_g", "negative_g"};

/// True if (gamma, g) is within relative `band` in g of the fitted threshold.
inline bool near_threshold_in_g(const cor_surrogate& s, double gamma, double g, double band) {
  if (!(g > s.g_split)) return false;
  const double x = std::log(g), h = 1e-4;
  const double xa = std::max(x - h, std::log(s.g_split)), xb = std::min(x + h, std::log(s.g_max));
  // d ln gamma_c / d ln g (the fitted line holds ln gamma_c + p ln g)
  const double slope = std::abs((s.log_gamma_c(xb) - s.log_gamma_c(xa)) / (xb - xa) - s.threshold_power);
  return std::abs(std::log(gamma / s.critical_gamma(g))) <= band * std::max(slope, 1e-3);
}

/// Which checks a certified row can decide. A row certified to d significant digits
/// (of e and 1 - e) carries an absolute uncertainty of about 10^(1-d) e in e. Rows with
/// d >= min_certified_digits decide every check. Below that (rebounds close to the
/// threshold, where the relative digits of e fall) a check is still decided when the
/// row's uncertainty in the compared quantity is at most 1e-3 of its target: then the
/// measured error is the surrogate's to within 0.1% of the target.
struct applicable_checks {
  bool abs_e = false, abs_e_squared = false, rel_one_minus_e = false;
  bool full = false;  ///< certified to min_certified_digits or more (or a stick)
  /// Whether the row decides any check.
  bool any() const noexcept { return abs_e || abs_e_squared || rel_one_minus_e; }
};

/// Which checks a certified row decides (see applicable_checks).
inline applicable_checks checks_for(const reference_value& r, const surrogate_targets& t, int min_certified_digits) {
  applicable_checks c;
  const bool small_gamma = r.gamma <= t.small_gamma && r.e >= 1e-2L && r.one_minus_e > 0;
  if (r.outcome == impact_outcome::stick || r.certified_digits >= min_certified_digits) {
    c.full = true;
    c.abs_e = r.outcome == impact_outcome::rebound && r.e >= 1e-2L;
    c.abs_e_squared = true;
    c.rel_one_minus_e = small_gamma;
    return c;
  }
  const long double rel = std::pow(10.0L, 1 - r.certified_digits);  // relative uncertainty of e and of 1 - e
  const long double u_e = rel * r.e;
  c.abs_e = r.e >= 1e-2L && u_e <= 1e-3L * t.abs_e;
  c.abs_e_squared = u_e * (2 * r.e + u_e) <= 1e-3L * t.abs_e_squared;
  c.rel_one_minus_e = small_gamma && rel <= 1e-3L * t.rel_one_minus_e;
  return c;
}

/// The worst errors of the surrogate against certified reference values, per region (region_names order).
inline std::vector<region_errors> compare_with_reference(const cor_surrogate& s, const std::vector<reference_value>& refs,
                                                         const surrogate_targets& targets, int min_certified_digits) {
  std::vector<region_errors> regions;
  for (const char* name : region_names) {
    regions.emplace_back();
    regions.back().name = name;
  }
  for (const auto& r : refs) {
    const bool in[5] = {true, r.gamma <= targets.small_gamma, near_threshold_in_g(s, r.gamma, r.g, 0.05),
                        r.g >= 100, r.g < 0};
    const surrogate_value v = s(r.gamma, r.g);
    const bool exempt = near_threshold_in_g(s, r.gamma, r.g, 1e-10);
    const double err_e = std::abs(static_cast<double>(static_cast<long double>(v.e) - r.e));
    const double err_e2 = std::abs(static_cast<double>(static_cast<long double>(v.e) * v.e - r.e * r.e));
    const applicable_checks check = checks_for(r, targets, min_certified_digits);
    double err_rel = 0;
    if (check.rel_one_minus_e)
      err_rel = std::abs(static_cast<double>((static_cast<long double>(v.one_minus_e) - r.one_minus_e) / r.one_minus_e));
    for (std::size_t k = 0; k < regions.size(); ++k) {
      if (!in[k]) continue;
      auto& reg = regions[k];
      ++reg.points;
      if (!v.in_domain) { ++reg.outside_domain; continue; }
      if (exempt) { ++reg.exempt; continue; }
      if (v.outcome != r.outcome) ++reg.wrong_outcomes;  // a certified outcome needs no digits of e
      if (!check.full) {
        if (!check.any()) { ++reg.left_out; continue; }
        ++reg.judged_by_absolute_digits;
      }
      if (check.abs_e && err_e > reg.abs_e) reg.abs_e = err_e, reg.worst_e = r;
      if (check.abs_e_squared && err_e2 > reg.abs_e_squared) reg.abs_e_squared = err_e2, reg.worst_e_squared = r;
      if (err_rel > reg.rel_one_minus_e) reg.rel_one_minus_e = err_rel, reg.worst_rel = r;
    }
  }
  return regions;
}

}  // namespace viscor::surrogate
