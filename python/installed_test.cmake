# Installs viscor from BUILD_DIR into PREFIX and imports the installed Python module
# from WORK, outside the repository, with neither PYTHONPATH to the build tree nor
# VISCOR_DATA: it must compute and find the installed data (PREFIX/share/viscor).
# Invoked by CTest (test "python_installed").
include("${CMAKE_CURRENT_LIST_DIR}/../cmake/install_to_fresh_prefix.cmake")
set(ENV{VISCOR_DATA} "")
set(ENV{PYTHONPATH} "${PREFIX}/${PACKAGE_DIR}")
execute_process(COMMAND "${PYTHON}" -c
  "import viscor; print(viscor.__file__); print(viscor.data_directory()); print(viscor.exact('linear', '0.1').e_exact)"
  WORKING_DIRECTORY "${WORK}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "import of the installed module failed (${rc}): ${err}")
endif()
string(FIND "${out}" "${PREFIX}/${PACKAGE_DIR}/viscor/__init__.py" at_module)
string(FIND "${out}" "${PREFIX}/share/viscor" at_data)
if(at_module EQUAL -1 OR at_data EQUAL -1)
  message(FATAL_ERROR "the installed module or its data directory was not used:\n${out}")
endif()
# e of the linear law at gamma = 0.1, g = 0: exp(-0.1 pi / (2 sqrt(1 - 0.0025))), to 15 digits.
string(FIND "${out}" "8.5446789300675" at_value)
if(at_value EQUAL -1)
  message(FATAL_ERROR "wrong value from the installed module:\n${out}")
endif()
message(STATUS "installed module:\n${out}")
