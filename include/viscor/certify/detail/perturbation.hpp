// A test seam of certify, not part of the API: one of the three computations gets
// a deliberately wrong damping coefficient, gamma (1 + relative), so that a test can
// show that certification drops. Only detail::certify_perturbed takes it; the
// public certify and its options carry no such field.
#pragma once

#include <optional>
#include <string>

namespace viscor {

enum class certified_source;

namespace detail {

struct certify_perturbation {
  std::optional<certified_source> which;  ///< the computation to perturb (none: a plain certify)
  std::string relative = "0";             ///< relative perturbation of its gamma, as decimal text
};

}  // namespace detail
}  // namespace viscor
