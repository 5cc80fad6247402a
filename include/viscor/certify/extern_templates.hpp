// extern template declarations for what src/instantiation.cpp.in compiles once per type,
// in the style of heyoka's HEYOKA_TAYLOR_ADAPTIVE_EXTERN_INST.
#pragma once

#include <viscor/exact/exact_solutions.hpp>
#include <viscor/core/scaling.hpp>
#include <viscor/certify/certification.hpp>
#include <viscor/impact/adaptive_impact.hpp>
#include <viscor/impact/solve_impact.hpp>
#include <viscor/impact/taylor_impact.hpp>
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

// The two solvers' own entry points, which tests and certify call directly: without
// them every such unit instantiated a whole solver per type (adaptive_impact_test 132 s
// of a build, docs/performance.md "After an edit"). Not for double-double, whose
// solve_impact is its own (impact/double_double_impact.hpp).
#define VISCOR_SOLVER_TEMPLATES(PREFIX, Real)                                                           \
  PREFIX template impact_result<Real> solve_impact_taylor<Real>(const contact_law&, const Real&, const Real&, \
                                                                const solve_options<Real>&);          \
  PREFIX template impact_result<Real> solve_impact_adaptive<Real>(const contact_law&, const Real&, const Real&, \
                                                                  const solve_options<Real>&);

#define VISCOR_EXTERN_TEMPLATES(Real) VISCOR_TEMPLATES(extern, Real)
#define VISCOR_EXTERN_SOLVER_TEMPLATES(Real) VISCOR_SOLVER_TEMPLATES(extern, Real)

#ifndef VISCOR_COMPILING_INSTANTIATIONS
namespace viscor {
VISCOR_FOR_EACH_REAL(VISCOR_EXTERN_TEMPLATES)
VISCOR_FOR_EACH_REAL(VISCOR_EXTERN_SOLVER_TEMPLATES)
#if VISCOR_HAS_QD
VISCOR_EXTERN_TEMPLATES(::viscor::double_double)
#endif
}
#endif
