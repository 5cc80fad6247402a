// Taylor-series arithmetic on ball coefficients: the k-th coefficient of a
// quotient, a product, a real power and an integer monomial, each from the
// coefficients 0..k of its operands (so a jet is built order by order).
#pragma once

#include <viscor/enclose/ball.hpp>

#include <cstddef>
#include <vector>

namespace viscor::proofs::series {

/// (a b)_k = sum_{j<=k} a_j b_{k-j}.
inline ball product(const std::vector<ball>& a, const std::vector<ball>& b, std::size_t k) {
  ball s;
  for (std::size_t j = 0; j <= k; ++j) s += a[j] * b[k - j];
  return s;
}

/// q = a / b: q_k = (a_k - sum_{j<k} q_j b_{k-j}) / b_0, from q_0..q_{k-1}
/// (b_0 containing 0 gives an infinite ball, which no validation accepts).
inline ball quotient(const ball& a_k, const std::vector<ball>& q, const std::vector<ball>& b, std::size_t k) {
  ball s = a_k;
  for (std::size_t j = 0; j < k; ++j) s -= q[j] * b[k - j];
  return s / b[0];
}

/// w = u^a (u_0 > 0): w_0 = u_0^a, and from u w' = a u' w,
/// w_k = sum_{j=1..k} (a j - (k - j)) u_j w_{k-j} / (k u_0).
inline ball power(const std::vector<ball>& u, const std::vector<ball>& w, const ball& a, std::size_t k) {
  if (k == 0) {
    ball r;
    arb_pow(r.get(), u[0].get(), a.get(), ball_bits());  // indeterminate unless u_0 > 0
    return r;
  }
  ball s;
  for (std::size_t j = 1; j <= k; ++j) s += (a * ball(static_cast<long>(j)) - ball(static_cast<long>(k - j))) * u[j] * w[k - j];
  return s / (ball(static_cast<long>(k)) * u[0]);
}

/// The coefficient k of (s0 + d sigma)^m in sigma, m >= 0 an integer and d = +1 or
/// -1: binomial(m, k) s0^(m-k) d^k, from the powers s0^0..s0^m.
inline ball monomial(const std::vector<ball>& s0_powers, long m, int d, std::size_t k) {
  if (static_cast<long>(k) > m) return ball(0);
  ball binomial(1);
  for (std::size_t j = 0; j < k; ++j)
    binomial = binomial * ball(m - static_cast<long>(j)) / ball(static_cast<long>(j + 1));
  ball r = binomial * s0_powers[static_cast<std::size_t>(m) - k];
  return (d < 0 && k % 2 == 1) ? -r : r;
}

}  // namespace viscor::proofs::series
