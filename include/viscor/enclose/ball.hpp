// Ball arithmetic for proofs: a value type around Arb's arb_t (midpoint-radius
// intervals; every operation returns a ball that contains the exact result for
// every choice of points in its operands). Arb rather than MPFI: its balls keep
// a full-precision midpoint with a low-precision radius, so a ball costs about
// one MPFR number where an MPFI interval costs two, and it has rigorous
// elementary functions (pow, log) that MPFI lacks for rational exponents.
// docs/proofs.md says what is proven with it and how.
#pragma once

#include <viscor/core/real_io.hpp>
#include <viscor/core/exceptions.hpp>

#include <arb.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <string_view>
#include <utility>

/// @namespace viscor::proofs
/// Proven enclosures: ball arithmetic, validated Taylor steps, proven impacts (docs/proofs.md).
namespace viscor::proofs {

namespace detail {
/// Precision of every ball operation on this thread, in bits.
inline thread_local slong ball_bits = 256;
}  // namespace detail

/// Sets the ball precision of this thread to `bits` for a scope.
class scoped_ball_bits {
 public:
  /// Sets `bits` (>= 16; throws invalid_parameter otherwise) until the end of the scope.
  explicit scoped_ball_bits(slong bits) : m_saved(detail::ball_bits) {
    if (bits < 16) throw invalid_parameter("ball precision must be >= 16 bits, got " + std::to_string(bits));
    detail::ball_bits = bits;
  }
  ~scoped_ball_bits() { detail::ball_bits = m_saved; }
  scoped_ball_bits(const scoped_ball_bits&) = delete;
  scoped_ball_bits& operator=(const scoped_ball_bits&) = delete;

 private:
  slong m_saved;
};

/// The ball precision of this thread, in bits.
inline slong ball_bits() { return detail::ball_bits; }

/// A real ball [mid +/- rad] (an arb_t).
class ball {
 public:
  /// The exact zero.
  ball() { arb_init(m); }
  /// The exact integer n.
  ball(long n) {  // NOLINT: implicit, so that 2 * x reads as in the formulas
    arb_init(m);
    arb_set_si(m, n);
  }
  /// The smallest ball Arb finds around the decimal number `text` (exact when
  /// the decimal is a dyadic number representable at the current precision).
  /// Throws invalid_parameter naming `text` when it is not a finite decimal.
  static ball from_decimal(std::string_view text, std::string_view name = "number") {
    ball b;
    const std::string s(text);
    if (s.find('[') != std::string::npos || s.find("+/-") != std::string::npos)
      throw invalid_parameter("parameter " + std::string(name) + " must be an exact decimal, got the ball '" + s +
                              "': a proof is for one exact value, not an interval");
    // The grammar every other input of viscor is read with (one number parser): no
    // spaces, one sign, no Arb-only forms.
    if (!viscor::detail::looks_like_decimal(s) || arb_set_str(b.m, s.c_str(), ball_bits()) != 0 || !arb_is_finite(b.m))
      throw invalid_parameter("parameter " + std::string(name) + " must be a finite decimal number, but got '" + s +
                              "'");
    return b;
  }
  /// The interval [lo, hi] (lo <= hi).
  static ball hull(const ball& lo, const ball& hi) {
    ball b;
    arb_union(b.m, lo.m, hi.m, ball_bits());
    return b;
  }
  /// Copies (and moves) keep the ball exactly.
  ball(const ball& o) {
    arb_init(m);
    arb_set(m, o.m);
  }
  /// Takes o's ball; o becomes the exact zero.
  ball(ball&& o) noexcept {
    arb_init(m);
    arb_swap(m, o.m);
  }
  /// Copies o's ball.
  ball& operator=(const ball& o) {
    if (this != &o) arb_set(m, o.m);
    return *this;
  }
  /// Swaps with o's ball.
  ball& operator=(ball&& o) noexcept {
    arb_swap(m, o.m);
    return *this;
  }
  ~ball() { arb_clear(m); }

  /// The underlying arb_t, for Arb functions not wrapped here.
  arb_ptr get() noexcept { return m; }
  /// The underlying arb_t, read-only.
  arb_srcptr get() const noexcept { return m; }

  /// Whether every point of the ball is > 0 (proven).
  bool positive() const { return arb_is_positive(m); }
  /// Whether every point is < 0 (proven).
  bool negative() const { return arb_is_negative(m); }
  /// Whether every point is >= 0 (proven).
  bool nonnegative() const { return arb_is_nonnegative(m); }
  /// Whether every point is <= 0 (proven).
  bool nonpositive() const { return arb_is_nonpositive(m); }
  /// Whether midpoint and radius are finite.
  bool finite() const { return arb_is_finite(m); }
  /// Whether `inner` lies in the interior of this ball.
  bool contains_interior(const ball& inner) const { return arb_contains_interior(m, inner.m); }
  /// Whether `inner` lies in this ball.
  bool contains(const ball& inner) const { return arb_contains(m, inner.m); }
  /// Whether the two balls share a point.
  bool overlaps(const ball& o) const { return arb_overlaps(m, o.m); }

  /// The midpoint rounded to double (for heuristics and reports only).
  double mid_double() const { return arf_get_d(arb_midref(m), ARF_RND_NEAR); }
  /// The radius rounded to double (for heuristics and reports only).
  double rad_double() const { return mag_get_d(arb_radref(m)); }
  /// An integer e with |mid| < 2^e (for step-size heuristics; very negative for 0).
  long log2_bound() const {
    if (arf_is_zero(arb_midref(m))) return -1000000;
    return arf_abs_bound_lt_2exp_si(arb_midref(m));
  }
  /// The exact midpoint as a ball of radius 0.
  ball mid() const {
    ball b;
    arb_get_mid_arb(b.m, m);
    return b;
  }
  /// The radius as a ball of radius 0.
  ball rad() const {
    ball b;
    arb_get_rad_arb(b.m, m);
    return b;
  }
  /// Upper bound of |x| over the ball, as a ball of radius 0.
  ball abs_upper() const {
    arf_t u;
    arf_init(u);
    arb_get_abs_ubound_arf(u, m, ball_bits());
    ball b;
    arb_set_arf(b.m, u);
    arf_clear(u);
    return b;
  }
  /// The ball grown by |e| (every point of e's ball counted).
  ball widened(const ball& e) const {
    ball b(*this);
    arb_add_error(b.m, e.m);
    return b;
  }
  /// Decimal text "mid +/- rad" that encloses the ball (Arb's rigorous printout),
  /// with `digits` significant digits of the midpoint.
  std::string str(long digits) const {
    char* c = arb_get_str(m, digits, 0);
    std::string s(c);
    flint_free(c);
    return s;
  }
  /// The midpoint as a decimal with `digits` significant digits (not an enclosure).
  std::string mid_str(long digits) const {
    char* c = arb_get_str(m, digits, ARB_STR_NO_RADIUS);
    std::string s(c);
    flint_free(c);
    return s;
  }
  /// Relative accuracy in bits (Arb's rel_accuracy_bits; large for exact balls).
  long relative_accuracy_bits() const { return arb_rel_accuracy_bits(m); }

  friend ball operator-(const ball& x) {
    ball r;
    arb_neg(r.m, x.m);
    return r;
  }
  friend ball operator+(const ball& x, const ball& y) {
    ball r;
    arb_add(r.m, x.m, y.m, ball_bits());
    return r;
  }
  friend ball operator-(const ball& x, const ball& y) {
    ball r;
    arb_sub(r.m, x.m, y.m, ball_bits());
    return r;
  }
  friend ball operator*(const ball& x, const ball& y) {
    ball r;
    arb_mul(r.m, x.m, y.m, ball_bits());
    return r;
  }
  /// x / y; a ball containing 0 in y gives an infinite ball (never a wrong one).
  friend ball operator/(const ball& x, const ball& y) {
    ball r;
    arb_div(r.m, x.m, y.m, ball_bits());
    return r;
  }
  /// *this = *this + y (in place: Arb allows the output to alias an input).
  ball& operator+=(const ball& y) {
    arb_add(m, m, y.m, ball_bits());
    return *this;
  }
  /// *this = *this - y.
  ball& operator-=(const ball& y) {
    arb_sub(m, m, y.m, ball_bits());
    return *this;
  }
  /// *this = *this * y.
  ball& operator*=(const ball& y) {
    arb_mul(m, m, y.m, ball_bits());
    return *this;
  }

 private:
  arb_t m;
};

/// sqrt(x); a ball reaching below 0 gives an indeterminate ball.
inline ball sqrt(const ball& x) {
  ball r;
  arb_sqrt(r.get(), x.get(), ball_bits());
  return r;
}

/// x^n for an integer n >= 0.
inline ball pow(const ball& x, unsigned long n) {
  ball r;
  arb_pow_ui(r.get(), x.get(), n, ball_bits());
  return r;
}

/// The bits a proof at `digits` decimal digits works with: the digits plus at least
/// 24 guard bits, rounded up to whole 64-bit limbs. The guard bits absorb the widening
/// of the enclosure over an impact (about 15-21 bits, measured: docs/proofs.md); a
/// part-used limb costs as much as a full one, and Arb is fastest at one or two limbs,
/// so 30 digits work in 128 bits (64 guard bits would take them to 192).
inline slong working_bits(int digits) {
  const slong needed = static_cast<slong>(std::ceil(digits * 3.3219280948873623)) + 24;
  return (needed + 63) / 64 * 64;
}

}  // namespace viscor::proofs
