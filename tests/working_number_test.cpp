// working_number (core/working_number.hpp): a value keeps its working type, so its
// decimals are the type's own wherever it is printed, and it reads as the nearest
// double. The expected texts are to_decimal_string of the same value in its type.
#include <viscor/core/working_number.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace viscor {
namespace {

TEST(WorkingNumber, DoubleIsItself) {
  const working_number x = 0.1;
  EXPECT_EQ(x.value(), 0.1);
  EXPECT_EQ(x.decimal(), to_decimal_string(0.1));
  EXPECT_EQ(x * 2, 0.2);
  ASSERT_NE(x.as<double>(), nullptr);
  EXPECT_EQ(x.as<long double>(), nullptr);
}

#if VISCOR_HAS_MPFR
TEST(WorkingNumber, MpfrKeepsItsPrecisionOutsideTheScope) {
  std::string inside;
  working_number third;
  {
    scoped_precision precision(60);
    const mpfr_real x = mpfr_real(1) / 3;
    inside = to_decimal_string(x);
    third = working_number::of(x);
  }
  {
    scoped_precision other(20);  // printing under another thread precision changes nothing
    EXPECT_EQ(third.decimal(), inside);
  }
  EXPECT_EQ(third.decimal(), inside);
  EXPECT_EQ(inside.size(), std::string("3.").size() + 61 + std::string("e-01").size());  // 62 significant digits
  EXPECT_EQ(third.decimal(5), "3.3333e-01");
  EXPECT_DOUBLE_EQ(third.value(), 1.0 / 3);
}
#endif

#if VISCOR_HAS_FLOAT128
TEST(WorkingNumber, Float128PrintsItsDigits) {
  const quad x = quad(2) / 3;
  const working_number n = working_number::of(x);
  EXPECT_EQ(n.decimal(), to_decimal_string(x));
  EXPECT_EQ(n.value(), static_cast<double>(x));
  ASSERT_NE(n.as<quad>(), nullptr);
  EXPECT_EQ(*n.as<quad>(), x);
}
#endif

TEST(WorkingNumber, ZeroInfinityAndNan) {
  EXPECT_TRUE(working_number(0.0).is_zero());
  EXPECT_TRUE(working_number(INFINITY).is_infinite());
  EXPECT_FALSE(working_number(NAN).is_infinite());
  EXPECT_TRUE(working_number(NAN).is_nan());
  EXPECT_EQ(working_number::of(-INFINITY).decimal(), "-inf");
  EXPECT_FALSE(working_number(1.5).is_zero());
}

}  // namespace
}  // namespace viscor
