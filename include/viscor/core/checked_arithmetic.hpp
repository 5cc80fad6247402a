// Checked 64-bit integer arithmetic: the one place where an integer computed from
// user input (an exponent's numerator times a common denominator, a grid size, a
// count) is either exact or refused with an invalid_parameter naming what it is.
#pragma once

#include <viscor/core/exceptions.hpp>

#include <cstdint>
#include <numeric>
#include <string>
#include <type_traits>

namespace viscor {

namespace detail {
/// The name of what overflowed: `what` itself, or what it returns when it is a function
/// (so that a caller on a hot path builds the name only when there is an error).
template <class What>
std::string overflow_subject(const What& what) {
  if constexpr (std::is_invocable_v<const What&>) return what();
  else return std::string(what);
}
}  // namespace detail

/// a * b, or invalid_parameter "<what> overflows ..." when it does not fit in 64 bits.
template <class What = std::string>
std::int64_t checked_product(std::int64_t a, std::int64_t b, const What& what) {
  std::int64_t r = 0;
  if (__builtin_mul_overflow(a, b, &r))
    throw invalid_parameter(detail::overflow_subject(what) + " overflows 64-bit integers (" + std::to_string(a) +
                            " * " + std::to_string(b) + ")");
  return r;
}

/// a + b, or invalid_parameter naming `what` when it does not fit in 64 bits.
template <class What = std::string>
std::int64_t checked_sum(std::int64_t a, std::int64_t b, const What& what) {
  std::int64_t r = 0;
  if (__builtin_add_overflow(a, b, &r))
    throw invalid_parameter(detail::overflow_subject(what) + " overflows 64-bit integers (" + std::to_string(a) +
                            " + " + std::to_string(b) + ")");
  return r;
}

/// a - b, or invalid_parameter naming `what` when it does not fit in 64 bits.
template <class What = std::string>
std::int64_t checked_difference(std::int64_t a, std::int64_t b, const What& what) {
  std::int64_t r = 0;
  if (__builtin_sub_overflow(a, b, &r))
    throw invalid_parameter(detail::overflow_subject(what) + " overflows 64-bit integers (" + std::to_string(a) +
                            " - " + std::to_string(b) + ")");
  return r;
}

/// lcm(a, b) of positive a, b, or invalid_parameter naming `what` when it does not fit.
template <class What = std::string>
std::int64_t checked_lcm(std::int64_t a, std::int64_t b, const What& what) {
  return checked_product(a / std::gcd(a, b), b, what);
}

}  // namespace viscor
