// extern template declarations for what src/instantiation.cpp.in compiles once per type,
// in the style of heyoka's HEYOKA_TAYLOR_ADAPTIVE_EXTERN_INST.
#pragma once

#include <viscor/exact/exact_solutions.hpp>
#include <viscor/core/scaling.hpp>
#include <viscor/certify/certification.hpp>
#include <viscor/impact/solve_impact.hpp>
#if VISCOR_HAS_QD
#include <viscor/core/double_double.hpp>
#endif

#define VISCOR_TEMPLATES(PREFIX, Real)                                                                  \
  PREFIX template std::optional<exact_result<Real>> exact_cor<Real>(const contact_law&, const Real&,    \
                                                                     const Real&);                      \
  PREFIX template scaled_parameters<Real> to_scaled<Real>(const contact_law&, const physical_parameters<Real>&); \
  PREFIX template impact_result<Real> solve_impact<Real>(const contact_law&, const Real&, const Real&,          \
                                                         const solve_options<Real>&);                  \
  PREFIX template certified_result<Real> certify<Real>(const contact_law&, const Real&, const Real&,            \
                                                       const certify_options&);                           \
  PREFIX template certified_result<Real> detail::certify_perturbed<Real>(                                       \
      const contact_law&, const Real&, const Real&, const certify_options&, const detail::certify_perturbation&);

#define VISCOR_EXTERN_TEMPLATES(Real) VISCOR_TEMPLATES(extern, Real)

#ifndef VISCOR_COMPILING_INSTANTIATIONS
namespace viscor {
VISCOR_FOR_EACH_REAL(VISCOR_EXTERN_TEMPLATES)
#if VISCOR_HAS_QD
VISCOR_EXTERN_TEMPLATES(::viscor::double_double)
#endif
}
#endif
