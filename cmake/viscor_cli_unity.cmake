# The subcommands compiled in a few translation units (docs/performance.md, "Build
# time"). Compiled one by one, every src/cli/cmd_*.cpp generated its own copy of the
# inline code of CLI11, nlohmann-json and the MPFR expression templates: 5.1 of the
# 8.3 MB of their object code was such duplicates. Grouped, each copy is compiled
# once per group. Groups of about equal compile time keep both cores of a 2-core
# machine busy. Each subcommand lives in its own namespace (viscor::cli::cmd_<name>),
# so the files can share a translation unit.
option(VISCOR_CLI_UNITY_BUILD "Compile the CLI subcommands in a few grouped translation units" ON)

set(VISCOR_CLI_UNITY_GROUPS
  "cor|cmd_cor cmd_exact cmd_scale cmd_calibrate cmd_dem cmd_prove"
  "tables|cmd_table cmd_report cmd_errormap cmd_approx cmd_bench"
  "scenes|cmd_scene cmd_surrogate")

# viscor_cli_unity(TARGET): group TARGET's src/cli/cmd_*.cpp as listed above (a
# subcommand not listed compiles on its own), or, with the option off, compile
# them one by one with a precompiled header.
function(viscor_cli_unity target)
  if(NOT VISCOR_CLI_UNITY_BUILD)
    viscor_precompile(${target} <viscor/viscor.hpp> <CLI/CLI.hpp> <nlohmann/json.hpp>)
    return()
  endif()
  set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_MODE GROUP)
  foreach(group IN LISTS VISCOR_CLI_UNITY_GROUPS)
    string(REPLACE "|" ";" fields "${group}")
    list(GET fields 0 name)
    list(GET fields 1 stems)
    string(REPLACE " " ";" stems "${stems}")
    foreach(stem IN LISTS stems)
      set_source_files_properties(${PROJECT_SOURCE_DIR}/src/cli/${stem}.cpp PROPERTIES UNITY_GROUP ${name})
    endforeach()
  endforeach()
endfunction()
