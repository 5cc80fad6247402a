// Fixture for the check_layers_catches_violation test: an approximation that calls a solver.
#pragma once
#include <viscor/impact/solve_impact.hpp>
