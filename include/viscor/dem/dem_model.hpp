// The (DEM code, damping model) pairs viscor can map onto its force law
//   F = k delta^alpha + gamma0 k d/dt(delta^beta),
// with the program version each convention was read from and checked against.
// Every supported model but YADE's visco-elastic one (a linear spring of the user's
// stiffness, alpha = beta = 1) has Hertz elasticity (alpha = 3/2); all have a damping force
//   F_d = D P delta^(beta - 1) d(delta)/dt,
// where D is the number written in the deck (or computed by the code from a
// coefficient of restitution written in the deck) and P depends on the contact
// only (see deck_convention.hpp). Then gamma0 = D P / (beta k).
#pragma once

#include <viscor/core/contact_law.hpp>
#include <viscor/core/exceptions.hpp>

#include <array>
#include <string>
#include <string_view>

namespace viscor::dem {

enum class dem_code { lammps, liggghts, yade };

enum class damping_model {
  velocity,       ///< LAMMPS: F_d = eta delta'
  mass_velocity,  ///< LAMMPS: F_d = eta m* delta'
  viscoelastic,   ///< LAMMPS: F_d = eta m* sqrt(R* delta) delta'
  tsuji,          ///< LAMMPS: F_d = eta'(e) sqrt(m* K sqrt(R* delta)) delta', eta' a polynomial in the deck's e
  hertz_restitution,  ///< LIGGGHTS model hertz: F_d = sqrt(5) b(e) sqrt(m* k) delta^(1/4) delta', b from the deck's e
  mindlin,  ///< YADE Hertz-Mindlin: F = max(0, k delta^(3/2) + sqrt(6) betan sqrt(m* k) delta^(1/4) delta'), deck betan
  yade_viscoelastic,  ///< YADE ViscEl: F = max(0, kn delta + cn delta'), a linear spring of the user's stiffness, deck cn
};

/// What the deck's damping number is.
enum class deck_damping_kind {
  coefficient,              ///< a damping coefficient (LAMMPS damp), written as is
  coefficient_of_restitution,  ///< an e that the code turns into damping by its own formula
};

/// A DEM code's damping model: which code, its name there, the force law it means and what its damping input is.
struct dem_model {
  dem_code code;
  damping_model damping;
  std::string_view code_name;     ///< as on the command line
  std::string_view damping_name;  ///< as on the command line (and in the deck, where the code names it)
  std::string_view law_name;      ///< viscor's named law with the same exponents
  deck_damping_kind deck_kind;
  std::string_view version;       ///< the program version the convention was read from and checked in
  std::string_view source;        ///< where in that program's source
  bool clamped = false;           ///< the code sets a pulling total normal force to zero (impact/clamped_impact.hpp)
};

inline constexpr std::string_view lammps_version = "LAMMPS 29 Sep 2021 update 2 (Debian 12 lammps 20220106.git7586adbb6a+ds1-2+b2)";
inline constexpr std::string_view liggghts_version = "LIGGGHTS-PUBLIC 3.8.0 (Debian 12 liggghts 3.8.0+repack1-9+b2)";

inline constexpr std::string_view yade_version = "YADE 2023.02a (Debian 12 yade 2023.02a-1)";

inline constexpr std::array<dem_model, 7> dem_models{{
    {dem_code::lammps, damping_model::velocity, "lammps", "velocity", "hertz_linear_damping",
     deck_damping_kind::coefficient, lammps_version, "src/GRANULAR/pair_granular.cpp, fix_wall_gran.cpp"},
    {dem_code::lammps, damping_model::mass_velocity, "lammps", "mass_velocity", "hertz_linear_damping",
     deck_damping_kind::coefficient, lammps_version, "src/GRANULAR/pair_granular.cpp, fix_wall_gran.cpp"},
    {dem_code::lammps, damping_model::viscoelastic, "lammps", "viscoelastic", "kuwabara_kono",
     deck_damping_kind::coefficient, lammps_version, "src/GRANULAR/pair_granular.cpp, fix_wall_gran.cpp"},
    {dem_code::lammps, damping_model::tsuji, "lammps", "tsuji", "tsuji", deck_damping_kind::coefficient_of_restitution,
     lammps_version, "src/GRANULAR/pair_granular.cpp, fix_wall_gran.cpp"},
    {dem_code::liggghts, damping_model::hertz_restitution, "liggghts", "hertz", "tsuji",
     deck_damping_kind::coefficient_of_restitution, liggghts_version,
     "src/normal_model_hertz.h, src/global_properties.cpp"},
    {dem_code::yade, damping_model::mindlin, "yade", "mindlin", "tsuji", deck_damping_kind::coefficient, yade_version,
     "pkg/dem/HertzMindlin.cpp (Ip2_FrictMat_FrictMat_MindlinPhys, Law2_ScGeom_MindlinPhys_Mindlin)", true},
    {dem_code::yade, damping_model::yade_viscoelastic, "yade", "viscoelastic", "linear", deck_damping_kind::coefficient,
     yade_version, "pkg/dem/ViscoelasticPM.cpp (Ip2_ViscElMat_ViscElMat_ViscElPhys, Law2_ScGeom_ViscElPhys_Basic)", true},
}};

/// Models whose stiffness is not Hertz from the material but a linear spring the
/// user gives (--k, N/m): YADE's visco-elastic law.
inline bool takes_linear_stiffness(const dem_model& m) { return m.damping == damping_model::yade_viscoelastic; }

/// The model for a code and damping name, or invalid_parameter naming the bad value.
inline const dem_model& find_dem_model(const std::string& code, const std::string& damping) {
  bool code_known = false;
  for (const auto& m : dem_models) {
    if (m.code_name != code) continue;
    code_known = true;
    if (m.damping_name == damping) return m;
  }
  if (!code_known) throw invalid_parameter("unknown DEM code '" + code + "': expected lammps, liggghts or yade");
  std::string names;
  for (const auto& m : dem_models)
    if (m.code_name == code) names += (names.empty() ? "" : ", ") + std::string(m.damping_name);
  if (code == "lammps" && damping == "coeff_restitution")
    throw invalid_parameter("damping model 'coeff_restitution' is not in the installed LAMMPS (29 Sep 2021; it came "
                            "with the granular rewrite of 2023): expected one of " + names);
  throw invalid_parameter("unknown damping model '" + damping + "' for " + code + ": expected one of " + names);
}

/// viscor's contact law with the model's exponents.
inline contact_law law_of(const dem_model& m) { return law_by_name(m.law_name); }

}  // namespace viscor::dem
