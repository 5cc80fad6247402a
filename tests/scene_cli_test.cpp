// viscor scene / calibrate / errormap from the command line: rows, the round trip
// through calibration, bad scenes (a clear error naming the field and line, exit
// code 2, no output file), and error maps used by a scene.
#include "scaling_reference.hpp"
#include "test_utils.hpp"

#include <viscor/certify/extern_templates.hpp>
#include <viscor/core/precision.hpp>
#include <viscor/core/real_io.hpp>
#include <viscor/impact/solve_impact.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace viscor {
namespace {

using test::run_cli;

std::string temp_path(const std::string& name) { return ::testing::TempDir() + "viscor_scene_" + name; }

std::string write_file(const std::string& name, const std::string& text) {
  const std::string path = temp_path(name);
  std::ofstream(path) << text;
  return path;
}

std::vector<std::string> lines_of(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> out;
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(line);
  for (std::string f; std::getline(in, f, ',');) out.push_back(f);
  return out;
}

const char* const steel_scene = R"({
  "description": "8 mm steel bead, Kuwabara-Kono, calibrated at 0.246 m/s",
  "law": "kuwabara_kono",
  "bead": {"m": 2.05e-3, "k": 6.9716e9},
  "damping": {"measured_e": 0.893, "v0": 0.246, "gravity": 9.8},
  "gravity": 9.8,
  "velocities": [0.05, 0.246, 1],
  "tolerance": 1e-8,
  "contact_time": true
})";

TEST(scene_cli, rows_and_calibration_round_trip) {
  const std::string scene = write_file("steel.json", steel_scene), out = temp_path("steel.csv");
  std::filesystem::remove(out);
  const auto r = run_cli("scene " + scene + " -o " + out);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("impacts    3 at tolerance 1e-8"), std::string::npos) << r.out;
  const auto rows = lines_of(out);
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0],
            "index,v0,gamma,g,outcome,sticking,e,one_minus_e,contact_time_s,empirical_bound,method,working_digits,seconds");
  const auto hit = split(rows[2]);  // v0 = 0.246, where e = 0.893 was measured
  ASSERT_EQ(hit.size(), 13u);
  EXPECT_EQ(hit[1], "2.4600000000000000e-01");
  EXPECT_EQ(hit[4], "rebound");
  EXPECT_EQ(hit[5], "false");
  EXPECT_LE(std::abs(std::stod(hit[6]) - 0.893), 1e-8) << rows[2];
  // The load of this row against eq. (2) evaluated outside the library (the same bead, v0 and gravity).
  const auto ref = viscor::test::scaling_reference("steel_bead_unit_damping", "kuwabara_kono");
  EXPECT_NEAR(std::stod(hit[3]), std::stod(ref.g), 1e-14 * std::stod(ref.g)) << rows[2];
  EXPECT_LE(std::stod(hit[9]), 1e-8);
  EXPECT_GT(std::stod(hit[8]), 0);  // contact time, s (tens of microseconds for this bead)
  EXPECT_LT(std::stod(hit[8]), 1e-3);

  // JSON, chosen by the file name.
  const std::string json_out = temp_path("steel.json.out.json");
  ASSERT_EQ(run_cli("scene " + scene + " -o " + json_out).status, 0);
  std::ifstream in(json_out);
  const auto j = nlohmann::json::parse(in);
  EXPECT_EQ(j["impacts"], 3);
  ASSERT_EQ(j["rows"].size(), 3u);
  EXPECT_EQ(j["rows"][1]["outcome"], "rebound");
  EXPECT_LE(std::abs(std::stod(j["rows"][1]["e"].get<std::string>()) - 0.893), 1e-8);
  EXPECT_TRUE(j.contains("calibration"));
}

TEST(scene_cli, bad_scenes_name_the_field_and_write_nothing) {
  struct bad {
    const char* what;
    std::string text;
    std::string expected;
  };
  auto with = [](const std::string& from, const std::string& to) {
    std::string s = steel_scene;
    const auto at = s.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    s.replace(at, from.size(), to);
    return s;
  };
  const std::vector<bad> cases{
      {"missing tolerance", with(",\n  \"tolerance\": 1e-8", ""), "field tolerance: missing"},
      {"negative mass", with("\"m\": 2.05e-3", "\"m\": -2.05e-3"), ":4: parameter bead.m must be > 0"},
      {"unknown law", with("\"kuwabara_kono\"", "\"kuwabara\""), ":3: field law: unknown contact law 'kuwabara'"},
      {"zero tolerance", with("\"tolerance\": 1e-8", "\"tolerance\": 0"), ":8: parameter tolerance must be > 0"},
      {"negative tolerance", with("\"tolerance\": 1e-8", "\"tolerance\": -1e-3"), "tolerance must be > 0"},
      {"unreachable target", with("\"measured_e\": 0.893", "\"measured_e\": 1.5"),
       ":5: scene: damping.measured_e: target_e = 1.5"},
      {"zero target", with("\"measured_e\": 0.893", "\"measured_e\": 0"), "threshold"},
      {"missing gravity of the measurement", with(", \"gravity\": 9.8}", "}"), "field damping.gravity: missing"},
      {"misspelt field", with("\"gravity\": 9.8,\n", "\"gravty\": 9.8,\n"), ":6: field gravty: unknown field"},
      {"missing bead", with("\"bead\": {\"m\": 2.05e-3, \"k\": 6.9716e9},", ""), "missing field bead"},
      {"bad number", with("\"k\": 6.9716e9", "\"k\": \"lots\""), ":4: field bead.k: must be a finite decimal number, got 'lots'"},
      {"missing gravity", with("\"gravity\": 9.8,\n", ""), "field gravity: missing"},
      {"negative speed", with("[0.05, 0.246, 1]", "[0.05, -0.246, 1]"), ":7: parameter velocities[1] must be > 0"},
      {"not JSON", "{\"law\": \"linear\",\n \"bead\": }", "invalid JSON at line 2"},
  };
  for (const bad& c : cases) {
    const std::string scene = write_file("bad.json", c.text), out = temp_path("bad.csv");
    std::filesystem::remove(out);
    const auto r = run_cli("scene " + scene + " -o " + out);
    EXPECT_EQ(r.status, 2) << c.what << "\n" << r.err;
    EXPECT_NE(r.err.find(c.expected), std::string::npos) << c.what << ": got\n" << r.err;
    EXPECT_NE(r.err.find("viscor_scene_bad.json"), std::string::npos) << c.what << ": the file is named\n" << r.err;
    EXPECT_FALSE(std::filesystem::exists(out)) << c.what;
    for (const auto& entry : std::filesystem::directory_iterator(::testing::TempDir()))
      EXPECT_EQ(entry.path().filename().string().find("viscor_scene_bad.csv.tmp"), std::string::npos) << c.what;
  }
  EXPECT_EQ(run_cli("scene /nonexistent/scene.json").status, 2);
}

TEST(scene_cli, calibrate_command) {
  const auto r = run_cli("calibrate --model tsuji --target-e 0.5 --g 0 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  // Antypov-Elliott: gamma = (4/sqrt 5)(-ln e)/sqrt(pi^2 + ln^2 e) = 0.3868... at e = 0.5.
  const double L = std::log(0.5), exact = 4 / std::sqrt(5.0) * (-L) / std::sqrt(M_PI * M_PI + L * L);
  EXPECT_NEAR(std::stod(j["gamma"].get<std::string>()), exact, 1e-9);
  const auto phys = run_cli("calibrate --model kuwabara_kono --target-e 0.893 --m 2.05e-3 --k 6.9716e9 --v0 0.246");
  EXPECT_EQ(phys.status, 2);
  EXPECT_NE(phys.err.find("--gravity"), std::string::npos) << phys.err;
  const auto unreachable = run_cli("calibrate --model kuwabara_kono --target-e 1.01 --g 0.1");
  EXPECT_EQ(unreachable.status, 2);
  EXPECT_NE(unreachable.err.find("unreachable"), std::string::npos) << unreachable.err;
}

TEST(scene_cli, errormap_feeds_a_scene) {
  const std::string dir = temp_path("maps");
  std::filesystem::create_directories(dir);
  const auto built = run_cli("errormap --model hunt_crossley --gamma-edges 1e-3,1e-2,3e-2 --g-edges 0,0.01,0.1 "
                             "--reference-digits 30 --per-interval 1 -o " + dir + "/hunt_crossley.csv");
  ASSERT_EQ(built.status, 0) << built.err;
  EXPECT_NE(built.out.find("cells      4 mapped of 4"), std::string::npos) << built.out;
  // Soft bead, slow impacts: gamma ~ 0.005-0.015, g ~ 0.01: inside the map.
  const std::string scene = write_file("soft.json", R"({
    "law": "hunt_crossley",
    "bead": {"m": 1e-3, "k": 1e6},
    "damping": {"gamma0": 1e-2},
    "gravity": 0.5,
    "velocities": {"from": 0.2, "to": 0.5, "count": 50, "spacing": "linear"},
    "tolerance": 1e-2,
    "error_maps": "viscor_scene_maps"
  })");
  const std::string out = temp_path("soft.csv");
  const auto r = run_cli("scene " + scene + " -o " + out);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("error map  " + dir + "/hunt_crossley.csv"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("methods    taylor 50"), std::string::npos) << r.out;  // approximations were used
  EXPECT_EQ(lines_of(out).size(), 51u);
}

// The README's example scene (docs/examples/steel_bead.json): 10,000 impacts at
// 1e-4 with the committed error maps; every 250th row checked against a solve
// at 30 digits of the row's own (gamma, g).
TEST(scene_cli, readme_example_scene_keeps_its_bounds) {
  const std::string out = temp_path("readme_example.csv");
  const auto r = run_cli("scene " + std::string(VISCOR_SOURCE_DIR) + "/docs/examples/steel_bead.json -o " + out);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto lines = lines_of(out);
  ASSERT_EQ(lines.size(), 10001u);
  const auto header = split(lines[0]);
  auto col = [&](const char* name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  int checked = 0;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const auto f = split(lines[i]);
    const double bound = std::stod(f[col("empirical_bound")]);
    ASSERT_LE(bound, 1e-4) << lines[i];
    if (i % 250 != 1) continue;
    with_working_precision(30, [&]<class Real>() {
      const auto ref = solve_impact(law_by_name("kuwabara_kono"), parse_real<Real>(f[col("gamma")], "gamma"),
                                    parse_real<Real>(f[col("g")], "g"));
      using std::abs;
      EXPECT_LE(abs(parse_real<Real>(f[col("e")], "e") - ref.e), Real(bound)) << lines[i];
    });
    ++checked;
  }
  EXPECT_EQ(checked, 40);
  std::filesystem::remove(out);
}

}  // namespace
}  // namespace viscor
