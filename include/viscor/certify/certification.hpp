// Certified digits of a CoR: agreement of independent computations.
//
//   1. the Taylor method (taylor_impact.hpp) at the working precision of Real;
//   2. the Taylor method again at a higher precision (by default working + max(5,
//      working/20) digits) with the tolerance of that precision: the reference;
//   3. the adaptive GBS method (adaptive_impact.hpp) at the working precision, or,
//      where it is undecided there (an e or a creep below what the working precision
//      resolves), at the reference precision.
// The reported values are the reference rounded to Real. Their certified
// significant digits are the smallest number of digits on which 1 and 3 agree with
// the reference, over e, 1 - e, T_f and u_max, minus a safety margin, and never more
// than Real carries. Methods 1 and 3 share no integrator code (series vs.
// extrapolation, different event location and phase logic), so agreement to d digits
// is evidence that the reference is right to d digits; 2 checks that the working
// precision, not the method, limits 1.
//
// The outcome (rebound or stick) must be the same in all three: disagreement is
// reported as uncertified (outcome_certified = false, 0 digits), never averaged.
// An adaptive run undecided at the working precision is repeated at the reference
// precision, where it is the independent check instead (it is still the other
// method; its agreement is capped at the working digits like the others). Undecided
// there too, the outcome stays uncertified: an undecided e = 0 may be a creep the
// method failed to follow, so it never certifies an absolute e either.
// NOTE: the reference needs only to be right to more digits than Real carries, since
// agreement is capped at the working digits and the safety margin comes off that;
// working + max(5, working/20) digits were measured to suffice (docs/performance.md,
// section "certify/certification.hpp", has the measurements and the cost).
//
// Near the sticking threshold e -> 0 and its relative digits fall (e ~ sqrt of the
// distance to the threshold); absolute digits of e are reported as well.
//
// Where the linear law's closed form applies (alpha = beta = 1: every gamma and g,
// exact/exact_linear.hpp) the closed form is the independent check instead of the
// two integrators (which face a stiff creep when overdamped): it is evaluated at the working precision and
// at the reference precision, the values reported are the reference's, and the
// certified digits are their agreement minus the margin. The formula's loss of
// digits to its conditioning (about log10(g) at large g) shows in that agreement,
// and it costs microseconds at any gamma and g, where the integrators face a stiff
// creep at large gamma. certify_options::closed_form = false asks for the
// integrators anyway (tests of the integrators' certification).
#pragma once

#include <viscor/impact/adaptive_impact.hpp>
#include <viscor/certify/certified_digits_goal.hpp>
#include <viscor/certify/detail/perturbation.hpp>
#include <viscor/core/contact_law.hpp>
#include <viscor/core/detail/agreement_digits.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/core/impact_result.hpp>
#include <viscor/core/parameters.hpp>
#include <viscor/core/real_io.hpp>
#include <viscor/core/real_types.hpp>
#include <viscor/core/widen.hpp>
#include <viscor/exact/exact_linear.hpp>
#include <viscor/exact/exact_solutions.hpp>
#include <viscor/impact/taylor_impact.hpp>

#include <boost/math/special_functions/fpclassify.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace viscor {

/// Which computation a certificate entry is.
enum class certified_source {
  taylor,
  taylor_reference,
  adaptive,
  adaptive_reference,
  closed_form,
  closed_form_reference
};

/// The source's name as written in tables and JSON.
inline std::string_view to_string(certified_source s) {
  switch (s) {
    case certified_source::taylor: return "taylor";
    case certified_source::taylor_reference: return "taylor (reference precision)";
    case certified_source::adaptive: return "adaptive";
    case certified_source::adaptive_reference: return "adaptive (reference precision)";
    case certified_source::closed_form: return "closed form";
    case certified_source::closed_form_reference: return "closed form (reference precision)";
  }
  return "?";
}

/// Options of certify.
struct certify_options {
  int safety_margin = default_safety_margin;  ///< decimal digits subtracted from the agreement
  /// Precision of the reference run in decimal digits; 0: the default
  /// detail::reference_digits<Real>() = working + max(5, working/20), in a fixed-precision
  /// mpfr type (fast); any other value runs the reference in mpfr_real at that precision.
  int reference_digits = 0;
  /// Where the linear law's closed form applies, certify it (at the working and the
  /// reference precision) instead of running the two integrators (header comment).
  bool closed_form = true;
};

/// One contributing computation, as a reader would audit it.
template <class Real>
struct certified_computation {
  certified_source source = certified_source::taylor;
  int precision_digits = 0;  ///< decimal digits it computed with
  impact_outcome outcome = impact_outcome::rebound;
  Real e = 0, one_minus_e = 1, max_compression = 0;  ///< rounded to Real
  std::optional<Real> contact_time = Real(0);       ///< rounded to Real; empty: unknown
  std::string e_text, one_minus_e_text, contact_time_text;  ///< at its own full precision
  Real error_estimate = 0;  ///< the method's own estimate (not used for the digits)
  std::size_t steps = 0;
  double seconds = 0;  ///< wall time, for the cost report
  /// Digits on which it agrees with the reference (relative; e also absolute).
  int certified_digits_e = 0, certified_digits_one_minus_e = 0, certified_digits_contact_time = 0;
  int certified_digits_max_compression = 0;
  int certified_absolute_digits_e = 0;
};

/// A certified coefficient of restitution.
template <class Real>
struct certified_result {
  impact_outcome outcome = impact_outcome::rebound;
  bool outcome_certified = true;  ///< false: the computations disagree on rebound versus stick
  Real e = 0, one_minus_e = 1, max_compression = 0;  ///< the reference, rounded to Real
  std::optional<Real> contact_time = Real(0);       ///< the reference's, rounded to Real; empty: unknown
  int certified_digits = 0;  ///< certified significant digits of e, 1 - e, T_f and u_max (0: none)
  /// Per quantity, before the safety margin: the least agreement of taylor and adaptive with the reference.
  int certified_digits_e = 0, certified_digits_one_minus_e = 0, certified_digits_contact_time = 0;
  int certified_digits_max_compression = 0;
  int certified_absolute_digits_e = 0;       ///< certified decimal places of e (-log10 of its absolute spread, minus margin)
  bool near_sticking = false;      ///< e < 1e-3 or an uncertified outcome: read certified_absolute_digits_e
  int working_digits = 0;          ///< decimal_digits<Real>()
  int safety_margin = 0;
  /// taylor, reference, adaptive, and adaptive at the reference precision where the
  /// adaptive run was undecided at the working precision
  std::vector<certified_computation<Real>> computations;
};

namespace detail {

/// Default reference precision: working + max(5, working/20) decimal digits.
constexpr int reference_extra_digits(int working) { return working / 20 > 5 ? working / 20 : 5; }
template <class Real>
int reference_digits() {
  const int working = decimal_digits<Real>();
  return working + reference_extra_digits(working);
}

#if VISCOR_HAS_MPFR
template <unsigned D>
using mpfr_fixed = boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<D>>;
/// The reference type: fixed-precision mpfr at reference_digits<Real>(), derived
/// from Real's width (mpfr_real for run-time precision, checked in certify).
template <class Real>
struct certify_reference {
  using type = mpfr_real;
};
template <class Real>
  requires(std::numeric_limits<Real>::is_specialized && !is_mpfr<Real>::value)
struct certify_reference<Real> {
  static constexpr int working = fixed_decimal_digits<Real>();  // double 15, x87 long double 18, float128 33
  using type = mpfr_fixed<static_cast<unsigned>(working + reference_extra_digits(working))>;
  static_assert(fixed_decimal_digits<type>() >= working + reference_extra_digits(working),
                "the certification reference must be wider than the working type by the intended margin");
};
template <unsigned D, boost::multiprecision::mpfr_allocation_type A, boost::multiprecision::expression_template_option ET>
  requires(D > 0)
struct certify_reference<boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<D, A>, ET>> {
  using type = mpfr_fixed<D + reference_extra_digits(static_cast<int>(D))>;
  static_assert(fixed_decimal_digits<type>() >= static_cast<int>(D) + reference_extra_digits(static_cast<int>(D)),
                "the certification reference must be wider than the working type by the intended margin");
};
#endif

/// A computation's entry: its result (in its own type R) rounded to Real, its texts at
/// its own precision. caller_digits: the caller's precision for narrow() (run-time mpfr).
template <class Real, class R>
certified_computation<Real> record_narrowed(certified_source source, int digits, const impact_result<R>& r,
                                            double seconds, unsigned caller_digits) {
  certified_computation<Real> c;
  c.source = source;
  c.precision_digits = digits;
  c.outcome = r.outcome;
  c.e = narrow<Real>(r.e, caller_digits), c.one_minus_e = narrow<Real>(r.one_minus_e, caller_digits);
  if (r.contact_time) c.contact_time = narrow<Real>(*r.contact_time, caller_digits);
  else c.contact_time = std::nullopt;
  c.max_compression = narrow<Real>(r.max_compression, caller_digits);
  c.e_text = to_decimal_string(r.e), c.one_minus_e_text = to_decimal_string(r.one_minus_e);
  c.contact_time_text = to_decimal_string(or_nan(r.contact_time));
  c.error_estimate = narrow<Real>(r.error_estimate, caller_digits);
  c.steps = r.steps;
  c.seconds = seconds;
  return c;
}

/// A working-precision computation's entry.
template <class Real>
certified_computation<Real> record(certified_source source, int digits, const impact_result<Real>& r, double seconds) {
  certified_computation<Real> c;
  c.source = source;
  c.precision_digits = digits;
  c.outcome = r.outcome;
  c.e = r.e, c.one_minus_e = r.one_minus_e, c.contact_time = r.contact_time, c.max_compression = r.max_compression;
  c.e_text = to_decimal_string(r.e), c.one_minus_e_text = to_decimal_string(r.one_minus_e);
  c.contact_time_text = to_decimal_string(or_nan(r.contact_time));
  c.error_estimate = r.error_estimate;
  c.steps = r.steps;
  c.seconds = seconds;
  return c;
}

template <class F>
auto timed(F f, double& seconds) {
  const auto start = std::chrono::steady_clock::now();
  auto result = f();
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace detail

namespace detail {

// Digits on which a computation (x, in Ref) agrees with the reference, each capped at
// `working`, into c; a stick agreed on has e = 0 and 1 - e = 1 exactly.
template <class Ref, class Real>
void compare_with_reference(const impact_result<Ref>& x, const impact_result<Ref>& ref, int working,
                            certified_computation<Real>& c) {
  const Ref one = 1;
  c.certified_digits_e = agreement_digits(x.e, ref.e, ref.e, working);
  c.certified_absolute_digits_e = agreement_digits(x.e, ref.e, one, working);
  c.certified_digits_one_minus_e = agreement_digits(x.one_minus_e, ref.one_minus_e, ref.one_minus_e, working);
  const Ref x_time = or_nan(x.contact_time), ref_time = or_nan(ref.contact_time);
  c.certified_digits_contact_time = agreement_digits(x_time, ref_time, ref_time, working);
  c.certified_digits_max_compression = agreement_digits(x.max_compression, ref.max_compression, ref.max_compression, working);
  if (ref.outcome == impact_outcome::stick && x.outcome == impact_outcome::stick)
    c.certified_digits_e = c.certified_digits_one_minus_e = c.certified_absolute_digits_e = working;
}

/// A working-precision result exactly in Ref.
template <class Ref, class Real>
impact_result<Ref> widened(const impact_result<Real>& r) {
  impact_result<Ref> w;
  w.outcome = r.outcome;
  w.e = widen<Ref>(r.e), w.one_minus_e = widen<Ref>(r.one_minus_e);
  if (r.contact_time) w.contact_time = widen<Ref>(*r.contact_time);
  else w.contact_time = std::nullopt;
  w.max_compression = widen<Ref>(r.max_compression);
  return w;
}

// The reference solve and every comparison, in the reference type Ref; the adaptive
// run again at the reference precision where it was undecided at the working one.
template <class Ref, class Real>
void certify_against_reference(const contact_law& law, const Real& gamma, const Real& g, const certify_options& options,
                               const certify_perturbation& perturbation, int reference, unsigned caller_digits,
                               const impact_result<Real>& taylor, const impact_result<Real>& adaptive,
                               certified_result<Real>& out) {
  const int working = out.working_digits;
  // NOTE: the inputs are exact binary numbers of Real; widen converts them exactly.
  auto ref_gamma = [&](certified_source s) {
    Ref x = widen<Ref>(gamma);
    if (perturbation.which == s) x *= 1 + parse_real<Ref>(perturbation.relative, "perturbation");
    return x;
  };
  const Ref ref_g = widen<Ref>(g);
  double seconds = 0;
  const impact_result<Ref> ref = timed(
      [&] { return solve_impact_taylor<Ref>(law, ref_gamma(certified_source::taylor_reference), ref_g, {}); },
      seconds);
  certified_computation<Real> entry =
      record_narrowed<Real>(certified_source::taylor_reference, reference, ref, seconds, caller_digits);
  entry.certified_digits_e = entry.certified_digits_one_minus_e = entry.certified_digits_contact_time = reference;
  entry.certified_digits_max_compression = entry.certified_absolute_digits_e = reference;
  out.computations.insert(out.computations.begin() + 1, entry);
  out.outcome = ref.outcome;
  out.e = entry.e, out.one_minus_e = entry.one_minus_e;
  out.contact_time = entry.contact_time, out.max_compression = entry.max_compression;

  // The independent check: the adaptive method, at the reference precision if undecided.
  impact_result<Ref> independent = widened<Ref>(adaptive);
  if (adaptive.outcome == impact_outcome::undecided) {
    independent = timed(
        [&] { return solve_impact_adaptive<Ref>(law, ref_gamma(certified_source::adaptive_reference), ref_g, {}); },
        seconds);
    out.computations.push_back(
        record_narrowed<Real>(certified_source::adaptive_reference, reference, independent, seconds, caller_digits));
  }
  // An undecided outcome (any of them) is never certified, even if all agree on it.
  out.outcome_certified = taylor.outcome == ref.outcome && independent.outcome == ref.outcome &&
                          ref.outcome != impact_outcome::undecided;

  compare_with_reference(widened<Ref>(taylor), ref, working, out.computations[0]);
  compare_with_reference(widened<Ref>(adaptive), ref, working, out.computations[2]);
  if (out.computations.size() > 3) compare_with_reference(independent, ref, working, out.computations[3]);
  // Certified: the least agreement of the Taylor run and of the independent check.
  const certified_computation<Real>& t = out.computations[0];
  const certified_computation<Real>& i = out.computations.back();
  out.certified_digits_e = std::min(t.certified_digits_e, i.certified_digits_e);
  out.certified_digits_one_minus_e = std::min(t.certified_digits_one_minus_e, i.certified_digits_one_minus_e);
  out.certified_digits_contact_time = std::min(t.certified_digits_contact_time, i.certified_digits_contact_time);
  out.certified_digits_max_compression = std::min(t.certified_digits_max_compression, i.certified_digits_max_compression);
  out.certified_absolute_digits_e = std::min(t.certified_absolute_digits_e, i.certified_absolute_digits_e);
  const int agreement =
      std::min({out.certified_digits_e, out.certified_digits_one_minus_e, out.certified_digits_contact_time,
                out.certified_digits_max_compression});
  out.certified_digits = std::max(0, agreement - options.safety_margin);
  out.certified_absolute_digits_e = std::max(0, out.certified_absolute_digits_e - options.safety_margin);
  out.near_sticking = !out.outcome_certified || (ref.outcome == impact_outcome::rebound && ref.e < Ref(1) / 1000);
  if (!out.outcome_certified) out.certified_digits = 0, out.certified_absolute_digits_e = 0;
}

}  // namespace detail

namespace detail {

// The closed-form path (header comment): x is the linear law's closed form at the
// working precision; the reference evaluation and every comparison run in Ref.
template <class Ref, class Real>
void certify_closed_form_against_reference(const Real& gamma, const Real& g, const certify_options& options,
                                           const certify_perturbation& perturbation, int reference,
                                           unsigned caller_digits, const exact_result<Real>& x,
                                           certified_result<Real>& out) {
  const int working = out.working_digits;
  Ref ref_gamma = widen<Ref>(gamma);
  if (perturbation.which == certified_source::closed_form_reference)
    ref_gamma *= 1 + parse_real<Ref>(perturbation.relative, "perturbation");
  const Ref ref_g = widen<Ref>(g);
  double seconds = 0;
  const exact_result<Ref> ref = timed([&] { return exact_linear<Ref>(ref_gamma, ref_g); }, seconds);
  const Ref ref_time = or_nan(ref.contact_time), ref_u_max = or_nan(ref.max_compression);
  certified_computation<Real> entry;
  entry.source = certified_source::closed_form_reference;
  entry.precision_digits = reference;
  entry.outcome = ref.outcome;
  entry.e = narrow<Real>(ref.e, caller_digits);
  entry.one_minus_e = narrow<Real>(ref.one_minus_e, caller_digits);
  if (ref.contact_time) entry.contact_time = narrow<Real>(*ref.contact_time, caller_digits);
  else entry.contact_time = std::nullopt;
  entry.max_compression = narrow<Real>(ref_u_max, caller_digits);
  entry.e_text = to_decimal_string(ref.e), entry.one_minus_e_text = to_decimal_string(ref.one_minus_e);
  entry.contact_time_text = to_decimal_string(ref_time);
  entry.seconds = seconds;
  entry.certified_digits_e = entry.certified_digits_one_minus_e = entry.certified_digits_contact_time = reference;
  entry.certified_digits_max_compression = entry.certified_absolute_digits_e = reference;
  out.computations.push_back(entry);

  out.outcome = ref.outcome;
  out.e = entry.e, out.one_minus_e = entry.one_minus_e;
  out.contact_time = entry.contact_time, out.max_compression = entry.max_compression;
  out.outcome_certified = x.outcome == ref.outcome;

  certified_computation<Real>& c = out.computations.front();
  const Ref one = 1;
  c.certified_digits_e = agreement_digits(widen<Ref>(x.e), ref.e, ref.e, working);
  c.certified_absolute_digits_e = agreement_digits(widen<Ref>(x.e), ref.e, one, working);
  c.certified_digits_one_minus_e = agreement_digits(widen<Ref>(x.one_minus_e), ref.one_minus_e, ref.one_minus_e, working);
  c.certified_digits_contact_time = agreement_digits(widen<Ref>(or_nan(x.contact_time)), ref_time, ref_time, working);
  c.certified_digits_max_compression = agreement_digits(widen<Ref>(or_nan(x.max_compression)), ref_u_max, ref_u_max, working);
  if (x.outcome == impact_outcome::stick && ref.outcome == impact_outcome::stick)
    c.certified_digits_e = c.certified_digits_one_minus_e = c.certified_absolute_digits_e = working;  // e = 0, 1 - e = 1 exactly
  out.certified_digits_e = c.certified_digits_e, out.certified_digits_one_minus_e = c.certified_digits_one_minus_e;
  out.certified_digits_contact_time = c.certified_digits_contact_time;
  out.certified_digits_max_compression = c.certified_digits_max_compression;
  const int agreement =
      std::min({out.certified_digits_e, out.certified_digits_one_minus_e, out.certified_digits_contact_time,
                out.certified_digits_max_compression});
  out.certified_digits = std::max(0, agreement - options.safety_margin);
  out.certified_absolute_digits_e = std::max(0, c.certified_absolute_digits_e - options.safety_margin);
  out.near_sticking = !out.outcome_certified || (ref.outcome == impact_outcome::rebound && ref.e < Ref(1) / 1000);
  if (!out.outcome_certified) out.certified_digits = 0, out.certified_absolute_digits_e = 0;
}

// Runs f.template operator()<Ref>(reference digits) in certify's reference type for
// Real: the fixed-precision type, or mpfr_real at options.reference_digits.
template <class Real, class F>
void in_reference_type(const certify_options& options, int reference, int working, F f) {
  using Ref = typename certify_reference<Real>::type;
  if (options.reference_digits > 0 || std::is_same_v<Ref, mpfr_real>) {
    scoped_precision precision(reference);
    // Run-time precision: check what static_assert checks for the fixed types.
    if (decimal_digits<mpfr_real>() < reference || decimal_digits<mpfr_real>() <= working)
      throw precision_unavailable("certify: the reference precision (" + std::to_string(decimal_digits<mpfr_real>()) +
                                  " digits) is not wider than the working precision (" + std::to_string(working) +
                                  " digits)");
    f.template operator()<mpfr_real>(reference);
  } else {
    f.template operator()<Ref>(decimal_digits<Ref>());
  }
}

}  // namespace detail

namespace detail {

/// certify with one computation deliberately wrong (a test seam, see
/// detail/perturbation.hpp); certify itself calls it with no perturbation.
template <class Real>
certified_result<Real> certify_perturbed(const contact_law& law, const Real& gamma, const Real& g,
                                         const certify_options& options, const certify_perturbation& perturbation) {
  impact_parameters<Real>{law, gamma, g}.validate();
  if (options.safety_margin < 0)
    throw invalid_parameter("parameter safety_margin must be >= 0, got " + std::to_string(options.safety_margin));
#if !VISCOR_HAS_MPFR
  (void)perturbation;
  throw precision_unavailable("viscor::certify needs MPFR for its reference computation");
#else
  const int working = decimal_digits<Real>();
  const unsigned caller_digits = std::is_same_v<Real, mpfr_real> ? mpfr_real::thread_default_precision() : 0u;
  const int reference = options.reference_digits > 0 ? options.reference_digits : reference_digits<Real>();
  if (reference <= working)
    throw invalid_parameter("parameter reference_digits = " + std::to_string(reference) +
                            " must exceed the working precision of " + std::to_string(working) + " digits");

  auto perturbed = [&](certified_source s, const Real& x) {
    if (perturbation.which != s) return x;
    return Real(x * (1 + parse_real<Real>(perturbation.relative, "perturbation")));
  };

  certified_result<Real> out;
  out.working_digits = working;
  out.safety_margin = options.safety_margin;
  double seconds = 0;
  if (options.closed_form && closed_form_for(law, gamma == 0, g == 0) == closed_form::linear) {
    const exact_result<Real> x =
        timed([&] { return exact_linear<Real>(perturbed(certified_source::closed_form, gamma), g); }, seconds);
    certified_computation<Real> c;
    c.source = certified_source::closed_form;
    c.precision_digits = working;
    c.outcome = x.outcome;
    c.e = x.e, c.one_minus_e = x.one_minus_e;
    c.contact_time = x.contact_time, c.max_compression = or_nan(x.max_compression);
    c.e_text = to_decimal_string(x.e), c.one_minus_e_text = to_decimal_string(x.one_minus_e);
    c.contact_time_text = to_decimal_string(or_nan(x.contact_time));
    c.seconds = seconds;
    out.computations.push_back(c);
    in_reference_type<Real>(options, reference, working, [&]<class Ref>(int digits) {
      certify_closed_form_against_reference<Ref>(gamma, g, options, perturbation, digits, caller_digits, x, out);
    });
    return out;
  }
  const impact_result<Real> taylor = timed(
      [&] { return solve_impact_taylor<Real>(law, perturbed(certified_source::taylor, gamma), g, solve_options<Real>{}); },
      seconds);
  out.computations.push_back(record(certified_source::taylor, working, taylor, seconds));
  const impact_result<Real> adaptive = timed(
      [&] {
        return solve_impact_adaptive<Real>(law, perturbed(certified_source::adaptive, gamma), g, solve_options<Real>{});
      },
      seconds);
  out.computations.push_back(record(certified_source::adaptive, working, adaptive, seconds));

  in_reference_type<Real>(options, reference, working, [&]<class Ref>(int digits) {
    certify_against_reference<Ref>(law, gamma, g, options, perturbation, digits, caller_digits, taylor, adaptive, out);
  });
  return out;
#endif
}

}  // namespace detail

/// Certifies e, 1 - e, T_f and u_max at (law, gamma, g) by three computations (see the
/// header comment). Throws invalid_parameter for bad input, precision_unavailable
/// without MPFR, and lets convergence_error of any computation through.
template <class Real>
certified_result<Real> certify(const contact_law& law, const Real& gamma, const Real& g,
                               const certify_options& options = {}) {
  return detail::certify_perturbed(law, gamma, g, options, detail::certify_perturbation{});
}

}  // namespace viscor

// certify is compiled once per scalar type into libviscor (src/instantiation.cpp.in):
// declared extern here, so that no unit including this header instantiates it again.
#define VISCOR_CERTIFY_TEMPLATES(PREFIX, Real) \
  PREFIX template certified_result<Real> certify<Real>(const contact_law&, const Real&, const Real&,   \
                                                       const certify_options&);                  \
  PREFIX template certified_result<Real> detail::certify_perturbed<Real>(                              \
      const contact_law&, const Real&, const Real&, const certify_options&, const detail::certify_perturbation&);
#ifndef VISCOR_COMPILING_INSTANTIATIONS
namespace viscor {
VISCOR_FOR_EACH_COMPILED_WITH(VISCOR_CERTIFY_TEMPLATES, extern)
}
#endif
