// Fuzz target: table specs (viscor table SPEC.json): include/viscor/jobs/table_spec.hpp's
// reader and the library's checks and grid expansion (tables/grid_spec.hpp).
// Checks beyond "no crash": the normalised spec (spec_to_json, what --resume and
// merge compare), written back as a spec and read, gives the same normalised spec; a spec that validates
// and expands has axes of exact decimals inside the stated limits, and every gamma >= 0.
// Skipped: specs with an axis of more than 20000 values, or 200 log-spaced ones
// (allowed up to 10^7 by design; the reader expands them, seconds each under the
// sanitizers).
#include "fuzz_support.hpp"

#include <viscor/jobs/table_spec.hpp>

#include <viscor/core/detail/exact_decimal.hpp>

#include <cmath>
#include <cstdlib>

namespace {

// Whether every item of the axis has few values (counted roughly; exactness is expand's business).
bool small_axis(const viscor::grid_axis& axis) {
  for (const auto& item : axis.items) {
    if (item.type == viscor::axis_item::kind::value) continue;
    if (!item.step.empty()) {
      const long double from = std::strtold(item.from.c_str(), nullptr), to = std::strtold(item.to.c_str(), nullptr),
                        step = std::strtold(item.step.c_str(), nullptr);
      if (!(step > 0) || !((to - from) / step < 10000)) return false;
    } else if (item.count > 10000) {
      return false;
    }
  }
  return true;
}

// Whether the text asks for an axis of more than 20000 values, or of more than 200
// log-spaced ones: the reader expands the axes (up to 10^7 values by design), and a
// log value costs a pow in 50 digits (about a millisecond under the sanitizers), so
// larger axes say nothing new and only risk the run's per-input timeout.
bool large_axes(const std::string& text) {
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (!j.is_object()) return false;
  auto number = [](const nlohmann::json& x) {
    return x.is_number() ? x.get<long double>()
                         : x.is_string() ? std::strtold(x.get<std::string>().c_str(), nullptr) : 0.0L;
  };
  for (const char* name : {"gamma", "g"}) {
    if (!j.contains(name)) continue;
    const nlohmann::json axis = j[name].is_array() ? j[name] : nlohmann::json::array({j[name]});
    long double values = 0, log_values = 0;
    for (const auto& item : axis) {
      if (!item.is_object()) continue;
      if (item.contains("count")) {
        const long double count = number(item["count"]);
        if (!(count <= 20000)) return true;
        const bool log = item.contains("spacing") && item["spacing"] == "log";
        (log ? log_values : values) += count;
      }
      if (item.contains("step") && item.contains("from") && item.contains("to")) {
        const long double step = number(item["step"]);
        const long double count = (number(item["to"]) - number(item["from"])) / step;
        if (!(step > 0) || !(count < 20000)) return true;
        values += count;
      }
    }
    if (values > 20000 || log_values > 200) return true;
  }
  return false;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using viscor::fuzz::fuzz_require;
  if (size > 65536) return 0;
  const std::string text = viscor::fuzz::text_of(data, size);
  if (large_axes(text)) return 0;
  viscor::fuzz::refusal_or_result([&] {
    const viscor::jobs::table_spec spec = viscor::jobs::parse_spec_json(text, "spec.json");
    const nlohmann::json normalised = viscor::jobs::spec_to_json(spec);
    nlohmann::json reread;
    try {
      reread = viscor::jobs::spec_to_json(viscor::jobs::parse_normalised_spec(normalised, "normalised.json"));
    } catch (const viscor::error& e) {
      fuzz_require(false, std::string("the normalised spec is refused: ") + e.what() + "\n" + normalised.dump(1));
    }
    fuzz_require(reread == normalised,
                 "normalised spec changes when read back:\n" + normalised.dump(1) + "\n" + reread.dump(1));

    viscor::validate(spec.grid);
    if (!small_axis(spec.grid.gamma) || !small_axis(spec.grid.g)) return;
    const viscor::expanded_axes axes = viscor::expand(spec.grid);
    for (const auto& gamma : axes.gamma)
      fuzz_require(viscor::detail::exact_decimal::parse(gamma, "gamma").sign() >= 0, "a negative gamma: " + gamma);
    for (const auto& g : axes.g) (void)viscor::detail::exact_decimal::parse(g, "g");
  });
  return 0;
}
