// A scene file (docs/scenes.md) evaluated as `viscor scene FILE` does: an 8 mm steel
// bead calibrated to e = 0.893 at 0.246 m/s under gravity, at 20 impact speeds, each
// to 1e-6. The scene job picks for every impact the cheapest method that meets the
// tolerance (the committed surrogate, an error map's formula, or a solve).
#include <viscor/viscor.hpp>

#include <iostream>

int main() {
  const viscor::jobs::scene_file file = viscor::jobs::parse_scene_json(R"({
    "law": "kuwabara_kono",
    "bead": {"m": 2.05e-3, "k": 6.9716e9},
    "damping": {"measured_e": 0.893, "v0": 0.246, "gravity": 9.8},
    "gravity": 9.8,
    "velocities": {"from": 0.01, "to": 1, "count": 20, "spacing": "log"},
    "tolerance": 1e-6
  })", "steel.json");
  const viscor::jobs::scene_result result = viscor::jobs::run_scene_file(file, "steel.json", "", /*as_json=*/true);
  const auto& rows = result.object["rows"];
  for (const auto& row : rows)
    std::cout << "v0 = " << row["v0"].get<std::string>() << " m/s: e = " << row["e"].get<std::string>() << " ("
              << row["method"].get<std::string>() << ")\n";
  std::cout << result.summary;
  return rows.size() == 20 ? 0 : 1;
}
