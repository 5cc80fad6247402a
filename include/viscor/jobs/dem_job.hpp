// The damping to write into a DEM code's contact model so the code reproduces a
// measured e at an impact speed under a load (the exact calibration of viscor's
// force law, mapped through the code's own conventions, include/viscor/dem/), and
// the reverse: the e a deck damping entry produces. As `viscor dem` and viscor.dem
// report it; the forward job can also write a complete single-bead drop deck.
#pragma once

#include <viscor/core/field_names.hpp>
#include <viscor/jobs/command_output.hpp>
#include <viscor/jobs/files.hpp>
#include <viscor/jobs/json_fields.hpp>
#include <viscor/jobs/physical_inputs.hpp>
#include <viscor/jobs/unit_checks.hpp>

#include <viscor/core/precision.hpp>
#include <viscor/core/real_io.hpp>
#include <viscor/core/text_fields.hpp>
#include <viscor/dem/dem_calibration.hpp>
#include <viscor/dem/deck_snippet.hpp>
#include <viscor/dem/drop_deck.hpp>

#include <chrono>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace viscor::jobs {

/// The code and its damping model, the bead, the load, and either a target e
/// (forward: the deck entries) or a deck entry (reverse: the e it gives). Values
/// are exact decimal text; "" is an input not given.
struct dem_request {
  std::string code;              ///< lammps, liggghts or yade
  std::string damping;           ///< the code's damping model (dem/dem_models.hpp)
  std::string contact = "wall";  ///< wall or pair
  std::string youngs_modulus, poisson_ratio, radius, density;
  std::string wall_youngs_modulus, wall_poisson_ratio;  ///< a wall of its own material ("": rigid)
  /// A pair of two materials: the other bead ("": a bead like the first).
  std::string other_youngs_modulus, other_poisson_ratio, other_radius, other_density;
  std::string stiffness;         ///< yade viscoelastic: the linear spring's kn, N/m
  std::string target_e;          ///< forward: the measured e
  std::string deck_damping;      ///< reverse: the deck's damping entry
  std::string deck_en;           ///< reverse, yade mindlin: YADE's own en input
  std::string v0, gravity, force = "0";
  std::string speeds = "0.001,0.01,0.1,1,10";  ///< reverse: impact speeds, comma-separated
  std::string drop_deck_path;    ///< forward: also write a complete single-bead drop deck here
  std::string variables_path;    ///< forward, LAMMPS/LIGGGHTS: also write the entries as a `variable` block here
  int digits = 15;               ///< working precision in decimal digits
  bool strict = false;           ///< refuse, not only warn about, implausible inputs
};

namespace detail {

struct dem_job : dem_request {
  void require(const std::string& value, const char* option, const char* what) const {
    if (value.empty()) throw invalid_parameter(std::string("dem needs ") + option + " (" + what + ")");
  }

  // The inputs echoed under `physical`, with the names of their options, as given.
  json physical_echo(bool linear) const {
    json p;
    if (linear)
      p["k"] = stiffness;
    else
      p["youngs_modulus"] = youngs_modulus, p["poisson_ratio"] = poisson_ratio;
    p["radius"] = radius;
    p["density"] = density;
    for (const auto& [name, value] : partner_inputs())
      if (!value->empty()) p[name] = *value;
    if (!v0.empty()) p["v0"] = v0;
    p["gravity"] = gravity;
    p["force"] = force;
    return p;
  }

  /// The wall's and the other bead's inputs, under their field names.
  std::vector<std::pair<std::string, const std::string*>> partner_inputs() const {
    return {{"wall_youngs_modulus", &wall_youngs_modulus}, {"wall_poisson_ratio", &wall_poisson_ratio},
            {"other_youngs_modulus", &other_youngs_modulus}, {"other_poisson_ratio", &other_poisson_ratio},
            {"other_radius", &other_radius}, {"other_density", &other_density}};
  }

  /// The wall's material or the other bead, checked for completeness against the contact.
  template <class Real>
  dem::contact_partner<Real> partner(dem::contact_kind kind) const {
    dem::contact_partner<Real> p;
    const bool wall_given = !wall_youngs_modulus.empty() || !wall_poisson_ratio.empty();
    const bool other_given = !other_youngs_modulus.empty() || !other_poisson_ratio.empty() || !other_radius.empty() ||
                             !other_density.empty();
    if (wall_given && kind != dem::contact_kind::wall)
      throw invalid_parameter("--wall-youngs-modulus and --wall-poisson-ratio describe a wall: they need --contact "
                              "wall, not --contact " + contact);
    if (other_given && kind != dem::contact_kind::pair)
      throw invalid_parameter("--other-youngs-modulus, --other-poisson-ratio, --other-radius and --other-density "
                              "describe the second bead of --contact pair, not of --contact " + contact);
    if (wall_given) {
      require(wall_youngs_modulus, "--wall-youngs-modulus", "the wall's Young's modulus, Pa; neither: a rigid wall");
      require(wall_poisson_ratio, "--wall-poisson-ratio", "the wall's Poisson ratio");
      p.wall = elastic_material<Real>{parse_real<Real>(wall_youngs_modulus, "wall_youngs_modulus"),
                                      parse_real<Real>(wall_poisson_ratio, "wall_poisson_ratio")};
    }
    if (other_given) {
      const char* what = "the other bead's material: give all four, or none for a bead like the first";
      require(other_youngs_modulus, "--other-youngs-modulus", what);
      require(other_poisson_ratio, "--other-poisson-ratio", what);
      require(other_radius, "--other-radius", what);
      require(other_density, "--other-density", what);
      p.other = dem::bead_material<Real>{parse_real<Real>(other_youngs_modulus, "other_youngs_modulus"),
                                         parse_real<Real>(other_poisson_ratio, "other_poisson_ratio"),
                                         parse_real<Real>(other_radius, "other_radius"),
                                         parse_real<Real>(other_density, "other_density")};
    }
    return p;
  }

  /// The readable line for the wall or the other bead, as given.
  std::string partner_line(dem::contact_kind kind) const {
    if (kind == dem::contact_kind::wall)
      return wall_youngs_modulus.empty() ? "wall        rigid\n"
                                         : "wall        youngs_modulus = " + wall_youngs_modulus +
                                               " Pa, poisson_ratio = " + wall_poisson_ratio + "\n";
    if (other_youngs_modulus.empty()) return "other bead  like the first\n";
    return "other bead  youngs_modulus = " + other_youngs_modulus + " Pa, poisson_ratio = " + other_poisson_ratio +
           ", radius = " + other_radius + " m, density = " + other_density + " kg/m^3\n";
  }

  /// A negative gravity is refused; values far outside their range are warned about (refused under --strict).
  void check_units() const {
    require_gravity_towards_wall(std::optional<std::string>(gravity));
    const auto given = [](const std::string& v) { return v.empty() ? std::nullopt : std::optional<std::string>(v); };
    check_plausible_unit(physical_quantity::youngs_modulus, given(youngs_modulus), "--youngs-modulus", strict);
    check_plausible_unit(physical_quantity::density, given(density), "--density", strict);
    check_plausible_unit(physical_quantity::radius, given(radius), "--radius", strict);
    check_plausible_unit(physical_quantity::speed, given(v0), "--v0", strict);
    check_plausible_unit(physical_quantity::gravity, given(gravity), "--gravity", strict);
    check_plausible_unit(physical_quantity::youngs_modulus, given(wall_youngs_modulus), "--wall-youngs-modulus", strict);
    check_plausible_unit(physical_quantity::youngs_modulus, given(other_youngs_modulus), "--other-youngs-modulus", strict);
    check_plausible_unit(physical_quantity::density, given(other_density), "--other-density", strict);
    check_plausible_unit(physical_quantity::radius, given(other_radius), "--other-radius", strict);
  }

  command_output run() const {
    command_output out;
    require(code, "CODE", "lammps, liggghts or yade");
    require(damping, "--damping", "the code's damping model");
    const dem::dem_model& model = dem::find_dem_model(code, damping);
    const dem::contact_kind kind = dem::parse_contact_kind(contact);
    const bool linear = dem::takes_linear_stiffness(model);
    if (linear) {  // YADE's visco-elastic law: a linear spring, not a Hertz contact of the material
      require(stiffness, "--k", "the contact's normal stiffness kn, N/m: the visco-elastic law is a linear spring");
      for (const auto& [value, option] : {std::pair{&youngs_modulus, "--youngs-modulus"}, {&poisson_ratio, "--poisson-ratio"}})
        if (!value->empty())
          throw invalid_parameter(std::string(option) + " " + *value + " is not an input of " + code + " " + damping +
                                  ": its linear spring takes the contact stiffness --k (N/m), not a Hertz material");
    } else {
      if (!stiffness.empty())
        throw invalid_parameter("--k " + stiffness + " is the linear stiffness of yade viscoelastic; " + code + " " +
                                damping + " takes its Hertz stiffness from --youngs-modulus and --poisson-ratio");
      require(youngs_modulus, "--youngs-modulus", "Pa");
      require(poisson_ratio, "--poisson-ratio", "dimensionless");
    }
    require(radius, "--radius", "m");
    require(density, "--density", "kg/m^3");
    require(gravity, "--gravity", "m/s^2 towards the wall; 0 for none");
    check_units();
    if (!deck_damping.empty() && !deck_en.empty())
      throw invalid_parameter("give either --deck-damping (the deck's betan) or --deck-en (YADE's en), not both");
    if (!deck_en.empty() && model.damping != dem::damping_model::mindlin)
      throw invalid_parameter("--deck-en " + deck_en + " is YADE's `en` input of Hertz-Mindlin (yade --damping "
                              "mindlin), not an input of " + code + " " + damping);
    const bool reverse = !deck_damping.empty() || !deck_en.empty();
    if (reverse && !target_e.empty())
      throw invalid_parameter("give either --target-e (deck for a measured e) or --deck-damping/--deck-en (e for a "
                              "deck), not both");
    if (!drop_deck_path.empty() && reverse)
      throw invalid_parameter("--drop-deck " + drop_deck_path + " writes the drop for a calibrated deck: give "
                              "--target-e, not --deck-damping/--deck-en");
    if (!drop_deck_path.empty() && kind != dem::contact_kind::wall)
      throw invalid_parameter("--drop-deck " + drop_deck_path + " drops one bead on a wall: it needs --contact wall, "
                              "not --contact " + contact);
    if (!drop_deck_path.empty() && model.code == dem::dem_code::yade && !drop_deck_path.ends_with(".py"))
      throw invalid_parameter("--drop-deck " + drop_deck_path + ": a YADE script must end in .py (yade -x "
                              "silently skips other files)");
    if (!variables_path.empty()) check_variables_request(model, reverse);
    refuse_outputs_not_ours();  // before any work: a foreign file, a FIFO or a directory
    if (!reverse) {
      require(target_e, "--target-e", "the measured coefficient of restitution, 0 < e < 1");
      require(v0, "--v0", "impact speed, m/s");
    }
    with_working_precision(digits, [&]<class Real>() {
      dem::dem_impact<Real> impact;
      impact.bead.radius = parse_real<Real>(radius, "radius");
      impact.bead.density = parse_real<Real>(density, "density");
      if (linear) {
        impact.stiffness = parse_real<Real>(stiffness, "k");
      } else {
        impact.bead.youngs_modulus = parse_real<Real>(youngs_modulus, "youngs_modulus");
        impact.bead.poisson_ratio = parse_real<Real>(poisson_ratio, "poisson_ratio");
        impact.bead.validate();
      }
      impact.kind = kind;
      impact.partner = partner<Real>(kind);
      impact.gravity = parse_real<Real>(gravity, "gravity");
      impact.force = parse_real<Real>(force, "force");
      const auto start = std::chrono::steady_clock::now();
      json j;
      j["command"] = "dem";
      j["code"] = code;
      j["damping_model"] = damping;
      j["contact"] = contact;
      j["law"] = law_json(dem::law_of(model));
      j["clamped"] = model.clamped;  // the code sets a pulling normal force to zero
      j["version"] = std::string(model.version);
      j["code_source"] = std::string(model.source);
      j["physical"] = physical_echo(linear);  // as given, named as the options (docs/json-schema.md)
      const dem::hertz_contact<Real> c = dem::model_contact(model, impact);
      if (!linear) j["effective_modulus_pa"] = number(c.effective_modulus);
      j["effective_radius_m"] = number(c.effective_radius);
      j["effective_mass_kg"] = number(c.effective_mass);
      j["k"] = number(c.stiffness);
      std::ostringstream text;
      text << "code        " << model.version << "\n"
           << "model       " << code << " damping " << damping << " on a " << contact << " (viscor law "
           << model.law_name << ")\n";
      text << partner_line(kind);
      if (linear)
        text << "contact     linear spring k = " << number(c.stiffness) << " N/m, m* = " << number(c.effective_mass)
             << " kg\n";
      else
        text << "contact     E* = " << number(c.effective_modulus) << " Pa, R* = " << number(c.effective_radius)
             << " m, m* = " << number(c.effective_mass) << " kg, k = " << number(c.stiffness) << " N/m^1.5\n";
      if (reverse)
        run_reverse<Real>(model, impact, j, text);
      else
        run_forward<Real>(model, impact, j, text);
      j["precision"] = scalar_json<Real>(digits);
      j[field::seconds] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      out = {text.str(), j};
    });
    return out;
  }

  template <class Real>
  void run_forward(const dem::dem_model& model, dem::dem_impact<Real>& impact, json& j, std::ostringstream& text) const {
    impact.v0 = parse_real<Real>(v0, "v0");
    const Real target = parse_real<Real>(target_e, "target_e");
    calibration_options<Real> options;
    const dem::dem_deck<Real> d = dem::dem_deck_for(model, impact, target, options);
    const dem::deck_strings s = deck_strings_for(model, impact, d, target);
    json deck;
    if (d.stiffness) {  // YADE visco-elastic: the bead material's kn, cn; a rigid wall material
      deck["kn"] = s.stiffness;
      deck["cn"] = s.damping;
      if (s.wall_youngs_modulus) deck["wall_kn"] = deck["wall_cn"] = *s.wall_youngs_modulus;
    } else {
      deck["youngs_modulus"] = s.youngs_modulus;
      deck["poisson_ratio"] = s.poisson_ratio;
      const std::pair<const char*, const std::optional<std::string>*> optional_entries[] = {
          {"wall_youngs_modulus", &s.wall_youngs_modulus}, {"wall_poisson_ratio", &s.wall_poisson_ratio},
          {"other_youngs_modulus", &s.other_youngs_modulus}, {"other_poisson_ratio", &s.other_poisson_ratio},
          {"cross_youngs_modulus", &s.cross_youngs_modulus}, {"bead_bead_youngs_modulus", &s.bead_bead_youngs_modulus},
          {"bead_bead_damping", &s.bead_bead_damping}, {"other_other_damping", &s.other_other_damping}};
      for (const auto& [name, value] : optional_entries)
        if (*value) deck[name] = **value;
    }
    deck["damping"] = s.damping;
    deck["damping_kind"] = model.deck_kind == dem::deck_damping_kind::coefficient ? "coefficient"
                                                                                   : "coefficient_of_restitution";
    j[field::target_e] = target_e;
    j["deck"] = deck;
    j["damping_number"] = number(d.damping_number);
    j["gamma0"] = number(d.gamma0);
    j["gamma"] = number(d.calibration.scaled.gamma);
    j["g"] = number(d.calibration.scaled.g);
    j[field::e] = number(d.calibration.scaled.e);
    j[field::target_bound] = number(d.calibration.scaled.target_bound);
    j["time_scale_s"] = number(d.calibration.time_scale);
    text << "impact      e = " << target_e << " at v0 = " << v0 << " m/s, gravity = " << gravity
         << " m/s^2, force = " << force << " N\n"
         << "viscor      gamma0 = " << number(d.gamma0) << " (scaled gamma = " << number(d.calibration.scaled.gamma)
         << ", g = " << number(d.calibration.scaled.g) << "), e = " << number(d.calibration.scaled.e) << "\n"
         << "deck        ";
    if (d.stiffness) {
      text << "bead material kn = " << s.stiffness << " N/m, cn = " << s.damping << " N s/m\n";
      if (s.wall_youngs_modulus) text << "            wall material kn = cn = " << *s.wall_youngs_modulus << " (rigid)\n";
    } else {
      text << "youngs_modulus = " << s.youngs_modulus << ", poisson_ratio = " << s.poisson_ratio
           << ", damping = " << s.damping << "\n";
      if (s.wall_youngs_modulus)
        text << "            wall " << (model.code == dem::dem_code::yade ? "material young" : "type youngs_modulus")
             << " = " << *s.wall_youngs_modulus
             << (s.wall_material ? ", poisson_ratio = " + *s.wall_poisson_ratio + "\n" : std::string(" (rigid)\n"));
      if (s.other_youngs_modulus)
        text << "            other bead youngs_modulus = " << *s.other_youngs_modulus << ", poisson_ratio = "
             << *s.other_poisson_ratio << "\n";
      if (s.cross_youngs_modulus)
        text << "            cross entry (1,2) youngs_modulus = " << *s.cross_youngs_modulus
             << " (LAMMPS does not mix hertz/material right)\n";
      if (s.bead_bead_damping)
        text << "            bead-bead (two like beads, same e and v0, no load): youngs_modulus = "
             << s.bead_bead_youngs_modulus.value_or(s.youngs_modulus) << ", damping = " << *s.bead_bead_damping << "\n";
      if (s.other_other_damping)
        text << "            other-other (two like beads, same e and v0, no load): damping = " << *s.other_other_damping
             << "\n";
    }
    if (d.builtin_e) {
      const Real miss = *d.builtin_e - target;
      j["builtin_e"] = number(*d.builtin_e);
      j["builtin_error"] = number(miss);
      j["builtin_error_percent_of_one_minus_e"] = number(dem::percent_of_one_minus_e(*d.builtin_e, target));
      const bool yade = model.code == dem::dem_code::yade;
      if (model.damping == dem::damping_model::mindlin)
        j["builtin_conversion"] = "Ip2_FrictMat_FrictMat_MindlinPhys(en=target_e) instead of betan (Thornton et al. 2013 fit)";
      if (d.builtin_tc) {
        j["builtin_tc_s"] = number(*d.builtin_tc);
        j["builtin_conversion"] = "ViscElMat(tc=builtin_tc_s, en=target_e, et=target_e) for bead and wall instead of kn, "
                                  "cn: YADE's kn is then k, its cn comes from the reduced mass m/2";
        text << "builtin     tc = " << to_decimal_string(*d.builtin_tc, 10) << " s gives YADE's kn = k\n";
      }
      text << "builtin     writing " << (yade ? "en = " : "e = ") << target_e << " into the " << (yade ? "input" : "deck") << " gives e = " << to_decimal_string(*d.builtin_e, 10)
           << " (" << to_decimal_string(miss, 3) << ", " << to_decimal_string(dem::percent_of_one_minus_e(*d.builtin_e, target), 3)
           << " % of 1 - e)\n";
    }
    std::string snippet = dem::deck_snippet(model, impact.kind, s);
    if (model.code == dem::dem_code::yade)  // the YADE script names the beads' sizes, densities, speed and the load
      for (const auto& [name, value] : {std::pair<std::string, std::string>{"OTHER_DENSITY", other_density},
                                        {"OTHER_RADIUS", other_radius}, {"DENSITY", density}, {"RADIUS", radius},
                                        {"GRAVITY", gravity}, {"V0", v0}})
        for (std::size_t at = snippet.find(name); at != std::string::npos; at = snippet.find(name, at + value.size()))
          snippet.replace(at, name.size(), value);
    const dem::drop_timing<Real> timing = dem::drop_timing_for(model, impact, d);
    snippet += dem::snippet_time_step_line(model, to_decimal_string(timing.time_step, 6),
                                           to_decimal_string(timing.contact_time, 6), timing.steps_per_time_scale);
    j["snippet"] = snippet;
    j[field::contact_time_s] = number(timing.contact_time);
    j["time_step_s"] = number(timing.time_step);
    text << "time step   the contact lasts " << to_decimal_string(timing.contact_time, 6) << " s; dt = T/"
         << timing.steps_per_time_scale << " = " << to_decimal_string(timing.time_step, 6) << " s (T = "
         << to_decimal_string(timing.time_scale, 6) << " s, about "
         << static_cast<long>(static_cast<double>(timing.contact_time / timing.time_step)) << " steps per contact)\n";
    text << "snippet\n" << snippet;
    write_deck_files(drop_deck_path.empty() ? std::string() : dem::drop_deck(model, s, drop_inputs(impact, timing)),
                     variables_path.empty() ? std::string()
                                            : variable_block(model, impact.kind, s, drop_inputs(impact, timing),
                                                             to_decimal_string(timing.contact_time)));
    if (!drop_deck_path.empty()) {
      j["drop_deck"] = drop_deck_path;
      text << "drop deck   wrote " << drop_deck_path << " (run: " << drop_run_command(model) << ")\n";
    }
    if (!variables_path.empty()) {
      j["variables"] = variables_path;
      text << "variables   wrote " << variables_path << " (in the deck: include " << variables_path
           << ", then ${viscor_...}; units si)\n";
    }
  }

  /// The first line of every variable block viscor writes (--variables replaces only such a file).
  static constexpr const char* variables_marker = "# viscor dem variables";

  /// --variables: LAMMPS and LIGGGHTS only (a YADE script asks viscor itself), forward only.
  void check_variables_request(const dem::dem_model& model, bool reverse) const {
    if (model.code == dem::dem_code::yade)
      throw invalid_parameter("--variables " + variables_path + " writes a LAMMPS/LIGGGHTS `variable` block; a YADE "
                              "script is Python: import viscor and call viscor.dem(...) in it (docs/dem.md)");
    if (reverse)
      throw invalid_parameter("--variables " + variables_path + " writes the entries of a calibrated deck: give "
                              "--target-e, not --deck-damping/--deck-en");
  }

  /// The deck entries, the impact they are calibrated for and the time step as LAMMPS/LIGGGHTS
  /// `variable NAME string VALUE` lines (exact decimal text, substituted verbatim by ${NAME}).
  static std::string variable_block(const dem::dem_model& model, dem::contact_kind kind, const dem::deck_strings& s,
                                    const dem::drop_deck_inputs& in, const std::string& contact_time) {
    std::string b = std::string(variables_marker) + ": " + std::string(model.version) + ", " +
                    std::string(model.code_name) + " damping " + std::string(model.damping_name) + " on a " +
                    std::string(dem::to_string(kind)) + " (viscor law " + std::string(model.law_name) + ")\n";
    b += "# use: `include FILE` in a deck with `units si`, then ${viscor_NAME} where the values go\n";
    const auto line = [&b](const std::string& name, const std::string& value) {
      b += "variable viscor_" + name + " string " + value + "\n";
    };
    b += "# the impact the entries are calibrated for (SI units, as given to viscor dem)\n";
    line("radius", in.radius), line("diameter", in.diameter), line("density", in.density);
    line("v0", in.v0), line("gravity", in.gravity), line("force", in.force), line("target_e", in.target_e);
    b += model.code == dem::dem_code::liggghts
             ? "# model hertz: youngsModulus and poissonsRatio of the bead type; damping = the bead-wall\n"
               "# coefficientRestitution; wall_youngs_modulus = the wall type's youngsModulus (1e30: rigid)\n"
             : "# hertz/material E damp nu damping " + std::string(model.damping_name) +
                   ": youngs_modulus = E, damping = damp, poisson_ratio = nu\n";
    line("youngs_modulus", s.youngs_modulus), line("poisson_ratio", s.poisson_ratio), line("damping", s.damping);
    if (s.wall_youngs_modulus) line("wall_youngs_modulus", *s.wall_youngs_modulus);
    if (s.wall_poisson_ratio) line("wall_poisson_ratio", *s.wall_poisson_ratio);
    if (s.other_youngs_modulus) {
      b += "# the other bead (type 2) and, for LAMMPS, the explicit cross entry pair_coeff 1 2\n";
      line("other_youngs_modulus", *s.other_youngs_modulus), line("other_poisson_ratio", *s.other_poisson_ratio);
      if (s.cross_youngs_modulus) line("cross_youngs_modulus", *s.cross_youngs_modulus);
      if (s.other_other_damping) line("other_other_damping", *s.other_other_damping);
    }
    if (s.bead_bead_damping) {
      b += "# bead-bead entries: two beads at the same e and approach speed, without load\n";
      line("bead_bead_youngs_modulus", s.bead_bead_youngs_modulus.value_or(s.youngs_modulus));
      line("bead_bead_damping", *s.bead_bead_damping);
    }
    b += "# the recommended time step, T/" + in.steps_per_time_scale + " (halve it for a smaller error), and how "
         "long the contact lasts, s\n";
    line("time_step", in.time_step), line("contact_time", contact_time);
    return b;
  }

  /// Refuses a --drop-deck or --variables path that holds anything but viscor's own
  /// unedited file of that kind (jobs/files.hpp: its seal), a FIFO, a directory or a device.
  void refuse_outputs_not_ours() const {
    if (!drop_deck_path.empty())
      refuse_unless_own_or_absent(drop_deck_path, dem::drop_deck_marker, "--drop-deck", "a drop deck");
    if (!variables_path.empty())
      refuse_unless_own_or_absent(variables_path, variables_marker, "--variables", "a variable block");
  }

  /// Writes the drop deck and the variable block that were asked for, each sealed (its last
  /// line the SHA-256 of the rest), after checking both again: neither is written when the
  /// other may not be, and both published together.
  void write_deck_files(const std::string& deck, const std::string& block) const {
    refuse_outputs_not_ours();
    std::vector<output_file> files;
    if (!drop_deck_path.empty()) files.push_back({drop_deck_path, sealed(deck)});
    if (!variables_path.empty()) files.push_back({variables_path, sealed(block)});
    write_together(files);
  }

  /// LAMMPS and LIGGGHTS read the like-bead entries apart from the contact's (pair_coeff, type pairs (1,1), (2,2))
  /// on a wall and for two bead types.
  template <class Real>
  static bool reads_like_beads_separately(const dem::dem_model& model, const dem::dem_impact<Real>& impact) {
    return model.code != dem::dem_code::yade && (impact.kind == dem::contact_kind::wall || impact.partner.other);
  }

  /// The deck of two beads like `bead` at the same e and approach speed without load (gravity drops out of a pair).
  template <class Real>
  static dem::dem_deck<Real> like_beads_deck(const dem::dem_model& model, const dem::dem_impact<Real>& impact,
                                             const dem::bead_material<Real>& bead, const Real& target) {
    dem::dem_impact<Real> pair = impact;
    pair.bead = bead;
    pair.kind = dem::contact_kind::pair, pair.partner = {}, pair.gravity = 0, pair.force = 0;
    return dem::dem_deck_for(model, pair, target);
  }

  /// The deck values as written into the input (dem::deck_number), with the like-bead entries where the code
  /// reads them apart.
  template <class Real>
  static dem::deck_strings deck_strings_for(const dem::dem_model& model, const dem::dem_impact<Real>& impact,
                                            const dem::dem_deck<Real>& d, const Real& target) {
    using dem::deck_number;
    dem::deck_strings s;
    s.damping = deck_number(d.damping);
    s.wall_material = impact.partner.wall.has_value();
    auto put = [](std::optional<std::string>& to, const std::optional<Real>& value) {
      if (value) to = deck_number(*value);
    };
    if (d.stiffness) {  // YADE visco-elastic: the bead material's kn, cn; a rigid wall material
      s.stiffness = deck_number(*d.stiffness);
      if (impact.kind == dem::contact_kind::wall) s.wall_youngs_modulus = dem::yade_rigid_wall_viscel;
      return s;
    }
    s.youngs_modulus = deck_number(d.youngs_modulus);
    s.poisson_ratio = deck_number(d.poisson_ratio);
    put(s.wall_youngs_modulus, d.wall_youngs_modulus), put(s.wall_poisson_ratio, d.wall_poisson_ratio);
    if (s.wall_youngs_modulus && !d.wall_poisson_ratio) s.wall_youngs_modulus = dem::liggghts_rigid_wall_modulus;
    put(s.other_youngs_modulus, d.other_youngs_modulus), put(s.other_poisson_ratio, d.other_poisson_ratio);
    put(s.cross_youngs_modulus, d.cross_youngs_modulus);
    if (reads_like_beads_separately(model, impact)) {
      const dem::dem_deck<Real> like = like_beads_deck(model, impact, impact.bead, target);
      if (impact.kind == dem::contact_kind::wall) s.bead_bead_youngs_modulus = deck_number(like.youngs_modulus);
      s.bead_bead_damping = deck_number(like.damping);
      if (impact.partner.other)
        s.other_other_damping = deck_number(like_beads_deck(model, impact, *impact.partner.other, target).damping);
    }
    return s;
  }

  template <class Real>
  dem::drop_deck_inputs drop_inputs(const dem::dem_impact<Real>& impact, const dem::drop_timing<Real>& timing) const {
    dem::drop_deck_inputs in;
    in.radius = radius, in.density = density, in.v0 = v0, in.gravity = gravity, in.force = force;
    in.target_e = target_e;
    dem::set_drop_geometry_and_steps(impact.bead.radius, timing, in);
    return in;
  }

  std::string drop_run_command(const dem::dem_model& model) const {
    switch (model.code) {
      case dem::dem_code::lammps: return "lmp -in " + drop_deck_path;
      case dem::dem_code::liggghts: return "liggghts -in " + drop_deck_path;
      case dem::dem_code::yade: return "yade -n -x " + drop_deck_path;
    }
    return {};
  }


  template <class Real>
  void run_reverse(const dem::dem_model& model, dem::dem_impact<Real>& impact, json& j, std::ostringstream& text) const {
    Real deck_value;
    if (!deck_en.empty()) {  // YADE's own conversion: `en` becomes betan by Thornton's fit
      const Real en = parse_real<Real>(deck_en, "deck_en");
      if (!(en > 0 && en <= 1))
        throw invalid_parameter("parameter deck_en must be in (0, 1], got " + to_decimal_string(en));
      deck_value = dem::yade_thornton_betan(en);
      j["deck_en"] = deck_en;
      j["builtin_conversion"] = "Ip2_FrictMat_FrictMat_MindlinPhys(en=deck_en): betan by Thornton et al. (2013)";
    } else {
      deck_value = parse_real<Real>(deck_damping, "deck_damping");
    }
    dem::validate_deck_damping(model, deck_value);
    std::vector<std::string> speed_list = split_list(speeds, "--speeds");
    if (!v0.empty()) speed_list.insert(speed_list.begin(), v0);
    if (speed_list.empty()) throw invalid_parameter("--speeds lists no speed (got '" + speeds + "')");
    struct load { std::string gravity, force; };
    std::vector<load> loads{{"0", "0"}};
    if (impact.gravity != 0 || impact.force != 0) loads.push_back({gravity, force});
    j["deck_damping"] = deck_en.empty() ? deck_damping : to_decimal_string(deck_value);
    j["damping_number"] = number(dem::damping_number(model, deck_value));
    json rows = json::array();
    if (!deck_en.empty()) text << "deck        en = " << deck_en << " (YADE's own conversion)\n";
    text << "deck        damping = " << (deck_en.empty() ? deck_damping : to_decimal_string(deck_value))
         << (dem::takes_linear_stiffness(model) ? " (the bead material's cn, N s/m; its kn as viscor dem writes it)\n"
                                                : " (the deck modulus as viscor dem writes it)\n")
         << "v0 (m/s)    gravity (m/s^2)  force (N)  e\n";
    for (const std::string& speed : speed_list) {
      for (const load& l : loads) {
        dem::dem_impact<Real> at = impact;
        at.v0 = parse_real<Real>(speed, "v0");
        at.gravity = parse_real<Real>(l.gravity, "gravity");
        at.force = parse_real<Real>(l.force, "force");
        require_positive(at.v0, "v0");
        const impact_result<Real> r = dem::e_for_deck(model, at, deck_value);
        json row;
        row["v0"] = speed, row["gravity"] = l.gravity, row["force"] = l.force;
        row[field::e] = number(r.e);
        row[field::outcome] = to_string(r.outcome);
        rows.push_back(row);
        text << speed << std::string(speed.size() < 12 ? 12 - speed.size() : 1, ' ') << l.gravity
             << std::string(l.gravity.size() < 17 ? 17 - l.gravity.size() : 1, ' ') << l.force
             << std::string(l.force.size() < 11 ? 11 - l.force.size() : 1, ' ') << to_decimal_string(r.e, 12) << "\n";
      }
    }
    j["table"] = rows;
  }
};

}  // namespace detail

/// The deck entries for a target e, or the e of a deck entry at the listed speeds.
inline command_output run_dem(const dem_request& q) { return detail::dem_job{q}.run(); }

}  // namespace viscor::jobs
