// A fast double-precision CoR with a stated accuracy, as viscor::evaluate sees it
// (the surrogates). evaluate (scenes/) uses a surrogate (surrogate/) through this small
// interface, so that neither layer includes the other: surrogate/surrogate_source.hpp
// implements it for a cor_surrogate; evaluate_options::surrogate takes a pointer to it.
#pragma once

#include <viscor/core/outcome.hpp>

#include <string>

namespace viscor {

/// One fast evaluation.
struct fast_cor_value {
  bool in_domain = false;  ///< false: nothing else is set, the caller must fall back
  impact_outcome outcome = impact_outcome::rebound;
  double e = 0, one_minus_e = 1;
  double e_squared = 0;  ///< signed: negative past the sticking threshold
};

/// The accuracy the source claims (measured maxima times a safety factor; empirical).
struct fast_cor_bound {
  bool verified = false;       ///< false: no claim, never use the values
  double abs_e = 0;            ///< |e_s - e| where e >= 1e-2
  double abs_e_squared = 0;    ///< |e_s^2 - e^2| everywhere (outside the exempt band)
  double rel_one_minus_e = 0;  ///< relative error of 1 - e where gamma <= small_gamma and e >= 1e-2
  double small_gamma = 1e-2;
  /// Outcomes are right except where |e_s^2| is below this (near the threshold).
  double uncertain_e_squared = 1e-8;
};

/// A fast CoR of one law (alpha, beta as exact texts, e.g. "3/2").
class fast_cor {
 public:
  virtual ~fast_cor() = default;
  /// The law's alpha as an exact text ("3/2").
  virtual std::string alpha() const = 0;
  /// The law's beta as an exact text.
  virtual std::string beta() const = 0;
  /// e, 1 - e, e^2 and the outcome at (gamma, g); in_domain false outside the domain.
  virtual fast_cor_value at(double gamma, double g) const noexcept = 0;
  /// The measured error bounds and where they hold.
  virtual fast_cor_bound bound() const noexcept = 0;
};

}  // namespace viscor
