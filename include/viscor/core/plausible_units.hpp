// Physical inputs far outside the range of their quantity, and the unit mistake
// they most likely are. A modulus of 70 "Pa" or a density of 2.5 "kg/m^3" still
// gives a CoR, just one of another bead: without this check such a run looks
// fine and is wrong. The ranges are wide on purpose (every solid a DEM model
// meets is inside them), so a warning means a unit, not an unusual material.
#pragma once

#include <optional>
#include <string>

namespace viscor {

/// The physical quantities whose plausible range is known independently of the law.
enum class physical_quantity { youngs_modulus, density, radius, speed, gravity };

/// What to say about an input outside its plausible range.
struct implausible_input {
  const char* below;  ///< likely mistake when the value is below the range
  const char* above;  ///< likely mistake when the value is above it
  double low;             ///< the plausible range's lower end, SI units
  double high;            ///< its upper end
  const char* low_text;   ///< the lower end as the message writes it
  const char* high_text;  ///< the upper end as the message writes it
  const char* unit;       ///< the SI unit of the quantity
};

/// The plausible range of a quantity and the unit mistakes its ends suggest.
inline implausible_input plausible_range(physical_quantity q) {
  switch (q) {
    case physical_quantity::youngs_modulus:
      return {"softer than any elastomer: a modulus in GPa or MPa? (70 GPa is 7e10 Pa)",
              "stiffer than diamond (about 1.1e12 Pa): a modulus in kPa or kN/m^2?", 1e5, 1e13, "1e5", "1e13", "Pa"};
    case physical_quantity::density:
      return {"lighter than any solid: a density in g/cm^3? (2.5 g/cm^3 is 2500 kg/m^3)",
              "denser than osmium (22,590 kg/m^3): a density in g/L or g/m^3?", 10, 3e4, "10", "3e4", "kg/m^3"};
    case physical_quantity::radius:
      return {"smaller than a molecule: a radius in km?", "a radius in mm or cm? (1 mm is 1e-3 m)", 1e-9, 10, "1e-9", "10", "m"};
    case physical_quantity::speed:
      return {"", "faster than a bullet: a speed in cm/s or mm/s? (50 cm/s is 0.5 m/s)", 0, 1e3, "0", "1e3", "m/s"};
    case physical_quantity::gravity:
      return {"", "ten times the Earth's: a gravity in cm/s^2? (the Earth's is 9.81 m/s^2, 981 cm/s^2)", 0, 100, "0", "100", "m/s^2"};
  }
  return {"", "", 0, 0, "", "", ""};
}

/// A warning naming `option` and its value `text` when `value` (SI) is outside the
/// quantity's plausible range; nothing when it is inside (or zero for the ranges that start at 0).
inline std::optional<std::string> implausible_unit(physical_quantity q, double value, const std::string& option,
                                                   const std::string& text) {
  const implausible_input r = plausible_range(q);
  const bool low = value < r.low, high = value > r.high;
  if (!low && !high) return std::nullopt;
  return option + " " + text + " " + r.unit + " is " + (low ? "below " : "above ") +
         (low ? r.low_text : r.high_text) + " " + r.unit + ", " + (low ? r.below : r.above);
}

}  // namespace viscor
