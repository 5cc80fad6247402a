// What src/instantiation.cpp.in compiles once per type, in the style of heyoka's
// HEYOKA_TAYLOR_ADAPTIVE_EXTERN_INST; the extern declarations are at the end of each header.
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

// What one instantiation file compiles per type; each header declares its own part
// extern (VISCOR_FOR_EACH_COMPILED_WITH, core/real_types.hpp). The two solvers' entry
// points are apart: not for double-double, whose solve_impact is its own
// (impact/double_double_impact.hpp).
#define VISCOR_TEMPLATES(PREFIX, Real)                                                       \
  VISCOR_EXACT_TEMPLATES(PREFIX, Real) VISCOR_SCALING_TEMPLATES(PREFIX, Real)               \
  VISCOR_SOLVE_IMPACT_TEMPLATES(PREFIX, Real) VISCOR_CERTIFY_TEMPLATES(PREFIX, Real)
#define VISCOR_SOLVER_TEMPLATES(PREFIX, Real) \
  VISCOR_TAYLOR_TEMPLATES(PREFIX, Real) VISCOR_ADAPTIVE_TEMPLATES(PREFIX, Real)
