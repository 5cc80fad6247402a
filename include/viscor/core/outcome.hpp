// How an impact ends: the one outcome of a solver's result and of a proof.
#pragma once

#include <string_view>

namespace viscor {

/// How an impact ends, as a solver (impact_result) or a proof (proofs::proven_impact) found it.
/// rebound: the bead leaves the wall (u = 0 with u' < 0) and e = -u'(T_f) > 0 (a proof
/// encloses e > 0). stick: it never leaves; e = 0. NOTE: every result says which
/// end-of-contact criterion it uses: viscor ends contact at zero overlap u = 0, as the
/// report does. undecided: the method cannot tell at its working precision (or within
/// its step budget) whether or when the contact ends: a solver's e is 0 to within the
/// result's error_estimate and its contact_time is unknown (empty); a proof claims nothing.
/// Never certified: certify counts it as a disagreement.
enum class impact_outcome { rebound, stick, undecided };

/// The outcome's name as written in tables and JSON.
inline std::string_view to_string(impact_outcome o) {
  switch (o) {
    case impact_outcome::rebound: return "rebound";
    case impact_outcome::stick: return "stick";
    case impact_outcome::undecided: return "undecided";
  }
  return "undecided";
}

}  // namespace viscor
