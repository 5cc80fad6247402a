// Committed data files carry checksums that are verified when read
// (core/checksums.hpp): every manifest under reference_data/ is true and lists
// every data file of its directory; a copy of a committed surrogate, error map or
// table with one digit changed is refused with a message naming the file, through
// the library and the CLI; viscor's own writes keep a listed file's line true.
#include "test_utils.hpp"

#include <viscor/core/checksums.hpp>
#include <viscor/jobs/files.hpp>
#include <viscor/scenes/error_map.hpp>
#include <viscor/surrogate/cor_surrogate.hpp>
#include <viscor/tables/reference_table.hpp>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <sys/stat.h>
#include <unistd.h>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

namespace {

using viscor::test::scratch_dir;

namespace fs = std::filesystem;

const fs::path data_root = fs::path(VISCOR_SOURCE_DIR) / "reference_data";

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Copies `file` and the manifest beside it into `to`, then changes the first nonzero
/// digit of the line after the one holding `after` to another digit: a coefficient or
/// a value, so that the file stays well formed.
fs::path damaged_copy(const fs::path& file, const fs::path& to, const std::string& after) {
  fs::copy_file(file.parent_path() / viscor::checksum_manifest_name, to / viscor::checksum_manifest_name);
  std::string text = slurp(file);
  std::size_t at = text.find(after);
  EXPECT_NE(at, std::string::npos);
  at = text.find('\n', at + after.size());
  at = text.find_first_of("123456789", at);
  text[at] = text[at] == '9' ? '8' : static_cast<char>(text[at] + 1);
  const fs::path copy = to / file.filename();
  std::ofstream(copy, std::ios::binary) << text;
  return copy;
}

TEST(Checksums, CommittedManifestsAreTrueAndComplete) {
  const std::pair<const char*, std::set<std::string>> dirs[] = {
      {"", {".csv"}},         {"proven", {".csv"}},     {"proven/digits50", {".csv"}},
      {"dem", {".csv"}},      {"error_maps", {".csv"}}, {"surrogates", {".surrogate", ".csv"}}};
  for (const auto& [sub, extensions] : dirs) {
    const fs::path dir = data_root / sub;
    std::set<std::string> listed;
    for (const auto& e : viscor::read_checksum_manifest(dir / "x")) {
      listed.insert(e.name);
      EXPECT_NO_THROW(viscor::verify_checksum((dir / e.name).string(), slurp(dir / e.name))) << e.name;
    }
    EXPECT_FALSE(listed.empty()) << dir;
    for (const auto& entry : fs::directory_iterator(dir))
      if (entry.is_regular_file() && extensions.count(entry.path().extension().string()))
        EXPECT_TRUE(listed.count(entry.path().filename().string()))
            << entry.path() << " is not in " << (dir / viscor::checksum_manifest_name)
            << ": run tools/update_checksums.sh";
  }
}

TEST(Checksums, ChangedSurrogateCoefficientIsRefused) {
  scratch_dir s{"viscor_checksums"};
  const fs::path copy = damaged_copy(data_root / "surrogates" / "tsuji.surrogate", s.path, "\nthreshold");
  try {
    viscor::surrogate::read_cor_surrogate(copy.string());
    FAIL() << "a changed coefficient was read";
  } catch (const viscor::parse_error& e) {
    EXPECT_NE(std::string(e.what()).find(copy.string() + ": content does not match its SHA-256"), std::string::npos)
        << e.what();
  }
  // the same bytes without the manifest: a user's file, read as before
  fs::remove(s.path / viscor::checksum_manifest_name);
  EXPECT_NO_THROW(viscor::surrogate::read_cor_surrogate(copy.string()));
}

TEST(Checksums, ChangedErrorMapAndTableAreRefused) {
  scratch_dir s{"viscor_checksums"};
  const fs::path map = damaged_copy(data_root / "error_maps" / "tsuji.csv", s.path, "\n");
  EXPECT_THROW(viscor::read_error_map(map.string()), viscor::parse_error);
  fs::remove(s.path / viscor::checksum_manifest_name);
  scratch_dir t{"viscor_checksums"};
  const fs::path table = damaged_copy(data_root / "cor_g_sweep.csv", t.path, "\n1,");
  EXPECT_THROW(viscor::read_table(table.string()), viscor::parse_error);
}

// The report: `approx --formula surrogate` used a surrogate whose coefficients
// were changed; now the CLI refuses it, naming the file.
TEST(Checksums, CliRefusesAChangedCommittedSurrogate) {
  scratch_dir s{"viscor_checksums"};
  for (const auto& entry : fs::directory_iterator(data_root / "surrogates"))
    fs::copy_file(entry.path(), s.path / entry.path().filename());
  const fs::path copy = s.path / "kuwabara_kono.surrogate";
  fs::remove(copy);
  fs::remove(s.path / viscor::checksum_manifest_name);
  damaged_copy(data_root / "surrogates" / "kuwabara_kono.surrogate", s.path, "\nthreshold");
  const auto r = viscor::test::run_cli("", "VISCOR_SURROGATE_DIR='" + s.path.string() + "' " +
                                               std::string(VISCOR_CLI_PATH) +
                                               " approx --model kuwabara_kono --gamma 0.05 --g 1 --formula surrogate");
  EXPECT_NE(r.status, 0) << r.out;
  EXPECT_NE(r.err.find("kuwabara_kono.surrogate: content does not match its SHA-256"), std::string::npos) << r.err;
}

// Allows replacing committed data for one scope (the CLI's --update-committed).
struct committed_data_replaceable {
  committed_data_replaceable() { viscor::jobs::replacing_committed_data_allowed() = true; }
  ~committed_data_replaceable() { viscor::jobs::replacing_committed_data_allowed() = false; }
};

TEST(Checksums, ListedFilesAreReplacedOnlyWhenAskedAndThenKeepTheirLineTrue) {
  scratch_dir s{"viscor_checksums"};
  const fs::path file = s.path / "a.csv", other = s.path / "b.csv", manifest = s.path / viscor::checksum_manifest_name;
  viscor::jobs::write_atomically(file.string(), "first\n");
  viscor::jobs::write_atomically(other.string(), "other\n");
  EXPECT_FALSE(fs::exists(manifest));  // no manifest: none is made
  std::ofstream(manifest) << viscor::sha256_hex("first\n") << "  a.csv\n";
  // An ordinary write over a listed file is refused: the file and its checksum stay.
  try {
    viscor::jobs::write_atomically(file.string(), "second\n");
    ADD_FAILURE() << "a listed file was replaced";
  } catch (const viscor::invalid_parameter& e) {
    EXPECT_NE(std::string(e.what()).find("is committed data listed in"), std::string::npos) << e.what();
  }
  EXPECT_EQ(slurp(file), "first\n");
  EXPECT_EQ(slurp(manifest), viscor::sha256_hex("first\n") + "  a.csv\n");
  const committed_data_replaceable asked;
  viscor::jobs::write_atomically(file.string(), "second\n");
  EXPECT_EQ(slurp(manifest), viscor::sha256_hex("second\n") + "  a.csv\n");
  EXPECT_NO_THROW(viscor::verify_checksum(file.string(), "second\n"));
  viscor::jobs::write_atomically(other.string(), "changed\n");  // not listed: not added
  EXPECT_EQ(slurp(manifest), viscor::sha256_hex("second\n") + "  a.csv\n");
  // the known SHA-256 of "abc" (FIPS 180-2, appendix B.1), so the digest itself is right
  EXPECT_EQ(viscor::sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
}

// The manifest is read as sha256sum writes it on any platform, or refused naming the line.
TEST(Checksums, ManifestsAreReadCorrectlyOrRefusedNeverIgnored) {
  scratch_dir s{"viscor_checksums"};
  const fs::path file = s.path / "a.csv", manifest = s.path / viscor::checksum_manifest_name;
  std::ofstream(file) << "value\n";
  const std::string hash = viscor::sha256_hex("value\n"), wrong = viscor::sha256_hex("other\n");
  for (const std::string& line : {hash + "  a.csv\r\n", hash + "  ./a.csv\n", hash + " *a.csv\n"}) {
    std::ofstream(manifest, std::ios::binary) << line;
    EXPECT_TRUE(viscor::listed_in_checksum_manifest(file)) << line;
    EXPECT_NO_THROW(viscor::verify_checksum(file.string(), "value\n")) << line;
  }
  for (const std::string& line : {wrong + "  a.csv\r\n", wrong + "  ./a.csv\n", wrong + " *a.csv\n"}) {
    std::ofstream(manifest, std::ios::binary) << line;
    EXPECT_THROW(viscor::verify_checksum(file.string(), "value\n"), viscor::parse_error) << line;  // not ignored
  }
  for (const std::string& line : {hash + "  sub/a.csv\n", hash + "  ../a.csv\n", hash + "  ./\n",
                                  hash + "  a.csv\n" + wrong + "  ./a.csv\n", hash + "\ta.csv\n"}) {
    std::ofstream(manifest, std::ios::binary) << line;
    EXPECT_THROW(viscor::read_checksum_manifest(file), viscor::parse_error) << line;
  }
  // A name with a control character (a second CR before the line end: found by the
  // manifest fuzzer) names no file viscor lists: refused, not read as another name.
  for (const std::string& text : {hash + "  a.csv\r\r\n", hash + "  a\x01.csv\n"})
    EXPECT_THROW(viscor::parse_checksum_manifest(text, "SHA256SUMS"), viscor::parse_error) << text;
}

// The manifest's temporary file is created exclusively: a symbolic link planted at its name
// is not followed (the write fails and the file it points to is untouched).
TEST(Checksums, ThePlantedTemporaryOfAManifestIsNotFollowed) {
  scratch_dir s{"viscor_checksums"}, outside{"viscor_outside"};
  const fs::path file = s.path / "a.csv", manifest = s.path / viscor::checksum_manifest_name;
  const fs::path victim = outside.path / "victim.txt";
  std::ofstream(victim) << "keep me\n";
  std::ofstream(file) << "first\n";
  std::ofstream(manifest) << viscor::sha256_hex("first\n") << "  a.csv\n";
  fs::create_symlink(victim, manifest.string() + ".tmp");
  fs::create_symlink(victim, manifest.string() + ".tmp." + std::to_string(::getpid()));
  EXPECT_THROW(viscor::update_checksum(file.string(), "second\n"), viscor::error);
  EXPECT_EQ(slurp(victim), "keep me\n");
  EXPECT_EQ(slurp(manifest), viscor::sha256_hex("first\n") + "  a.csv\n");
}

// A deck or block viscor may replace carries a seal; the name, the first line or a FIFO is no proof.
TEST(Checksums, OnlyAnUneditedSealedFileCountsAsViscors) {
  scratch_dir s{"viscor_sealed"};
  const std::string marker = "# viscor dem variables";
  const fs::path own = s.path / "own.in", edited = s.path / "edited.in", marker_only = s.path / "marker.in";
  const fs::path big = s.path / "big.in", fifo = s.path / "fifo.in";
  const std::string body = marker + ": test\nvariable x string 1\n";
  std::ofstream(own, std::ios::binary) << viscor::jobs::sealed(body);
  EXPECT_TRUE(viscor::jobs::is_unedited_viscor_file(own.string(), marker));
  std::string text = viscor::jobs::sealed(body);
  text.replace(text.find("string 1"), 8, "string 2");
  std::ofstream(edited, std::ios::binary) << text;
  EXPECT_FALSE(viscor::jobs::is_unedited_viscor_file(edited.string(), marker));
  std::ofstream(marker_only, std::ios::binary) << body;
  EXPECT_FALSE(viscor::jobs::is_unedited_viscor_file(marker_only.string(), marker));
  std::ofstream(big, std::ios::binary) << viscor::jobs::sealed(body + std::string(2 << 20, '#') + "\n");
  EXPECT_FALSE(viscor::jobs::is_unedited_viscor_file(big.string(), marker));  // not read: too large to be ours
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_FALSE(viscor::jobs::is_unedited_viscor_file(fifo.string(), marker));  // returns at once, no hang
  EXPECT_THROW(viscor::jobs::refuse_unless_own_or_absent(fifo.string(), marker, "--variables", "a variable block"),
               viscor::invalid_parameter);
  EXPECT_NO_THROW(viscor::jobs::refuse_unless_own_or_absent(own.string(), marker, "--variables", "a variable block"));
  EXPECT_NO_THROW(viscor::jobs::refuse_unless_own_or_absent((s.path / "new.in").string(), marker, "--variables", "x"));
  EXPECT_EQ(viscor::jobs::sealed("no line end").rfind("no line end\n# viscor sha256 ", 0), 0u);
}

// A C export's seal is a C comment, checked the same way; a seal of the other style is no seal.
TEST(Checksums, TheSealOfACExportIsACComment) {
  scratch_dir s{"viscor_sealed_c"};
  const std::string marker = "/* viscor_x.h: ";
  const std::string body = marker + "test */\nint x;\n";
  const std::string text = viscor::jobs::sealed(body, viscor::jobs::c_comment_seal);
  EXPECT_EQ(text, body + "/* viscor sha256 " + viscor::sha256_hex(body) + " */\n");
  const fs::path own = s.path / "own.h", other_style = s.path / "other.h";
  std::ofstream(own, std::ios::binary) << text;
  EXPECT_TRUE(viscor::jobs::is_unedited_viscor_file(own.string(), marker, viscor::jobs::c_comment_seal));
  EXPECT_FALSE(viscor::jobs::is_unedited_viscor_file(own.string(), marker));  // looked for as '# viscor sha256'
  std::ofstream(other_style, std::ios::binary) << viscor::jobs::sealed(body);
  EXPECT_FALSE(viscor::jobs::is_unedited_viscor_file(other_style.string(), marker, viscor::jobs::c_comment_seal));
}

// A command's outputs are published together: when one of them may not be written, none is,
// and no temporary is left behind.
TEST(Checksums, OutputsArePublishedTogetherOrNotAtAll) {
  scratch_dir s{"viscor_together"};
  const fs::path a = s.path / "a.csv", b = s.path / "b.json", dir = s.path / "d";
  std::ofstream(a, std::ios::binary) << "old a\n";
  fs::create_directory(dir);
  EXPECT_THROW(viscor::jobs::write_together({{a.string(), "new a\n"}, {dir.string(), "x\n"}}), viscor::invalid_parameter);
  EXPECT_EQ(slurp(a), "old a\n");
  // A failure while writing (the second temporary cannot be created: its folder is missing).
  const fs::path missing = s.path / "no_such_folder" / "b.json";
  EXPECT_THROW(viscor::jobs::write_together({{a.string(), "new a\n"}, {missing.string(), "x\n"}}), viscor::error);
  EXPECT_EQ(slurp(a), "old a\n");
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(s.path)) ++entries;
  EXPECT_EQ(entries, 2u);  // a.csv and d: no temporary left
  viscor::jobs::write_together({{a.string(), "new a\n"}, {b.string(), "new b\n"}});
  EXPECT_EQ(slurp(a), "new a\n");
  EXPECT_EQ(slurp(b), "new b\n");
}

// `cor -o` over a committed table: refused before any work, the table and the manifest untouched;
// viscor --update-committed replaces it and keeps its line true.
TEST(Checksums, TheCliReplacesCommittedDataOnlyWithUpdateCommitted) {
  if (std::string(VISCOR_CLI_PATH).empty()) GTEST_SKIP() << "viscor CLI not built";
  scratch_dir s{"viscor_committed"};
  const fs::path table = s.path / "cor_report_grid.csv", manifest = s.path / viscor::checksum_manifest_name;
  std::ofstream(table) << "law,gamma\n";
  std::ofstream(manifest) << viscor::sha256_hex("law,gamma\n") << "  cor_report_grid.csv\n";
  const std::string cor = " cor --model linear --gamma 0.1 --digits 20 -o " + table.string();
  const auto refused = viscor::test::run_cli(cor);
  EXPECT_EQ(refused.status, 2);
  EXPECT_NE(refused.err.find("is committed data"), std::string::npos) << refused.err;
  EXPECT_EQ(slurp(table), "law,gamma\n");
  EXPECT_EQ(slurp(manifest), viscor::sha256_hex("law,gamma\n") + "  cor_report_grid.csv\n");
  const auto asked = viscor::test::run_cli("--update-committed" + cor);
  EXPECT_EQ(asked.status, 0) << asked.err;
  EXPECT_EQ(slurp(manifest), viscor::sha256_hex(slurp(table)) + "  cor_report_grid.csv\n");
}

}  // namespace
