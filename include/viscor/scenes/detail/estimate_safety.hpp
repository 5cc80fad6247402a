// How far the Taylor solver's error_estimate is trusted.
#pragma once

namespace viscor::detail {

// NOTE: solve_impact's error_estimate is a heuristic (step count x tolerance x
// energy scale, plus the energy residual), not a bound. Measured against
// solve_impact at 50 digits on 800 random points of the four Hertz-type and
// linear laws (gamma in [1e-4, 1], g in [-0.1, 10]): the true error of e was at
// most 0.43 x the estimate at the working precision of double, and at most
// 1.3e-3 x with a loose step tolerance (1e-8..1e-4). Callers that turn the
// estimate into a guarantee multiply it by this factor (23x margin over the
// worst case seen); tests of calibrate and evaluate check the result.
inline constexpr int taylor_estimate_safety = 10;

}  // namespace viscor::detail
