// `viscor scale` (include/viscor/jobs/scale_job.hpp), compiled once.
#include <viscor/jobs/scale_job.hpp>

#include <viscor/core/precision.hpp>
#include <viscor/core/real_io.hpp>
#include <viscor/core/scaling.hpp>

namespace viscor::jobs {

scale_result run_scale(scale_request q) {
  const bool inverse = q.gamma || q.g;
  if (inverse && (!q.gamma || !q.g)) throw invalid_parameter("scaled -> physical needs both " VISCOR_FIELD("gamma")
                                                             " and " VISCOR_FIELD("g"));
  if (inverse && q.physical.gamma0)
    throw invalid_parameter("give either " VISCOR_FIELD("gamma0") " (physical -> scaled) or " VISCOR_FIELD("gamma")
                            "/" VISCOR_FIELD("g") " (scaled -> physical)");
  if (inverse && q.physical.force) throw invalid_parameter("scaled -> physical computes " VISCOR_FIELD("force")
                                                           " from " VISCOR_FIELD("g") "; do not give it");
  q.physical.check("scale");
  return with_working_precision(q.digits, [&]<class Real>() {
    scale_result out;
    out.law = q.law;
    out.physical = q.physical;
    out.precision = precision_used::of<Real>(q.digits);
    out.scaled_to_physical = inverse;
    if (inverse) {
      const auto [mass, stiffness] = q.physical.bead<Real>(q.law);
      const Real speed = parse_real<Real>(*q.physical.v0, "v0");
      const Real grav = q.physical.acting_gravity<Real>();
      const Real gamma_value = parse_real<Real>(*q.gamma, "gamma"), g_value = parse_real<Real>(*q.g, "g");
      const physical_parameters<Real> p = to_physical(q.law, gamma_value, g_value, mass, stiffness, speed, grav);
      out.gamma = working_number::of(gamma_value), out.g = working_number::of(g_value);
      out.gamma0 = working_number::of(p.gamma0), out.force = working_number::of(p.force);
    } else {
      const scaled_parameters<Real> sc = to_scaled(q.law, q.physical.parameters<Real>(q.law));
      out.gamma = working_number::of(sc.gamma), out.g = working_number::of(sc.g);
      out.time_scale = working_number::of(sc.time_scale), out.length_scale = working_number::of(sc.length_scale);
    }
    return out;
  });
}

}  // namespace viscor::jobs
