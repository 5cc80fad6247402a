// Taylor-series arithmetic on ball coefficients: the k-th coefficient of a
// quotient, a product, a real power and an integer monomial, each from the
// coefficients 0..k of its operands (so a jet is built order by order).
//
// The convolutions are Arb dot products (arb_dot: the sum is accumulated exactly
// and rounded once, its error bound added to the radius), which encloses the same
// exact sum as a loop of ball products and sums, with no temporary balls: the jets
// are most of a proof's time (docs/proofs.md, "Cost").
#pragma once

#include <viscor/enclose/ball.hpp>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace viscor::proofs::series {

// NOTE: arb_dot reads a vector<ball> as an array of arb_struct (stride 1, or -1 to
// run backwards): a ball is exactly one arb_t.
static_assert(sizeof(ball) == sizeof(arb_struct), "a ball must be exactly one arb_struct");

/// (a b)_k = sum_{j<=k} a_j b_{k-j}.
inline ball product(const std::vector<ball>& a, const std::vector<ball>& b, std::size_t k) {
  ball s;
  arb_dot(s.get(), nullptr, 0, a[0].get(), 1, b[k].get(), -1, static_cast<slong>(k + 1), ball_bits());
  return s;
}

/// (a b)_k for a polynomial a (a.size() coefficients, usually few) and a series b:
/// sum_{j <= min(k, deg a)} a_j b_{k-j}, one dot product of at most a.size() terms.
inline ball polynomial_product(const std::vector<ball>& a, const std::vector<ball>& b, std::size_t k) {
  ball s;
  const std::size_t terms = std::min(k + 1, a.size());
  arb_dot(s.get(), nullptr, 0, a[0].get(), 1, b[k].get(), -1, static_cast<slong>(terms), ball_bits());
  return s;
}

/// q = a / b: q_k = (a_k - sum_{j<k} q_j b_{k-j}) / b_0, from q_0..q_{k-1}
/// (b_0 containing 0 gives an infinite ball, which no validation accepts).
inline ball quotient(const ball& a_k, const std::vector<ball>& q, const std::vector<ball>& b, std::size_t k) {
  ball s;
  if (k == 0)
    arb_set(s.get(), a_k.get());
  else
    arb_dot(s.get(), a_k.get(), 1, q[0].get(), 1, b[k].get(), -1, static_cast<slong>(k), ball_bits());
  arb_div(s.get(), s.get(), b[0].get(), ball_bits());
  return s;
}

/// w = u^a (u_0 > 0) for a rational exponent a = num/den (den > 0): w_0 = u_0^a, and
/// from u w' = a u' w,
///     w_k = sum_{j=1..k} (a j - (k - j)) u_j w_{k-j} / (k u_0)
///         = sum_{j=1..k} ((num + den) j - den k) u_j w_{k-j} / (den k u_0),
/// as one dot product of the integer-weighted u_j with w backwards, divided once.
/// `weighted` is scratch space for the weighted u_j, kept by the caller from one order
/// to the next: a fresh vector per coefficient cost k allocations of multi-limb balls
/// (Arb keeps at most two limbs inline), O(p^2) per jet.
/// NOTE: the weights stay on each term. Splitting the sum into (a + 1) sum j u_j w_{k-j}
/// - k sum u_j w_{k-j} (two dot products, no weighted copy) is faster but widens the
/// remainder over a step's box enough to cost steps and to hide a 1e-9 under-estimated
/// remainder (enclose_impact_test). With
/// integer weights (one arb_mul_si per term; they were three ball operations with the
/// weight a j - (k - j) as a ball) the arithmetic is the same as with those exact weights
/// when den is a power of two (every named law): the scaling by den is exact.
inline ball power(const std::vector<ball>& u, const std::vector<ball>& w, long num, long den, std::size_t k,
                  std::vector<ball>& weighted) {
  ball r;
  const slong prec = ball_bits();
  if (k == 0) {
    ball a(num);
    arb_div_si(a.get(), a.get(), den, prec);
    arb_pow(r.get(), u[0].get(), a.get(), prec);  // indeterminate unless u_0 > 0
    return r;
  }
  if (weighted.size() < k) weighted.resize(k);  // ((num + den) j - den k) u_j, j = 1..k
  const slong K = static_cast<slong>(k);
  for (slong j = 1; j <= K; ++j)
    arb_mul_si(weighted[static_cast<std::size_t>(j - 1)].get(), u[static_cast<std::size_t>(j)].get(),
               (num + den) * j - den * K, prec);
  arb_dot(r.get(), nullptr, 0, weighted[0].get(), 1, w[k - 1].get(), -1, K, prec);
  arb_div(r.get(), r.get(), u[0].get(), prec);
  arb_div_si(r.get(), r.get(), K * den, prec);
  return r;
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
