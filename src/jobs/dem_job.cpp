// `viscor dem` (include/viscor/jobs/dem_job.hpp), compiled once: the request checks,
// the two directions and the deck files.
#include <viscor/jobs/dem_job.hpp>

#include <viscor/jobs/files.hpp>
#include <viscor/jobs/surrogate_files.hpp>
#include <viscor/jobs/physical_inputs.hpp>
#include <viscor/jobs/unit_checks.hpp>
#include <viscor/core/precision.hpp>
#include <viscor/core/real_io.hpp>
#include <viscor/core/text_fields.hpp>
#include <viscor/dem/deck_entries.hpp>
#include <viscor/dem/dem_calibration.hpp>
#include <viscor/dem/drop_deck.hpp>
#include <viscor/dem/stepped_drop.hpp>
#include <viscor/dem/surrogate_deck.hpp>
#include <viscor/dem/variable_block.hpp>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <type_traits>

namespace viscor::jobs {

namespace detail {

struct dem_job : dem_request {
  void require(const std::string& value, const char* option, const char* what) const {
    if (value.empty()) throw invalid_parameter(std::string("dem needs ") + option + " (" + what + ")");
  }

  /// The wall's material or the other bead, checked for completeness against the contact.
  template <class Real>
  dem::contact_partner<Real> partner(dem::contact_kind kind) const {
    dem::contact_partner<Real> p;
    const bool wall_given = !wall_youngs_modulus.empty() || !wall_poisson_ratio.empty();
    const bool other_given = !other_youngs_modulus.empty() || !other_poisson_ratio.empty() || !other_radius.empty() ||
                             !other_density.empty();
    if (wall_given && kind != dem::contact_kind::wall)
      throw invalid_parameter(VISCOR_FIELD("wall_youngs_modulus") " and " VISCOR_FIELD("wall_poisson_ratio")
                              " describe a wall: they need " VISCOR_FIELD("contact") " "
                              "wall, not " VISCOR_FIELD("contact") " " + contact);
    if (other_given && kind != dem::contact_kind::pair)
      throw invalid_parameter(VISCOR_FIELD("other_youngs_modulus") ", " VISCOR_FIELD("other_poisson_ratio") ", "
                              VISCOR_FIELD("other_radius") " and " VISCOR_FIELD("other_density") " "
                              "describe the second bead of " VISCOR_FIELD("contact") " pair, not of "
                              VISCOR_FIELD("contact") " " + contact);
    if (wall_given) {
      require(wall_youngs_modulus, VISCOR_FIELD("wall_youngs_modulus"), "the wall's Young's modulus, Pa; neither: a rigid wall");
      require(wall_poisson_ratio, VISCOR_FIELD("wall_poisson_ratio"), "the wall's Poisson ratio");
      p.wall = elastic_material<Real>{parse_real<Real>(wall_youngs_modulus, "wall_youngs_modulus"),
                                      parse_real<Real>(wall_poisson_ratio, "wall_poisson_ratio")};
    }
    if (other_given) {
      const char* what = "the other bead's material: give all four, or none for a bead like the first";
      require(other_youngs_modulus, VISCOR_FIELD("other_youngs_modulus"), what);
      require(other_poisson_ratio, VISCOR_FIELD("other_poisson_ratio"), what);
      require(other_radius, VISCOR_FIELD("other_radius"), what);
      require(other_density, VISCOR_FIELD("other_density"), what);
      p.other = dem::bead_material<Real>{parse_real<Real>(other_youngs_modulus, "other_youngs_modulus"),
                                         parse_real<Real>(other_poisson_ratio, "other_poisson_ratio"),
                                         parse_real<Real>(other_radius, "other_radius"),
                                         parse_real<Real>(other_density, "other_density")};
    }
    return p;
  }

  /// A negative gravity is refused; values far outside their range are warned about (refused under --strict).
  void check_units() const {
    require_gravity_towards_wall(std::optional<std::string>(gravity));
    const auto given = [](const std::string& v) { return v.empty() ? std::nullopt : std::optional<std::string>(v); };
    check_plausible_unit(physical_quantity::youngs_modulus, given(youngs_modulus), VISCOR_FIELD("youngs_modulus"), strict);
    check_plausible_unit(physical_quantity::density, given(density), VISCOR_FIELD("density"), strict);
    check_plausible_unit(physical_quantity::radius, given(radius), VISCOR_FIELD("radius"), strict);
    check_plausible_unit(physical_quantity::speed, given(v0), VISCOR_FIELD("v0"), strict);
    check_plausible_unit(physical_quantity::gravity, given(gravity), VISCOR_FIELD("gravity"), strict);
    check_plausible_unit(physical_quantity::youngs_modulus, given(wall_youngs_modulus), VISCOR_FIELD("wall_youngs_modulus"), strict);
    check_plausible_unit(physical_quantity::youngs_modulus, given(other_youngs_modulus), VISCOR_FIELD("other_youngs_modulus"), strict);
    check_plausible_unit(physical_quantity::density, given(other_density), VISCOR_FIELD("other_density"), strict);
    check_plausible_unit(physical_quantity::radius, given(other_radius), VISCOR_FIELD("other_radius"), strict);
  }

  dem_result run() const {
    require(code, VISCOR_FIELD("code"), "lammps, liggghts or yade");
    require(damping, VISCOR_FIELD("damping"), "the code's damping model");
    const dem::dem_model& model = dem::find_dem_model(code, damping);
    const dem::contact_kind kind = dem::parse_contact_kind(contact);
    const bool linear = dem::takes_linear_stiffness(model);
    if (linear) {  // YADE's visco-elastic law: a linear spring, not a Hertz contact of the material
      require(stiffness, VISCOR_FIELD("k"), "the contact's normal stiffness kn, N/m: the visco-elastic law is a linear spring");
      for (const auto& [value, option] : {std::pair{&youngs_modulus, VISCOR_FIELD("youngs_modulus")}, {&poisson_ratio, VISCOR_FIELD("poisson_ratio")}})
        if (!value->empty())
          throw invalid_parameter(std::string(option) + " " + *value + " is not an input of " + code + " " + damping +
                                  ": its linear spring takes the contact stiffness " VISCOR_FIELD("k")
                                  " (N/m), not a Hertz material");
    } else {
      if (!stiffness.empty())
        throw invalid_parameter(VISCOR_FIELD("k")
                                " " + stiffness + " is the linear stiffness of yade viscoelastic; " + code + " " +
                                damping + " takes its Hertz stiffness from " VISCOR_FIELD("youngs_modulus") " and "
                                          VISCOR_FIELD("poisson_ratio"));
      require(youngs_modulus, VISCOR_FIELD("youngs_modulus"), "Pa");
      require(poisson_ratio, VISCOR_FIELD("poisson_ratio"), "dimensionless");
    }
    require(radius, VISCOR_FIELD("radius"), "m");
    require(density, VISCOR_FIELD("density"), "kg/m^3");
    require(gravity, VISCOR_FIELD("gravity"), "m/s^2 towards the wall; 0 for none");
    check_units();
    if (!deck_damping.empty() && !deck_en.empty())
      throw invalid_parameter("give either " VISCOR_FIELD("deck_damping") " (the deck's betan) or "
                              VISCOR_FIELD("deck_en") " (YADE's en), not both");
    if (!deck_en.empty() && model.damping != dem::damping_model::mindlin)
      throw invalid_parameter(VISCOR_FIELD("deck_en") " " + deck_en + " is YADE's `en` input of Hertz-Mindlin (yade "
                              VISCOR_FIELD("damping") " "
                              "mindlin), not an input of " + code + " " + damping);
    const bool reverse = !deck_damping.empty() || !deck_en.empty();
    if (reverse && !target_e.empty())
      throw invalid_parameter("give either " VISCOR_FIELD("target_e") " (deck for a measured e) or "
                              VISCOR_FIELD("deck_damping") "/" VISCOR_FIELD("deck_en") " (e for a "
                              "deck), not both");
    if (!drop_deck_path.empty() && reverse)
      throw invalid_parameter(VISCOR_FIELD("drop_deck")
                              " " + drop_deck_path + " writes the drop for a calibrated deck: give "
                              VISCOR_FIELD("target_e") ", not " VISCOR_FIELD("deck_damping") "/"
                              VISCOR_FIELD("deck_en"));
    if (!drop_deck_path.empty() && kind != dem::contact_kind::wall)
      throw invalid_parameter(VISCOR_FIELD("drop_deck") " " + drop_deck_path + " drops one bead on a wall: it needs "
                              VISCOR_FIELD("contact") " wall, "
                              "not " VISCOR_FIELD("contact") " " + contact);
    if (!drop_deck_path.empty() && model.code == dem::dem_code::yade && !drop_deck_path.ends_with(".py"))
      throw invalid_parameter(VISCOR_FIELD("drop_deck")
                              " " + drop_deck_path + ": a YADE script must end in .py (yade -x "
                              "silently skips other files)");
    if (!variables_path.empty()) check_variables_request(model, reverse);
    check_method(model, reverse);
    refuse_outputs_not_ours();  // before any work: a foreign file, a FIFO or a directory
    if (!reverse) {
      require(target_e, VISCOR_FIELD("target_e"), "the measured coefficient of restitution, 0 < e < 1");
      require(v0, VISCOR_FIELD("v0"), "impact speed, m/s");
    }
    return with_working_precision(digits, [&]<class Real>() {
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
      dem_result out;
      out.model = model;
      out.kind = kind;
      out.inputs = *this;
      const dem::hertz_contact<Real> c = dem::model_contact(model, impact);
      if (!linear) out.contact.effective_modulus = working_number::of(c.effective_modulus);
      out.contact.effective_radius = working_number::of(c.effective_radius);
      out.contact.effective_mass = working_number::of(c.effective_mass);
      out.contact.stiffness = working_number::of(c.stiffness);
      if (reverse)
        out.reverse = run_reverse<Real>(model, impact);
      else
        out.forward = run_forward<Real>(model, impact);
      out.precision = precision_used::of<Real>(digits);
      out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      return out;
    });
  }

  template <class Real>
  dem_forward run_forward(const dem::dem_model& model, dem::dem_impact<Real>& impact) const {
    const auto of = [](const Real& x) { return working_number::of(x); };
    impact.v0 = parse_real<Real>(v0, "v0");
    const Real target = parse_real<Real>(target_e, "target_e");
    dem_forward out;
    dem::dem_deck<Real> d;
    std::optional<Real> dt;  // --timestep: the step the entries are calibrated for, s
    // the continuous calibration: by the solve, or by the surrogate as the C export does
    std::function<dem::dem_deck<Real>(const dem::dem_model&, const dem::dem_impact<Real>&, const Real&)> continuous =
        [](const dem::dem_model& m, const dem::dem_impact<Real>& i, const Real& e) {
          return dem::dem_deck_for(m, i, e, calibration_options<Real>{});
        };
    if (method == "surrogate") {
      if constexpr (std::is_same_v<Real, double>) {
        const surrogate::cor_surrogate& s = surrogate_of(model);
        // a model that clamps (with --timestep only): the unclamped deck, the stepped calibration's bracket
        continuous = [&s](const dem::dem_model& m, const dem::dem_impact<Real>& i, const Real& e) {
          return m.clamped ? dem::unclamped_deck_by_surrogate(m, i, e, s) : dem::dem_deck_by_surrogate(m, i, e, s);
        };
        out.surrogate_bound = s.bound;
      }
    }
    if (!timestep.empty()) {
      dt = calibrate_at_time_step(model, impact, target, continuous, d, out);
    } else {
      d = continuous(model, impact, target);
      out.deck = dem::deck_entries_for(model, impact, d, target, continuous);
    }
    out.target_e = target_e;
    out.damping_number = of(d.damping_number);
    out.gamma0 = of(d.gamma0);
    out.gamma = of(d.calibration.scaled.gamma), out.g = of(d.calibration.scaled.g);
    out.e = of(d.calibration.scaled.e), out.target_bound = of(d.calibration.scaled.target_bound);
    out.time_scale = of(d.calibration.time_scale);
    if (d.builtin_e) {
      dem_builtin b;
      b.e = of(*d.builtin_e);
      b.error = of(Real(*d.builtin_e - target));
      b.error_percent = of(dem::percent_of_one_minus_e(*d.builtin_e, target));
      if (model.damping == dem::damping_model::mindlin)
        b.conversion = "Ip2_FrictMat_FrictMat_MindlinPhys(en=target_e) instead of betan (Thornton et al. 2013 fit)";
      if (d.builtin_tc) {
        b.tc = of(*d.builtin_tc);
        b.conversion = "ViscElMat(tc=builtin_tc_s, en=target_e, et=target_e) for bead and wall instead of kn, "
                       "cn: YADE's kn is then k, its cn comes from the reduced mass m/2";
      }
      out.builtin = std::move(b);
    }
    std::string snippet = dem::deck_snippet(model, impact.kind, out.deck);
    if (model.code == dem::dem_code::yade)  // the YADE script names the beads' sizes, densities, speed and the load
      for (const auto& [name, value] : {std::pair<std::string, std::string>{"OTHER_DENSITY", other_density},
                                        {"OTHER_RADIUS", other_radius}, {"DENSITY", density}, {"RADIUS", radius},
                                        {"GRAVITY", gravity}, {"V0", v0}})
        for (std::size_t at = snippet.find(name); at != std::string::npos; at = snippet.find(name, at + value.size()))
          snippet.replace(at, name.size(), value);
    dem::drop_timing<Real> timing = dem::drop_timing_for(model, impact, d);
    if (dt) {
      timing.time_step = *dt;
      timing.steps_per_time_scale = static_cast<int>(std::lround(static_cast<double>(timing.time_scale / *dt)));
      snippet += model.code == dem::dem_code::yade
                     ? "O.dt = " + to_decimal_string(*dt) + "  # exactly: the entries are calibrated for this step\n"
                     : "# time step: timestep " + to_decimal_string(*dt) +
                           " exactly: the entries are calibrated for this step\n";
    } else {
      snippet += dem::snippet_time_step_line(model, to_decimal_string(timing.time_step, 6),
                                             to_decimal_string(timing.contact_time, 6), timing.steps_per_time_scale);
    }
    out.snippet = snippet;
    out.contact_time = of(timing.contact_time), out.time_step = of(timing.time_step);
    out.timing_time_scale = of(timing.time_scale);
    out.steps_per_time_scale = timing.steps_per_time_scale;
    out.steps_per_contact = static_cast<long>(static_cast<double>(timing.contact_time / timing.time_step));
    write_deck_files(drop_deck_path.empty() ? std::string() : dem::drop_deck(model, out.deck, drop_inputs(impact, timing)),
                     variables_path.empty() ? std::string()
                                            : dem::variable_block(model, impact.kind, out.deck, drop_inputs(impact, timing),
                                                             to_decimal_string(timing.contact_time)));
    out.drop_deck_path = drop_deck_path, out.variables_path = variables_path;
    return out;
  }

  /// --timestep: the deck whose drop, stepped by the code with that step, gives the target
  /// (dem/stepped_drop.hpp) from the continuous one, its like-bead entries at the same step,
  /// and what the continuous calibration's entry gives there. Returns the step, s.
  template <class Real, class Continuous>
  Real calibrate_at_time_step(const dem::dem_model& model, const dem::dem_impact<Real>& impact, const Real& target,
                              const Continuous& continuous, dem::dem_deck<Real>& d, dem_forward& out) const {
    const dem::dem_deck<Real> c = continuous(model, impact, target);
    const dem::drop_timing<Real> t = dem::drop_timing_for(model, impact, c);
    const Real dt = dem::time_step_of(timestep, t.time_scale, t.contact_time);
    d = dem::dem_deck_at_time_step(model, impact, target, dt, c);
    out.deck = dem::deck_entries_for(model, impact, d, target,
                                     [&](const dem::dem_model& m, const dem::dem_impact<Real>& i, const Real& e) {
                                       return dem::dem_deck_at_time_step(m, i, e, dt, continuous(m, i, e));
                                     });
    // What the continuous calibration's entry gives at this step: of a model that clamps, by
    // the solve (the surrogate's deck above is only the bracket of the unclamped force).
    const dem::dem_deck<Real> reported =
        method == "surrogate" && model.clamped ? dem::dem_deck_for(model, impact, target, calibration_options<Real>{}) : c;
    dem_forward::at_time_step s;
    s.time_step = working_number::of(dt);
    s.e = working_number::of(d.calibration.scaled.e);
    s.continuous_damping = dem::deck_number(reported.damping);
    s.continuous_e = working_number::of(dem::stepped_e_for_deck(model, impact, reported, reported.damping, dt));
    out.stepped = s;
    return dt;
  }

  /// The committed surrogate of the model's law, checked against its verification table.
  static const surrogate::cor_surrogate& surrogate_of(const dem::dem_model& model) {
    const contact_law law = dem::law_of(model);
    const surrogate::cor_surrogate* s = find_surrogate(law);
    if (!s || !s->bound.verified())
      throw invalid_parameter(VISCOR_FIELD("method") " surrogate: no surrogate for " + law.describe() +
                              " (looked in '" + surrogate_directory() + "'; docs/surrogate.md)");
    return *s;
  }

  /// Method surrogate: a forward deck in double, of a model the surrogates describe.
  void check_method(const dem::dem_model& model, bool reverse) const {
    if (!timestep.empty() && reverse)
      throw invalid_parameter(VISCOR_FIELD("timestep") " " + timestep + " calibrates a deck for "
                              VISCOR_FIELD("target_e") " at that step, not the reverse table");
    if (!timestep.empty() && model.damping == dem::damping_model::yade_viscoelastic)
      throw invalid_parameter(VISCOR_FIELD("timestep") " " + timestep + ": yade viscoelastic's own stepping is not "
                              "reproduced yet (YADE's ViscEl drop at T/20 differs from a leapfrog of its force law by "
                              "6e-3 in e): no step-aware entries for it (docs/dem.md)");
    if (method == "solve") return;
    if (method != "surrogate")
      throw invalid_parameter(VISCOR_FIELD("method") " must be solve or surrogate, got '" + method + "'");
    if (reverse)
      throw invalid_parameter(VISCOR_FIELD("method") " surrogate calibrates a deck for " VISCOR_FIELD("target_e")
                              "; the e of a deck entry is solved (method solve)");
    if (digits > 15)
      throw invalid_parameter(VISCOR_FIELD("method") " surrogate computes in double: " VISCOR_FIELD("digits")
                              " must be at most 15, got " + std::to_string(digits));
    // A model that clamps has a step-aware deck by the surrogate: the stepped calibration
    // needs only a bracket, which the surrogate of the unclamped force gives.
    if (timestep.empty()) dem::require_surrogate_model(model);
  }

  /// --variables: LAMMPS and LIGGGHTS only (a YADE script asks viscor itself), forward only.
  void check_variables_request(const dem::dem_model& model, bool reverse) const {
    if (model.code == dem::dem_code::yade)
      throw invalid_parameter(VISCOR_FIELD("variables")
                              " " + variables_path + " writes a LAMMPS/LIGGGHTS `variable` block; a YADE "
                              "script is Python: import viscor and call viscor.dem(...) in it (docs/dem.md)");
    if (reverse)
      throw invalid_parameter(VISCOR_FIELD("variables")
                              " " + variables_path + " writes the entries of a calibrated deck: give "
                              VISCOR_FIELD("target_e") ", not " VISCOR_FIELD("deck_damping") "/"
                              VISCOR_FIELD("deck_en"));
  }

  /// Refuses a --drop-deck or --variables path that holds anything but viscor's own
  /// unedited file of that kind (jobs/files.hpp: its seal), a FIFO, a directory or a device.
  void refuse_outputs_not_ours() const {
    if (!drop_deck_path.empty())
      refuse_unless_own_or_absent(drop_deck_path, dem::drop_deck_marker, VISCOR_FIELD("drop_deck"), "a drop deck");
    if (!variables_path.empty())
      refuse_unless_own_or_absent(variables_path, dem::variables_marker, VISCOR_FIELD("variables"), "a variable block");
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

  template <class Real>
  dem::drop_deck_inputs drop_inputs(const dem::dem_impact<Real>& impact, const dem::drop_timing<Real>& timing) const {
    dem::drop_deck_inputs in;
    in.radius = radius, in.density = density, in.v0 = v0, in.gravity = gravity, in.force = force;
    in.target_e = target_e;
    dem::set_drop_geometry_and_steps(impact.bead.radius, timing, in);
    return in;
  }

  template <class Real>
  dem_reverse run_reverse(const dem::dem_model& model, dem::dem_impact<Real>& impact) const {
    dem_reverse out;
    Real deck_value;
    if (!deck_en.empty()) {  // YADE's own conversion: `en` becomes betan by Thornton's fit
      const Real en = parse_real<Real>(deck_en, "deck_en");
      if (!(en > 0 && en <= 1))
        throw invalid_parameter("parameter deck_en must be in (0, 1], got " + to_decimal_string(en));
      deck_value = dem::yade_thornton_betan(en);
      out.deck_en = deck_en;
    } else {
      deck_value = parse_real<Real>(deck_damping, "deck_damping");
    }
    dem::validate_deck_damping(model, deck_value);
    std::vector<std::string> speed_list = split_list(speeds, VISCOR_FIELD("speeds"));
    if (!v0.empty()) speed_list.insert(speed_list.begin(), v0);
    if (speed_list.empty()) throw invalid_parameter(VISCOR_FIELD("speeds") " lists no speed (got '" + speeds + "')");
    struct load { std::string gravity, force; };
    std::vector<load> loads{{"0", "0"}};
    if (impact.gravity != 0 || impact.force != 0) loads.push_back({gravity, force});
    out.deck_damping = deck_en.empty() ? deck_damping : to_decimal_string(deck_value);
    out.damping_number = working_number::of(dem::damping_number(model, deck_value));
    for (const std::string& speed : speed_list) {
      for (const load& l : loads) {
        dem::dem_impact<Real> at = impact;
        at.v0 = parse_real<Real>(speed, "v0");
        at.gravity = parse_real<Real>(l.gravity, "gravity");
        at.force = parse_real<Real>(l.force, "force");
        require_positive(at.v0, "v0");
        const impact_result<Real> r = dem::e_for_deck(model, at, deck_value);
        out.rows.push_back({speed, l.gravity, l.force, working_number::of(r.e), r.outcome});
      }
    }
    return out;
  }
};

}  // namespace detail

dem_result run_dem(const dem_request& q) { return detail::dem_job{q}.run(); }

}  // namespace viscor::jobs
