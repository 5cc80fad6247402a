// The dem job's result (jobs/dem_job.hpp) as readable text and as JSON, for
// `viscor dem` and Python's viscor.dem.
#pragma once

#include <viscor/core/field_names.hpp>
#include <viscor/jobs/dem_job.hpp>
#include <viscor/jobs/json_fields.hpp>
#include <viscor/jobs/surrogate_files.hpp>

#include <sstream>
#include <string>

namespace viscor::render {

namespace detail {

// The inputs echoed under `physical`, with the names of their fields, as given.
inline jobs::json dem_physical_echo(const jobs::dem_request& q, bool linear) {
  jobs::json p;
  if (linear)
    p["k"] = q.stiffness;
  else
    p["youngs_modulus"] = q.youngs_modulus, p["poisson_ratio"] = q.poisson_ratio;
  p["radius"] = q.radius;
  p["density"] = q.density;
  for (const auto& [name, value] : q.partner_inputs())
    if (!value->empty()) p[name] = *value;
  if (!q.v0.empty()) p["v0"] = q.v0;
  p["gravity"] = q.gravity;
  p["force"] = q.force;
  return p;
}

// The readable line for the wall or the other bead, as given.
inline std::string dem_partner_line(const jobs::dem_request& q, dem::contact_kind kind) {
  if (kind == dem::contact_kind::wall)
    return q.wall_youngs_modulus.empty() ? "wall        rigid\n"
                                         : "wall        youngs_modulus = " + q.wall_youngs_modulus +
                                               " Pa, poisson_ratio = " + q.wall_poisson_ratio + "\n";
  if (q.other_youngs_modulus.empty()) return "other bead  like the first\n";
  return "other bead  youngs_modulus = " + q.other_youngs_modulus + " Pa, poisson_ratio = " + q.other_poisson_ratio +
         ", radius = " + q.other_radius + " m, density = " + q.other_density + " kg/m^3\n";
}

inline void add_forward_json(jobs::json& j, const jobs::dem_result& r, const jobs::dem_forward& f) {
  using jobs::number;
  const dem::deck_strings& s = f.deck;
  jobs::json deck;
  if (!s.stiffness.empty()) {  // YADE visco-elastic: the bead material's kn, cn; a rigid wall material
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
  deck["damping_kind"] = r.model.deck_kind == dem::deck_damping_kind::coefficient ? "coefficient"
                                                                                   : "coefficient_of_restitution";
  if (f.surrogate_bound) j[field::method] = "surrogate";
  j[field::target_e] = f.target_e;
  j["deck"] = deck;
  j["damping_number"] = number(f.damping_number);
  j["gamma0"] = number(f.gamma0);
  j["gamma"] = number(f.gamma);
  j["g"] = number(f.g);
  j[field::e] = number(f.e);
  j[field::target_bound] = number(f.target_bound);
  if (f.surrogate_bound) j["error_bound"] = jobs::surrogate_bound_json(*f.surrogate_bound);
  j["time_scale_s"] = number(f.time_scale);
  if (f.builtin) {
    j["builtin_e"] = number(f.builtin->e);
    j["builtin_error"] = number(f.builtin->error);
    j["builtin_error_percent_of_one_minus_e"] = number(f.builtin->error_percent);
    if (f.builtin->tc) j["builtin_tc_s"] = number(*f.builtin->tc);
    if (!f.builtin->conversion.empty()) j["builtin_conversion"] = f.builtin->conversion;
  }
  j["snippet"] = f.snippet;
  j[field::contact_time_s] = number(f.contact_time);
  j["time_step_s"] = number(f.time_step);
  if (f.stepped) {
    j["timestep"] = r.inputs.timestep;
    j["timestep_e"] = number(f.stepped->e);
    j["continuous_deck_damping"] = f.stepped->continuous_damping;
    j["continuous_timestep_e"] = number(f.stepped->continuous_e);
  }
  if (!f.drop_deck_path.empty()) j["drop_deck"] = f.drop_deck_path;
  if (!f.variables_path.empty()) j["variables"] = f.variables_path;
}

inline std::string drop_run_command(const dem::dem_model& model, const std::string& path) {
  switch (model.code) {
    case dem::dem_code::lammps: return "lmp -in " + path;
    case dem::dem_code::liggghts: return "liggghts -in " + path;
    case dem::dem_code::yade: return "yade -n -x " + path;
  }
  return {};
}

inline void write_forward_text(std::ostream& text, const jobs::dem_result& r, const jobs::dem_forward& f) {
  using jobs::number;
  const jobs::dem_request& q = r.inputs;
  const dem::deck_strings& s = f.deck;
  text << "impact      e = " << f.target_e << " at v0 = " << q.v0 << " m/s, gravity = " << q.gravity
       << " m/s^2, force = " << q.force << " N\n"
       << "viscor      gamma0 = " << number(f.gamma0) << " (scaled gamma = " << number(f.gamma)
       << ", g = " << number(f.g) << "), e = " << number(f.e) << "\n";
  if (f.surrogate_bound)
    text << "            by the committed surrogate's inverse in double (the C export's entries): |e - target| <= "
         << f.target_bound.decimal(3) << "\n";
  text << "deck        ";
  if (!s.stiffness.empty()) {
    text << "bead material kn = " << s.stiffness << " N/m, cn = " << s.damping << " N s/m\n";
    if (s.wall_youngs_modulus) text << "            wall material kn = cn = " << *s.wall_youngs_modulus << " (rigid)\n";
  } else {
    text << "youngs_modulus = " << s.youngs_modulus << ", poisson_ratio = " << s.poisson_ratio
         << ", damping = " << s.damping << "\n";
    if (s.wall_youngs_modulus)
      text << "            wall " << (r.model.code == dem::dem_code::yade ? "material young" : "type youngs_modulus")
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
  if (f.builtin) {
    const bool yade = r.model.code == dem::dem_code::yade;
    if (f.builtin->tc) text << "builtin     tc = " << f.builtin->tc->decimal(10) << " s gives YADE's kn = k\n";
    text << "builtin     writing " << (yade ? "en = " : "e = ") << f.target_e << " into the "
         << (yade ? "input" : "deck") << " gives e = " << f.builtin->e.decimal(10) << " ("
         << f.builtin->error.decimal(3) << ", " << f.builtin->error_percent.decimal(3) << " % of 1 - e)\n";
  }
  text << "time step   the contact lasts " << f.contact_time.decimal(6) << " s; dt = T/" << f.steps_per_time_scale
       << " = " << f.time_step.decimal(6) << " s (T = " << f.timing_time_scale.decimal(6) << " s, about "
       << f.steps_per_contact << " steps per contact)\n";
  if (f.stepped)
    text << "            calibrated for that step as " << r.model.code_name << " steps the drop: e = "
         << f.stepped->e.decimal(10) << "; the continuous entry " << f.stepped->continuous_damping << " gives "
         << f.stepped->continuous_e.decimal(10) << " there\n";
  text << "snippet\n" << f.snippet;
  if (!f.drop_deck_path.empty())
    text << "drop deck   wrote " << f.drop_deck_path << " (run: " << drop_run_command(r.model, f.drop_deck_path) << ")\n";
  if (!f.variables_path.empty())
    text << "variables   wrote " << f.variables_path << " (in the deck: include " << f.variables_path
         << ", then ${viscor_...}; units si)\n";
}

inline void add_reverse_json(jobs::json& j, const jobs::dem_reverse& v) {
  if (!v.deck_en.empty()) {
    j["deck_en"] = v.deck_en;
    j["builtin_conversion"] = "Ip2_FrictMat_FrictMat_MindlinPhys(en=deck_en): betan by Thornton et al. (2013)";
  }
  j["deck_damping"] = v.deck_damping;
  j["damping_number"] = jobs::number(v.damping_number);
  jobs::json rows = jobs::json::array();
  for (const jobs::dem_reverse_row& row : v.rows) {
    jobs::json one;
    one["v0"] = row.v0, one["gravity"] = row.gravity, one["force"] = row.force;
    one[field::e] = jobs::number(row.e);
    one[field::outcome] = to_string(row.outcome);
    rows.push_back(one);
  }
  j["table"] = rows;
}

inline void write_reverse_text(std::ostream& text, const jobs::dem_result& r, const jobs::dem_reverse& v) {
  if (!v.deck_en.empty()) text << "deck        en = " << v.deck_en << " (YADE's own conversion)\n";
  text << "deck        damping = " << v.deck_damping
       << (dem::takes_linear_stiffness(r.model) ? " (the bead material's cn, N s/m; its kn as viscor dem writes it)\n"
                                                : " (the deck modulus as viscor dem writes it)\n")
       << "v0 (m/s)    gravity (m/s^2)  force (N)  e\n";
  const auto pad = [](const std::string& s, std::size_t width) {
    return std::string(s.size() < width ? width - s.size() : 1, ' ');
  };
  for (const jobs::dem_reverse_row& row : v.rows)
    text << row.v0 << pad(row.v0, 12) << row.gravity << pad(row.gravity, 17) << row.force << pad(row.force, 11)
         << row.e.decimal(12) << "\n";
}

}  // namespace detail

/// The object of `viscor dem --json`.
inline jobs::json dem_json(const jobs::dem_result& r) {
  using jobs::number;
  const jobs::dem_request& q = r.inputs;
  const bool linear = dem::takes_linear_stiffness(r.model);
  jobs::json j;
  j["command"] = "dem";
  j["code"] = q.code;
  j["damping_model"] = q.damping;
  j["contact"] = q.contact;
  j["law"] = jobs::law_json(dem::law_of(r.model));
  j["clamped"] = r.model.clamped;  // the code sets a pulling normal force to zero
  j["version"] = std::string(r.model.version);
  j["code_source"] = std::string(r.model.source);
  j["physical"] = detail::dem_physical_echo(q, linear);  // as given (docs/json-schema.md)
  if (r.contact.effective_modulus) j["effective_modulus_pa"] = number(*r.contact.effective_modulus);
  j["effective_radius_m"] = number(r.contact.effective_radius);
  j["effective_mass_kg"] = number(r.contact.effective_mass);
  j["k"] = number(r.contact.stiffness);
  if (r.reverse) detail::add_reverse_json(j, *r.reverse);
  if (r.forward) detail::add_forward_json(j, r, *r.forward);
  j["precision"] = jobs::precision_json(r.precision);
  j[field::seconds] = r.seconds;
  return j;
}

/// The readable summary of `viscor dem`.
inline std::string dem_text(const jobs::dem_result& r) {
  using jobs::number;
  const jobs::dem_request& q = r.inputs;
  std::ostringstream text;
  text << "code        " << r.model.version << "\n"
       << "model       " << q.code << " damping " << q.damping << " on a " << q.contact << " (viscor law "
       << r.model.law_name << ")\n";
  text << detail::dem_partner_line(q, r.kind);
  if (!r.contact.effective_modulus)
    text << "contact     linear spring k = " << number(r.contact.stiffness) << " N/m, m* = "
         << number(r.contact.effective_mass) << " kg\n";
  else
    text << "contact     E* = " << number(*r.contact.effective_modulus) << " Pa, R* = "
         << number(r.contact.effective_radius) << " m, m* = " << number(r.contact.effective_mass)
         << " kg, k = " << number(r.contact.stiffness) << " N/m^1.5\n";
  if (r.reverse) detail::write_reverse_text(text, r, *r.reverse);
  if (r.forward) detail::write_forward_text(text, r, *r.forward);
  return text.str();
}

}  // namespace viscor::render
