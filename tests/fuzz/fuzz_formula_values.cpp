// Fuzz target: the values file of `viscor formula check` (a user's formula evaluated
// at the reference points: gamma,g,e or gamma,g,one_minus_e): jobs/formula_job.hpp,
// parse_formula_values. Checks beyond "no crash": every value accepted is a finite
// double at a finite (gamma, g), and a refusal names the file.
#include "fuzz_support.hpp"

#include <viscor/jobs/formula_job.hpp>

#include <cmath>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 65536) return 0;
  const std::string text = viscor::fuzz::text_of(data, size);
  try {
    const viscor::jobs::formula_values v = viscor::jobs::parse_formula_values(text, "values.csv");
    for (const auto& [point, value] : v.at)
      viscor::fuzz::fuzz_require(std::isfinite(point.first) && std::isfinite(point.second) && std::isfinite(value),
                                 "a value accepted that is not finite");
  } catch (const viscor::error& e) {
    viscor::fuzz::fuzz_require(std::string(e.what()).rfind("values.csv", 0) == 0 ||
                                   std::string(e.what()).find("(values.csv:") != std::string::npos,
                               std::string("a refusal that does not name the file: ") + e.what());
  } catch (const std::exception& e) {
    viscor::fuzz::fuzz_require(false, std::string("an exception other than viscor::error escaped: ") + e.what());
  }
  return 0;
}
