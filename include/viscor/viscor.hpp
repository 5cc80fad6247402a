// viscor: certified coefficient of restitution of visco-elastic impacts under load.
// Umbrella header: includes the whole public API.
#pragma once

#include <viscor/config.hpp>
#include <viscor/contact_law.hpp>
#include <viscor/exact_solutions.hpp>
#include <viscor/exceptions.hpp>
#include <viscor/outcome.hpp>
#include <viscor/parameters.hpp>
#include <viscor/precision.hpp>
#include <viscor/real_io.hpp>
#include <viscor/real_types.hpp>
#include <viscor/scaling.hpp>
#include <viscor/solve_impact.hpp>
#include <viscor/extern_templates.hpp>
