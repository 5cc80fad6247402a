// Fixture for check_api_docs_catches_undocumented: one documented and one
// undocumented public function; the check must name the second.
#pragma once

/// The fixture namespace.
namespace viscor {

/// Twice x.
inline double twice(double x) { return 2 * x; }

inline double thrice(double x) { return 3 * x; }

}  // namespace viscor
