// The precision a computation ran at, as every job result reports it.
#pragma once

#include <viscor/core/precision.hpp>
#include <viscor/core/real_types.hpp>

#include <optional>

namespace viscor::jobs {

/// The precision a computation ran at.
struct precision_used {
  int digits = 0;         ///< decimal digits of the working type
  int binary_digits = 0;  ///< its significand bits
  scalar_kind arithmetic = scalar_kind::double_;
  /// The arithmetic the requested digits chose, when the computation left it
  /// (with_working_precision's escalation out of double's exponent range).
  std::optional<scalar_kind> escalated_from;

  /// The working type Real's precision; given the requested digits, also where it escalated from.
  template <class Real>
  static precision_used of(std::optional<int> requested_digits = std::nullopt) {
    precision_used p{viscor::decimal_digits<Real>(), viscor::binary_digits<Real>(), scalar_kind_of<Real>(), std::nullopt};
    if (requested_digits) {
      const scalar_kind asked = scalar_for_digits(*requested_digits);
      if (asked != p.arithmetic) p.escalated_from = asked;
    }
    return p;
  }
};

}  // namespace viscor::jobs
