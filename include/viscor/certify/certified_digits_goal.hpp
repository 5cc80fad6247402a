// The working precision for a number of certified digits asked for (`--certified-digits
// N`, `certified_digits=N`). certify keeps the digits on which independent
// computations agree, less its safety margin, so N certified digits need N + margin
// working digits at least. The fixed-width types (double to float128) agree to their
// full width; MPFR runs agree to one digit less than their precision at about half of
// the points measured (10 to 105 digits, docs/performance.md "Certified digits"), so
// an MPFR precision starts one digit higher. A run that falls short (the outcome
// decided late, next to the sticking threshold) is repeated at a precision raised by
// the shortfall, as Arb's precision loops do, at most max_precision_runs times.
#pragma once

#include <viscor/core/exceptions.hpp>
#include <viscor/core/precision.hpp>

#include <algorithm>
#include <string>
#include <vector>

namespace viscor {

/// One run towards the goal: the precision it worked at and the digits it certified.
struct precision_run {
  int working_digits = 0;
  int certified_digits = 0;
};

/// A goal of certified digits and the runs made for it, in order (the last one met it).
struct certified_digits_goal {
  int certified_digits = 0;          ///< asked for
  std::vector<precision_run> runs;   ///< each run's precision and result
};

/// The goal was not met within max_precision_runs runs: `best` says how many digits
/// could be certified, and at which precision.
struct certified_digits_unreached : certification_error {
  /// `message` says what `goal` and `best` hold.
  certified_digits_unreached(const std::string& message, certified_digits_goal goal, precision_run best)
      : certification_error(message), goal(std::move(goal)), best(best) {}
  certified_digits_goal goal;  ///< the goal and every run made for it
  precision_run best;          ///< the run that certified the most digits
};

/// The digits certify subtracts from the agreement of its computations
/// (certify_options::safety_margin's default).
inline constexpr int default_safety_margin = 2;

/// How many runs a goal may take before it is refused.
inline constexpr int max_precision_runs = 4;

/// The precision of the first run for `wanted` certified digits (`margin`: certify's
/// safety margin).
inline int first_working_digits(int wanted, int margin = default_safety_margin) {
  const int digits = wanted + margin;
  return scalar_for_digits(digits) == scalar_kind::mpfr ? digits + 1 : digits;
}

/// The precision of the run after one that certified `got` < `wanted` digits at
/// `working` digits: raised by the shortfall and one more, at most doubled.
inline int next_working_digits(int wanted, const precision_run& last) {
  const int raised = last.working_digits + (wanted - last.certified_digits) + 1;
  return std::min(raised, 2 * last.working_digits);
}

/// Runs run(working_digits) at rising precision until measure(result) (a
/// precision_run) certifies at least `wanted` digits, and returns that result; `goal`
/// records every run. Throws invalid_parameter for a goal out of range and
/// certified_digits_unreached when max_precision_runs runs fall short.
template <class Run, class Measure>
auto certify_to_goal(int wanted, int margin, Run&& run, Measure&& measure, certified_digits_goal& goal)
    -> decltype(run(0)) {
  if (wanted < 1 || wanted > max_working_digits - margin - 1)
    throw invalid_parameter(VISCOR_FIELD("certified_digits") " must be from 1 to " +
                            std::to_string(max_working_digits - margin - 1) + ", got " + std::to_string(wanted));
  goal = certified_digits_goal{wanted, {}};
  precision_run best;
  int digits = first_working_digits(wanted, margin);
  for (int i = 0; i < max_precision_runs && digits <= max_working_digits; ++i) {
    auto result = run(digits);
    const precision_run done = measure(result);
    goal.runs.push_back(done);
    if (done.certified_digits >= wanted) return result;
    if (goal.runs.size() == 1 || done.certified_digits > best.certified_digits) best = done;
    digits = std::max(next_working_digits(wanted, done), digits + 1);
  }
  std::string tried;
  for (const precision_run& r : goal.runs)
    tried += (tried.empty() ? "" : ", ") + std::to_string(r.certified_digits) + " at " +
             std::to_string(r.working_digits);
  throw certified_digits_unreached(VISCOR_FIELD("certified_digits") " = " + std::to_string(wanted) +
                                       " not reached: at most " + std::to_string(best.certified_digits) +
                                       " digits could be certified (certified at working digits: " + tried + ")",
                                   goal, best);
}

}  // namespace viscor
