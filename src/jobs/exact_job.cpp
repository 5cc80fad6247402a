// `viscor exact` (include/viscor/jobs/exact_job.hpp), compiled once.
#include <viscor/jobs/exact_job.hpp>

#include <viscor/core/precision.hpp>
#include <viscor/core/real_io.hpp>

#include <chrono>

namespace viscor::jobs {

exact_job_result run_exact(const exact_request& q) {
  return with_working_precision(q.digits, [&]<class Real>() {
    const Real gamma_value = parse_real<Real>(q.gamma, "gamma");
    const Real g_value = parse_real<Real>(q.g, "g");
    const auto start = std::chrono::steady_clock::now();
    const std::optional<exact_result<Real>> r = exact_cor(q.law, gamma_value, g_value);
    exact_job_result out;
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    out.law = q.law;
    out.gamma_text = q.gamma, out.g_text = q.g;
    out.gamma = working_number::of(gamma_value), out.g = working_number::of(g_value);
    out.precision = precision_used::of<Real>(q.digits);
    if (r) out.exact = detail::erased(*r);
    return out;
  });
}

}  // namespace viscor::jobs
