// Single-bead drops on a rigid wall in the installed YADE with the deck of
// `viscor dem yade` (tools/dem/yade_drop.py runs a batch of drops in one yade
// start-up, which takes seconds). e is exact from the force-free flight after
// YADE's clamp (see the script), so what remains is YADE's stepping error:
// NewtonIntegrator is leapfrog and the Mindlin damping reads the half-step
// velocity, a first-order error in dt.
#pragma once

#include <viscor/core/real_io.hpp>
#include <viscor/dem/dem_calibration.hpp>

#include "dem_drop_utils.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace viscor::test::yade_drop {

using namespace viscor::dem;

/// The expected agreement at dt = T/400 (measured misses: docs/dem.md, "YADE").
inline constexpr double yade_tolerance_at_T_over_400 = 1e-4;

/// The visco-elastic law's stepping error is first order and larger (its time scale
/// T = sqrt(m/k)): |miss| <= 5e-4 at dt = T/400, halving with dt, so that the
/// extrapolation 2 e(T/800) - e(T/400) meets the target to 2e-6 (docs/dem.md, "YADE").
inline constexpr double yade_viscel_tolerance_at_T_over_400 = 5e-4;
inline constexpr double yade_viscel_extrapolated_tolerance = 2e-6;

/// One drop: the deck as viscor dem prints it, the time step and the e expected.
struct drop_case {
  std::string name;
  std::string young, poisson, betan;  ///< deck strings (betan empty: `en` below)
  std::string en;                     ///< YADE's own conversion instead of betan (viscel: with tc)
  bool viscel = false;                ///< the visco-elastic law: kn, cn (or tc, en) instead of young, betan
  std::string kn, cn, wall_kn, wall_cn, tc;  ///< viscel deck strings (tc with en: YADE's own conversion)
  double radius = 0, density = 0, v0 = 0, gravity = 0, dt = 0;
  bool pair = false;  ///< two beads head-on instead of a bead on the wall
  double force = 0;   ///< N pressing the pair together (each bead)
  int max_steps = 0;
  double expected_e = 0;
  double e = -1;           ///< simulated
  bool ok = false, force_free = false;
};

/// A drop of material m at v0 under gravity with viscor's deck for m.target_e, at dt = T/per_T.
inline drop_case deck_drop(const dem_drop::material_case& m, double v0, double gravity, int per_T,
                           contact_kind kind = contact_kind::wall, double force = 0) {
  const dem_model& model = find_dem_model("yade", "mindlin");
  dem_impact<double> impact;
  impact.bead = m.bead, impact.v0 = v0, impact.gravity = gravity, impact.kind = kind, impact.force = force;
  const dem_deck<double> d = dem_deck_for(model, impact, m.target_e);
  drop_case c;
  char name[160];
  std::snprintf(name, sizeof name, "%s %s v0 = %g m/s gravity = %g m/s^2 force = %g N dt = T/%d", m.name,
                kind == contact_kind::pair ? "pair" : "wall", v0, gravity, force, per_T);
  c.name = name;
  c.pair = kind == contact_kind::pair, c.force = force;
  c.young = to_decimal_string(d.youngs_modulus), c.poisson = to_decimal_string(d.poisson_ratio);
  c.betan = to_decimal_string(d.damping);
  c.radius = m.bead.radius, c.density = m.bead.density, c.v0 = v0, c.gravity = gravity;
  c.dt = d.calibration.time_scale / per_T, c.max_steps = 30 * per_T;
  c.expected_e = m.target_e;
  return c;
}

/// A visco-elastic bead: the mass of `bead`, the contact stiffness k (N/m) and the target e.
struct viscel_case {
  const char* name;
  bead_material<double> bead;  ///< radius and density (E and nu unused)
  double stiffness, target_e;
};

/// Two visco-elastic beads: a stiff steel-like contact and a soft polymer-like one.
inline const std::array<viscel_case, 2>& viscel_materials() {
  static const std::array<viscel_case, 2> m{{
      {"steel k = 1e6 N/m", {2e11, 0.3, 1e-3, 7800}, 1e6, 0.8},
      {"polymer k = 1e4 N/m", {3e9, 0.35, 1e-3, 1200}, 1e4, 0.5},
  }};
  return m;
}

/// A visco-elastic drop of m at v0 under gravity with viscor's deck for m.target_e, at dt = T/per_T
/// (a pair: two beads of the deck's material head-on, pressed together by `force` each).
inline drop_case viscel_drop(const viscel_case& m, double v0, double gravity, int per_T,
                             contact_kind kind = contact_kind::wall, double force = 0) {
  const dem_model& model = find_dem_model("yade", "viscoelastic");
  dem_impact<double> impact;
  impact.bead = m.bead, impact.v0 = v0, impact.gravity = gravity, impact.stiffness = m.stiffness;
  impact.kind = kind, impact.force = force;
  const dem_deck<double> d = dem_deck_for(model, impact, m.target_e);
  drop_case c;
  char name[160];
  std::snprintf(name, sizeof name, "viscoelastic %s %s v0 = %g m/s gravity = %g m/s^2 force = %g N dt = T/%d",
                m.name, kind == contact_kind::pair ? "pair" : "wall", v0, gravity, force, per_T);
  c.name = name;
  c.viscel = true;
  c.pair = kind == contact_kind::pair, c.force = force;
  c.kn = to_decimal_string(*d.stiffness), c.cn = to_decimal_string(d.damping);
  c.wall_kn = c.wall_cn = yade_rigid_wall_viscel;
  c.radius = m.bead.radius, c.density = m.bead.density, c.v0 = v0, c.gravity = gravity;
  c.dt = d.calibration.time_scale / per_T, c.max_steps = 30 * per_T;
  c.expected_e = m.target_e;
  return c;
}

inline std::optional<std::string> find_yade() { return dem_drop::find_program("yade"); }

/// Runs all cases in one yade process and fills e, ok, force_free; false (with a message) if yade failed.
inline bool run_drops(const std::string& yade, std::vector<drop_case>& cases, std::string& message) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("viscor_yade_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path json = dir / "cases.json";
  {
    std::ofstream out(json);
    out << "[";
    for (std::size_t i = 0; i < cases.size(); ++i) {
      const drop_case& c = cases[i];
      auto field = [&](const char* key, const std::string& value) {
        if (!value.empty()) out << "\"" << key << "\": \"" << value << "\", ";
      };
      out << (i ? ",\n" : "") << "{";
      if (c.viscel) {
        out << "\"law\": \"viscel\", ";
        field("kn", c.kn), field("cn", c.cn), field("wall_kn", c.wall_kn), field("wall_cn", c.wall_cn);
        field("tc", c.tc), field("en", c.en);
      } else {
        field("young", c.young), field("poisson", c.poisson);
        field(c.en.empty() ? "betan" : "en", c.en.empty() ? c.betan : c.en);
      }
      out << "\"density\": \""
          << dem_drop::format_double(c.density) << "\", \"radius\": \"" << dem_drop::format_double(c.radius)
          << "\", \"v0\": \"" << dem_drop::format_double(c.v0) << "\", \"gravity\": \""
          << dem_drop::format_double(c.gravity) << "\", \"dt\": \"" << dem_drop::format_double(c.dt)
          << "\", \"contact\": \"" << (c.pair ? "pair" : "wall") << "\", \"force\": \""
          << dem_drop::format_double(c.force) << "\", \"max_steps\": " << c.max_steps << "}";
    }
    out << "]\n";
  }
  const fs::path log = dir / "out.txt";
  const std::string command = "cd '" + dir.string() + "' && VISCOR_YADE_CASES='" + json.string() + "' '" + yade +
                              "' -n -x '" VISCOR_SOURCE_DIR "/tools/dem/yade_drop.py' > '" + log.string() + "' 2>&1";
  const int status = std::system(command.c_str());
  std::ifstream in(log);
  std::string line;
  std::size_t found = 0;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string tag;
    std::size_t index = 0;
    double e = 0;
    int ok = 0, free = 0;
    if (!(fields >> tag >> index >> e >> ok >> free) || tag != "DROP" || index >= cases.size()) continue;
    cases[index].e = e, cases[index].ok = ok != 0, cases[index].force_free = free != 0;
    ++found;
  }
  if (found != cases.size()) {
    std::ifstream again(log);
    std::stringstream text;
    text << again.rdbuf();
    message = "yade exited with status " + std::to_string(status) + " after " + std::to_string(found) + " of " +
              std::to_string(cases.size()) + " drops:\n" + text.str();
    return false;
  }
  fs::remove_all(dir);
  return true;
}

/// What halving dt must do to a drop's miss: `shrinks` (the Mindlin checks), or
/// `first_order`: it halves, and the extrapolation 2 e(dt/2) - e(dt) removes it to
/// yade_viscel_extrapolated_tolerance (the visco-elastic law's checks).
enum class halving { shrinks, first_order };

/// The same drop at dt (`coarse`) and dt/2 (`fine`): both ran and left the clamp
/// force-free, the miss at dt is within `tolerance` and behaves under halving as
/// `order` says. Prints the misses (the figures docs/dem.md quotes).
inline void check_halving(const drop_case& coarse, const drop_case& fine, double tolerance, halving order) {
  SCOPED_TRACE(coarse.name);
  ASSERT_TRUE(coarse.ok && fine.ok);
  EXPECT_TRUE(coarse.force_free && fine.force_free);  // the clamp released the bead before zero overlap
  const double miss = coarse.e - coarse.expected_e, fine_miss = fine.e - fine.expected_e;
  EXPECT_LE(std::abs(miss), tolerance) << "e = " << coarse.e;
  if (order == halving::shrinks) {
    EXPECT_LT(std::abs(fine_miss), std::abs(miss)) << "halving dt: e = " << fine.e;
    std::printf("[yade] %s: expected %.10f, e = %.10f (miss %.2e), at dt/2 e = %.10f (miss %.2e)\n",
                coarse.name.c_str(), coarse.expected_e, coarse.e, miss, fine.e, fine_miss);
    return;
  }
  EXPECT_NEAR(miss / fine_miss, 2.0, 0.1) << "halving dt: e = " << fine.e;
  const double extrapolated = 2 * fine.e - coarse.e;
  EXPECT_NEAR(extrapolated, coarse.expected_e, yade_viscel_extrapolated_tolerance);
  std::printf("[yade] %s: expected %.8f, e = %.10f (miss %.2e), at dt/2 e = %.10f (miss %.2e), "
              "extrapolated miss %.1e\n", coarse.name.c_str(), coarse.expected_e, coarse.e, miss, fine.e, fine_miss,
              extrapolated - coarse.expected_e);
}

}  // namespace viscor::test::yade_drop
