// viscor table from a spec in SI (docs/tables.md, "Physical specs"): every row is the
// e that `viscor cor` gives for the same physical inputs, compared field by field with
// the command line's own output (three materials x five speeds x two gravities, and
// (m, k) beads, walls of a material, a pair, forces and certified digits asked for);
// shards merge and interrupted runs resume to the same bytes; bad specs are refused
// naming the field or the row, with nothing written.
#include "certified_claims.hpp"
#include "test_utils.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using viscor::test::read_named_rows;
using viscor::test::run_cli;

class PhysicalTable : public viscor::test::scratch_dir_test {
 protected:
  PhysicalTable() : scratch_dir_test("viscor_physical_table_") {}
};

/// The `viscor cor` options that give the row's physical inputs (from the row's own
/// columns, which the callers check against the spec).
std::string cor_options(const std::map<std::string, std::string>& row) {
  std::string s;
  for (const auto& [column, option] : std::vector<std::pair<std::string, std::string>>{
           {"m", "--m"}, {"k", "--k"}, {"youngs_modulus", "--youngs-modulus"},
           {"poisson_ratio", "--poisson-ratio"}, {"radius", "--radius"}, {"density", "--density"},
           {"wall_youngs_modulus", "--wall-youngs-modulus"}, {"wall_poisson_ratio", "--wall-poisson-ratio"},
           {"other_youngs_modulus", "--other-youngs-modulus"}, {"other_poisson_ratio", "--other-poisson-ratio"},
           {"other_radius", "--other-radius"}, {"other_density", "--other-density"}, {"v0", "--v0"},
           {"gamma0", "--gamma0"}, {"gravity", "--gravity"}, {"force", "--force"}})
    if (row.count(column) && !row.at(column).empty()) s += " " + option + " " + row.at(column);
  if (row.at("contact") == "pair") s += " --contact pair";
  return s;
}

/// Checks every row against `viscor cor ... --certify --json` with `precision` (the
/// digits or certified digits asked for): the scaled point, outcome, e, 1 - e, T_f,
/// u_max and their certified digits are the same text; the SI contact time and
/// compression agree to the certified digits with cor's values in seconds and metres.
void expect_rows_equal_cor(const std::vector<std::map<std::string, std::string>>& rows, const std::string& precision) {
  for (const auto& row : rows) {
    const std::string args = "cor --model " + row.at("law") + cor_options(row) + " " + precision + " --certify --json";
    const auto r = run_cli(args);
    ASSERT_EQ(r.status, 0) << args << "\n" << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    const nlohmann::json& c = j.at("certified");
    const std::string what = "row " + row.at("index") + ": viscor " + args;
    EXPECT_EQ(row.at("gamma"), j.at("gamma").get<std::string>()) << what;
    EXPECT_EQ(row.at("g"), j.at("g").get<std::string>()) << what;
    EXPECT_EQ(row.at("outcome"), c.at("outcome").get<std::string>()) << what;
    EXPECT_EQ(row.at("e"), c.at("e").get<std::string>()) << what;
    EXPECT_EQ(row.at("one_minus_e"), c.at("one_minus_e").get<std::string>()) << what;
    EXPECT_EQ(row.at("contact_time"), c.at("contact_time").get<std::string>()) << what;
    EXPECT_EQ(row.at("max_compression"), c.at("max_compression").get<std::string>()) << what;
    EXPECT_EQ(row.at("digits"), std::to_string(c.at("certified_digits").get<int>())) << what;
    const int digits = std::stoi(row.at("digits"));
    if (row.at("contact_time") == "inf") {  // a stick: cor reports no contact time in seconds
      EXPECT_EQ(row.at("contact_time_s"), "inf") << what;
    }
    for (const auto& [column, field] : {std::pair{"contact_time_s", "contact_time_s"},
                                        std::pair{"max_compression_m", "max_compression_m"}}) {
      if (row.at(column) == "inf") continue;
      const long double table = std::strtold(row.at(column).c_str(), nullptr);
      const long double cor = std::strtold(j.at(field).get<std::string>().c_str(), nullptr);
      EXPECT_LE(std::fabs(table - cor), std::fabs(cor) * std::pow(10.0L, 1 - std::min(digits, 18)))
          << what << ": " << column;
    }
  }
}

struct bead_material {
  const char *name, *youngs_modulus, *poisson_ratio, *radius, *density;
};
const bead_material beads[] = {{"steel", "2.1e11", "0.3", "0.004", "7850"},
                               {"glass", "6.3e10", "0.23", "0.004", "2500"},
                               {"nylon", "3e9", "0.39", "0.004", "1140"}};
const std::vector<std::string> speeds{"0.01", "0.05", "0.1", "0.5", "1"};
const std::vector<std::string> gravities{"0", "9.81"};

std::string materials_spec() {
  std::string s = R"({"laws": ["kuwabara_kono"], "beads": [)";
  for (std::size_t i = 0; i < 3; ++i)
    s += std::string(i ? ", " : "") + R"({"name": ")" + beads[i].name + R"(", "youngs_modulus": )" +
         beads[i].youngs_modulus + R"(, "poisson_ratio": )" + beads[i].poisson_ratio + R"(, "radius": )" +
         beads[i].radius + R"(, "density": )" + beads[i].density + "}";
  return s + R"(], "v0": [1, 0.5, 0.1, 0.05, 0.01], "gravity": [9.81, 0], "gamma0": "8.49e-07", "digits": 20})";
}

// The acceptance case: three materials x five speeds x two gravities, row by row
// against viscor cor with the same inputs.
TEST_F(PhysicalTable, ThreeMaterialsFiveSpeedsTwoGravitiesEqualViscorCor) {
  const std::string spec = write("spec.json", materials_spec());
  const auto r = run_cli("table " + spec + " -o " + path("out.csv") + " --quiet --threads 2");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = read_named_rows(path("out.csv"));
  ASSERT_EQ(rows.size(), 30u);
  std::size_t i = 0;
  for (const auto& bead : beads)  // the table's order: beads, gravity, v0 (ascending)
    for (const std::string& gravity : gravities)
      for (const std::string& v0 : speeds) {
        const auto& row = rows[i];
        EXPECT_EQ(row.at("index"), std::to_string(i));
        EXPECT_EQ(row.at("bead"), bead.name);
        EXPECT_EQ(row.at("youngs_modulus"), bead.youngs_modulus);
        EXPECT_EQ(row.at("poisson_ratio"), bead.poisson_ratio);
        EXPECT_EQ(row.at("radius"), bead.radius);
        EXPECT_EQ(row.at("density"), bead.density);
        EXPECT_EQ(row.at("m"), "");
        EXPECT_EQ(row.at("contact"), "wall");
        EXPECT_EQ(row.at("wall"), "rigid");
        EXPECT_EQ(row.at("gravity"), gravity);
        EXPECT_EQ(row.at("force"), "0");
        EXPECT_EQ(row.at("v0"), v0);
        EXPECT_EQ(row.at("gamma0"), "8.49e-07");
        EXPECT_EQ(row.at("method"), "certified");
        ++i;
      }
  expect_rows_equal_cor(rows, "--digits 20");
  // Gravity matters: at the slowest impact of the softest bead e differs between the loads.
  EXPECT_NE(rows[20].at("e"), rows[25].at("e"));
}

// (m, k) beads of the linear law under a force, with the certified digits asked for.
TEST_F(PhysicalTable, MassAndStiffnessUnderForceWithCertifiedDigits) {
  const std::string spec = write("spec.json", R"({
    "laws": ["linear"],
    "beads": [{"name": "a", "m": 0.001, "k": 1e5}, {"m": "2e-3", "k": "4e5"}],
    "v0": [0.1, 1], "gravity": 9.81, "force": [0, 0.05], "gamma0": ["1e-5", "2.5e-4"],
    "certified_digits": 25})");
  const auto r = run_cli("table " + spec + " -o " + path("out.csv") + " --quiet");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = read_named_rows(path("out.csv"));
  ASSERT_EQ(rows.size(), 16u);
  EXPECT_EQ(rows[0].at("bead"), "a");
  EXPECT_EQ(rows[8].at("bead"), "bead1");  // an unnamed bead is named by its position
  for (const auto& row : rows) {
    EXPECT_GE(std::stoi(row.at("digits")), 25) << row.at("index");
    EXPECT_EQ(row.at("youngs_modulus"), "");
  }
  expect_rows_equal_cor(rows, "--certified-digits 25");
}

// Walls of a material (and the rigid one), and a pair of beads.
TEST_F(PhysicalTable, WallsOfAMaterialAndPairs) {
  const std::string walls = write("walls.json", R"({
    "laws": ["hertz_linear_damping", "tsuji"],
    "beads": {"name": "steel", "youngs_modulus": 2.1e11, "poisson_ratio": 0.3, "radius": 0.002, "m": 2.6e-4},
    "walls": ["rigid", {"name": "glass", "youngs_modulus": 6.3e10, "poisson_ratio": 0.23}],
    "v0": 0.3, "gravity": 9.81, "gamma0": ["5e-9", "1e-9"], "digits": 18})");
  auto r = run_cli("table " + walls + " -o " + path("walls.csv") + " --quiet");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto wall_rows = read_named_rows(path("walls.csv"));
  ASSERT_EQ(wall_rows.size(), 8u);
  EXPECT_EQ(wall_rows[2].at("wall"), "glass");
  EXPECT_EQ(wall_rows[2].at("wall_youngs_modulus"), "6.3e10");
  EXPECT_NE(wall_rows[0].at("gamma"), wall_rows[2].at("gamma"));  // a softer contact scales differently
  expect_rows_equal_cor(wall_rows, "--digits 18");

  const std::string pair = write("pair.json", R"({
    "laws": "kuwabara_kono",
    "beads": [{"name": "steel", "youngs_modulus": 2.1e11, "poisson_ratio": 0.3, "radius": 0.002, "density": 7850}],
    "contact": "pair",
    "other": {"youngs_modulus": 6.3e10, "poisson_ratio": 0.23, "radius": 0.003, "density": 2500},
    "v0": [0.2, 2], "gravity": 9.81, "force": 0.01, "gamma0": 1e-6, "digits": 30})");
  r = run_cli("table " + pair + " -o " + path("pair.csv") + " --quiet");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto pair_rows = read_named_rows(path("pair.csv"));
  ASSERT_EQ(pair_rows.size(), 2u);
  EXPECT_EQ(pair_rows[0].at("contact"), "pair");
  EXPECT_EQ(pair_rows[0].at("wall"), "none");
  EXPECT_EQ(pair_rows[0].at("other_radius"), "0.003");
  expect_rows_equal_cor(pair_rows, "--digits 30");
}

// A target CoR instead of the damping: gamma0 is what viscor calibrate finds for the
// row's inputs, and the row is viscor cor at that gamma0 (its e the target, to the
// calibration's tolerance).
TEST_F(PhysicalTable, TargetCorsAreCalibratedAsViscorCalibrateDoes) {
  const std::string spec = write("spec.json", R"({
    "laws": ["tsuji", "hunt_crossley"],
    "beads": {"name": "glass", "youngs_modulus": 6.3e10, "poisson_ratio": 0.23, "radius": 0.003, "density": 2500},
    "v0": [0.02, 0.5], "gravity": 9.81, "target_e": [0.5, 0.8], "digits": 20})");
  const auto r = run_cli("table " + spec + " -o " + path("out.csv") + " --quiet");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = read_named_rows(path("out.csv"));
  ASSERT_EQ(rows.size(), 8u);
  for (const auto& row : rows) {
    ASSERT_FALSE(row.at("target_e").empty());
    std::map<std::string, std::string> inputs = row;
    inputs["gamma0"] = "";
    const std::string args = "calibrate --model " + row.at("law") + cor_options(inputs) + " --target-e " +
                             row.at("target_e") + " --digits 20 --json";
    const auto c = run_cli(args);
    ASSERT_EQ(c.status, 0) << args << "\n" << c.err;
    const nlohmann::json calibrated = nlohmann::json::parse(c.out);
    EXPECT_EQ(row.at("gamma0"), calibrated.at("gamma0").get<std::string>()) << args;
    // The certified e is the target to the calibration's stated bound plus the rounding
    // to the row's certified digits (compared in 100-digit MPFR, not in double).
    using viscor::test::claim_number;
    const claim_number miss = abs(claim_number(row.at("e")) - claim_number(row.at("target_e")));
    const claim_number allowed = claim_number(calibrated.at("target_bound").get<std::string>()) +
                                 pow(claim_number(10), -std::stoi(row.at("digits")));
    EXPECT_LE(miss, allowed) << row.at("index") << ": e = " << row.at("e") << ", target " << row.at("target_e");
  }
  expect_rows_equal_cor(rows, "--digits 20");
}

// A stick's contact never ends, in seconds too, whatever the arithmetic (double-double's
// inf * x is NaN: the conversion must not multiply it).
TEST_F(PhysicalTable, AStickLastsForeverInSecondsInEveryArithmetic) {
  for (const char* digits : {"15", "20", "33", "40"}) {
    const auto r = run_cli(std::string("cor --model linear --m 0.001 --k 1e5 --v0 0.1 --gamma0 0.1 --gravity 9.81 "
                                       "--certify --json --digits ") + digits);
    ASSERT_EQ(r.status, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j.at("outcome"), "stick") << digits;
    EXPECT_EQ(j.at("contact_time_s"), "inf") << digits;
  }
  const std::string spec = write("spec.json", R"({"laws": "linear", "beads": {"m": 0.001, "k": 1e5}, "v0": 0.1,
    "gravity": 9.81, "gamma0": 0.1, "digits": 20})");
  ASSERT_EQ(run_cli("table " + spec + " -o " + path("out.csv") + " --quiet").status, 0);
  const auto rows = read_named_rows(path("out.csv"));
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].at("outcome"), "stick");
  EXPECT_EQ(rows[0].at("contact_time_s"), "inf");
}

TEST_F(PhysicalTable, ShardsMergeAndInterruptedRunsResumeToTheSameBytes) {
  const std::string spec = write("spec.json", materials_spec());
  ASSERT_EQ(run_cli("table " + spec + " -o " + path("full.csv") + " --quiet").status, 0);
  for (int i = 0; i < 3; ++i)
    ASSERT_EQ(run_cli("table " + spec + " -o " + path("s" + std::to_string(i) + ".csv") + " --quiet --shard " +
                      std::to_string(i) + "/3")
                  .status,
              0);
  auto r = run_cli("table merge " + path("s0.csv") + " " + path("s1.csv") + " " + path("s2.csv") + " -o " +
                   path("merged.csv") + " --quiet");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(read(path("merged.csv")), read(path("full.csv")));

  setenv("VISCOR_TABLE_STOP_AFTER", "7", 1);
  r = run_cli("table " + spec + " -o " + path("out.csv") + " --threads 1", VISCOR_CLI_TEST_HOOKS_PATH);
  unsetenv("VISCOR_TABLE_STOP_AFTER");
  EXPECT_NE(r.status, 0);
  EXPECT_FALSE(fs::exists(path("out.csv")));
  r = run_cli("table " + spec + " -o " + path("out.csv") + " --resume --quiet");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(read(path("out.csv")), read(path("full.csv")));

  // A kept row whose inputs are not the ones its index names is refused on resume.
  setenv("VISCOR_TABLE_STOP_AFTER", "3", 1);
  r = run_cli("table " + spec + " -o " + path("bad.csv") + " --threads 1", VISCOR_CLI_TEST_HOOKS_PATH);
  unsetenv("VISCOR_TABLE_STOP_AFTER");
  ASSERT_NE(r.status, 0);
  const std::string partial = read(path("bad.csv.partial"));
  const std::size_t at = partial.find(",steel,");
  ASSERT_NE(at, std::string::npos);
  write("bad.csv.partial", partial.substr(0, at) + ",glass," + partial.substr(at + 7));
  r = run_cli("table " + spec + " -o " + path("bad.csv") + " --resume");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("not the grid point"), std::string::npos) << r.err;
}

TEST_F(PhysicalTable, BadSpecsAreRefusedNamingTheFieldOrRowAndWriteNothing) {
  const std::string bead = R"("beads": [{"name": "steel", "youngs_modulus": 2.1e11, "poisson_ratio": 0.3, "radius": 0.004, "density": 7850}])";
  const std::vector<std::pair<std::string, std::string>> cases{
      {R"({"laws": "tsuji", )" + bead + R"(, "v0": 1, "gamma0": 1e-6, "digits": 15})", "field gravity: missing"},
      {R"({"laws": "tsuji", )" + bead + R"(, "v0": 1, "gravity": 9.81, "gamma0": 1e-6, "gamma": 0.1, "digits": 15})",
       "field gamma: a spec in SI"},
      {R"({"laws": "tsuji", )" + bead + R"(, "v0": 1, "gravity": -9.81, "gamma0": 1e-6, "digits": 15})", "gravity"},
      {R"({"laws": "linear", )" + bead + R"(, "v0": 1, "gravity": 9.81, "gamma0": 1e-6, "digits": 15})",
       "row 0 (linear"},
      {R"({"laws": "tsuji", "beads": [{"name": "x", "m": 1, "k": 1, "radius": 0.1}], "v0": 1, "gravity": 0, "gamma0": 1, "digits": 15})",
       "field beads[0]"},
      {R"({"laws": "tsuji", )" + bead + R"(, "v0": 1, "gravity": 9.81, "gamma0": 1e-6, "method": "exact", "digits": 15})",
       "field method"},
      {R"({"laws": "tsuji", )" + bead + R"(, "walls": "concrete", "v0": 1, "gravity": 9.81, "gamma0": 1e-6, "digits": 15})",
       "field walls[0]"},
      {R"({"laws": "tsuji", )" + bead + R"(, "contact": "pair", "walls": "rigid", "v0": 1, "gravity": 9.81, "gamma0": 1e-6, "digits": 15})",
       "field walls"},
      {R"({"laws": "tsuji", )" + bead + R"(, "v0": [1, -1], "gravity": 9.81, "gamma0": 1e-6, "digits": 15})", "v0"},
      {R"({"laws": "tsuji", )" + bead + R"(, "v0": 1, "gravity": 9.81, "gamma0": 1e-6, "target_e": 0.5, "digits": 15})",
       "field gamma0: give either gamma0 or target_e"},
      {R"({"laws": "tsuji", )" + bead + R"(, "v0": 1, "gravity": 9.81, "target_e": [0.5, 1], "digits": 15})",
       "field target_e: must be in (0, 1), got 1"},
  };
  for (const auto& [text, message] : cases) {
    const std::string spec = write("spec.json", text);
    const auto r = run_cli("table " + spec + " -o " + path("out.csv"));
    EXPECT_EQ(r.status, 2) << text << "\n" << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << text << "\n" << r.err;
    EXPECT_FALSE(fs::exists(path("out.csv"))) << text;
    EXPECT_FALSE(fs::exists(path("out.csv.partial"))) << text;
  }
}

}  // namespace
