// `viscor approx` (include/viscor/jobs/approx_job.hpp), compiled once.
#include <viscor/jobs/approx_job.hpp>

#include <viscor/jobs/surrogate_files.hpp>
#include <viscor/core/precision.hpp>
#include <viscor/core/real_io.hpp>

#include <array>
#include <sstream>

namespace viscor::jobs {

namespace detail {

constexpr std::array<const char*, 8> formula_names{"all",   "small_g",       "large_g",         "schwager_poschel",
                                                   "prop2", "prop2_squared", "prop2_linearized", "surrogate"};

struct approx_job : approx_request {
  bool wants(const char* name) const { return formula == "all" || formula == name; }

  // --formula surrogate: the committed surrogate in double (docs/surrogate.md); never silently
  // outside its domain or for a law without one.
  approx_result run_surrogate(const contact_law& model) const {
    const surrogate::cor_surrogate* s = find_surrogate(model);
    if (!s)
      throw invalid_parameter("no surrogate for " + model.describe() + " (looked in '" + surrogate_directory() +
                              "'; build one with 'viscor surrogate build', docs/surrogate.md)");
    const double gamma_value = parse_real<double>(gamma, "gamma"), g_value = parse_real<double>(g, "g");
    const surrogate::surrogate_value v = (*s)(gamma_value, g_value);
    if (!v.in_domain) {
      std::ostringstream domain;
      domain << "0 <= gamma <= " << s->gamma_max << ", " << s->g_min << " <= g <= " << s->g_max;
      throw invalid_parameter("gamma = " + gamma + ", g = " + g + " is outside the domain of the " + model.name +
                              " surrogate (" + domain.str() + ")");
    }
    approx_result out;
    out.law = model;
    out.gamma_text = gamma, out.g_text = g;
    out.by_surrogate = true;
    out.e = v.e, out.one_minus_e = v.one_minus_e, out.outcome = v.outcome;
    out.bound = s->bound;
    return out;
  }

  approx_result run() const {
    const contact_law& model = law;
    if (gamma.empty()) throw invalid_parameter("approx needs " VISCOR_FIELD("gamma"));
    if (formula == "surrogate") return run_surrogate(model);
    bool known = false;
    for (const char* f : formula_names) known = known || formula == f;
    if (!known)
      throw invalid_parameter("parameter formula must be one of all, small_g, large_g, schwager_poschel, prop2, "
                              "prop2_squared, prop2_linearized, surrogate; got '" + formula + "'");
    std::vector<coefficient_source> sources;
    if (source == "all") {
      sources.assign(coefficient_sources.begin(), coefficient_sources.end());
    } else {
      sources.push_back(parse_coefficient_source(source));
    }
    return with_working_precision(digits, [&]<class Real>() {
      const auto of = [](const Real& x) { return working_number::of(x); };
      const Real gamma_value = parse_real<Real>(gamma, "gamma");
      const Real g_value = parse_real<Real>(g, "g");
      const cor_approximations<Real> approx(model, order);
      const auto& c = approx.closed_forms();

      approx_result out;
      out.law = model;
      out.gamma_text = gamma, out.g_text = g;
      out.gamma = of(gamma_value), out.g = of(g_value);
      out.precision = precision_used::of<Real>(digits);
      out.chebyshev_order = order;
      out.closed.I0 = of(c.I0), out.closed.Q0 = of(c.Q0), out.closed.dI_dg0 = of(c.dI_dg0);
      out.closed.C0 = of(c.C0), out.closed.C1 = of(c.C1), out.closed.C = of(c.C);
      out.closed.p = of(c.p), out.closed.C2 = of(c.C2);
      if (gamma_value > 0) out.critical_g = of(critical_g(c.alpha, c.beta, gamma_value));
      if (g_value > 0) out.critical_gamma = of(critical_gamma(c.alpha, c.beta, g_value));
      const bool all = formula == "all";

      if (wants("small_g")) out.small_g = of(approx.small_g(gamma_value, g_value));
      if (wants("large_g")) {
        if (all && g_value < 0) out.not_applicable.push_back("large_g (23) needs g >= 0");
        else out.large_g = of(approx.large_g(gamma_value, g_value));
      }
      if (wants("schwager_poschel")) {
        if (all && !approx.is_kuwabara_kono())
          out.not_applicable.push_back("schwager_poschel (25)+(30) exists for Kuwabara-Kono only");
        else out.schwager_poschel = of(approx.schwager_poschel(gamma_value, g_value));
      }
      out.prop2_asked = wants("prop2") || wants("prop2_squared") || wants("prop2_linearized");
      if (out.prop2_asked) {
        for (const coefficient_source s : sources) {
          if (source == "all" && s == coefficient_source::exact_at_zero && g_value != 0) {
            out.not_applicable.push_back("prop2 with exact_at_zero coefficients needs g = 0");
            continue;
          }
          if (source == "all" && s == coefficient_source::chebyshev_beta && g_value < 0) {
            out.not_applicable.push_back("prop2 with chebyshev_beta coefficients needs g >= 0");
            continue;
          }
          const prop2_result<Real> r = approx.prop2(gamma_value, g_value, s);
          prop2_value one;
          one.source = s;
          one.I = of(r.I), one.Q = of(r.Q), one.e_squared = of(r.e_squared);
          if (s == coefficient_source::chebyshev_beta) one.theta = of(theta_of_g(c.alpha, g_value));
          if (wants("prop2")) one.e = of(r.e);
          if (wants("prop2_squared")) one.e_plus = of(r.e_plus);
          if (wants("prop2_linearized")) one.e_linearized = of(r.e_linearized);
          out.prop2.push_back(std::move(one));
        }
      }
      return out;
    });
  }
};

}  // namespace detail

approx_result run_approx(const approx_request& q) {
  if (q.order < 1 || q.order > 999) throw invalid_parameter("order must be from 1 to 999, got " + std::to_string(q.order));
  return detail::approx_job{q}.run();
}

}  // namespace viscor::jobs
