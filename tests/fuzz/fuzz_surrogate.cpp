// Fuzz target: surrogate files (reference_data/surrogates/*.surrogate, --surrogate
// FILE): surrogate/cor_surrogate.hpp's reader, then evaluations. Checks beyond
// "no crash": a file that reads writes back to text that reads to the same text;
// the surrogate evaluates, inverts and locates patches at points across and
// outside its domain without reading outside its tables (the sanitizers watch)
// or looping (libFuzzer's timeout watches).
#include "fuzz_support.hpp"

#include <viscor/surrogate/cor_surrogate.hpp>

#include <sstream>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using viscor::fuzz::fuzz_require;
  if (size > (1u << 20)) return 0;
  const std::string text = viscor::fuzz::text_of(data, size);
  viscor::fuzz::refusal_or_result([&] {
    std::istringstream in(text);
    const viscor::surrogate::cor_surrogate s = viscor::surrogate::read_cor_surrogate(in, "s.surrogate");
    std::ostringstream out;
    viscor::surrogate::write_cor_surrogate(out, s);
    std::istringstream in2(out.str());
    viscor::surrogate::cor_surrogate s2;
    try {
      s2 = viscor::surrogate::read_cor_surrogate(in2, "written.surrogate");
    } catch (const viscor::error& e) {
      fuzz_require(false, std::string("a surrogate as written is refused: ") + e.what());
    }
    std::ostringstream out2;
    viscor::surrogate::write_cor_surrogate(out2, s2);
    fuzz_require(out.str() == out2.str(), "a surrogate changes when written and read back");

    const double gammas[] = {0, 1e-12, 1e-3, 0.5 * s.gamma_max, s.gamma_max, -1, 2 * s.gamma_max + 1};
    const double gs[] = {s.g_min, 0, s.g_split, 0.5 * (s.g_min + s.g_max), s.g_max, 1e300, -1e300};
    for (const double gamma : gammas)
      for (const double g : gs) {
        const auto v = s(gamma, g);
        if (v.in_domain) (void)s.gamma_for(0.5, g);
      }
  });
  return 0;
}
