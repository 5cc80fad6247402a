// One rule for decimal digits (std::numeric_limits<T>::digits10), and the
// precision choices derived from the widths of the types (docs/precision.md). The
// static_asserts in the headers check the margins at compile time; this checks the
// values a reader relies on.
#include "test_utils.hpp"

#include <viscor/certify/certification.hpp>
#include <viscor/core/precision.hpp>
#include <viscor/ode/adaptive_integrator.hpp>

#include <gtest/gtest.h>

#include <limits>

namespace viscor {
namespace {

template <class T>
void expect_standard_digits() {
  EXPECT_EQ(decimal_digits<T>(), std::numeric_limits<T>::digits10);
  EXPECT_EQ(roundtrip_digits<T>(), std::numeric_limits<T>::max_digits10);
}

TEST(PrecisionRules, DecimalDigitsAreDigits10) {
  expect_standard_digits<double>();
  expect_standard_digits<long double>();
  EXPECT_EQ(decimal_digits<double>(), 15);
  if (std::numeric_limits<long double>::digits == 64) EXPECT_EQ(decimal_digits<long double>(), 18);
#if VISCOR_HAS_FLOAT128
  EXPECT_EQ(decimal_digits<quad>(), 33);  // as the README says
  EXPECT_EQ(roundtrip_digits<quad>(), 36);
#endif
#if VISCOR_HAS_MPFR
  EXPECT_EQ(decimal_digits<mpfr_50>(), 50);
  EXPECT_EQ(decimal_digits<mpfr_100>(), 100);
  for (int d : {16, 19, 34, 40, 50, 333, 1000}) {
    scoped_precision precision(d);
    EXPECT_EQ(decimal_digits<mpfr_real>(), d) << d;
  }
#endif
}

TEST(PrecisionRules, DigitsChooseTheCheapestTypeThatCarriesThem) {
  EXPECT_EQ(scalar_for_digits(15), scalar_kind::double_);
  EXPECT_EQ(scalar_for_digits(16), scalar_kind::long_double);
  EXPECT_EQ(scalar_for_digits(decimal_digits<long double>()), scalar_kind::long_double);
#if VISCOR_HAS_QD  // double-double: about 5 times faster than float128 (docs/performance.md)
  EXPECT_EQ(scalar_for_digits(decimal_digits<long double>() + 1), scalar_kind::double_double);
  EXPECT_EQ(scalar_for_digits(31), scalar_kind::double_double);
#endif
#if VISCOR_HAS_FLOAT128
  EXPECT_EQ(scalar_for_digits(VISCOR_HAS_QD ? 32 : decimal_digits<long double>() + 1), scalar_kind::quad);
  EXPECT_EQ(scalar_for_digits(33), scalar_kind::quad);
#endif
#if VISCOR_HAS_MPFR
  EXPECT_EQ(scalar_for_digits(34), scalar_kind::mpfr);
#endif
}

#if VISCOR_HAS_MPFR
template <class Real>
void expect_wider_work_and_reference(int gbs_margin) {
  using work = detail::gbs_work<Real>;
  const int working = decimal_digits<Real>();
  EXPECT_GE(work::guard_digits(), gbs_margin);
  scoped_precision precision(working + work::guard_digits());
  EXPECT_GE(decimal_digits<typename work::type>(), working + gbs_margin);
  using ref = typename detail::certify_reference<Real>::type;
  EXPECT_GE(decimal_digits<ref>(), working + detail::reference_extra_digits(working));
}

TEST(PrecisionRules, WorkAndReferenceTypesAreWiderByTheirMargins) {
  expect_wider_work_and_reference<double>(3);
  expect_wider_work_and_reference<long double>(10);
#if VISCOR_HAS_FLOAT128
  expect_wider_work_and_reference<quad>(10);
#endif
  expect_wider_work_and_reference<mpfr_50>(7);
  expect_wider_work_and_reference<mpfr_100>(11);
}
#endif

}  // namespace
}  // namespace viscor
