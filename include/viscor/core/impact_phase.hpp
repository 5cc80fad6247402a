// The phases of one impact, named alike in the three methods that compute it: the
// Taylor solver (impact/taylor_impact.hpp), the GBS solver (impact/adaptive_impact.hpp)
// and the proof (enclose/proven_impact.hpp). Each method writes its own phase code (a
// shared proof would be a shared blind spot); they share the names, the order and
// what each phase decides, so the three implementations of a phase read side by side
// (docs/architecture.md, "One argument, three implementations"). Each method's
// function for a phase is named <phase>_phase and returns what happened.
#pragma once

#include <string_view>

namespace viscor {

/// A phase of an impact (contact_state names the state the phases hand over).
enum class impact_phase {
  /// From first contact (u = 0, v = 1) in an endpoint variable (s = u^(1/Q), or ln u),
  /// in which u = 0 is a regular point, until v has fallen far enough that the
  /// turning point v = 0 (singular in that variable) is near.
  compress,
  /// In tau, through maximal compression (v = 0): where the bead turns back (v = 0
  /// again with u > 0), is trapped (a barrier or a sector it never leaves), is shown
  /// to stick by its energy, or provably heads for u = 0.
  turn,
  /// Past maximal compression, a strongly damped creep on the slow manifold followed
  /// by an implicit (L-stable) method where explicit steps would take too many steps
  /// (the two solvers; the proof has no creep phase).
  creep,
  /// In the endpoint variable back down to u = 0 exactly, where e = -v.
  exit,
};

/// The phase's name ("compress", "turn", "creep", "exit").
inline std::string_view to_string(impact_phase p) {
  switch (p) {
    case impact_phase::compress: return "compress";
    case impact_phase::turn: return "turn";
    case impact_phase::creep: return "creep";
    case impact_phase::exit: return "exit";
  }
  return "exit";
}

}  // namespace viscor
