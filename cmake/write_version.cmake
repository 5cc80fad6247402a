# Writes src/version.cpp with the commit of the source tree at build time (run by
# the viscor_version target on every build), "-dirty" when tracked files differ
# from it: a table's sidecar must name the code that computed it, not the commit
# seen when CMake last configured. configure_file rewrites only on change, so an
# unchanged commit recompiles nothing.
# Inputs: SOURCE_DIR, INPUT (version.cpp.in), OUTPUT.
execute_process(COMMAND git rev-parse --short=12 HEAD
                WORKING_DIRECTORY ${SOURCE_DIR}
                OUTPUT_VARIABLE VISCOR_GIT_COMMIT OUTPUT_STRIP_TRAILING_WHITESPACE
                ERROR_QUIET RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  set(VISCOR_GIT_COMMIT "unknown")
else()
  execute_process(COMMAND git status --porcelain --untracked-files=no
                  WORKING_DIRECTORY ${SOURCE_DIR}
                  OUTPUT_VARIABLE changes OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(NOT changes STREQUAL "")
    string(APPEND VISCOR_GIT_COMMIT "-dirty")
  endif()
endif()
configure_file(${INPUT} ${OUTPUT} @ONLY)
