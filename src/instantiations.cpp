// Compiled instantiations of the templated core for the common scalar types, so
// that programs linking viscor::viscor do not instantiate them again.
#define VISCOR_COMPILING_INSTANTIATIONS
#include <viscor/viscor.hpp>

#define VISCOR_INSTANTIATE(Real) VISCOR_TEMPLATES(, Real)

namespace viscor {
VISCOR_FOR_EACH_REAL(VISCOR_INSTANTIATE)
}
