# Precompiled headers (docs/performance.md, "Build time"). Every viscor translation
# unit parses Boost.Multiprecision and Boost.Math, about 10 s of CPU each, the CLI's
# also CLI11 and nlohmann-json (4 s each): more time than some of them spend
# generating code. A precompiled header parses them once per target. Used by the
# tests (one header for the suite) and by the subcommands when they are compiled
# one by one (VISCOR_CLI_UNITY_BUILD=OFF); not by the library's instantiation files,
# where it cost more than it saved.
option(VISCOR_PRECOMPILED_HEADERS "Precompile the heavy headers once per target" ON)

set(VISCOR_PCH_BOOST
  <boost/math/special_functions/fpclassify.hpp> <boost/math/constants/constants.hpp> <boost/math/tools/precision.hpp>
  <boost/math/tools/toms748_solve.hpp> <boost/math/special_functions/gamma.hpp> <boost/math/special_functions/beta.hpp>
  <boost/math/quadrature/tanh_sinh.hpp> <boost/math/quadrature/gauss_kronrod.hpp> <boost/math/quadrature/exp_sinh.hpp>
  <boost/multiprecision/cpp_bin_float.hpp> <boost/multiprecision/cpp_int.hpp>)
if(VISCOR_WITH_FLOAT128)
  list(APPEND VISCOR_PCH_BOOST <boost/multiprecision/float128.hpp>)
endif()
if(VISCOR_WITH_MPFR)
  list(APPEND VISCOR_PCH_BOOST <boost/multiprecision/mpfr.hpp>)
endif()

# viscor_precompile(TARGET [HEADER...]): Boost's headers and the given ones, if enabled.
function(viscor_precompile target)
  if(VISCOR_PRECOMPILED_HEADERS)
    target_precompile_headers(${target} PRIVATE ${VISCOR_PCH_BOOST} ${ARGN})
  endif()
endfunction()

# viscor_reuse_precompiled(TARGET FROM): TARGET uses FROM's precompiled header
# (same compile flags and definitions required).
function(viscor_reuse_precompiled target from)
  if(VISCOR_PRECOMPILED_HEADERS)
    target_precompile_headers(${target} REUSE_FROM ${from})
  endif()
endfunction()
