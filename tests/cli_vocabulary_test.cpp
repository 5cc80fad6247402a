// One vocabulary for users, and bad input that once slipped through, through the
// CLI:
// - every subcommand's physical mode refuses to run without --gravity (exit 2,
//   the message names gravity);
// - every --json output uses only the field names of docs/json-schema.md, and a
//   name with a unit suffix has that unit there;
// - old spellings still work with a deprecation warning naming the new one;
// - usage errors exit 2 and name the option; -o FILE.json writes the --json form;
// - `--g ''`, `--max-steps -1`, `approx --order 100001`, a scene's error_maps that
//   is missing or a file, and `report --data` on a directory without tables are
//   refused (exit 2, no output file).
#include "test_utils.hpp"

#include <viscor/core/outcome.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>

namespace {

using viscor::test::run_cli;
namespace fs = std::filesystem;

bool cli_built() { return std::string(VISCOR_CLI_PATH).size() > 0; }

std::string temp_path(const std::string& name) { return ::testing::TempDir() + "viscor_vocab_" + name; }

std::string write_file(const std::string& name, const std::string& text) {
  const std::string path = temp_path(name);
  std::ofstream(path) << text;
  return path;
}

const char* const bead = "--model kuwabara_kono --m 2.05e-3 --k 6.9716e9 --v0 0.246";
const std::string polymer = " --youngs-modulus 3e9 --poisson-ratio 0.35 --radius 1e-3 --density 1200";

// A scene with every field but the scene's gravity.
const char* const scene_without_gravity = R"({
  "law": "kuwabara_kono",
  "bead": {"m": 2.05e-3, "k": 6.9716e9},
  "damping": {"gamma0": 1.6e-6},
  "velocities": [0.1, 0.2],
  "tolerance": 1e-6
})";

TEST(CliVocabulary, PhysicalModeWithoutGravityIsRefused) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  const std::vector<std::string> commands{
      std::string("cor ") + bead + " --gamma0 1.6e-6",
      std::string("scale ") + bead + " --gamma0 1.6e-6",
      std::string("scale ") + bead + " --gamma 0.1 --g 0.01",
      std::string("calibrate ") + bead + " --target-e 0.9",
      std::string("cor --model kuwabara_kono --youngs-modulus 2e11 --poisson-ratio 0.3 --radius 4e-3 --density 7800 "
                  "--v0 0.246 --gamma0 1.6e-6"),
      "scene " + write_file("no_gravity.json", scene_without_gravity),
      "dem lammps --damping tsuji" + polymer + " --target-e 0.5 --v0 0.01",
      "dem yade --damping viscoelastic --k 1e5 --radius 1e-3 --density 1200 --deck-damping 0.01",
  };
  for (const auto& c : commands) {
    SCOPED_TRACE(c);
    const auto r = run_cli(c);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find("gravity"), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
  // 0 is a value the user types.
  const auto r = run_cli(std::string("cor ") + bead + " --gamma0 1.6e-6 --gravity 0 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(std::stod(nlohmann::json::parse(r.out)["g"].get<std::string>()), 0.0);
}

// The schema's names and units: rows "| `name` | meaning | unit |".
std::map<std::string, std::string> schema_units() {
  std::ifstream in(std::string(VISCOR_SOURCE_DIR) + "/docs/json-schema.md");
  EXPECT_TRUE(in) << "docs/json-schema.md";
  std::map<std::string, std::string> out;
  const std::regex row(R"(^\| `([A-Za-z0-9_]+)` \|.*\| ([^|]+) \|$)");
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (std::regex_match(line, m, row)) out[m[1]] = m[2];
  }
  return out;
}

// Every key of a JSON value; the keys of `methods` and `prop2` are data (method
// and source names), not field names, and are skipped (their values are not).
void collect_keys(const nlohmann::json& j, std::set<std::string>& keys) {
  if (j.is_array()) {
    for (const auto& x : j) collect_keys(x, keys);
  } else if (j.is_object()) {
    for (const auto& [k, v] : j.items()) {
      keys.insert(k);
      if (k == "methods") continue;
      if (k == "prop2") {
        for (const auto& [source, one] : v.items()) collect_keys(one, keys);
        continue;
      }
      collect_keys(v, keys);
    }
  }
}

TEST(CliVocabulary, EveryJsonFieldIsInTheSchema) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  const auto units = schema_units();
  ASSERT_GT(units.size(), 50u);
  // The unit-suffix rule: _s is seconds, _m metres, _ns nanoseconds, _kg kilograms, _pa pascals, as the schema says.
  const auto ends_with = [](const std::string& name, const std::string& suffix) {
    return name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
  };
  for (const auto& [name, unit] : units)
    for (const auto& [suffix, expected] : {std::pair<std::string, std::string>{"_s", "s"}, {"_m", "m"}, {"_ns", "ns"}, {"_kg", "kg"}, {"_pa", "Pa"}})
      if (ends_with(name, suffix)) EXPECT_EQ(unit, expected) << name;
  const std::string scene = write_file("schema_scene.json", R"({
    "law": "kuwabara_kono",
    "bead": {"m": 2.05e-3, "k": 6.9716e9},
    "damping": {"measured_e": 0.893, "v0": 0.246, "gravity": 9.8},
    "gravity": 9.8, "velocities": [0.1, 0.246], "tolerance": 1e-6, "contact_time": true
  })");
  const std::vector<std::string> commands{
      "cor --model tsuji --gamma 0.1 --g 0.5 --json",
      "cor --model linear --gamma 3 --g 0.5 --json",
      "cor --model hunt_crossley --gamma 0.1 --certify --json",
      "cor --model hunt_crossley --gamma 0.1 --certified-digits 20 --json",
      std::string("cor ") + bead + " --gamma0 1.6e-6 --gravity 9.8 --json",
      std::string("scale ") + bead + " --gamma0 1.6e-6 --gravity 9.8 --force 1e-3 --json",
      std::string("scale ") + bead + " --gamma 0.1 --g 0.01 --gravity 9.8 --json",
      std::string("calibrate ") + bead + " --target-e 0.9 --gravity 9.8 --json",
      "calibrate --model tsuji --target-e 0.5 --json",
      "exact --model linear --gamma 0.1 --g 1 --json",
      "exact --model tsuji --gamma 0.1 --g 1 --json",
      "approx --model kuwabara_kono --gamma 0.05 --g 0.5 --json",
      "approx --model kuwabara_kono --gamma 0.05 --g 0.5 --formula surrogate --json",
      "calibrate --model kuwabara_kono --target-e 0.5 --g 0.5 --method surrogate --json",
      "prove --model linear --gamma 0.05 --g 0.5 --digits 20 --json",
      "cor --model linear --gamma 0.05 --g 0.5 --digits 20 --prove --json",
      "bench --surrogate --points 64 --passes 1 --taylor-points 4 --json",
      "scene " + scene + " --json",
      "dem lammps --damping tsuji" + polymer + " --target-e 0.5 --v0 0.01 --gravity 9.81 --json",
      "dem liggghts --damping hertz" + polymer + " --target-e 0.5 --v0 0.01 --gravity 9.81 --json",
      "dem yade --damping mindlin" + polymer + " --deck-en 0.5 --gravity 9.81 --json",
      "dem yade --damping viscoelastic --k 1e5 --radius 1e-3 --density 1200 --target-e 0.5 --v0 0.01 --gravity 9.81 "
      "--json",
      "dem yade --damping viscoelastic --k 1e5 --radius 1e-3 --density 1200 --deck-damping 0.01 --gravity 9.81 --json",
  };
  for (const auto& c : commands) {
    SCOPED_TRACE(c);
    const auto r = run_cli(c);
    if (r.status == 2 && r.err.find("without Arb") != std::string::npos) continue;  // no proofs in this build
    ASSERT_EQ(r.status, 0) << r.err;
    std::set<std::string> keys;
    collect_keys(nlohmann::json::parse(r.out), keys);
    for (const auto& k : keys) EXPECT_TRUE(units.count(k)) << "field '" << k << "' is not in docs/json-schema.md";
  }
}

// The schema's `outcome` row names every value the JSON can carry.
TEST(CliVocabulary, SchemaListsEveryOutcome) {
  std::ifstream in(std::string(VISCOR_SOURCE_DIR) + "/docs/json-schema.md");
  ASSERT_TRUE(in) << "docs/json-schema.md";
  std::string row;
  for (std::string line; std::getline(in, line);)
    if (line.rfind("| `outcome` |", 0) == 0) row = line;
  ASSERT_FALSE(row.empty()) << "no `outcome` row in docs/json-schema.md";
  using viscor::impact_outcome;
  for (auto o : {impact_outcome::rebound, impact_outcome::stick, impact_outcome::undecided})
    EXPECT_NE(row.find("`" + std::string(viscor::to_string(o)) + "`"), std::string::npos) << row;
}

TEST(CliVocabulary, SameQuantitySameNameInEveryCommand) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  // cor in physical mode and scale agree on the scaled parameters and the scales.
  const auto cor = run_cli(std::string("cor ") + bead + " --gamma0 1.6e-6 --gravity 9.8 --json");
  const auto scale = run_cli(std::string("scale ") + bead + " --gamma0 1.6e-6 --gravity 9.8 --json");
  ASSERT_EQ(cor.status, 0) << cor.err;
  ASSERT_EQ(scale.status, 0) << scale.err;
  const auto a = nlohmann::json::parse(cor.out), b = nlohmann::json::parse(scale.out);
  for (const char* name : {"gamma", "g", "time_scale_s", "length_scale_m"}) EXPECT_EQ(a[name], b[name]) << name;
  EXPECT_EQ(a["physical"], b["physical"]);
  EXPECT_EQ(a["physical"]["force"], "0");
  EXPECT_TRUE(a["precision"].is_object());
  // dem echoes the same inputs under the same names as cor with a material bead.
  const std::string material = " --youngs-modulus 3e9 --poisson-ratio 0.35 --radius 1e-3 --density 1200 --v0 0.01";
  const auto dem = run_cli("dem lammps --damping tsuji" + material + " --target-e 0.5 --gravity 9.81 --json");
  const auto cor_material = run_cli("cor --model tsuji" + material + " --gamma0 1e-7 --gravity 9.81 --json");
  ASSERT_EQ(dem.status, 0) << dem.err;
  ASSERT_EQ(cor_material.status, 0) << cor_material.err;
  const auto d = nlohmann::json::parse(dem.out), m = nlohmann::json::parse(cor_material.out);
  for (const char* name : {"youngs_modulus", "poisson_ratio", "radius", "density", "v0", "gravity", "force"})
    EXPECT_EQ(d["physical"][name], m["physical"][name]) << name;
  EXPECT_TRUE(d["precision"].is_object());
  // contact_time is scaled, contact_time_s its value in seconds: T x T_f.
  const double T = std::stod(a["time_scale_s"].get<std::string>());
  EXPECT_NEAR(std::stod(a["contact_time_s"].get<std::string>()), T * std::stod(a["contact_time"].get<std::string>()),
              1e-12 * T * 10);
}

TEST(CliVocabulary, OldSpellingsWarnAndStillWork) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  const auto now = run_cli(std::string("cor ") + bead + " --gamma0 1.6e-6 --gravity 9.8 --force 1e-3 --json");
  const auto old = run_cli("cor --model kuwabara_kono --physical m=2.05e-3,k=6.9716e9,gamma0=1.6e-6,v0=0.246,"
                           "gravity=9.8,F=1e-3 --json");
  ASSERT_EQ(now.status, 0) << now.err;
  ASSERT_EQ(old.status, 0) << old.err;
  EXPECT_NE(old.err.find("--physical"), std::string::npos) << old.err;
  EXPECT_NE(old.err.find("deprecated"), std::string::npos) << old.err;
  EXPECT_NE(old.err.find("--gravity"), std::string::npos) << old.err;
  EXPECT_EQ(nlohmann::json::parse(now.out)["e"], nlohmann::json::parse(old.out)["e"]);
  // --physical without gravity= is now refused like the new spelling.
  const auto no_gravity = run_cli("cor --model kuwabara_kono --physical m=2.05e-3,k=6.9716e9,gamma0=0,v0=0.246");
  EXPECT_EQ(no_gravity.status, 2);
  EXPECT_NE(no_gravity.err.find("gravity"), std::string::npos) << no_gravity.err;

  const auto f = run_cli(std::string("scale ") + bead + " --gamma0 0 --gravity 9.8 --F 1e-3 --json");
  ASSERT_EQ(f.status, 0) << f.err;
  EXPECT_NE(f.err.find("--F is deprecated; use --force"), std::string::npos) << f.err;
  EXPECT_EQ(nlohmann::json::parse(f.out)["physical"]["force"], "1e-3");

  const std::string scene = write_file("old_scene.json", R"({
    "law": "kuwabara_kono",
    "bead": {"mass": 2.05e-3, "stiffness": 6.9716e9},
    "damping": {"measured_e": 0.893, "speed": 0.246, "gravity": 9.8},
    "gravity": 9.8, "velocities": [0.246], "tolerance": 1e-6
  })");
  const auto s = run_cli("scene " + scene + " --json");
  ASSERT_EQ(s.status, 0) << s.err;
  for (const char* spelling : {"bead.mass is deprecated; use bead.m", "bead.stiffness is deprecated; use bead.k",
                               "damping.speed is deprecated; use damping.v0"})
    EXPECT_NE(s.err.find(spelling), std::string::npos) << spelling << "\n" << s.err;
}

TEST(CliVocabulary, UsageErrorsExitTwoAndNameTheOption) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  struct usage {
    std::string args, names;
  };
  const std::vector<usage> cases{
      {"cor --model linear --gamma 0.1 --no-such-option", "--no-such-option"},
      {"cor --model linear --gamma", "--gamma"},
      {"approx --model linear", "--gamma"},
      {"cor --model linear --gamma 0.1 --digits many", "--digits"},
      {"nosuchcommand", "nosuchcommand"},
      {"cor --model linear --gamma 0.1 --g ''", "--g"},
      {"cor --model linear --gamma 0.1 --max-steps -1", "--max-steps"},
      {"cor --model linear --gamma 0.1 --max-steps 0", "--max-steps"},
      {"approx --model linear --gamma 0.1 --order 100001", "--order"},
      {"scale --model linear --m '' --k 1 --v0 1 --gravity 0", "--m"},
      {"cor --model linear --gamma 0.1 --method euler", "--method"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.args);
    const auto r = run_cli(c.args);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find(c.names), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
  EXPECT_EQ(run_cli("cor --help").status, 0);
  EXPECT_EQ(run_cli("--version").status, 0);
}

TEST(CliVocabulary, OutputFileEndingInJsonHoldsTheJsonForm) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  for (const std::string c : {"cor --model tsuji --gamma 0.1 --g 0.5", "approx --model tsuji --gamma 0.1",
                              "exact --model linear --gamma 0.1", "calibrate --model tsuji --target-e 0.5"}) {
    SCOPED_TRACE(c);
    const std::string path = temp_path("out.json");
    fs::remove(path);
    const auto to_file = run_cli(c + " -o " + path);
    ASSERT_EQ(to_file.status, 0) << to_file.err;
    std::ifstream in(path);
    const auto from_file = nlohmann::json::parse(in);
    const auto printed = nlohmann::json::parse(run_cli(c + " --json").out);
    EXPECT_EQ(from_file["command"], printed["command"]);
    EXPECT_EQ(from_file.contains("e"), printed.contains("e"));
    if (printed.contains("e")) EXPECT_EQ(from_file["e"], printed["e"]);
  }
}

TEST(CliVocabulary, SceneErrorMapsMustExist) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  const std::string file = write_file("a_file.csv", "not a directory\n");
  for (const std::string maps : {std::string("\"no_such_directory\""), std::string("\"viscor_vocab_a_file.csv\"")}) {
    SCOPED_TRACE(maps);
    const std::string scene = write_file("maps_scene.json", R"({
      "law": "tsuji", "bead": {"m": 1e-3, "k": 1e6}, "damping": {"gamma0": 1e-2},
      "gravity": 0, "velocities": [0.2], "tolerance": 1e-3,
      "error_maps": )" + maps + "}");
    const std::string out = temp_path("maps_out.csv");
    fs::remove(out);
    const auto r = run_cli("scene " + scene + " -o " + out);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find("error_maps"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("not a directory"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out));
  }
  const auto r = run_cli("scene " + write_file("maps_scene2.json", scene_without_gravity) + " --error-maps " + file);
  EXPECT_EQ(r.status, 2);
}

TEST(CliVocabulary, ReportRefusesADirectoryWithoutTables) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  const std::string dir = temp_path("empty_data"), out = temp_path("report.md");
  fs::create_directories(dir);
  fs::remove(out);
  const auto r = run_cli("report --data " + dir + " -o " + out);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("--data"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("no certified CoR tables"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(run_cli("report --data " + dir + "/missing").status, 2);
}

}  // namespace
