// A number computed at a precision chosen at run time (with_working_precision):
// a job's result keeps the value in the type it was computed in, so a front end
// prints its exact decimals and rounds it as the working type rounds, while C++
// and Python code reads it as a double (result.e * 2).
#pragma once

#include <viscor/core/precision.hpp>
#include <viscor/core/real_io.hpp>
#include <viscor/core/real_types.hpp>

#include <boost/math/special_functions/fpclassify.hpp>

#include <memory>
#include <string>
#include <type_traits>

namespace viscor {

/// A value of the working type (double, long double, double-double, float128 or
/// MPFR), held as that type; copies share it.
class working_number {
 public:
  /// A double (implicit, so that results built in double default to 0 and 1).
  working_number(double x = 0) : working_number(of(x)) {}  // NOLINT(google-explicit-constructor)

  /// x in its own type; an MPFR value keeps the thread's precision of the moment.
  template <class Real>
    requires(!std::is_same_v<Real, working_number>)
  static working_number of(const Real& x) {
    return working_number(std::make_shared<const model<Real>>(x));
  }

  /// The nearest double (what arithmetic in C++ or Python sees).
  double value() const { return m_value; }
  /// The nearest double, where a double is wanted (result.e * 2).
  operator double() const { return m_value; }  // NOLINT(google-explicit-constructor)

  /// The decimal text of the value in its own type: `digits` significant digits,
  /// 0 for the digits that round-trip (to_decimal_string, real_io.hpp).
  std::string decimal(int digits = 0) const { return m_held->decimal(digits); }

  /// Exactly zero in its own type (a double would also call 1e-400 zero).
  bool is_zero() const { return m_held->is_zero(); }
  /// Neither infinite nor NaN, in its own type.
  bool is_finite() const { return m_held->is_finite(); }
  /// +infinity or -infinity (a contact time that never ends).
  bool is_infinite() const { return !is_finite() && !is_nan(); }
  /// Not a number (an unknown quantity).
  bool is_nan() const { return m_held->is_nan(); }

  /// The value in its own type, or nullptr when it has another one.
  template <class Real>
  const Real* as() const {
    const auto* held = dynamic_cast<const model<Real>*>(m_held.get());
    return held ? &held->x : nullptr;
  }

 private:
  struct concept_base {
    virtual ~concept_base() = default;
    virtual std::string decimal(int digits) const = 0;
    virtual bool is_zero() const = 0;
    virtual bool is_finite() const = 0;
    virtual bool is_nan() const = 0;
    double nearest_double = 0;
  };
  template <class Real>
  struct model final : concept_base {
    explicit model(const Real& value) : x(value) {
      nearest_double = static_cast<double>(x);
#if VISCOR_HAS_MPFR
      if constexpr (std::is_same_v<Real, mpfr_real>) precision = mpfr_real::thread_default_precision();
#endif
    }
    std::string decimal(int digits) const override {
#if VISCOR_HAS_MPFR
      // The round-trip digits of an MPFR value are those of the precision it was computed at.
      if constexpr (std::is_same_v<Real, mpfr_real>) {
        scoped_precision working(static_cast<int>(precision));
        return to_decimal_string(x, digits);
      }
#endif
      return to_decimal_string(x, digits);
    }
    bool is_zero() const override { return x == 0; }
    bool is_finite() const override { return (boost::math::isfinite)(x); }
    bool is_nan() const override { return (boost::math::isnan)(x); }
    Real x;
    unsigned precision = 0;  // MPFR only: the thread precision (decimal digits) x was made at
  };

  explicit working_number(std::shared_ptr<const concept_base> held)
      : m_held(std::move(held)), m_value(m_held->nearest_double) {}

  std::shared_ptr<const concept_base> m_held;
  double m_value = 0;
};

/// The decimal text of x (working_number::decimal): the one to_decimal_string every
/// scalar type has, so templates that print a Real print a working_number too.
inline std::string to_decimal_string(const working_number& x, int digits = 0) { return x.decimal(digits); }

}  // namespace viscor
