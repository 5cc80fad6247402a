// The C export of the committed surrogates (jobs/surrogate_export.hpp): SHA-256
// against the standard's vectors; the committed export (examples/c_export/) is a
// fresh export byte for byte and names the current files' hashes; the export compiles
// warning-free as C99 (gcc, clang) and as C++; and, compiled with plain `cc` (no
// viscor include path) with tests/data/c_export/check_driver.c, it gives the library's
// outcome and values within the stated bound at every committed verification point
// of every law (the worst difference and the count of bit-identical values printed).
#include <viscor/jobs/surrogate_export.hpp>
#include <viscor/core/sha256.hpp>
#include <viscor/jobs/files.hpp>
#include <viscor/jobs/surrogate_files.hpp>
#include <viscor/surrogate/cor_surrogate.hpp>
#include <viscor/core/scaling.hpp>

#include "required_dependencies.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using viscor::jobs::surrogate_export_options;

std::string source_dir() { return VISCOR_SOURCE_DIR; }
std::string surrogate_dir() { return VISCOR_SOURCE_DIR "/reference_data/surrogates"; }

// A scratch directory under the build tree, beside the test program.
fs::path scratch(const std::string& name) {
  std::error_code ec;
  fs::path base = fs::read_symlink("/proc/self/exe", ec);
  base = ec ? fs::current_path() : base.parent_path();
  const fs::path dir = base / "surrogate_export_scratch" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

bool have(const std::string& program) {
  return std::system(("command -v " + program + " > /dev/null 2>&1").c_str()) == 0;
}

std::string file_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Runs `command`; its exit status and what it printed (stdout and stderr).
std::pair<int, std::string> run(const std::string& command, const fs::path& log) {
  const int status = std::system((command + " > '" + log.string() + "' 2>&1").c_str());
  return {status, file_text(log)};
}

std::vector<viscor::jobs::exported_file> export_all() {
  surrogate_export_options o;
  o.surrogate_directory = surrogate_dir();
  return viscor::jobs::surrogate_export_files(o);
}

std::string hex(double x) {
  char b[64];
  std::snprintf(b, sizeof b, "%a", x);
  return b;
}

TEST(SurrogateExport, Sha256MatchesTheStandardsVectors) {
  using viscor::sha256_hex;
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(sha256_hex(std::string(1000000, 'a')), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(SurrogateExport, RefusesUnknownLanguageAndLaw) {
  surrogate_export_options o;
  o.surrogate_directory = surrogate_dir();
  o.language = "fortran";
  EXPECT_THROW(viscor::jobs::surrogate_export_files(o), viscor::invalid_parameter);
  o.language = "c";
  o.laws = {"no_such_law"};
  EXPECT_THROW(viscor::jobs::surrogate_export_files(o), viscor::invalid_parameter);
}

TEST(SurrogateExport, RefusesAnOutputThatIsNotADirectory) {
  const fs::path dir = scratch("not_a_directory");
  { std::ofstream(dir / "file") << "x"; }
  surrogate_export_options o;
  o.surrogate_directory = surrogate_dir();
  o.laws = {"linear"};
  o.output_directory = (dir / "file").string();
  EXPECT_THROW(viscor::jobs::export_surrogates(o), viscor::invalid_parameter);
  EXPECT_EQ(viscor::jobs::read_file((dir / "file").string()), "x");
}

TEST(SurrogateExport, OneLawGivesItsOwnPair) {
  surrogate_export_options o;
  o.surrogate_directory = surrogate_dir();
  o.laws = {"tsuji"};
  const auto files = viscor::jobs::surrogate_export_files(o);
  ASSERT_EQ(files.size(), 2u);
  EXPECT_EQ(files[0].name, "viscor_surrogate_tsuji.h");
  EXPECT_EQ(files[1].name, "viscor_surrogate_tsuji.c");
  EXPECT_NE(files[1].text.find("const viscor_surrogate viscor_surrogate_tsuji = {"), std::string::npos);
  EXPECT_EQ(files[1].text.find("viscor_surrogate_linear"), std::string::npos);
}

// A committed surrogate changed without exporting again fails here: the committed
// export must be a fresh export byte for byte, and it names the files' current hashes.
TEST(SurrogateExport, CommittedExportIsCurrent) {
  const auto files = export_all();
  for (const auto& f : files) {
    const std::string committed = viscor::jobs::read_file(source_dir() + "/examples/c_export/" + f.name);
    EXPECT_TRUE(committed == f.text) << "examples/c_export/" << f.name << " is not a fresh export of "
                                     << "reference_data/surrogates/: run viscor surrogate export --language c "
                                     << "-o examples/c_export";
    for (const auto& law : viscor::named_laws) {
      const std::string file = surrogate_dir() + "/" + std::string(law.name) + ".surrogate";
      if (!fs::exists(file)) continue;
      EXPECT_NE(committed.find(viscor::sha256_hex(viscor::jobs::read_file(file))), std::string::npos)
          << "examples/c_export/" << f.name << " does not carry the SHA-256 of " << file;
    }
  }
}

// A copy of tsuji's committed surrogate and verification table in a scratch folder,
// the surrogate's text passed through `edit`; with `manifest`, a SHA256SUMS listing
// the committed (unedited) hashes of both.
fs::path tsuji_copy(const std::string& name, const std::function<void(std::string&)>& edit, bool manifest) {
  const fs::path dir = scratch(name);
  const std::string surrogate = viscor::jobs::read_file(surrogate_dir() + "/tsuji.surrogate");
  const std::string table = viscor::jobs::read_file(surrogate_dir() + "/tsuji.surrogate.verification.csv");
  std::string edited = surrogate;
  edit(edited);
  std::ofstream(dir / "tsuji.surrogate", std::ios::binary) << edited;
  std::ofstream(dir / "tsuji.surrogate.verification.csv", std::ios::binary) << table;
  if (manifest)
    std::ofstream(dir / "SHA256SUMS", std::ios::binary)
        << viscor::sha256_hex(surrogate) << "  tsuji.surrogate\n"
        << viscor::sha256_hex(table) << "  tsuji.surrogate.verification.csv\n";
  return dir;
}

std::string export_refusal(const fs::path& surrogates) {
  surrogate_export_options o;
  o.surrogate_directory = surrogates.string();
  o.laws = {"tsuji"};
  o.output_directory = (surrogates / "out").string();
  try {
    viscor::jobs::export_surrogates(o);
  } catch (const viscor::invalid_parameter& e) {
    EXPECT_FALSE(fs::exists(surrogates / "out" / "viscor_surrogate_tsuji.c"));
    return e.what();
  }
  return "";
}

// The export reads the surrogates through the checking reader: one changed digit in a
// surrogate a manifest lists is refused, and nothing is written.
TEST(SurrogateExport, ReadsOnlyCheckedSurrogates) {
  const auto one_digit = [](std::string& t) { t.replace(t.find("0.33417913660990911"), 19, "0.33417913660990912"); };
  EXPECT_EQ(export_refusal(tsuji_copy("checked_intact", [](std::string&) {}, true)), "");
  const std::string why = export_refusal(tsuji_copy("checked_changed", one_digit, true));
  EXPECT_NE(why.find("tsuji.surrogate: content does not match its SHA-256"), std::string::npos) << why;
}

// Without a manifest to catch it, the export's own accuracy table does: a surrogate
// whose stated bound its verification points break is not exported.
TEST(SurrogateExport, RefusesASurrogateThatBreaksItsOwnBound) {
  const auto changed_coefficient = [](std::string& t) {
    t.replace(t.find("0.33417913660990911"), 19, "0.34417913660990911");  // one digit of the threshold's first coefficient
  };
  const auto tighter_bound = [](std::string& t) {
    t.replace(t.find("bound 2.8800713645026586e-13"), 28, "bound 2.8800713645026586e-17");
  };
  for (const auto& [what, edit] : std::vector<std::pair<std::string, std::function<void(std::string&)>>>{
           {"a changed coefficient", changed_coefficient}, {"a bound tighter than measured", tighter_bound}}) {
    const std::string why = export_refusal(tsuji_copy("own_bound", edit, false));
    EXPECT_NE(why.find("breaks the bound it states on its own verification table"), std::string::npos)
        << what << ": " << (why.empty() ? "exported" : why);
  }
}

// -o DIR replaces only an export viscor wrote and nobody edited (its seal matches);
// both files are checked before either is written.
TEST(SurrogateExport, ReplacesOnlyItsOwnUneditedFiles) {
  const fs::path dir = scratch("own_files");
  surrogate_export_options o;
  o.surrogate_directory = surrogate_dir();
  o.laws = {"tsuji"};
  o.output_directory = dir.string();
  const fs::path h = dir / "viscor_surrogate_tsuji.h", c = dir / "viscor_surrogate_tsuji.c";
  viscor::jobs::export_surrogates(o);
  const std::string header = viscor::jobs::read_file(h.string()), source = viscor::jobs::read_file(c.string());
  EXPECT_NO_THROW(viscor::jobs::export_surrogates(o));  // its own, unedited: replaced
  std::ofstream(c, std::ios::app) << "/* a user's note */\n";
  EXPECT_THROW(viscor::jobs::export_surrogates(o), viscor::invalid_parameter);
  EXPECT_EQ(viscor::jobs::read_file(c.string()), source + "/* a user's note */\n");
  fs::remove(c);
  std::ofstream(h, std::ios::trunc) << "/* viscor_surrogate_tsuji.h: somebody else's header */\n";
  EXPECT_THROW(viscor::jobs::export_surrogates(o), viscor::invalid_parameter);
  EXPECT_FALSE(fs::exists(c));  // the .c is not written when the .h may not be
  fs::remove(h);
  viscor::jobs::export_surrogates(o);
  EXPECT_EQ(viscor::jobs::read_file(h.string()), header);
}

// A null surrogate and a negative gravity are documented results in C (NaN, or the
// outcome VISCOR_OUTSIDE_DOMAIN), not a crash or a silent number.
TEST(SurrogateExport, NullSurrogateAndNegativeGravityAreRefusedInC) {
  if (!have("cc")) VISCOR_SKIP_OR_FAIL_MISSING("a C compiler (cc)");
  const fs::path dir = scratch("refusals_in_c");
  surrogate_export_options o;
  o.surrogate_directory = surrogate_dir();
  o.laws = {"tsuji"};
  o.output_directory = dir.string();
  viscor::jobs::export_surrogates(o);
  std::ofstream(dir / "driver.c") << R"(#include <math.h>
#include <stdio.h>
#include "viscor_surrogate_tsuji.h"
int main(void) {
    const viscor_surrogate* s = viscor_surrogate_named("tsuji");
    const viscor_surrogate* none = viscor_surrogate_named("no_such_law");
    int bad = 0;
    bad += none != 0;
    bad += viscor_cor_at(none, 0.1, 0.5).outcome != VISCOR_OUTSIDE_DOMAIN || !isnan(viscor_e(none, 0.1, 0.5));
    bad += !isnan(viscor_critical_gamma(none, 1.0)) || !isnan(viscor_gamma_for(none, 0.8, 0.5));
    bad += !isnan(viscor_time_scale(none, 1e-3, 1e6, 1.0)) || !isnan(viscor_scaled_g(none, 1e-3, 1e6, 1.0, 9.81, 0));
    bad += viscor_cor_physical(none, 1e-3, 1e6, 1e-3, 1.0, 9.81, 0).outcome != VISCOR_OUTSIDE_DOMAIN;
    bad += !isnan(viscor_damping_for(none, 0.8, 1e-3, 1e6, 1.0, 9.81, 0));
    bad += viscor_cor_physical(s, 1e-3, 1e6, 1e-6, 1.0, -9.81, 0).outcome != VISCOR_OUTSIDE_DOMAIN;
    bad += !isnan(viscor_damping_for(s, 0.8, 1e-3, 1e6, 1.0, -9.81, 0));
    bad += !isnan(viscor_scaled_g(s, 1e-3, 1e6, 1.0, -9.81, 0));
    /* the same inputs with gravity towards the wall give numbers */
    bad += viscor_cor_physical(s, 1e-3, 1e6, 1e-6, 1.0, 9.81, 0).outcome != VISCOR_REBOUND;
    bad += isnan(viscor_damping_for(s, 0.8, 1e-3, 1e6, 1.0, 9.81, 0));
    printf("%d wrong\n", bad);
    return bad != 0;
}
)";
  const auto [status, output] =
      run("cd '" + dir.string() + "' && cc -std=c99 -O2 driver.c viscor_surrogate_tsuji.c -lm -o driver && ./driver",
          dir / "driver.log");
  EXPECT_EQ(status, 0) << output;
  EXPECT_NE(output.find("0 wrong"), std::string::npos) << output;
}

TEST(SurrogateExport, CompilesWarningFreeAsC99AndAsCxx) {
  const fs::path dir = scratch("warnings");
  surrogate_export_options o;
  o.surrogate_directory = surrogate_dir();
  o.output_directory = dir.string();
  viscor::jobs::export_surrogates(o);
  const std::string c = "'" + (dir / "viscor_surrogates.c").string() + "'";
  // -O2: some warnings (maybe-uninitialized) need the optimizer's analysis.
  const std::string flags_out = " -O2 -c -o '" + (dir / "out.o").string() + "' ";
  const std::vector<std::pair<std::string, std::string>> compilers{
      {"gcc", "gcc -std=c99 -Wall -Wextra -pedantic -Werror" + flags_out + c},
      {"clang", "clang -std=c99 -Wall -Wextra -pedantic -Werror" + flags_out + c},
      {"g++", "g++ -x c++ -Wall -Wextra -Werror" + flags_out + c},
      {"clang++", "clang++ -x c++ -Wall -Wextra -Werror" + flags_out + c}};
  int tried = 0;
  for (const auto& [program, command] : compilers) {
    if (!have(program)) continue;
    ++tried;
    const auto [status, output] = run(command, dir / (program + ".log"));
    EXPECT_EQ(status, 0) << command << "\n" << output;
    EXPECT_EQ(output, "") << command;
  }
  if (tried == 0) VISCOR_SKIP_OR_FAIL_MISSING("a C compiler (gcc or clang)");
}

struct worst {
  double diff = 0;
  std::size_t identical = 0, total = 0, both_nan = 0;
  void add(double c, double lib, double d) {
    ++total;
    if (std::isnan(c) && std::isnan(lib)) ++both_nan;
    if (std::memcmp(&c, &lib, sizeof c) == 0 || (std::isnan(c) && std::isnan(lib))) ++identical;
    diff = std::max(diff, d);
  }
};

// Every committed verification point of every law, through the exported C compiled
// with plain cc, against the library.
TEST(SurrogateExport, CompiledWithCcAgreesWithTheLibrary) {
  if (!have("cc")) VISCOR_SKIP_OR_FAIL_MISSING("cc, a C compiler");
  const fs::path dir = scratch("check");
  surrogate_export_options o;
  o.surrogate_directory = surrogate_dir();
  o.output_directory = dir.string();
  viscor::jobs::export_surrogates(o);
  fs::copy_file(source_dir() + "/tests/data/c_export/check_driver.c", dir / "check_driver.c");
  const std::string build = "cd '" + dir.string() + "' && cc -std=c99 -O2 check_driver.c viscor_surrogates.c -lm -o check_driver";
  const auto [status, output] = run(build, dir / "cc.log");
  ASSERT_EQ(status, 0) << build << "\n" << output;

  struct request {
    const viscor::surrogate::cor_surrogate* s;
    std::string law;
    char kind;
    std::vector<double> a;
  };
  std::vector<viscor::surrogate::cor_surrogate> surrogates;
  std::vector<std::string> laws;
  for (const auto& n : viscor::named_laws)
    if (fs::exists(surrogate_dir() + "/" + std::string(n.name) + ".surrogate")) {
      laws.emplace_back(n.name);
      surrogates.push_back(viscor::surrogate::read_cor_surrogate(surrogate_dir() + "/" + std::string(n.name) + ".surrogate"));
    }
  ASSERT_FALSE(laws.empty());
  std::vector<request> requests;
  std::mt19937_64 rng(39);
  auto uniform = [&](double a, double b) { return a + (b - a) * static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  for (std::size_t l = 0; l < laws.size(); ++l) {
    const auto& s = surrogates[l];
    const auto rows = viscor::jobs::read_verification_rows(surrogate_dir() + "/" + laws[l] + ".surrogate.verification.csv");
    for (const auto& r : rows) requests.push_back({&s, laws[l], 'c', {r.gamma, r.g}});
    for (std::size_t i = 0; i < rows.size(); i += 10) requests.push_back({&s, laws[l], 't', {rows[i].g}});
    for (int i = 0; i < 2000; ++i) {  // the inverse, as docs/surrogate.md measures its round trip
      const double e = uniform(0.01, 1);
      const double g = i % 2 ? uniform(s.g_min, 0) : std::exp(uniform(std::log(1e-3), std::log(s.g_max)));
      requests.push_back({&s, laws[l], 'i', {e, g}});
    }
    for (int i = 0; i < 500; ++i) {  // physical inputs: m, k, gamma0, v0, gravity, force
      const double m = std::exp(uniform(-12, 0)), k = std::exp(uniform(0, 20)), v0 = std::exp(uniform(-4, 2));
      const double gamma0 = std::exp(uniform(-12, 2)), gravity = uniform(0, 20), force = uniform(-1, 1) * m;
      requests.push_back({&s, laws[l], 'p', {m, k, gamma0, v0, gravity, force}});
      requests.push_back({&s, laws[l], 'd', {uniform(0.05, 0.99), m, k, v0, gravity, force}});
    }
  }
  {
    std::ofstream in(dir / "requests.txt");
    for (const auto& r : requests) {
      in << r.kind << ' ' << r.law;
      for (const double x : r.a) in << ' ' << hex(x);
      in << '\n';
    }
  }
  const std::string command = "cd '" + dir.string() + "' && ./check_driver < requests.txt > answers.txt";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  std::ifstream answers(dir / "answers.txt");
  std::map<std::string, worst> e_diff, e2_diff, rel_diff, inverse_diff, threshold_diff, physical_diff, damping_diff;
  std::size_t outcome_mismatches = 0, rebounds = 0;
  for (const auto& r : requests) {
    const auto& s = *r.s;
    auto read = [&] {
      std::string t;
      answers >> t;
      return std::strtod(t.c_str(), nullptr);
    };
    if (r.kind == 'c' || r.kind == 'p') {
      int outcome = 0;
      answers >> outcome;
      const double e = read(), one_minus_e = read(), e2 = read();
      viscor::surrogate::surrogate_value v;
      if (r.kind == 'c') {
        v = s(r.a[0], r.a[1]);
      } else {
        viscor::physical_parameters<double> p;
        p.m = r.a[0], p.k = r.a[1], p.gamma0 = r.a[2], p.v0 = r.a[3], p.gravity = r.a[4], p.force = r.a[5];
        const auto sc = viscor::to_scaled(viscor::law_by_name(r.law), p);
        v = s(sc.gamma, sc.g);
      }
      const int lib = !v.in_domain ? -1 : v.outcome == viscor::impact_outcome::stick ? 1 : 0;
      if (outcome != lib) {
        ++outcome_mismatches;
        ADD_FAILURE() << r.law << " " << r.kind << " at " << hex(r.a[0]) << ", " << hex(r.a[1]) << ": outcome " << outcome
                      << ", library " << lib;
        continue;
      }
      if (lib < 0) continue;
      if (r.kind == 'p') {
        physical_diff[r.law].add(e, v.e, std::abs(e - v.e));
        continue;
      }
      if (lib == 0) ++rebounds;
      e_diff[r.law].add(e, v.e, std::abs(e - v.e));
      e2_diff[r.law].add(e2, v.e_squared, std::abs(e2 - v.e_squared));
      rel_diff[r.law].add(one_minus_e, v.one_minus_e, std::abs(one_minus_e / v.one_minus_e - 1));
      EXPECT_LE(std::abs(e - v.e), s.bound.abs_e) << r.law << " at gamma = " << hex(r.a[0]) << ", g = " << hex(r.a[1]);
      EXPECT_LE(std::abs(e2 - v.e_squared), s.bound.abs_e_squared) << r.law << " at " << hex(r.a[0]) << ", " << hex(r.a[1]);
      EXPECT_LE(std::abs(one_minus_e / v.one_minus_e - 1), s.bound.rel_one_minus_e) << r.law << " at " << hex(r.a[0]);
    } else if (r.kind == 'i') {
      const double c = read(), lib = s.gamma_for(r.a[0], r.a[1]);
      ASSERT_EQ(std::isnan(c), std::isnan(lib)) << r.law << " gamma_for(" << hex(r.a[0]) << ", " << hex(r.a[1]) << ")";
      if (std::isnan(lib)) {
        inverse_diff[r.law].add(c, lib, 0);
        continue;
      }
      // gamma itself has no stated bound; both must give e_target back within the bound on e.
      inverse_diff[r.law].add(c, lib, std::abs(c - lib) / std::max(lib, 1e-300));
      EXPECT_LE(std::abs(s(c, r.a[1]).e - r.a[0]), 2 * s.bound.abs_e + 1e-14) << r.law << " round trip at " << hex(r.a[0]);
    } else if (r.kind == 't') {
      const double c = read(), lib = r.a[0] <= s.g_split ? HUGE_VAL : s.critical_gamma(r.a[0]);
      threshold_diff[r.law].add(c, lib, c == lib ? 0 : std::abs(c / lib - 1));
      EXPECT_LE(c == lib ? 0 : std::abs(c / lib - 1), 1e-15) << r.law << " gamma_c at g = " << hex(r.a[0]);
    } else {
      const double c = read();
      viscor::physical_parameters<double> p;
      p.m = r.a[1], p.k = r.a[2], p.v0 = r.a[3], p.gravity = r.a[4], p.force = r.a[5], p.gamma0 = 0;
      const auto law = viscor::law_by_name(r.law);
      const auto sc = viscor::to_scaled(law, p);
      const double gamma = s.gamma_for(r.a[0], sc.g);
      const double lib = std::isnan(gamma) ? gamma : viscor::to_physical(law, gamma, sc.g, p.m, p.k, p.v0, p.gravity).gamma0;
      ASSERT_EQ(std::isnan(c), std::isnan(lib)) << r.law << " damping_for";
      damping_diff[r.law].add(c, lib, std::isnan(lib) ? 0 : std::abs(c / lib - 1));
      EXPECT_LE(std::isnan(lib) ? 0 : std::abs(c / lib - 1), 1e-14) << r.law << " damping_for";
    }
  }
  EXPECT_EQ(outcome_mismatches, 0u);
  std::printf("exported C (cc -std=c99 -O2) against the library, per law: bit-identical / compared, worst difference\n");
  for (const auto& law : laws)
    std::printf("  %-21s e %zu/%zu (%.2e)  e^2 %zu/%zu (%.2e)  1-e %zu/%zu (rel %.2e)  gamma_c %zu/%zu (rel %.2e)  "
                "gamma_for %zu/%zu (rel %.2e; %zu NaN)  physical e %zu/%zu (%.2e)  damping_for %zu/%zu (rel %.2e; %zu NaN)\n",
                law.c_str(), e_diff[law].identical, e_diff[law].total, e_diff[law].diff, e2_diff[law].identical,
                e2_diff[law].total, e2_diff[law].diff, rel_diff[law].identical, rel_diff[law].total, rel_diff[law].diff,
                threshold_diff[law].identical, threshold_diff[law].total, threshold_diff[law].diff,
                inverse_diff[law].identical, inverse_diff[law].total, inverse_diff[law].diff, inverse_diff[law].both_nan,
                physical_diff[law].identical, physical_diff[law].total, physical_diff[law].diff,
                damping_diff[law].identical, damping_diff[law].total, damping_diff[law].diff, damping_diff[law].both_nan);
  std::printf("  (%zu rebounds among the verification points)\n", rebounds);

  // The same answers, bit for bit, from the export's portable copy (no run-time choice
  // of the FMA path) and in GNU C (-std=gnu99, where GCC fuses a * b + c into an fma on
  // its own when the target has one: a product-plus-sum written outside fma() in the
  // FMA copy would differ here).
  const std::string dispatched = file_text(dir / "answers.txt");
  ASSERT_GT(dispatched.size(), requests.size());
  for (const auto& [name, flags] : {std::pair<std::string, std::string>{"portable", "-std=c99 -DVISCOR_SG_NO_DISPATCH"},
                                    {"gnu", "-std=gnu99"}}) {
    const std::string program = "check_driver_" + name;
    const std::string compile_and_run = "(cd '" + dir.string() + "' && cc " + flags + " -O2 check_driver.c viscor_surrogates.c -lm -o " +
                                        program + " && ./" + program + " < requests.txt > " + program + ".answers)";
    const auto [status, output] = run(compile_and_run, dir / (program + ".log"));
    ASSERT_EQ(status, 0) << compile_and_run << "\n" << output;
    EXPECT_TRUE(file_text(dir / (program + ".answers")) == dispatched) << name << " (" << flags << ") differs from cc -std=c99 -O2";
  }
#if (defined(__x86_64__) || defined(__i386__)) && (defined(__GNUC__) || defined(__clang__))
  std::printf("  the same bits from the portable copy and from -std=gnu99; this CPU %s the FMA copy\n",
              __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") ? "takes" : "does not have");
#endif
}

}  // namespace
