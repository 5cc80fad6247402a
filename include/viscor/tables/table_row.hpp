// One row of a reference table: the single place where a grid point is turned
// into certified numbers. Every table command (viscor table, its shards and
// resumed runs, viscor table sticking) evaluates points only through
// evaluate_point / compute_row below.
//
// Sources of a row, in order of preference for row_method::automatic:
//   1. viscor::certify (include/viscor/certify/certification.hpp): Taylor and adaptive
//      solves at two precisions; certified digits = their agreement minus a margin.
//   2. viscor::exact_cor: a closed form (linear law at any g; gamma = 0; beta =
//      alpha + 1 and Tsuji at g = 0; closed_form_for decides) evaluated at the
//      working precision; its digits are those on which e, 1 - e, T_f and u_max
//      agree with the same closed form at 10 more digits (check_closed_form),
//      minus 1 (at most the working digits - 2), since a formula can lose digits
//      to its conditioning (the linear law about log10(g) at large g).
// A point with neither is an error: no row is ever written without a certificate.
#pragma once

#include <viscor/exact/exact_solutions.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/tables/grid_spec.hpp>
#include <viscor/core/outcome.hpp>
#include <viscor/core/precision.hpp>
#include <viscor/core/real_io.hpp>
#include <viscor/core/working_number.hpp>
#include <viscor/tables/reference_table.hpp>

#include <boost/math/special_functions/fpclassify.hpp>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>

#include <viscor/certify/certification.hpp>
#include <viscor/certify/certified_digits_goal.hpp>

namespace viscor {

/// How rows are computed (from the spec).
struct table_settings {
  int digits = 40;  ///< working precision, decimal digits
  row_method method = row_method::automatic;
  int min_digits = 0;  ///< rebound rows certified to fewer digits are errors
  /// Certified digits asked of every row (0: none): a row that falls short at `digits`
  /// is computed again at a raised precision (certify/certified_digits_goal.hpp).
  int certified_digits = 0;

  /// The settings a spec asks for.
  static table_settings from(const grid_spec& spec) {
    return {spec.digits, spec.method, spec.min_digits, spec.certified_digits};
  }
};

/// A certified evaluation at one point, in the working type.
template <class Real>
struct point_result {
  impact_outcome outcome = impact_outcome::rebound;
  Real e = 0, one_minus_e = 1;
  std::optional<Real> contact_time, max_compression;
  int certified_digits = 0;       ///< certified significant digits of e, 1 - e, T_f, u_max
  bool outcome_certified = true;  ///< false: the methods disagree on rebound versus stick
  row_source source = row_source::exact;
};

/// Throws invalid_parameter (before any work) if `method` cannot compute this point.
inline void require_computable(const contact_law& law, bool gamma_is_zero, bool g_is_zero, row_method method,
                               const std::string& what) {
  if (method != row_method::exact) return;
  if (!closed_form_exists(law, gamma_is_zero, g_is_zero))
    throw invalid_parameter(what + ": no closed form exists for " + law.describe() +
                            " (use method 'auto' or 'certify')");
}

namespace detail {

template <class Real>
point_result<Real> exact_point(const contact_law& law, const Real& gamma, const Real& g, int working_digits,
                               const decimal_inputs& inputs) {
  const std::optional<exact_result<Real>> x = exact_cor(law, gamma, g);
  if (!x)
    throw invalid_parameter("no closed form exists for " + law.describe() + " at gamma = " +
                            to_decimal_string(gamma) + ", g = " + to_decimal_string(g));
  point_result<Real> r;
  r.outcome = x->outcome;
  r.e = x->e, r.one_minus_e = x->one_minus_e;
  r.contact_time = x->contact_time, r.max_compression = x->max_compression;
  // The digits each quantity has (a second evaluation at more digits), less one for
  // rounding the row to them, and never more than the working digits - 2 (the
  // rounding of the inputs and of the evaluation).
  const int cap = std::min(working_digits, decimal_digits<Real>());
  const closed_form_digits checked = check_closed_form(law, gamma, g, *x, cap, inputs);
  r.outcome_certified = checked.outcome_agrees;
  r.certified_digits = std::max(0, std::min(checked.least() - 1, cap - 2));
  r.source = row_source::exact;
  return r;
}

// The one call into viscor::certify (certified_result of certification.hpp).
template <class Real>
point_result<Real> certified_point(const contact_law& law, const Real& gamma, const Real& g) {
  const auto c = certify<Real>(law, gamma, g);
  point_result<Real> r;
  r.outcome = c.outcome;
  r.e = c.e, r.one_minus_e = c.one_minus_e;
  r.contact_time = c.contact_time, r.max_compression = c.max_compression;
  r.certified_digits = c.certified_digits;
  r.outcome_certified = c.outcome_certified;
  r.source = row_source::certified;
  return r;
}

}  // namespace detail

/// The certified result at (law, gamma, g) in the working type Real, by the
/// method of `settings` (see the header comment). Throws invalid_parameter for
/// a point the method cannot certify.
/// `inputs`: the decimal texts gamma and g were rounded from (a table row's), so
/// that a closed-form row's digits account for that rounding too.
template <class Real>
point_result<Real> evaluate_point(const contact_law& law, const Real& gamma, const Real& g,
                                  const table_settings& settings, const decimal_inputs& inputs = std::nullopt) {
  impact_parameters<Real>{law, gamma, g}.validate();
  require_computable(law, gamma == 0, g == 0, settings.method,
                     "point gamma = " + to_decimal_string(gamma) + ", g = " + to_decimal_string(g));
  if (settings.method != row_method::exact) return detail::certified_point(law, gamma, g);
  return detail::exact_point(law, gamma, g, settings.digits, inputs);
}

/// x rounded to `digits` significant digits: "0" for zero, "inf" for infinity.
template <class Real>
std::string rounded_decimal(const Real& x, int digits) {
  using boost::math::isinf;
  if (x == 0) return "0";
  if (isinf(x)) return x > 0 ? "inf" : "-inf";
  return to_decimal_string(x, digits);
}

/// x, held in its working type, rounded as rounded_decimal rounds that type.
inline std::string rounded_decimal(const working_number& x, int digits) {
  if (x.is_zero()) return "0";
  if (x.is_infinite()) return x.value() > 0 ? "inf" : "-inf";
  return x.decimal(digits);
}

/// Formats a certified point as a table row (Real -> rounded decimal strings).
template <class Real>
table_row make_row(const grid_point& p, const point_result<Real>& r) {
  table_row row;
  row.index = p.index;
  row.law = p.law.name, row.alpha = p.law.alpha.to_string(), row.beta = p.law.beta.to_string();
  row.gamma = p.gamma, row.g = p.g;
  row.outcome = r.outcome;
  row.certified_digits = r.certified_digits;
  row.source = r.source;
  const int d = r.certified_digits;
  if (r.outcome == impact_outcome::stick) {
    row.e = "0", row.one_minus_e = "1";  // certified outcome: e = 0 exactly
  } else if (r.one_minus_e == 0) {
    row.e = "1", row.one_minus_e = "0";  // gamma = 0: energy is conserved exactly
  } else {
    row.e = rounded_decimal(r.e, d), row.one_minus_e = rounded_decimal(r.one_minus_e, d);
  }
  if (d >= 1) {
    if (r.contact_time) row.contact_time = rounded_decimal(*r.contact_time, d);
    if (r.max_compression) row.max_compression = rounded_decimal(*r.max_compression, d);
  }
  return row;
}

namespace detail {

/// One row computed at settings.digits, not yet judged.
struct row_attempt {
  table_row row;
  bool outcome_certified = true;
  int working_digits = 0;  ///< decimal digits of the type it ran in
};

inline row_attempt attempt_row(const grid_point& p, const table_settings& settings) {
  return with_working_precision(settings.digits, [&]<class Real>() -> row_attempt {
    const Real gamma = parse_real<Real>(p.gamma, "gamma"), g = parse_real<Real>(p.g, "g");
    const point_result<Real> r = evaluate_point(p.law, gamma, g, settings, decimal_inputs{{p.gamma, p.g}});
    return {make_row(p, r), r.outcome_certified, decimal_digits<Real>()};
  });
}

}  // namespace detail

/// Computes one row of a CoR table: parses the exact decimal inputs at the
/// working precision of `settings` (in the calling thread), certifies the point
/// and rounds the results to their certified digits; with settings.certified_digits,
/// again at a raised precision until the row has them. Throws certification_error
/// for an uncertified outcome or a rebound certified to fewer than
/// settings.min_digits (or certified_digits) digits: a row is written certified or
/// not at all.
inline table_row compute_row(const grid_point& p, const table_settings& settings) {
  const std::string where = "row " + std::to_string(p.index) + " (" + p.law.describe() + ", gamma = " + p.gamma +
                            ", g = " + p.g + ")";
  detail::row_attempt a;
  if (settings.certified_digits > 0) {
    table_settings at = settings;
    certified_digits_goal goal;
    try {
      a = certify_to_goal(
          settings.certified_digits, default_safety_margin,
          [&](int digits) {
            at.digits = digits;
            return detail::attempt_row(p, at);
          },
          [](const detail::row_attempt& x) {
            return precision_run{x.working_digits, x.outcome_certified ? x.row.certified_digits : 0};
          },
          goal);
    } catch (const certified_digits_unreached& e) {
      throw certification_error(where + ": " + e.marked());
    }
  } else {
    a = detail::attempt_row(p, settings);
  }
  if (!a.outcome_certified)
    throw certification_error(where + ": the methods disagree on the outcome (rebound or stick)");
  if (a.row.outcome == impact_outcome::rebound && (a.row.certified_digits < 1 || a.row.certified_digits < settings.min_digits))
    throw certification_error(where + ": certified to " + std::to_string(a.row.certified_digits) +
                              " digits only (min_digits = " + std::to_string(settings.min_digits) +
                              "); raise the working digits");
  return a.row;
}

}  // namespace viscor
