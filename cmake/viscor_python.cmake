# Finds what the Python module needs (docs/python.md): a Python 3 interpreter with
# its development headers, and pybind11. Sets VISCOR_PYTHON_FOUND (what
# VISCOR_BUILD_PYTHON=AUTO builds on) and says why when something is missing.
#
# The interpreter: Python3_EXECUTABLE when given; otherwise the first python3 on
# PATH, unless it lacks NumPy and the system's python3 (same minor version, so the
# same extension ABI) has it: the tests of the vectorised evaluate need NumPy, and
# ctest runs them with the interpreter found here. `import viscor` itself does not
# need NumPy, so the module also loads in the other interpreter.

function(viscor_python_has_numpy interpreter result)
  execute_process(COMMAND ${interpreter} -c "import numpy" RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
  if(rc EQUAL 0)
    set(${result} TRUE PARENT_SCOPE)
  else()
    set(${result} FALSE PARENT_SCOPE)
  endif()
endfunction()

function(viscor_python_minor interpreter result)
  execute_process(COMMAND ${interpreter} -c "import sys; print('%d.%d' % sys.version_info[:2])"
                  OUTPUT_VARIABLE version OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  set(${result} "${version}" PARENT_SCOPE)
endfunction()

if(NOT DEFINED Python3_EXECUTABLE)
  find_program(VISCOR_PATH_PYTHON3 NAMES python3 NO_CACHE)
  find_program(VISCOR_SYSTEM_PYTHON3 NAMES python3 PATHS /usr/bin NO_DEFAULT_PATH NO_CACHE)
  if(VISCOR_PATH_PYTHON3 AND VISCOR_SYSTEM_PYTHON3 AND NOT VISCOR_PATH_PYTHON3 STREQUAL VISCOR_SYSTEM_PYTHON3)
    viscor_python_has_numpy(${VISCOR_PATH_PYTHON3} path_has_numpy)
    viscor_python_has_numpy(${VISCOR_SYSTEM_PYTHON3} system_has_numpy)
    viscor_python_minor(${VISCOR_PATH_PYTHON3} path_minor)
    viscor_python_minor(${VISCOR_SYSTEM_PYTHON3} system_minor)
    if(NOT path_has_numpy AND system_has_numpy AND path_minor STREQUAL system_minor)
      message(STATUS "viscor: ${VISCOR_PATH_PYTHON3} has no NumPy; using ${VISCOR_SYSTEM_PYTHON3} "
                     "(Python ${system_minor}, same ABI) for the Python module and its tests")
      set(Python3_EXECUTABLE ${VISCOR_SYSTEM_PYTHON3} CACHE FILEPATH "Python interpreter for the viscor module")
    endif()
  endif()
endif()

set(VISCOR_PYTHON_FOUND OFF)
find_package(Python3 COMPONENTS Interpreter Development.Module)
if(NOT Python3_Development.Module_FOUND)
  message(STATUS "viscor: Python module not built by default: no Python 3 development headers "
                 "(Debian: apt-get install python3-dev pybind11-dev, or bash tools/install-deps.sh)")
  return()
endif()
find_package(pybind11 2.6 CONFIG QUIET)
if(NOT pybind11_FOUND)
  message(STATUS "viscor: Python module not built by default: pybind11 not found "
                 "(Debian: apt-get install pybind11-dev, or bash tools/install-deps.sh)")
  return()
endif()
viscor_python_has_numpy(${Python3_EXECUTABLE} VISCOR_PYTHON_HAS_NUMPY)
message(STATUS "viscor: Python module for ${Python3_EXECUTABLE} (Python ${Python3_VERSION}, pybind11 "
               "${pybind11_VERSION}, NumPy ${VISCOR_PYTHON_HAS_NUMPY})")
set(VISCOR_PYTHON_FOUND ON)
