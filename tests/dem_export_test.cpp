// Each DEM code's entries in the C export (jobs/dem_export.hpp): compiled with plain
// `cc` (no viscor include path) with tests/data/c_export/dem_driver.c, viscor_dem_deck
// gives, on 10,000 drawn impacts per code and model (walls rigid and of a material,
// like and unlike pairs, with and without gravity and force), the entries of `viscor dem
// --method surrogate` bit for bit (its deck strings read back), the same refusals, and
// the built-in conversions' e. Independently of the surrogate, the exact Taylor solve of
// each code's force with the exported entry lands on the target within the stated bound.
#include <viscor/dem/deck_entries.hpp>
#include <viscor/dem/stepped_drop.hpp>
#include <viscor/dem/surrogate_deck.hpp>
#include <viscor/jobs/dem_job.hpp>
#include <viscor/jobs/physical_inputs.hpp>
#include <viscor/jobs/surrogate_export.hpp>
#include <viscor/jobs/surrogate_files.hpp>

#include "required_dependencies.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

namespace fs = std::filesystem;
using viscor::dem::contact_kind;
using viscor::dem::dem_impact;

// The export's model numbers (viscor_dem_model) and viscor dem's names for them.
struct exported_model {
  int number;
  const char* code;
  const char* damping;
};
constexpr std::array<exported_model, 5> exported_models{{{0, "lammps", "velocity"},
                                                         {1, "lammps", "mass_velocity"},
                                                         {2, "lammps", "viscoelastic"},
                                                         {3, "lammps", "tsuji"},
                                                         {4, "liggghts", "hertz"}}};
// With the models that have entries at a time step only: YADE's Hertz-Mindlin clamps the force.
constexpr std::array<exported_model, 6> stepped_models{{{0, "lammps", "velocity"},
                                                        {1, "lammps", "mass_velocity"},
                                                        {2, "lammps", "viscoelastic"},
                                                        {3, "lammps", "tsuji"},
                                                        {4, "liggghts", "hertz"},
                                                        {5, "yade", "mindlin"}}};

std::string hex(double x) {
  char b[64];
  std::snprintf(b, sizeof b, "%a", x);
  return b;
}

fs::path scratch() {
  std::error_code ec;
  fs::path base = fs::read_symlink("/proc/self/exe", ec);
  base = ec ? fs::current_path() : base.parent_path();
  // One directory per process: ctest runs each test of this file as a process of its own, in parallel.
  const fs::path dir = base / "dem_export_scratch" / std::to_string(::getpid());
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// One drawn impact, with the export's flags for its partner.
struct drawn {
  dem_impact<double> impact;
  double target = 0;
};

std::string impact_text(const dem_impact<double>& i) {
  const bool pair = i.kind == contact_kind::pair;
  const auto& w = i.partner.wall;
  const auto& o = i.partner.other;
  std::ostringstream s;
  s << (pair ? 1 : 0) << ' ' << (w ? 1 : 0) << ' ' << hex(i.bead.youngs_modulus) << ' ' << hex(i.bead.poisson_ratio)
    << ' ' << hex(i.bead.radius) << ' ' << hex(i.bead.density) << ' ' << hex(w ? w->youngs_modulus : 0) << ' '
    << hex(w ? w->poisson_ratio : 0) << ' ' << (o ? 1 : 0) << ' ' << hex(o ? o->youngs_modulus : 0) << ' '
    << hex(o ? o->poisson_ratio : 0) << ' ' << hex(o ? o->radius : 0) << ' ' << hex(o ? o->density : 0) << ' '
    << hex(i.v0) << ' ' << hex(i.gravity) << ' ' << hex(i.force);
  return s.str();
}

// Impacts of every kind over the ranges DEM decks use.
std::vector<drawn> draw_impacts(std::size_t count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  auto uniform = [&](double a, double b) { return a + (b - a) * static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  auto log_uniform = [&](double a, double b) { return std::exp(uniform(std::log(a), std::log(b))); };
  auto bead = [&] {
    return viscor::dem::bead_material<double>{log_uniform(1e6, 3e11), uniform(0, 0.5), log_uniform(1e-4, 5e-2),
                                              uniform(500, 20000)};
  };
  std::vector<drawn> out;
  for (std::size_t n = 0; n < count; ++n) {
    drawn d;
    d.impact.bead = bead();
    d.impact.kind = n % 2 ? contact_kind::pair : contact_kind::wall;
    if (n % 4 == 2) d.impact.partner.wall = viscor::elastic_material<double>{log_uniform(1e6, 1e12), uniform(0, 0.5)};
    if (n % 4 == 3) d.impact.partner.other = bead();
    d.impact.v0 = log_uniform(1e-3, 5);
    d.impact.gravity = n % 3 == 0 ? 0.0 : uniform(0, 20);
    if (n % 5 == 0) d.impact.force = uniform(-0.5, 2) * d.impact.bead.mass() * 9.81;
    d.target = uniform(0.05, 0.98);
    out.push_back(d);
  }
  return out;
}

// The library's deck by the surrogate, as viscor dem --method surrogate makes it.
struct library_deck {
  int status = 0;  // viscor_deck_status: 0 ok, 1 invalid input, 2 unreachable
  viscor::dem::dem_deck<double> deck;
  viscor::dem::deck_strings strings;
};

library_deck library(const viscor::dem::dem_model& model, const drawn& d, const viscor::surrogate::cor_surrogate& s,
                     double dt = 0) {
  using viscor::dem::dem_impact;
  library_deck out;
  // as viscor dem --method surrogate [--timestep dt] makes its decks (a model that clamps: with
  // the unclamped deck as the stepped calibration's bracket)
  auto deck = [&](const viscor::dem::dem_model& m, const dem_impact<double>& i, const double& e) {
    const viscor::dem::dem_deck<double> continuous = m.clamped ? viscor::dem::unclamped_deck_by_surrogate(m, i, e, s)
                                                               : viscor::dem::dem_deck_by_surrogate(m, i, e, s);
    return dt > 0 ? viscor::dem::dem_deck_at_time_step(m, i, e, dt, continuous) : continuous;
  };
  try {
    out.deck = deck(model, d.impact, d.target);
    out.strings = viscor::dem::deck_entries_for(model, d.impact, out.deck, d.target, deck);
  } catch (const viscor::unreachable_target&) {
    out.status = 2;
  } catch (const viscor::invalid_parameter&) {
    out.status = 1;
  }
  return out;
}

// A deck entry as viscor dem prints it, read back (NaN where the deck has none).
double read_back(const std::optional<std::string>& text) { return text ? std::strtod(text->c_str(), nullptr) : NAN; }
double read_back(const std::string& text) { return std::strtod(text.c_str(), nullptr); }

bool same_bits(double a, double b) { return (std::isnan(a) && std::isnan(b)) || (a == b && std::signbit(a) == std::signbit(b)); }

class DemExport : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (std::system("command -v cc > /dev/null 2>&1") != 0) return;
    dir_ = scratch();
    viscor::jobs::surrogate_export_options o;
    o.surrogate_directory = VISCOR_SOURCE_DIR "/reference_data/surrogates";
    o.output_directory = dir_.string();
    viscor::jobs::export_surrogates(o);
    fs::copy_file(VISCOR_SOURCE_DIR "/tests/data/c_export/dem_driver.c", dir_ / "dem_driver.c");
    const std::string build = "cd '" + dir_.string() +
                              "' && cc -std=c99 -O2 -Wall -Wextra -pedantic -Werror dem_driver.c viscor_surrogates.c "
                              "-lm -o dem_driver > cc.log 2>&1";
    built_ = std::system(build.c_str()) == 0;
  }

  void SetUp() override {
    if (dir_.empty()) VISCOR_SKIP_OR_FAIL_MISSING("cc, a C compiler");
    ASSERT_TRUE(built_) << "the export with dem_driver.c did not compile: see " << (dir_ / "cc.log");
  }

  // The driver's answer lines, one per request line.
  static std::vector<std::string> ask(const std::vector<std::string>& requests) {
    {
      std::ofstream in(dir_ / "requests.txt");
      for (const auto& r : requests) in << r << '\n';
    }
    const std::string command = "cd '" + dir_.string() + "' && ./dem_driver < requests.txt > answers.txt";
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
    std::ifstream answers(dir_ / "answers.txt");
    std::vector<std::string> lines;
    for (std::string line; std::getline(answers, line);) lines.push_back(line);
    EXPECT_EQ(lines.size(), requests.size());
    return lines;
  }

  static const viscor::surrogate::cor_surrogate& surrogate_of(const viscor::dem::dem_model& model) {
    const auto* s = viscor::jobs::find_surrogate(viscor::dem::law_of(model));
    if (!s) throw std::runtime_error("no committed surrogate for " + std::string(model.law_name));
    return *s;
  }

  static void TearDownTestSuite() {
    std::error_code ec;
    if (!dir_.empty()) fs::remove_all(dir_, ec);
  }

  static inline fs::path dir_;
  static inline bool built_ = false;
};

// Compares the C decks (driver requests `kind`, with dt > 0 for the stepped ones) with the
// library's on `impacts`, every field bit for bit; the counts of decks and built-in e.
struct compared {
  std::size_t decks = 0, builtin = 0, mismatches = 0;
};

compared compare_decks(const exported_model& e, const std::vector<drawn>& impacts, const std::vector<double>& dts,
                       const std::vector<std::string>& answers, const std::vector<std::string>& requests,
                       const viscor::surrogate::cor_surrogate& s) {
  const viscor::dem::dem_model& model = viscor::dem::find_dem_model(e.code, e.damping);
  compared out;
  for (std::size_t n = 0; n < impacts.size(); ++n) {
    const library_deck lib = library(model, impacts[n], s, dts[n]);
    std::istringstream line(answers[n]);
    int status = -1;
    line >> status;
    std::array<double, 14> c{};
    for (double& x : c) {
      std::string t;
      line >> t;
      x = std::strtod(t.c_str(), nullptr);
    }
    if (status != lib.status) {
      if (++out.mismatches <= 5)
        ADD_FAILURE() << e.code << " " << e.damping << " impact " << n << ": C status " << status << ", library "
                      << lib.status << " (" << requests[n] << ")";
      continue;
    }
    if (status != 0) continue;
    ++out.decks;
    const auto& w = lib.strings;
    const std::array<std::pair<const char*, double>, 14> expected{{
        {"damping", read_back(w.damping)},
        {"damping_number", lib.deck.damping_number},
        {"gamma0", lib.deck.gamma0},
        {"youngs_modulus", read_back(w.youngs_modulus)},
        {"poisson_ratio", read_back(w.poisson_ratio)},
        {"wall_youngs_modulus", read_back(w.wall_youngs_modulus)},
        {"wall_poisson_ratio", read_back(w.wall_poisson_ratio)},
        {"other_youngs_modulus", read_back(w.other_youngs_modulus)},
        {"other_poisson_ratio", read_back(w.other_poisson_ratio)},
        {"cross_youngs_modulus", read_back(w.cross_youngs_modulus)},
        {"bead_bead_youngs_modulus", read_back(w.bead_bead_youngs_modulus)},
        {"bead_bead_damping", read_back(w.bead_bead_damping)},
        {"other_other_damping", read_back(w.other_other_damping)},
        {"builtin_e", lib.deck.builtin_e.value_or(NAN)},
    }};
    if (lib.deck.builtin_e) ++out.builtin;
    for (std::size_t f = 0; f < c.size(); ++f)
      if (!same_bits(c[f], expected[f].second) && ++out.mismatches <= 10)
        ADD_FAILURE() << e.code << " " << e.damping << " impact " << n << ": " << expected[f].first << " C "
                      << hex(c[f]) << ", library " << hex(expected[f].second) << " (" << requests[n] << ")";
  }
  return out;
}

TEST_F(DemExport, EveryEntryIsTheLibrarysBitForBit) {
  const std::vector<drawn> impacts = draw_impacts(10000, 56);
  const std::vector<double> continuous(impacts.size(), 0.0);
  for (const exported_model& e : exported_models) {
    const viscor::dem::dem_model& model = viscor::dem::find_dem_model(e.code, e.damping);
    std::vector<std::string> requests;
    for (const drawn& d : impacts)
      requests.push_back("deck " + std::to_string(e.number) + " " + hex(d.target) + " " + impact_text(d.impact));
    const std::vector<std::string> answers = ask(requests);
    ASSERT_EQ(answers.size(), impacts.size());
    const compared c = compare_decks(e, impacts, continuous, answers, requests, surrogate_of(model));
    EXPECT_EQ(c.mismatches, 0u) << e.code << " " << e.damping;
    // The comparison judged decks, not only refusals (about two thirds are reachable).
    EXPECT_GT(c.decks, impacts.size() / 2) << e.code << " " << e.damping;
    if (model.deck_kind == viscor::dem::deck_damping_kind::coefficient_of_restitution)
      EXPECT_GT(c.builtin, c.decks / 2) << e.code << " " << e.damping;
    std::printf("%-8s %-13s %zu of %zu impacts with a deck, %zu differences from the library; %zu built-in e\n",
                e.code, e.damping, c.decks, impacts.size(), c.mismatches, c.builtin);
  }
}

// viscor_contact_of is the contact `viscor cor` and `viscor calibrate` take from the same
// materials (jobs/physical_inputs.hpp bead_of_material, acting_gravity), bit for bit: with
// it the calculator page (web/) answers for a material bead as they do.
TEST_F(DemExport, TheContactIsTheOneCorAndCalibrateTake) {
  const std::vector<drawn> impacts = draw_impacts(10000, 58);
  std::vector<std::string> requests;
  for (const drawn& d : impacts) requests.push_back("contact 0 0 " + impact_text(d.impact));
  const std::vector<std::string> answers = ask(requests);
  ASSERT_EQ(answers.size(), impacts.size());
  const viscor::contact_law tsuji = viscor::law_by_name("tsuji");
  std::size_t valid = 0, mismatches = 0;
  for (std::size_t n = 0; n < impacts.size(); ++n) {
    const dem_impact<double>& i = impacts[n].impact;
    const auto [m, k] = viscor::jobs::bead_of_material<double>(tsuji, i.bead.youngs_modulus, i.bead.poisson_ratio,
                                                               i.bead.radius, std::nullopt, i.bead.density, i.kind,
                                                               i.partner);
    const double gravity = i.kind == contact_kind::pair ? 0.0 : i.gravity;
    std::istringstream line(answers[n]);
    int ok = 0;
    std::string modulus, radius, mass, stiffness, felt;
    line >> ok >> modulus >> radius >> mass >> stiffness >> felt;
    if (ok != 1) {
      ADD_FAILURE() << "impact " << n << " refused: " << requests[n];
      continue;
    }
    ++valid;
    if ((!same_bits(read_back(mass), m) || !same_bits(read_back(stiffness), k) ||
         !same_bits(read_back(felt), gravity)) &&
        ++mismatches <= 5)
      ADD_FAILURE() << "impact " << n << ": C m " << mass << " k " << stiffness << " gravity " << felt
                    << ", library " << hex(m) << " " << hex(k) << " " << hex(gravity) << " (" << requests[n] << ")";
  }
  EXPECT_EQ(valid, impacts.size());
  EXPECT_EQ(mismatches, 0u);
  std::printf("viscor_contact_of: %zu impacts, %zu differences from bead_of_material\n", valid, mismatches);
}

// The step-aware decks (viscor_dem_deck_at_step; dem/stepped_drop.hpp) at steps from T/20
// to T/100 of each impact: `viscor dem --method surrogate --timestep` bit for bit.
TEST_F(DemExport, StepAwareEntriesAreTheLibrarysBitForBit) {
  const std::vector<drawn> impacts = draw_impacts(120, 5658);
  std::mt19937_64 rng(5659);
  for (const exported_model& e : stepped_models) {
    const viscor::dem::dem_model& model = viscor::dem::find_dem_model(e.code, e.damping);
    const auto& s = surrogate_of(model);
    std::vector<std::string> requests;
    std::vector<double> dts;
    for (const drawn& d : impacts) {
      double dt = 1e-6;  // a step for impacts without a deck (both refuse them alike)
      try {
        const double per_t = 20 + static_cast<double>(rng() % 81);
        dt = viscor::dem::unclamped_deck_by_surrogate(model, d.impact, d.target, s).calibration.time_scale / per_t;
      } catch (const viscor::invalid_parameter&) {
      }
      dts.push_back(dt);
      requests.push_back("step " + std::to_string(e.number) + " " + hex(d.target) + " " + hex(dt) + " " +
                         impact_text(d.impact));
    }
    const std::vector<std::string> answers = ask(requests);
    ASSERT_EQ(answers.size(), impacts.size());
    const compared c = compare_decks(e, impacts, dts, answers, requests, s);
    EXPECT_EQ(c.mismatches, 0u) << e.code << " " << e.damping;
    EXPECT_GT(c.decks, impacts.size() / 2) << e.code << " " << e.damping;
    std::printf("%-8s %-13s step-aware: %zu of %zu impacts with a deck, %zu differences from the library\n", e.code,
                e.damping, c.decks, impacts.size(), c.mismatches);
  }
  // YADE's clamped force has no continuous deck in the export: a status that says so.
  const std::vector<std::string> yade = ask({"deck 5 " + hex(0.8) + " " + impact_text(impacts[0].impact)});
  ASSERT_EQ(yade.size(), 1u);
  EXPECT_EQ(yade[0].substr(0, 2), "4 ") << yade[0];  // VISCOR_DECK_NEEDS_TIME_STEP
}

// The library's surrogate deck is viscor dem's: its printed entries are the same strings.
TEST_F(DemExport, TheLibrarysDeckIsViscorDemMethodSurrogate) {
  const std::vector<drawn> impacts = draw_impacts(40, 5656);
  std::size_t compared = 0;
  for (const exported_model& e : exported_models) {
    const viscor::dem::dem_model& model = viscor::dem::find_dem_model(e.code, e.damping);
    for (const drawn& d : impacts) {
      const library_deck lib = library(model, d, surrogate_of(model));
      if (lib.status != 0) continue;
      viscor::jobs::dem_request q;
      q.code = e.code, q.damping = e.damping, q.method = "surrogate";
      q.contact = d.impact.kind == contact_kind::wall ? "wall" : "pair";
      const auto text = [](double x) { return viscor::dem::deck_number(x); };
      q.youngs_modulus = text(d.impact.bead.youngs_modulus), q.poisson_ratio = text(d.impact.bead.poisson_ratio);
      q.radius = text(d.impact.bead.radius), q.density = text(d.impact.bead.density);
      if (const auto& w = d.impact.partner.wall)
        q.wall_youngs_modulus = text(w->youngs_modulus), q.wall_poisson_ratio = text(w->poisson_ratio);
      if (const auto& o = d.impact.partner.other) {
        q.other_youngs_modulus = text(o->youngs_modulus), q.other_poisson_ratio = text(o->poisson_ratio);
        q.other_radius = text(o->radius), q.other_density = text(o->density);
      }
      q.v0 = text(d.impact.v0), q.gravity = text(d.impact.gravity), q.force = text(d.impact.force);
      q.target_e = text(d.target);
      const viscor::jobs::dem_result r = viscor::jobs::run_dem(q);
      ASSERT_TRUE(r.forward);
      EXPECT_EQ(r.forward->deck.damping, lib.strings.damping);
      EXPECT_EQ(r.forward->deck.youngs_modulus, lib.strings.youngs_modulus);
      EXPECT_EQ(r.forward->deck.bead_bead_damping, lib.strings.bead_bead_damping);
      EXPECT_EQ(r.forward->deck.other_other_damping, lib.strings.other_other_damping);
      EXPECT_EQ(r.forward->deck.cross_youngs_modulus, lib.strings.cross_youngs_modulus);
      ASSERT_TRUE(r.forward->surrogate_bound);
      EXPECT_EQ(r.forward->gamma0.value(), lib.deck.gamma0);
      ++compared;
    }
  }
  EXPECT_GT(compared, 100u);
}

// Independent of the surrogate: the code's force with the exported entry, solved exactly
// (the Taylor solve of dem_calibration.hpp e_for_deck), rebounds with the target within
// the bound viscor dem states (the surrogate's miss plus its bound on e).
TEST_F(DemExport, TheExactSolveOfTheEntryHitsTheTarget) {
  const std::vector<drawn> impacts = draw_impacts(60, 5657);
  std::size_t checked = 0;
  for (const exported_model& e : exported_models) {
    const viscor::dem::dem_model& model = viscor::dem::find_dem_model(e.code, e.damping);
    std::vector<std::string> requests;
    for (const drawn& d : impacts) {
      requests.push_back("deck " + std::to_string(e.number) + " " + hex(d.target) + " " + impact_text(d.impact));
    }
    const std::vector<std::string> answers = ask(requests);
    std::vector<std::string> entry_requests;
    std::vector<std::pair<std::size_t, double>> entries;
    for (std::size_t n = 0; n < impacts.size(); ++n) {
      std::istringstream line(answers[n]);
      int status = -1;
      std::string damping;
      line >> status >> damping;
      if (status != 0) continue;
      const double entry = std::strtod(damping.c_str(), nullptr);
      entries.push_back({n, entry});
      entry_requests.push_back("entry " + std::to_string(e.number) + " " + hex(entry) + " " +
                               impact_text(impacts[n].impact));
    }
    const std::vector<std::string> e_answers = ask(entry_requests);
    const auto& s = surrogate_of(model);
    for (std::size_t i = 0; i < entries.size(); ++i) {
      const auto& [n, entry] = entries[i];
      const double exact = viscor::dem::e_for_deck(model, impacts[n].impact, entry).e;
      const double c_e = std::strtod(e_answers[i].c_str(), nullptr);
      // |e_s(entry) - target| is the inverse's miss; s.bound.abs_e the surrogate's distance to the exact e.
      const double bound = std::abs(c_e - impacts[n].target) + s.bound.abs_e;
      EXPECT_LE(std::abs(exact - impacts[n].target), bound + 1e-14)
          << e.code << " " << e.damping << " impact " << n << ": entry " << hex(entry);
      EXPECT_LE(std::abs(c_e - exact), s.bound.abs_e) << e.code << " " << e.damping << " e of the entry, impact " << n;
      ++checked;
    }
  }
  EXPECT_GT(checked, 150u);
}

TEST_F(DemExport, RefusesWhatViscorDemRefuses) {
  drawn d = draw_impacts(1, 7)[0];
  d.impact.kind = contact_kind::wall, d.impact.partner = {}, d.target = 0.8;
  const viscor::dem::dem_model& tsuji = viscor::dem::find_dem_model("lammps", "tsuji");
  std::vector<std::pair<const char*, drawn>> cases;
  auto with = [&](const char* what, auto change) {
    drawn c = d;
    change(c);
    cases.push_back({what, c});
  };
  with("a negative Young's modulus", [](drawn& c) { c.impact.bead.youngs_modulus = -1; });
  with("a Poisson ratio above 0.5", [](drawn& c) { c.impact.bead.poisson_ratio = 0.6; });
  with("a zero speed", [](drawn& c) { c.impact.v0 = 0; });
  with("gravity away from the wall", [](drawn& c) { c.impact.gravity = -9.81; });
  with("a target below the surrogate's 0.01", [](drawn& c) { c.target = 0.005; });
  with("a target of 1", [](drawn& c) { c.target = 1; });
  std::vector<std::string> requests;
  for (const auto& [what, c] : cases) requests.push_back("deck 3 " + hex(c.target) + " " + impact_text(c.impact));
  const std::vector<std::string> answers = ask(requests);
  for (std::size_t i = 0; i < cases.size(); ++i) {
    EXPECT_EQ(answers[i].substr(0, 2), "1 ") << cases[i].first << ": " << answers[i];
    EXPECT_EQ(library(tsuji, cases[i].second, surrogate_of(tsuji)).status, 1) << cases[i].first;
  }
}

TEST(DemMethodSurrogate, IsRefusedWhereItCannotHold) {
  viscor::jobs::dem_request q;
  q.code = "lammps", q.damping = "tsuji", q.method = "surrogate";
  q.youngs_modulus = "2e11", q.poisson_ratio = "0.3", q.radius = "4e-3", q.density = "7800";
  q.target_e = "0.8", q.v0 = "0.5", q.gravity = "9.81";
  auto message = [](viscor::jobs::dem_request r) {
    try {
      viscor::jobs::run_dem(r);
    } catch (const viscor::invalid_parameter& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  auto yade = q;
  yade.code = "yade", yade.damping = "mindlin";
  EXPECT_NE(message(yade).find("clamps the contact force"), std::string::npos) << message(yade);
  auto digits = q;
  digits.digits = 30;
  EXPECT_NE(message(digits).find("computes in double"), std::string::npos) << message(digits);
  auto reverse = q;
  reverse.target_e.clear(), reverse.deck_damping = "0.5";
  EXPECT_NE(message(reverse).find("method"), std::string::npos) << message(reverse);
  auto unknown = q;
  unknown.method = "guess";
  EXPECT_NE(message(unknown).find("'guess'"), std::string::npos) << message(unknown);
}

}  // namespace
