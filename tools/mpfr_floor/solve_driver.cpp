// Times 50-digit CoR solves (the Taylor method, solve_impact<mpfr_50>) at the bench
// points of docs/performance.md, and, run under the counting library of
// mpfr_floor.py (LD_PRELOAD), brackets the solves so that only their MPFR calls count.
// Usage: solve_driver SOLVES   (prints: precision bits, steps, CPU microseconds per solve)
#include <viscor/impact/solve_impact.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <dlfcn.h>
#include <vector>

namespace {

double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// The counting library's hooks, when it is preloaded; otherwise nothing.
void call_hook(const char* name) {
  if (auto* f = reinterpret_cast<void (*)()>(dlsym(RTLD_DEFAULT, name))) f();
}

}  // namespace

int main(int argc, char** argv) {
  using viscor::mpfr_50;
  const int solves = argc > 1 ? std::atoi(argv[1]) : 20;
  const viscor::contact_law law = viscor::law_by_name("kuwabara_kono");
  struct point { const char* gamma; const char* g; };
  for (const point p : {point{"0.05", "1"}, point{"1e-3", "0.05"}}) {
    const mpfr_50 gamma = viscor::parse_real<mpfr_50>(p.gamma, "gamma"), g = viscor::parse_real<mpfr_50>(p.g, "g");
    const auto warm = viscor::solve_impact<mpfr_50>(law, gamma, g);  // first-call costs (constants) out
    std::vector<double> times;
    call_hook("mpfr_floor_reset");
    for (int i = 0; i < solves; ++i) {
      const double t0 = cpu_seconds();
      const auto r = viscor::solve_impact<mpfr_50>(law, gamma, g);
      times.push_back(cpu_seconds() - t0);
      if (r.e != warm.e) return 1;
    }
    call_hook("mpfr_floor_dump");
    std::sort(times.begin(), times.end());
    std::printf("point gamma=%s g=%s bits=%ld steps=%zu median_us=%.1f solves=%d\n", p.gamma, p.g,
                static_cast<long>(mpfr_get_prec(gamma.backend().data())), warm.steps, 1e6 * times[times.size() / 2],
                solves);
    std::fflush(stdout);
  }
}
