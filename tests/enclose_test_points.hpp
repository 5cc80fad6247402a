// Shared by enclose_test, enclose_slow_test and enclose_proof_mutation_test: a
// fixed-seed sample of (gamma, g) for the linear law and the comparison of proofs
// with the closed form.
#pragma once

#include <viscor/enclose/proven_linear.hpp>
#include <viscor/exact/exact_linear.hpp>
#include <viscor/core/real_io.hpp>
#include <viscor/core/real_types.hpp>

#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace viscor::proofs {

struct sample_point {
  std::string gamma, g;  ///< exact decimals
};

/// n points: edges (gamma 0, 2 and the overdamped side at g = 0; pressing and
/// pulling loads), then from std::mt19937_64(seed) 70 % with gamma uniform in
/// [0, 1] and g in [-0.5, 2], 30 % with gamma in [0, 3] and g in [-0.5, 10],
/// written with 6 decimals (exact inputs for both sides).
inline std::vector<sample_point> sample_points(std::size_t n, unsigned seed) {
  std::vector<sample_point> points{{"0", "0"}, {"0", "1"},   {"2", "0"},     {"2.5", "0"}, {"0.000001", "0"},
                                   {"1", "-0.5"}, {"0.05", "10"}, {"0.3", "0.05"}, {"1.5", "0"}};
  std::mt19937_64 random(seed);
  // Mostly where the bead rebounds (gamma < 0.5, g < 1), the rest over the whole box.
  std::uniform_real_distribution<double> coin(0, 1), small_gamma(0, 0.5), gamma(0, 3), small_g(-0.5, 1), g(-0.5, 10);
  auto decimal = [](double x) {
    std::ostringstream s;
    s.setf(std::ios::fixed);
    s.precision(6);
    s << x;
    return s.str();
  };
  while (points.size() < n) {
    const bool near = coin(random) < 0.7;
    const double x = near ? small_gamma(random) : gamma(random), y = near ? small_g(random) : g(random);
    points.push_back({decimal(x), decimal(y)});
  }
  return points;
}

struct comparison {
  int rebounds = 0, sticks = 0, undecided = 0;
  int outside = 0;           ///< an exact value outside its enclosure
  int outcome_mismatch = 0;  ///< a proven outcome the closed form contradicts
  int tight_candidates = 0, tight = 0;
  int least_digits = 1000;
  std::string first_problem;
};

/// The closed form at 2 digits + 20 digits as a ball that also holds its own error
/// (10^-(2 digits + 10): far above the formula's rounding, far below the proof's width).
inline ball closed_form_ball(const mpfr_real& x, int digits) {
  return ball::from_decimal(to_decimal_string(x, 2 * digits + 20))
      .widened(ball::from_decimal("1e-" + std::to_string(2 * digits + 10)));
}

/// Proves every point at `digits` and compares with exact_linear. `options` lets a
/// test make the proof coarse (see enclose_test).
inline comparison check_against_closed_form(const std::vector<sample_point>& points, int digits,
                                            const proof_options& options = {}) {
  comparison c;
  auto problem = [&c](const std::string& what) {
    if (c.first_problem.empty()) c.first_problem = what;
  };
  for (const auto& p : points) {
    const proven_impact proof = prove_linear_impact(p.gamma, p.g, digits, options);
    scoped_precision precision(2 * digits + 20);
    const auto exact = exact_linear(mpfr_real(p.gamma), mpfr_real(p.g));
    scoped_ball_bits bits(working_bits(2 * digits + 20));
    const std::string at = "gamma " + p.gamma + ", g " + p.g + ": ";
    if (proof.outcome == proven_outcome::undecided) {
      ++c.undecided;
      problem(at + "undecided (" + proof.how + ")");
      continue;
    }
    const bool exact_rebounds = exact.outcome == impact_outcome::rebound;
    if ((proof.outcome == proven_outcome::rebound) != exact_rebounds) {
      ++c.outcome_mismatch;
      problem(at + "proof says " + std::string(to_string(proof.outcome)) + ", the closed form the other");
      continue;
    }
    if (!exact_rebounds) {
      ++c.sticks;
      continue;
    }
    ++c.rebounds;
    // An exact ball (radius 0: gamma = 0 gives 1 - e = 0 exactly) is checked against
    // the closed form's own error ball by overlap; any other must contain it whole.
    auto holds = [digits](const ball& enclosure, const mpfr_real& value) {
      const ball truth = closed_form_ball(value, digits);
      return enclosure.rad_double() == 0 ? enclosure.overlaps(truth) : enclosure.contains(truth);
    };
    const bool inside = holds(proof.e, exact.e) && holds(proof.one_minus_e, exact.one_minus_e) &&
                        holds(proof.contact_time, *exact.contact_time);
    if (!inside) {
      ++c.outside;
      problem(at + "exact e " + to_decimal_string(exact.e, digits + 5) + " vs proof " + proof.e.str(digits + 5));
    }
    if (exact.e >= mpfr_real("1e-10")) {
      ++c.tight_candidates;
      const int d = proven_impact::relative_digits(proof.e);
      c.least_digits = std::min(c.least_digits, d);
      if (d >= digits - 10) ++c.tight;
    }
  }
  return c;
}

}  // namespace viscor::proofs
