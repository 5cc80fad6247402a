// viscor: certified coefficient of restitution of visco-elastic impacts under load.
// Umbrella header: includes the whole public API.
#pragma once

#include <viscor/approximations.hpp>
#include <viscor/certification.hpp>
#include <viscor/chebyshev_beta.hpp>
#include <viscor/closed_form.hpp>
#include <viscor/config.hpp>
#include <viscor/contact_law.hpp>
#include <viscor/exact_solutions.hpp>
#include <viscor/exceptions.hpp>
#include <viscor/integrals.hpp>
#include <viscor/outcome.hpp>
#include <viscor/parameters.hpp>
#include <viscor/precision.hpp>
#include <viscor/real_io.hpp>
#include <viscor/real_types.hpp>
#include <viscor/scaling.hpp>
#include <viscor/solve_impact.hpp>
#include <viscor/u_max.hpp>
#include <viscor/extern_templates.hpp>
