# curvebench_add_check: a CTest that runs your program and checks the CSV it writes against
# curvebench's 50-digit reference with `curvebench check` (included by curvebenchConfig.cmake when
# the package was installed with its tool).
#
#   curvebench_add_check(NAME <test name> SPEC <spec.json> COMMAND <program> [args...]
#                        [VALUES <csv>] [LENGTHS <csv>] [INVERSE <csv>]
#                        [MAX_ERROR <x>] [MAX_VALUE_ERROR <x>] [MAX_LENGTH_ERROR <x>]
#                        [MAX_INVERSE_ERROR <x>] [UNIT <unit>] [AGAINST truth|tool]
#                        [THRESHOLDS <thresholds.json>] [SUBJECT <name>] [WORKING_DIRECTORY <dir>]
#                        [BASELINE <results.json> [MAX_ERROR_GROWTH <x>]])
#
# The test runs COMMAND in WORKING_DIRECTORY (default: the current binary directory; a first word
# naming an executable target of this project runs that target's file), fails when it exits
# non-zero, then runs
#   curvebench check SPEC --values VALUES [--lengths LENGTHS] [--inverse INVERSE]
#                    [--max-error X] [--max-value-error X] [--max-length-error X]
#                    [--max-inverse-error X] [--unit U] [--against A] [--thresholds FILE] --name SUBJECT
# and fails when the check does (a row over MAX_ERROR, a breached rule, or bad input: a missing
# column, a parameter outside the domain, a non-numeric cell). Relative CSV paths are relative to
# WORKING_DIRECTORY. VALUES defaults to <NAME>.csv when neither LENGTHS nor INVERSE is given;
# SUBJECT (the records' method, which THRESHOLDS' rules name) defaults to NAME. For a channel spec
# ("type": "channel") VALUES holds t,value[,dvalue[,d2value]]: your channel at times, checked against
# the channel's truth, or with AGAINST tool against the tool's own evaluation (`curvebench check --help`).
#
# With BASELINE, the check writes its results as JSON to <NAME>.results.json in WORKING_DIRECTORY
# and the test then runs `curvebench compare BASELINE <NAME>.results.json [--max-error-growth X]`:
# it fails when an error grew beyond MAX_ERROR_GROWTH (default 0.1: 10 %, plus the rounding floor of
# its unit) or stopped being measured, against the results you stored. Store them once: run the test,
# copy <NAME>.results.json to the BASELINE path (in your source tree) and commit it.
#
# Example:
#   find_package(curvebench REQUIRED)
#   add_executable(my_spline_csv my_spline_csv.cpp)     # writes my_spline.csv: u,x,y
#   curvebench_add_check(NAME my_spline SPEC ${CMAKE_CURRENT_SOURCE_DIR}/spec.json
#                        COMMAND my_spline_csv my_spline.csv VALUES my_spline.csv MAX_ERROR 64)
#   add_executable(walk_cycle_csv walk_cycle_csv.cpp)   # writes walk.csv: t,value at frames
#   curvebench_add_check(NAME walk_cycle SPEC walk.json COMMAND walk_cycle_csv walk.csv
#                        VALUES walk.csv UNIT ulp-float MAX_VALUE_ERROR 4)
#   curvebench_add_check(NAME my_spline_baseline SPEC spec.json COMMAND my_spline_csv my_spline.csv
#                        VALUES my_spline.csv BASELINE ${CMAKE_CURRENT_SOURCE_DIR}/my_spline.baseline.json)
include_guard(GLOBAL)

function(curvebench_add_check)
  cmake_parse_arguments(PARSE_ARGV 0 arg "" "NAME;SPEC;VALUES;LENGTHS;INVERSE;MAX_ERROR;MAX_VALUE_ERROR;MAX_LENGTH_ERROR;MAX_INVERSE_ERROR;UNIT;AGAINST;THRESHOLDS;SUBJECT;WORKING_DIRECTORY;BASELINE;MAX_ERROR_GROWTH"
                        "COMMAND")
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "curvebench_add_check: unknown arguments: ${arg_UNPARSED_ARGUMENTS}")
  endif()
  foreach(required NAME SPEC COMMAND)
    if(NOT arg_${required})
      message(FATAL_ERROR "curvebench_add_check: ${required} is required")
    endif()
  endforeach()
  if(NOT arg_VALUES AND NOT arg_LENGTHS AND NOT arg_INVERSE)
    set(arg_VALUES ${arg_NAME}.csv)
  endif()
  if(NOT arg_SUBJECT)
    set(arg_SUBJECT ${arg_NAME})
  endif()
  if(NOT arg_WORKING_DIRECTORY)
    set(arg_WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  endif()
  if(NOT IS_ABSOLUTE "${arg_SPEC}")
    set(arg_SPEC ${CMAKE_CURRENT_SOURCE_DIR}/${arg_SPEC})
  endif()
  if(arg_THRESHOLDS AND NOT IS_ABSOLUTE "${arg_THRESHOLDS}")
    set(arg_THRESHOLDS ${CMAKE_CURRENT_SOURCE_DIR}/${arg_THRESHOLDS})
  endif()
  if(arg_BASELINE AND NOT IS_ABSOLUTE "${arg_BASELINE}")
    set(arg_BASELINE ${CMAKE_CURRENT_SOURCE_DIR}/${arg_BASELINE})
  endif()
  if(DEFINED arg_MAX_ERROR_GROWTH AND NOT arg_BASELINE)
    message(FATAL_ERROR "curvebench_add_check: MAX_ERROR_GROWTH goes with BASELINE")
  endif()
  if(TARGET curvebench::tool)
    set(tool "$<TARGET_FILE:curvebench::tool>")
  elseif(TARGET curvebench_tool)
    set(tool "$<TARGET_FILE:curvebench_tool>")
  elseif(CURVEBENCH_EXECUTABLE)
    set(tool "${CURVEBENCH_EXECUTABLE}")
  else()
    message(FATAL_ERROR "curvebench_add_check: no curvebench tool (install curvebench with CURVEBENCH_BUILD_BENCH=ON)")
  endif()

  # The user's command; a first word naming an executable target runs that target's file.
  set(command ${arg_COMMAND})
  list(GET command 0 program)
  if(TARGET ${program})
    get_target_property(type ${program} TYPE)
    if(type STREQUAL "EXECUTABLE")
      list(POP_FRONT command)
      list(PREPEND command "$<TARGET_FILE:${program}>")
    endif()
  endif()
  set(check ${tool} check ${arg_SPEC} --name ${arg_SUBJECT})
  foreach(pair VALUES:--values LENGTHS:--lengths INVERSE:--inverse MAX_ERROR:--max-error MAX_VALUE_ERROR:--max-value-error
               MAX_LENGTH_ERROR:--max-length-error MAX_INVERSE_ERROR:--max-inverse-error UNIT:--unit AGAINST:--against
               THRESHOLDS:--thresholds)
    string(REPLACE ":" ";" pair ${pair})
    list(GET pair 0 key)
    list(GET pair 1 option)
    if(DEFINED arg_${key} AND NOT arg_${key} STREQUAL "")
      list(APPEND check ${option} ${arg_${key}})
    endif()
  endforeach()

  set(steps command check)
  set(check_output "")
  if(arg_BASELINE)
    # The check's results as JSON, then compared with the stored ones.
    list(APPEND check --json)
    set(results ${arg_WORKING_DIRECTORY}/${arg_NAME}.results.json)
    set(check_output " OUTPUT_FILE [==[${results}]==]")
    set(compare ${tool} compare ${arg_BASELINE} ${results})
    if(DEFINED arg_MAX_ERROR_GROWTH)
      list(APPEND compare --max-error-growth ${arg_MAX_ERROR_GROWTH})
    endif()
    list(APPEND steps compare)
  endif()

  # One script per test: every word in a bracket argument, so spaces and semicolons inside a word
  # survive; generator expressions ($<TARGET_FILE:...>) are expanded by file(GENERATE).
  set(script "# curvebench_add_check(NAME ${arg_NAME}): generated, do not edit\n")
  foreach(step IN LISTS steps)
    set(words "")
    foreach(word IN LISTS ${step})
      string(APPEND words " [==[${word}]==]")
    endforeach()
    set(output "")
    if(step STREQUAL "check")
      set(output "${check_output}")
    endif()
    if(step STREQUAL "compare")
      string(APPEND script "if(NOT EXISTS [==[${arg_BASELINE}]==])\n"
                           "  message(FATAL_ERROR \"curvebench_add_check ${arg_NAME}: no baseline at ${arg_BASELINE}: \"\n"
                           "    \"copy ${results} there (the results of this run) and commit it\")\n"
                           "endif()\n")
    endif()
    string(APPEND script "execute_process(COMMAND${words}\n"
                         "  WORKING_DIRECTORY [==[${arg_WORKING_DIRECTORY}]==]${output} RESULT_VARIABLE rc)\n"
                         "if(NOT rc EQUAL 0)\n"
                         "  message(FATAL_ERROR \"curvebench_add_check ${arg_NAME}: the ${step} failed (exit \${rc})\")\n"
                         "endif()\n")
  endforeach()
  set(script_file ${CMAKE_CURRENT_BINARY_DIR}/curvebench_check/${arg_NAME}-$<CONFIG>.cmake)
  file(GENERATE OUTPUT ${script_file} CONTENT "${script}")
  file(MAKE_DIRECTORY ${arg_WORKING_DIRECTORY})
  add_test(NAME ${arg_NAME} COMMAND ${CMAKE_COMMAND} -P ${script_file})
endfunction()
