// Comparison helpers for the tests of the integrals, closed forms and
// approximations: relative errors computed in the tested type itself (never
// through double), with GoogleTest predicate formatters that print both values
// at full precision.
#pragma once

#include <viscor/real_io.hpp>
#include <viscor/real_types.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace viscor::test {

/// |a - b| / |b| (|a - b| when b = 0), in Real.
template <class Real>
Real relative_error(const Real& a, const Real& b) {
  using std::abs;
  const Real d = abs(Real(a - b));
  return b == 0 ? d : Real(d / abs(b));
}

/// EXPECT_PRED_FORMAT3(relatively_close, actual, expected, tolerance); the
/// comparison is made in the type of `expected`.
template <class Real, class A, class T>
::testing::AssertionResult relatively_close(const char* actual_expr, const char* expected_expr, const char*,
                                            const A& actual_in, const Real& expected, const T& tolerance_in) {
  const Real actual(actual_in), tolerance(tolerance_in);
  const Real err = relative_error(actual, expected);
  if (err <= tolerance) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << actual_expr << " = " << to_decimal_string(actual) << "\n"
                                       << expected_expr << " = " << to_decimal_string(expected) << "\n"
                                       << "relative error " << to_decimal_string(err, 3) << " > tolerance "
                                       << to_decimal_string(tolerance, 3);
}

/// A reference constant given as a decimal string, correctly rounded to Real.
template <class Real>
Real constant(const std::string& digits) {
  return parse_real<Real>(digits, "reference constant");
}

/// k machine epsilons of Real.
template <class Real>
Real ulps(int k) {
  return Real(k) * epsilon<Real>();
}

}  // namespace viscor::test

#define VISCOR_EXPECT_REL(actual, expected, tolerance) \
  EXPECT_PRED_FORMAT3(::viscor::test::relatively_close, actual, expected, tolerance)
