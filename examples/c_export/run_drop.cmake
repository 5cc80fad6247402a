# Builds examples/c_export/drop.c with the committed export, with plain `cc` (C99, no
# viscor include path, warnings as errors), and runs it: it exits 1 when the loaded
# conversion misses its target e by more than its tolerance (drop.c explains it).
# Run: cmake -DSOURCE=examples/c_export -DWORK=DIR -P run_drop.cmake
file(MAKE_DIRECTORY ${WORK})
execute_process(COMMAND cc -std=c99 -O2 -Wall -Wextra -pedantic -Werror ${SOURCE}/drop.c ${SOURCE}/viscor_surrogates.c
                        -lm -o ${WORK}/drop
                RESULT_VARIABLE built OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT built EQUAL 0 OR NOT out STREQUAL "")
  message(FATAL_ERROR "cc drop.c viscor_surrogates.c failed or warned (${built}):\n${out}")
endif()
execute_process(COMMAND ${WORK}/drop RESULT_VARIABLE ran OUTPUT_VARIABLE out ERROR_VARIABLE out)
message("${out}")
if(NOT ran EQUAL 0)
  message(FATAL_ERROR "drop failed (${ran})")
endif()
