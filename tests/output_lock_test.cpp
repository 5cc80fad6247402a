// One writer per output: a second `viscor table` on an output another process is
// writing stops at once with a message naming it, and writes nothing; the lock goes
// with its holder. And a scene's impact count is capped before anything is allocated.
#include "test_utils.hpp"

#include <viscor/jobs/files.hpp>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

using viscor::test::scratch_dir;

using viscor::test::run_cli;

TEST(OutputLock, SecondWriterStopsWithAMessage) {
  scratch_dir s{"viscor_lock"};
  ASSERT_FALSE(s.path.empty());
  const std::string spec = (s.path / "spec.json").string(), out = (s.path / "t.csv").string();
  std::ofstream(spec) << R"({"laws": ["linear"], "gamma": [0.05, 0.5], "g": 1, "digits": 20})";
  {
    const viscor::jobs::output_lock held(out);  // another writer, as far as the CLI can tell
    const auto r = run_cli("table " + spec + " -o " + out + " --quiet");
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.err.find("another viscor is writing '" + out + "'"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out));
    EXPECT_FALSE(std::filesystem::exists(out + ".partial"));
  }
  EXPECT_FALSE(std::filesystem::exists(out + ".lock"));  // the holder removes it
  const auto r = run_cli("table " + spec + " -o " + out + " --quiet");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(out));
  EXPECT_FALSE(std::filesystem::exists(out + ".lock"));
}

// A lock file that was there before (a user's, or a killed run's) is taken but never removed:
// viscor deletes only the lock file it created.
TEST(OutputLock, ALockFileItDidNotCreateIsLeftInPlace) {
  scratch_dir s{"viscor_lock"};
  const std::string out = (s.path / "t.csv").string();
  std::ofstream(out + ".lock") << "someone's file\n";
  { const viscor::jobs::output_lock held(out); }
  ASSERT_TRUE(std::filesystem::exists(out + ".lock"));
  std::ifstream in(out + ".lock");
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "someone's file");
  { const viscor::jobs::output_lock again(out); }  // and it still locks
  std::filesystem::remove(out + ".lock");
  { const viscor::jobs::output_lock own(out); }
  EXPECT_FALSE(std::filesystem::exists(out + ".lock"));  // its own is removed
}

TEST(OutputLock, TwoLocksInOneProcessExcludeEachOther) {
  scratch_dir s{"viscor_lock"};
  const std::string out = (s.path / "t.csv").string();
  const viscor::jobs::output_lock first(out);
  EXPECT_THROW(viscor::jobs::output_lock second(out), viscor::error);
}

// table merge writes the same outputs as a table run: it takes the same lock, before
// it reads anything, and writes nothing while another viscor holds it.
TEST(OutputLock, TableMergeTakesTheLock) {
  scratch_dir s{"viscor_lock"};
  ASSERT_FALSE(s.path.empty());
  const std::string spec = (s.path / "spec.json").string(), out = (s.path / "all.csv").string();
  std::ofstream(spec) << R"({"laws": ["linear"], "gamma": [0.05, 0.5], "g": 1, "digits": 20})";
  std::string shards;
  for (const char* part : {"0", "1"}) {
    const std::string shard = (s.path / ("s" + std::string(part) + ".csv")).string();
    const auto made = run_cli("table " + spec + " -o " + shard + " --shard " + part + "/2 --quiet");
    ASSERT_EQ(made.status, 0) << made.err;
    shards += " " + shard;
  }
  {
    const viscor::jobs::output_lock held(out);
    const auto r = run_cli("table merge" + shards + " -o " + out);
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.err.find("another viscor is writing '" + out + "'"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out));
    EXPECT_FALSE(std::filesystem::exists(out + ".json"));
  }
  const auto r = run_cli("table merge" + shards + " -o " + out);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(out));
  EXPECT_FALSE(std::filesystem::exists(out + ".lock"));
}

TEST(SceneLimits, HugeImpactCountIsRefusedNamingTheField) {
  scratch_dir s{"viscor_lock"};
  const std::string scene = (s.path / "scene.json").string();
  std::ofstream(scene) << R"({"law": "kuwabara_kono", "bead": {"m": 1e-3, "k": 1e9}, "damping": {"gamma0": 1e-6},
    "gravity": 9.81, "velocities": {"from": 0.1, "to": 1, "count": 999999999}, "tolerance": 1e-6})";
  const auto r = run_cli("scene " + scene);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("velocities.count"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("999999999"), std::string::npos) << r.err;
}

}  // namespace
