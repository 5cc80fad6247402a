// Each DEM code's deck entries in the C export (jobs/surrogate_export.hpp): for a target
// e, the bead, its wall or second bead and the load, the numbers the code's input line
// takes, and the e the code's own conversion would give. The C states, in double, the
// steps of include/viscor/dem/ (the contact, the codes' conventions, the like-bead
// entries) with the calibration by the committed surrogate's inverse: `viscor dem
// --method surrogate` (dem/surrogate_deck.hpp) gives the same bits, which a test checks.
#pragma once

#include <string>

namespace viscor::jobs {

/// The C declarations of the entries, placed in the export's header.
std::string dem_entries_c_declarations();

/// Their C definitions, placed in the export's source after the surrogates' evaluation.
std::string dem_entries_c_definitions();

}  // namespace viscor::jobs
