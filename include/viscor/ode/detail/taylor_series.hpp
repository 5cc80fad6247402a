// Automatic differentiation on truncated power series (normalised Taylor
// coefficients x(t0 + h) = sum_k x[k] h^k), one coefficient at a time: each
// function returns (or writes) coefficient k from coefficients 0..k of its
// inputs and 0..k-1 of its output, so that a Taylor integrator can interleave
// the recurrences of a whole system order by order (Jorba and Zou 2005,
// "A software package for the numerical integration of ODEs by means of
// high-order Taylor methods"; Griewank and Walther, "Evaluating Derivatives").
//
// NOTE: these loops are the whole cost of an integration, so no function
// allocates. Sums of products run in a local accumulator for the built-in and
// float128 types (out may alias the inputs, which keeps a sum into it in memory);
// on MPFR values up to fixed_point_dot_limbs limbs as an exact fixed-point sum of
// GMP limb products rounded once (mpfr_dot: about half the time of an mpfr_mul +
// mpfr_add per term, and more accurate), above that on MPFR's raw mpfr_mul +
// mpfr_add into a scratch variable (Boost turns x += a * b into a slower
// mpfr_fma). Measurements: docs/performance.md.
#pragma once

#include <viscor/core/detail/log_abs.hpp>
#include <viscor/core/real_types.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <vector>

namespace viscor::detail {

#if VISCOR_HAS_MPFR
/// A per-thread MPFR temporary of precision prec (for the products of the sums below).
inline mpfr_ptr mpfr_scratch(mpfr_prec_t prec) {
  struct holder {
    mpfr_t x;
    holder() { mpfr_init2(x, 64); }
    ~holder() { mpfr_clear(x); }
  };
  thread_local holder h;
  if (mpfr_get_prec(h.x) != prec) mpfr_set_prec(h.x, prec);
  return h.x;
}

template <class Real>
mpfr_ptr raw(Real& x) {
  return x.backend().data();
}
template <class Real>
mpfr_srcptr raw(const Real& x) {
  return x.backend().data();
}

/// acc = sum_{j=lo}^{hi} a[j] * b[k - j], one product and one sum at a time (the
/// general path: any precisions, special values).
template <class Real>
void mpfr_dot_rounded(mpfr_ptr acc, const Real* a, const Real* b, std::size_t k, std::size_t lo, std::size_t hi) {
  mpfr_ptr t = mpfr_scratch(mpfr_get_prec(acc));
  mpfr_set_zero(acc, 1);
  for (std::size_t j = lo; j <= hi; ++j) {
    mpfr_mul(t, raw(a[j]), raw(b[k - j]), MPFR_RNDN);
    mpfr_add(acc, acc, t, MPFR_RNDN);
  }
}

/// The most limbs for which mpfr_dot sums in fixed point (above, MPFR's short
/// products beat the full products the fixed-point sum needs).
inline constexpr std::size_t fixed_point_dot_limbs = 8;

/// acc = sum_{j=lo}^{hi} a[j] * b[k - j] on raw MPFR values, with one rounding:
/// the exact products (GMP limb products) are added in a fixed-point window of
/// 2n + 2 limbs whose top limb is headroom and whose bottom limb is below every
/// bit of the largest product, so the only errors are bits of products more than
/// 64 (2n + 1) bits below the largest, truncated, then the final rounding to acc.
/// Falls back to mpfr_dot_rounded for mixed precisions, special values or more
/// than fixed_point_dot_limbs limbs.
template <class Real>
void mpfr_dot(mpfr_ptr acc, const Real* a, const Real* b, std::size_t k, std::size_t lo, std::size_t hi) {
  const mpfr_prec_t prec = mpfr_get_prec(acc);
  const std::size_t n = static_cast<std::size_t>((prec + GMP_NUMB_BITS - 1) / GMP_NUMB_BITS);
  if (n > fixed_point_dot_limbs || lo > hi) return mpfr_dot_rounded(acc, a, b, k, lo, hi);
  constexpr long bits = GMP_NUMB_BITS;
  mpfr_exp_t top = 0;
  bool any = false;
  // (mpfr.h's macros, not calls: these checks run once per term.)
  for (std::size_t j = lo; j <= hi; ++j) {
    mpfr_srcptr x = raw(a[j]), y = raw(b[k - j]);
    if (mpfr_get_prec(x) != prec || mpfr_get_prec(y) != prec) return mpfr_dot_rounded(acc, a, b, k, lo, hi);
    if (mpfr_regular_p(x) && mpfr_regular_p(y)) {
      const mpfr_exp_t e = mpfr_get_exp(x) + mpfr_get_exp(y);
      if (!any || e > top) top = e, any = true;
    } else if (mpfr_nan_p(x) || mpfr_nan_p(y) || mpfr_inf_p(x) || mpfr_inf_p(y)) {
      return mpfr_dot_rounded(acc, a, b, k, lo, hi);
    }  // else a zero factor: no term
  }
  if (!any) return (void)mpfr_set_zero(acc, 1);
  const std::size_t w = 2 * n + 2;
  mp_limb_t pos[2 * fixed_point_dot_limbs + 2] = {}, neg[2 * fixed_point_dot_limbs + 2] = {};
  mp_limb_t product[2 * fixed_point_dot_limbs + 1], shifted[2 * fixed_point_dot_limbs + 1];
  for (std::size_t j = lo; j <= hi; ++j) {
    mpfr_srcptr x = raw(a[j]), y = raw(b[k - j]);
    if (!mpfr_regular_p(x) || !mpfr_regular_p(y)) continue;
    mpn_mul_n(product, static_cast<const mp_limb_t*>(mpfr_custom_get_significand(x)),
              static_cast<const mp_limb_t*>(mpfr_custom_get_significand(y)), static_cast<mp_size_t>(n));
    // The product's 2n limbs sit one limb up in the window when it is the largest,
    // lower by top - e bits otherwise.
    const long offset = bits - static_cast<long>(top - (mpfr_get_exp(x) + mpfr_get_exp(y)));
    mp_limb_t* sum = (mpfr_signbit(x) != mpfr_signbit(y)) ? neg : pos;
    if (offset >= 0) {
      const std::size_t q = static_cast<std::size_t>(offset / bits);
      const unsigned r = static_cast<unsigned>(offset % bits);
      shifted[2 * n] = r ? mpn_lshift(shifted, product, static_cast<mp_size_t>(2 * n), r) : 0;
      if (!r) std::copy(product, product + 2 * n, shifted);
      mpn_add(sum + q, sum + q, static_cast<mp_size_t>(w - q), shifted, static_cast<mp_size_t>(2 * n + 1));
    } else {
      const std::size_t q = static_cast<std::size_t>(-offset / bits);
      if (q >= 2 * n) continue;  // entirely below the window
      const unsigned r = static_cast<unsigned>(-offset % bits);
      const mp_size_t len = static_cast<mp_size_t>(2 * n - q);
      if (r) mpn_rshift(shifted, product + q, len, r);
      else std::copy(product + q, product + 2 * n, shifted);
      mpn_add(sum, sum, static_cast<mp_size_t>(w), shifted, len);
    }
  }
  const bool negative = mpn_cmp(pos, neg, static_cast<mp_size_t>(w)) < 0;
  if (negative) mpn_sub_n(pos, neg, pos, static_cast<mp_size_t>(w));
  else mpn_sub_n(pos, pos, neg, static_cast<mp_size_t>(w));
  mp_size_t size = static_cast<mp_size_t>(w);
  while (size > 0 && pos[size - 1] == 0) --size;
  if (size == 0) return (void)mpfr_set_zero(acc, 1);
  mpz_t z;
  mpz_roinit_n(z, pos, negative ? -size : size);
  // The window's unit: the largest product's lowest bit is at window bit 64, and that
  // product's value is (2n-limb integer) * 2^(top - 128 n).
  mpfr_set_z_2exp(acc, z, top - static_cast<mpfr_exp_t>(2 * n) * bits - bits, MPFR_RNDN);
}
#endif

/// out = sum_{j=lo}^{hi} a[j] * b[k - j]: the k-th coefficient of a product
/// restricted to j in [lo, hi].
template <class Real>
void convolution(Real& out, const Real* a, const Real* b, std::size_t k, std::size_t lo, std::size_t hi) {
#if VISCOR_HAS_MPFR
  if constexpr (is_mpfr<Real>::value) {
    mpfr_dot(raw(out), a, b, k, lo, hi);
    return;
  }
#endif
  Real acc = 0;
  for (std::size_t j = lo; j <= hi; ++j) acc += a[j] * b[k - j];
  out = acc;
}

/// 1/k for k = 0..n (0 at k = 0), for divide_by.
template <class Real>
std::vector<Real> integer_reciprocals(std::size_t n) {
  std::vector<Real> inv(n + 1, Real(0));
  for (std::size_t k = 1; k <= n; ++k) inv[k] = Real(1) / Real(static_cast<long>(k));
  return inv;
}

/// x /= k. NOTE: MPFR divides by a small integer in linear time, cheaper than a
/// product; in double and float128 a division costs several products, so there
/// it is a product with inv[k] = 1/k (one more rounding).
template <class Real>
void divide_by(Real& x, std::size_t k, const std::vector<Real>& inv) {
  if constexpr (is_mpfr<Real>::value) {
    x /= static_cast<long>(k);
  } else {
    x *= inv[k];
  }
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
  convolution(out, b, c, k, 1, k);
  out *= c[0];
  out = -out;
}

/// Coefficient k >= 1 of c = a^p for real p. Requires a[0] != 0 (and a[0] > 0
/// unless p is an integer); c[0] = a[0]^p is set by the caller. From c' a = p a' c:
///   k a[0] c[k] = sum_{j=1}^{k} ((p + 1) j - k) a[j] c[k-j].
/// `ja` holds j * a[j] (kept by the caller so the sum needs no extra products):
///   c[k] = ((p + 1) sum ja[j] c[k-j] - k sum a[j] c[k-j]) / (k a[0]).
template <class Real>
void real_power(Real& out, Real& scratch, const Real& p_plus_one, const Real* a, const Real* ja, const Real* c,
                std::size_t k) {
#if VISCOR_HAS_MPFR
  if constexpr (is_mpfr<Real>::value) {
    mpfr_dot(raw(out), ja, c, k, 1, k);
    mpfr_dot(raw(scratch), a, c, k, 1, k);
  } else
#endif
  {
    Real sum_ja = 0, sum_a = 0;
    for (std::size_t j = 1; j <= k; ++j) {
      sum_ja += ja[j] * c[k - j];
      sum_a += a[j] * c[k - j];
    }
    out = sum_ja;
    scratch = sum_a;
  }
  out *= p_plus_one;
  scratch *= static_cast<long>(k);
  out -= scratch;
  out /= a[0];
  out /= static_cast<long>(k);
}

/// real_power with 1/a[0] and the table inv[k] = 1/k given (divide_by): divisions
/// are costly in double (docs/performance.md).
template <class Real>
void real_power(Real& out, Real& scratch, const Real& p_plus_one, const Real* a, const Real* ja, const Real* c,
                std::size_t k, const Real& inv_a0, const std::vector<Real>& inv) {
#if VISCOR_HAS_MPFR
  if constexpr (is_mpfr<Real>::value) {
    mpfr_dot(raw(out), ja, c, k, 1, k);
    mpfr_dot(raw(scratch), a, c, k, 1, k);
    out *= p_plus_one;
    scratch *= static_cast<long>(k);
    out -= scratch;
    out *= inv_a0;
    out /= static_cast<long>(k);
    return;
  }
#endif
  Real sum_ja = 0, sum_a = 0;
  for (std::size_t j = 1; j <= k; ++j) {
    sum_ja += ja[j] * c[k - j];
    sum_a += a[j] * c[k - j];
  }
  // ((p + 1) sum_ja - k sum_a) / (k a0) = ((p + 1)/k sum_ja - sum_a) / a0
  sum_ja *= p_plus_one;
  sum_ja *= inv[k];
  sum_ja -= sum_a;
  sum_ja *= inv_a0;
  out = sum_ja;
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

/// Value of the polynomial sum_{k=0}^{order} c[k] h^k (Horner).
template <class Real>
void horner(Real& out, const Real* c, std::size_t order, const Real& h) {
#if VISCOR_HAS_MPFR
  if constexpr (is_mpfr<Real>::value) {
    mpfr_ptr acc = raw(out);
    mpfr_set(acc, raw(c[order]), MPFR_RNDN);
    for (std::size_t k = order; k-- > 0;) {
      mpfr_mul(acc, acc, raw(h), MPFR_RNDN);
      mpfr_add(acc, acc, raw(c[k]), MPFR_RNDN);
    }
    return;
  }
#endif
  Real acc = c[order];
  for (std::size_t k = order; k-- > 0;) {
    acc *= h;
    acc += c[k];
  }
  out = acc;
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
