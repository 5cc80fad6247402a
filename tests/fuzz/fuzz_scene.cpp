// Fuzz target: scene files (viscor scene FILE.json): include/viscor/jobs/scene_file.hpp's
// reader, then the library's resolve_scene (scenes/scene.hpp) in double, which
// turns the texts into the bead, the damping and the impact speeds. Checks beyond
// "no crash": a scene that resolves has a positive tolerance, mass and stiffness,
// a non-negative damping, and only finite, positive impact speeds.
// Not run here: a measured_e (calibration is a solve, seconds each) and more than
// 10000 speeds (resolve_scene makes them all; a real scene may ask for that).
#include "fuzz_support.hpp"

#include <viscor/jobs/scene_file.hpp>

#include <cmath>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using viscor::fuzz::fuzz_require;
  if (size > 65536) return 0;
  const std::string text = viscor::fuzz::text_of(data, size);
  viscor::fuzz::refusal_or_result([&] {
    const viscor::jobs::scene_file f = viscor::jobs::parse_scene_json(text, "scene.json");
    const viscor::scene_description& d = f.scene;
    if (d.measured_e || d.velocity_count > 10000 || d.velocities.size() > 10000) return;
    const viscor::resolved_scene<double> s = viscor::resolve_scene<double>(d);
    fuzz_require(s.tolerance > 0 && s.mass > 0 && s.stiffness > 0 && s.gamma0 >= 0,
                 "a resolved scene has a non-positive tolerance, mass or stiffness, or a negative damping");
    fuzz_require(!s.velocities.empty(), "a resolved scene without impact speeds");
    for (const double v : s.velocities) fuzz_require(std::isfinite(v) && v > 0, "a resolved impact speed is not > 0");
  });
  return 0;
}
