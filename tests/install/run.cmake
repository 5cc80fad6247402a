# Installs viscor from BUILD_DIR into PREFIX and runs the installed CLI from WORK,
# a directory outside the repository, without VISCOR_DATA: `viscor report` must
# find the certified tables and a scene the error maps in PREFIX/share/viscor.
# Invoked by CTest (test "installed_cli").
include("${CMAKE_CURRENT_LIST_DIR}/../../cmake/install_to_fresh_prefix.cmake")
foreach(f bin/viscor share/viscor/cor_report_grid.csv share/viscor/error_maps/kuwabara_kono.csv
          share/doc/viscor/README.md share/doc/viscor/json-schema.md)
  if(NOT EXISTS "${PREFIX}/${f}")
    message(FATAL_ERROR "not installed: ${f}")
  endif()
endforeach()

set(ENV{VISCOR_DATA} "")
set(ENV{VISCOR_ERROR_MAPS} "")
execute_process(COMMAND "${PREFIX}/bin/viscor" report -o report.md WORKING_DIRECTORY "${WORK}"
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "installed viscor report failed (${rc}): ${err}")
endif()
file(READ "${WORK}/report.md" report)
string(FIND "${report}" "${PREFIX}/share/viscor" at)
if(at EQUAL -1)
  message(FATAL_ERROR "the report does not name the installed data directory:\n${report}")
endif()

file(WRITE "${WORK}/bead.json" [=[{
  "law": "kuwabara_kono",
  "bead": {"m": 2.05e-3, "k": 6.9716e9},
  "damping": {"gamma0": 1.6e-6},
  "gravity": 9.8,
  "velocities": {"from": 0.05, "to": 1, "count": 100, "spacing": "log"},
  "tolerance": 1e-4
}]=])
execute_process(COMMAND "${PREFIX}/bin/viscor" scene bead.json -o rows.csv WORKING_DIRECTORY "${WORK}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "installed viscor scene failed (${rc}): ${err}")
endif()
string(FIND "${out}" "error map  ${PREFIX}/share/viscor/error_maps/kuwabara_kono.csv" at)
if(at EQUAL -1)
  message(FATAL_ERROR "the scene did not use the installed error maps:\n${out}")
endif()

# VISCOR_DATA overrides the prefix.
set(ENV{VISCOR_DATA} "${WORK}")
execute_process(COMMAND "${PREFIX}/bin/viscor" report WORKING_DIRECTORY "${WORK}" RESULT_VARIABLE rc
                OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT rc EQUAL 2)
  message(FATAL_ERROR "viscor report with VISCOR_DATA=<a directory without tables> returned ${rc}, not 2: ${err}")
endif()
message(STATUS "installed CLI: report and scene ran from ${WORK}")
