// `viscor cor` for one point (include/viscor/jobs/cor_job.hpp), compiled once, and
// solve_cor for the scalar types chosen at run time.
#include <viscor/jobs/cor_job.hpp>

#if defined(VISCOR_WITH_ENCLOSE)
#include <viscor/enclose/enclose.hpp>
#endif

namespace viscor::jobs {

VISCOR_SOLVE_COR_RUNTIME_TEMPLATES()

namespace detail {

// --prove needs exact decimal inputs and rational exponents: checked before any work.
inline void check_provable(const contact_law& law, bool is_physical) {
  if (is_physical)
    throw invalid_parameter(VISCOR_FIELD("prove") " needs the scaled " VISCOR_FIELD("gamma") " and "
                            VISCOR_FIELD("g") " (exact decimals), not physical inputs");
  if (const std::string why = law.why_not_provable(); !why.empty()) throw invalid_parameter(why);
#if !defined(VISCOR_WITH_ENCLOSE)
  throw invalid_parameter(VISCOR_FIELD("prove")
                          ": this viscor was built without Arb (apt-get install libflint-arb-dev)");
#endif
}

}  // namespace detail

namespace {

// One run of the job at q.digits.
cor_result run_cor_at_precision(const cor_request& q) {
  const bool is_physical = q.physical.given();
  cor_result out = with_working_precision(q.digits, [&]<class Real>() {
    Real gamma_value, g_value;
    std::optional<scaled_parameters<Real>> scales;
    std::optional<physical_parameters<Real>> bead;
    if (is_physical) {
      bead = q.physical.parameters<Real>(q.law);
      scales = to_scaled(q.law, *bead);
      gamma_value = scales->gamma, g_value = scales->g;
    } else {
      gamma_value = parse_real<Real>(*q.gamma, "gamma");
      g_value = q.g ? parse_real<Real>(*q.g, "g") : Real(0);
    }
    solve_options<Real> options;
    options.method = q.method;
    options.tolerance = parse_real<Real>(q.tolerance, "tolerance");
    options.max_steps = q.max_steps;
    cor_result r = solve_cor(q.law, gamma_value, g_value, options, q.certify, q.digits);
    if (scales) {
      physical_side side;
      side.inputs = q.physical;
      side.m = working_number::of(bead->m), side.k = working_number::of(bead->k);
      side.time_scale = working_number::of(scales->time_scale);
      side.length_scale = working_number::of(scales->length_scale);
      const auto seconds = [&](const Real& t) { return in_seconds(t, scales->time_scale); };
      if (r.contact_time) side.contact_time_s = working_number::of(seconds(*r.contact_time->as<Real>()));
      side.max_compression_m = working_number::of(Real(*r.max_compression.as<Real>() * scales->length_scale));
      if (r.certified) {  // held in Real (certify<Real>); a value of another type stays unknown
        const certified_result<working_number>& c = *r.certified;
        if (const Real* t = c.contact_time ? c.contact_time->as<Real>() : nullptr)
          side.certified_contact_time_s = working_number::of(seconds(*t));
        if (const Real* u = c.max_compression.as<Real>())
          side.certified_max_compression_m = working_number::of(Real(*u * scales->length_scale));
      }
      r.physical = std::move(side);
    }
    return r;
  });
#if defined(VISCOR_WITH_ENCLOSE)
  if (q.prove) out.proof = viscor::enclose(q.law, *q.gamma, q.g ? *q.g : std::string("0"), q.digits);
#endif
  return out;
}

// The goal's runs certify without proving; the proof, when asked for, runs once at the
// precision that met the goal.
cor_result run_cor_to_goal(cor_request q) {
  const int wanted = *q.certified_digits;
  const bool prove = q.prove;
  q.certified_digits.reset();
  q.certify = true, q.prove = false;
  cor_result out = certify_cor_to_goal(wanted, [&](int digits) {
    q.digits = digits;
    return run_cor_at_precision(q);
  });
#if defined(VISCOR_WITH_ENCLOSE)
  if (prove) out.proof = viscor::enclose(q.law, *q.gamma, q.g ? *q.g : std::string("0"), q.digits);
#else
  (void)prove;  // refused by run_cor's checks
#endif
  return out;
}

}  // namespace

cor_result run_cor(cor_request q) {
  const bool is_physical = q.physical.given();
  if (is_physical && (q.gamma || q.g))
    throw invalid_parameter("give either the physical inputs (" + q.physical.given_names() +
                            ") or the scaled " VISCOR_FIELD("gamma") "/" VISCOR_FIELD("g") ", not both");
  if (!is_physical && !q.gamma)
    throw invalid_parameter("cor needs " VISCOR_FIELD("gamma") " (and optionally " VISCOR_FIELD("g")
                            "), or the physical inputs " VISCOR_FIELD("m") " " VISCOR_FIELD("k") " "
                            VISCOR_FIELD("gamma0") " " VISCOR_FIELD("v0") " "
                            VISCOR_FIELD("gravity") " [" VISCOR_FIELD("force") "], or " VISCOR_FIELD("points") " FILE");
  if (is_physical) {
    q.physical.check("cor");
    q.physical.require_gamma0("cor");
  }
  if (q.prove) detail::check_provable(q.law, is_physical);
  if (q.certified_digits) return run_cor_to_goal(q);
  return run_cor_at_precision(q);
}

}  // namespace viscor::jobs
