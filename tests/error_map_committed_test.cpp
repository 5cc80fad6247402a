// The committed error maps (reference_data/error_maps/):
//  - they are what `viscor errormap --table` builds from the committed certified
//    tables today (tools/generate_error_maps.sh), so a change to an approximation
//    or to a table that leaves a map stale fails here;
//  - their bounds hold between the samples they were built from: random points
//    inside rebounding cells (fixed seed), reference e from solve_impact at 30
//    digits (not from the tables the maps came from).
#include "test_utils.hpp"

#include <viscor/scenes/error_map.hpp>
#include <viscor/certify/extern_templates.hpp>
#include <viscor/core/precision.hpp>
#include <viscor/impact/solve_impact.hpp>

#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace viscor {
namespace {

const std::vector<std::string> laws{"linear", "hertz_linear_damping", "tsuji", "kuwabara_kono", "hunt_crossley"};

std::string source_path(const std::string& relative) { return std::string(VISCOR_SOURCE_DIR) + "/" + relative; }

// The data lines of a map file (the '#' provenance lines name paths and commits).
std::vector<std::string> data_lines(const std::string& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in) << path;
  std::vector<std::string> out;
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] != '#') out.push_back(line);
  return out;
}

// The arguments of tools/generate_error_maps.sh, with absolute table paths.
std::string errormap_arguments(const std::string& law) {
  std::string args = "errormap --model " + law +
                     " --gamma-edges 1e-6,2e-6,5e-6,1e-5,2e-5,5e-5,1e-4,2e-4,5e-4,1e-3,2e-3,5e-3,0.01,0.02,0.05,0.1,0.2,0.5,1"
                     " --g-edges 0,1e-4,1e-3,0.01,0.1,1,10 --safety-factor 4 --floor 1e-14";
  for (const char* t : {"cor_error_map_grid", "cor_report_grid", "cor_report_g10_hertz_linear_damping",
                        "cor_report_g10_hunt_crossley", "cor_report_g10_kuwabara_kono", "cor_report_g10_tsuji",
                        "cor_gamma_sweep", "cor_g_sweep"})
    args += " --table " + source_path(std::string("reference_data/") + t + ".csv");
  return args;
}

TEST(CommittedErrorMaps, AreWhatTheCommittedTablesGive) {
  for (const auto& law : laws) {
    const std::string committed = source_path("reference_data/error_maps/" + law + ".csv");
    const std::string rebuilt = ::testing::TempDir() + "viscor_map_" + std::to_string(::getpid()) + "_" + law + ".csv";
    const test::cli_run r = test::run_cli(errormap_arguments(law) + " -o " + rebuilt);
    ASSERT_EQ(r.status, 0) << r.err;
    const auto want = data_lines(committed), got = data_lines(rebuilt);
    ASSERT_EQ(got.size(), want.size()) << law << ": rerun tools/generate_error_maps.sh";
    for (std::size_t i = 0; i < want.size(); ++i) EXPECT_EQ(got[i], want[i]) << law << ", cell line " << i;
    std::remove(rebuilt.c_str());
  }
}

TEST(CommittedErrorMaps, BoundsHoldBetweenTheirSamples) {
  std::mt19937_64 rng(20261122);
  std::uniform_real_distribution<double> unit(0, 1);
  int checked = 0;
  for (const auto& name : laws) {
    const error_map map = read_error_map(source_path("reference_data/error_maps/" + name + ".csv"));
    const contact_law law = law_by_name(name);
    ASSERT_EQ(map.law.alpha, law.alpha);
    const cor_approximations<double> approx(law);
    std::vector<const error_map_cell*> rebound;
    for (const auto& c : map.cells())
      if (c.outcome == cell_outcome::rebound) rebound.push_back(&c);
    ASSERT_GT(rebound.size(), 50u) << name;
    for (int n = 0; n < 60; ++n) {
      const error_map_cell& c = *rebound[static_cast<std::size_t>(unit(rng) * rebound.size())];
      // log-uniform in gamma, uniform in g: the cell's interior, away from its samples
      const double gamma = c.gamma_lo_v * std::pow(c.gamma_hi_v / c.gamma_lo_v, unit(rng));
      const double g = c.g_lo_v + (c.g_hi_v - c.g_lo_v) * unit(rng);
      const std::optional<map_bounds> b = map.at(gamma, g);
      ASSERT_TRUE(b) << name << " at gamma = " << gamma << ", g = " << g;
      const double e_ref = with_working_precision(30, [&]<class Real>() {
        return static_cast<double>(solve_impact(law, Real(gamma), Real(g)).e);
      });
      for (std::size_t k = 0; k < all_approximations.size(); ++k) {
        if (!b->bound[k]) continue;
        const std::optional<double> a = approximate_e(approx, all_approximations[k], gamma, g);
        ASSERT_TRUE(a) << to_string(all_approximations[k]);
        EXPECT_LE(std::abs(*a - e_ref), *b->bound[k])
            << name << ", " << to_string(all_approximations[k]) << " at gamma = " << gamma << ", g = " << g
            << " (cell [" << c.gamma_lo << ", " << c.gamma_hi << "] x [" << c.g_lo << ", " << c.g_hi << "])";
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 1000);
}

}  // namespace
}  // namespace viscor
