// Automatic differentiation on truncated power series (normalised Taylor
// coefficients x(t0 + h) = sum_k x[k] h^k), one coefficient at a time: each
// function returns (or writes) coefficient k from coefficients 0..k of its
// inputs and 0..k-1 of its output, so that a Taylor integrator can interleave
// the recurrences of a whole system order by order (Jorba and Zou 2005,
// "A software package for the numerical integration of ODEs by means of
// high-order Taylor methods"; Griewank and Walther, "Evaluating Derivatives").
//
// NOTE: no function allocates; every Real is updated in place (compound
// assignment, which Boost.Multiprecision turns into mpfr_fma for x += a * b),
// because these loops are the whole cost of a high-precision integration.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

namespace viscor::detail {

/// out = sum_{j=lo}^{hi} a[j] * b[k - j]: the k-th coefficient of a product
/// restricted to j in [lo, hi].
template <class Real>
void convolution(Real& out, const Real* a, const Real* b, std::size_t k, std::size_t lo, std::size_t hi) {
  out = 0;
  for (std::size_t j = lo; j <= hi; ++j) out += a[j] * b[k - j];
}

/// Coefficient k of the product c = a b.
template <class Real>
void product(Real& out, const Real* a, const Real* b, std::size_t k) {
  convolution(out, a, b, k, 0, k);
}

/// Coefficient k of c = a / b. Requires b[0] != 0 (the recurrence divides by it);
/// `c` holds coefficients 0..k-1 of the quotient.
///   c[k] = (a[k] - sum_{j=1}^{k} b[j] c[k-j]) / b[0]
template <class Real>
void quotient(Real& out, const Real* a, const Real* b, const Real* c, std::size_t k) {
  out = 0;
  for (std::size_t j = 1; j <= k; ++j) out -= b[j] * c[k - j];
  out += a[k];
  out /= b[0];
}

/// Coefficient k of c = 1 / b (k >= 1; c[0] = 1/b[0] is set by the caller).
/// Requires b[0] != 0.   c[k] = -c[0] sum_{j=1}^{k} b[j] c[k-j]
template <class Real>
void reciprocal(Real& out, const Real* b, const Real* c, std::size_t k) {
  out = 0;
  for (std::size_t j = 1; j <= k; ++j) out -= b[j] * c[k - j];
  out *= c[0];
}

/// Coefficient k >= 1 of c = a^p for real p. Requires a[0] != 0 (and a[0] > 0
/// unless p is an integer); c[0] = a[0]^p is set by the caller. From c' a = p a' c:
///   k a[0] c[k] = sum_{j=1}^{k} ((p + 1) j - k) a[j] c[k-j].
/// `ja` holds j * a[j] (kept by the caller so the sum needs no extra products):
///   c[k] = ((p + 1) sum ja[j] c[k-j] - k sum a[j] c[k-j]) / (k a[0]).
template <class Real>
void real_power(Real& out, Real& scratch, const Real& p_plus_one, const Real* a, const Real* ja, const Real* c,
                std::size_t k) {
  out = 0;
  scratch = 0;
  for (std::size_t j = 1; j <= k; ++j) {
    out += ja[j] * c[k - j];
    scratch += a[j] * c[k - j];
  }
  out *= p_plus_one;
  scratch *= static_cast<long>(k);
  out -= scratch;
  out /= a[0];
  out /= static_cast<long>(k);
}

/// Coefficients 0..order of (x0 + h)^m for an integer m >= 0:
///   c[j] = binomial(m, j) x0^(m-j), exact even at x0 = 0 (no division by x0).
/// `powers` is scratch space; it receives x0^0 .. x0^m.
template <class Real>
void integer_power_of_linear(std::vector<Real>& c, std::vector<Real>& powers, const Real& x0, long m,
                             std::size_t order) {
  powers.resize(static_cast<std::size_t>(m) + 1);
  powers[0] = 1;
  for (long i = 1; i <= m; ++i) {
    powers[static_cast<std::size_t>(i)] = powers[static_cast<std::size_t>(i - 1)];
    powers[static_cast<std::size_t>(i)] *= x0;
  }
  Real binomial = 1;
  for (std::size_t j = 0; j <= order; ++j) {
    if (static_cast<long>(j) > m) {
      c[j] = 0;
      continue;
    }
    if (j > 0) {
      binomial *= m - static_cast<long>(j) + 1;
      binomial /= static_cast<long>(j);
    }
    c[j] = binomial;
    c[j] *= powers[static_cast<std::size_t>(m - static_cast<long>(j))];
  }
}

/// Coefficients 0..order of exp(lambda (x0 + h)) = exp(lambda x0) sum (lambda h)^j / j!.
template <class Real>
void exponential_of_linear(std::vector<Real>& c, const Real& lambda, const Real& x0, std::size_t order) {
  using std::exp;
  c[0] = exp(lambda * x0);
  for (std::size_t j = 1; j <= order; ++j) {
    c[j] = c[j - 1];
    c[j] *= lambda;
    c[j] /= static_cast<long>(j);
  }
}

/// Coefficient k of c = a^n for an integer n >= 0 by the same recurrence as
/// real_power (requires a[0] != 0); for a[0] == 0 use repeated products.
template <class Real>
void integer_power(Real& out, Real& scratch, long n, const Real* a, const Real* ja, const Real* c, std::size_t k) {
  real_power(out, scratch, Real(n + 1), a, ja, c, k);
}

/// Value of the polynomial sum_{k=0}^{order} c[k] h^k (Horner).
template <class Real>
void horner(Real& out, const Real* c, std::size_t order, const Real& h) {
  out = c[order];
  for (std::size_t k = order; k-- > 0;) {
    out *= h;
    out += c[k];
  }
}

/// Value of the derivative sum_{k=1}^{order} k c[k] h^(k-1).
template <class Real>
void horner_derivative(Real& out, const Real* c, std::size_t order, const Real& h) {
  if (order == 0) {
    out = 0;
    return;
  }
  out = c[order];
  out *= static_cast<long>(order);
  for (std::size_t k = order - 1; k >= 1; --k) {
    out *= h;
    out += c[k] * static_cast<long>(k);
  }
}

}  // namespace viscor::detail
