// A cor_surrogate as a viscor::fast_cor (core/fast_cor.hpp), for evaluate_options::surrogate.
#pragma once

#include <viscor/core/fast_cor.hpp>
#include <viscor/surrogate/cor_surrogate.hpp>

namespace viscor::surrogate {

/// Refers to the surrogate (which must outlive it).
class surrogate_source final : public fast_cor {
 public:
  /// Refers to `s`, which must outlive this object.
  explicit surrogate_source(const cor_surrogate& s) : m_s(&s) {}
  /// The surrogate's alpha.
  std::string alpha() const override { return m_s->alpha; }
  /// The surrogate's beta.
  std::string beta() const override { return m_s->beta; }
  /// The surrogate's value at (gamma, g).
  fast_cor_value at(double gamma, double g) const noexcept override {
    const surrogate_value v = (*m_s)(gamma, g);
    return {v.in_domain, v.outcome, v.e, v.one_minus_e, v.e_squared};
  }
  /// The surrogate's verified bounds.
  fast_cor_bound bound() const noexcept override {
    fast_cor_bound b;
    b.verified = m_s->bound.verified();
    b.abs_e = m_s->bound.abs_e, b.abs_e_squared = m_s->bound.abs_e_squared;
    b.rel_one_minus_e = m_s->bound.rel_one_minus_e;
    b.small_gamma = surrogate_targets{}.small_gamma;
    // NOTE: the verification exempts relative 1e-10 in g around the threshold, where
    // e^2 ~ |d e^2 / d ln g| 1e-10 stays well below 1e-8 for the named laws.
    b.uncertain_e_squared = 1e-8;
    return b;
  }

 private:
  const cor_surrogate* m_s;
};

}  // namespace viscor::surrogate
