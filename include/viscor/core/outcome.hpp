// How an impact ends.
#pragma once

#include <string_view>

namespace viscor {

/// rebound: the bead leaves the wall (u = 0 with u' < 0) and e = -u'(T_f) > 0.
/// stick: it never leaves; e = 0. NOTE: every result says which end-of-contact
/// criterion it uses: viscor ends contact at zero overlap u = 0, as the report does.
enum class impact_outcome { rebound, stick };

/// The outcome's name as written in tables and JSON.
inline std::string_view to_string(impact_outcome o) { return o == impact_outcome::rebound ? "rebound" : "stick"; }

}  // namespace viscor
