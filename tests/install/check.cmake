# The installed tool and the example of a user's own implementation, end to end. Run by ctest as
# `install_own_implementation`:
#   1. installs curvebench from BINARY_DIR into a scratch prefix;
#   2. the installed bin/curvebench lists the installed cases without flags (from a directory with
#      no reports/ or bench/), runs `accuracy` on one fast case, and `gate` passes a rule it meets
#      and fails (exit 1) a rule it cannot meet;
#   3. examples/own_implementation configures, builds and passes its ctest against the prefix
#      (the subject API's gate, curvebench_add_check's CSV checks), and its benchmark runs under
#      curvebench's benchmark names;
#   4. the same example built with -DOWN_BUG=ON (a wrong end tangent) fails: its gate program and
#      `curvebench check` on its CSV exit 1, its ctest fails, and `curvebench compare` of its check
#      with the stored baseline names the grown error.
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR}/run)
set(prefix ${WORK_DIR}/prefix)
set(tool ${prefix}/bin/curvebench)
set(example ${SOURCE_DIR}/examples/own_implementation)

# run(<expected exit code> <what> COMMAND...): fails the test unless the command exits so; its
# output is kept in `out`.
macro(run expected what)
  execute_process(COMMAND ${ARGN} WORKING_DIRECTORY ${WORK_DIR}/run RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  if(NOT "${rc}" STREQUAL "${expected}")
    message(FATAL_ERROR "${what}: exit ${rc}, expected ${expected}\n--- stdout\n${out}\n--- stderr\n${err}")
  endif()
endmacro()

run(0 "install" ${CMAKE_COMMAND} --install ${BINARY_DIR} --prefix ${prefix})

# 2. The installed tool finds its cases and thresholds beside itself.
run(0 "installed curvebench list cases" ${tool} list cases)
if(NOT out MATCHES "share/curvebench/cases" OR NOT out MATCHES "catmull_rom_centripetal_2d")
  message(FATAL_ERROR "curvebench list cases did not list the installed cases:\n${out}")
endif()
run(0 "installed curvebench accuracy" ${tool} accuracy --quick --only arch_cubic_bezier --threads 1
    --out ${WORK_DIR}/run/accuracy.json)
# Adaptive Gauss-Kronrod at tol 1e-10 on a cubic arch measures ~1e-16 (reports/REPORT.md): 1e-9
# must hold; no method reaches an error of 1e-300, so that rule must breach.
file(WRITE ${WORK_DIR}/run/pass.json
     [=[{"rules": [{"quantity": "length", "method": "adaptive_gk", "setting": "tol=1e-10", "max_error": 1e-9}]}]=])
file(WRITE ${WORK_DIR}/run/fail.json [=[{"rules": [{"quantity": "length", "method": "gauss", "max_error": 1e-300}]}]=])
run(0 "installed curvebench gate (a rule the results meet)" ${tool} gate --results accuracy.json --thresholds pass.json)
run(1 "installed curvebench gate (a rule they cannot meet)" ${tool} gate --results accuracy.json --thresholds fail.json)

# 3. The example against the installed package.
run(0 "configuring the example" ${CMAKE_COMMAND} -S ${example} -B ${WORK_DIR}/example -DCMAKE_PREFIX_PATH=${prefix}
    -DCMAKE_CXX_COMPILER=${CXX})
run(0 "building the example" ${CMAKE_COMMAND} --build ${WORK_DIR}/example)
run(0 "the example's ctest" ${CMAKE_CTEST_COMMAND} --test-dir ${WORK_DIR}/example --output-on-failure)
foreach(test own_gate own_csv_values own_csv_lengths own_csv_values_baseline own_csv_easing)
  if(NOT out MATCHES "${test} [.]+ +Passed")
    message(FATAL_ERROR "the example's ctest did not run ${test}:\n${out}")
  endif()
endforeach()
# The subject's results are accuracy.json records the installed gate accepts.
run(0 "installed curvebench gate on the subject's results" ${tool} gate
    --results ${WORK_DIR}/example/own_results.json --thresholds ${example}/thresholds.json)
if(EXISTS ${WORK_DIR}/example/own_bench)
  run(0 "the example's benchmark" ${WORK_DIR}/example/own_bench --benchmark_filter=own_catmull_rom/calls:single
      --benchmark_format=json)
  if(NOT out MATCHES "\"name\": \"catmull_rom/own_catmull_rom/calls:single\"" OR NOT out MATCHES "\"label\": \"evaluation\"")
    message(FATAL_ERROR "the example's benchmark is not named as curvebench's:\n${out}")
  endif()
endif()

# 4. The deliberate bug must be caught.
run(0 "configuring the example with OWN_BUG" ${CMAKE_COMMAND} -S ${example} -B ${WORK_DIR}/bug
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_CXX_COMPILER=${CXX} -DOWN_BUG=ON)
run(0 "building the example with OWN_BUG" ${CMAKE_COMMAND} --build ${WORK_DIR}/bug --target own_measure own_write_csv own_write_easing)
run(1 "the example's gate with OWN_BUG" ${WORK_DIR}/bug/own_measure ${prefix}/share/curvebench/cases
    ${example}/thresholds.json ${WORK_DIR}/bug/own_results.json)
if(NOT err MATCHES "eval/own_catmull_rom/\\* at case catmull_rom_centripetal_2d")
  message(FATAL_ERROR "the gate with OWN_BUG did not name the Catmull-Rom's breach:\n${err}")
endif()
run(0 "the example's CSV writer with OWN_BUG" ${WORK_DIR}/bug/own_write_csv values.csv lengths.csv inverse.csv)
run(1 "installed curvebench check on OWN_BUG's CSV" ${tool} check ${example}/spec.json --values values.csv
    --max-error 64)
# The easing checked by time: the bug (y(t) without the inversion) is 2.4e6 float ulps off.
run(0 "the example's easing writer with OWN_BUG" ${WORK_DIR}/bug/own_write_easing easing.csv)
run(1 "installed curvebench check on OWN_BUG's easing" ${tool} check ${example}/easing.json --values easing.csv
    --unit ulp-float --max-value-error 16)
if(NOT out MATCHES "OVER easing.csv: row [0-9]+ [(]t = [0-9.e-]+[)]: error [0-9.e+]+ > allowed 16 ulps of float")
  message(FATAL_ERROR "the check of OWN_BUG's easing did not name a row over its limit:\n${out}")
endif()
run(8 "the example's ctest with OWN_BUG" ${CMAKE_CTEST_COMMAND} --test-dir ${WORK_DIR}/bug)
# Its check against the stored baseline ran (no MAX_ERROR there) and compare named the grown errors.
run(1 "installed curvebench compare of OWN_BUG's check with the baseline" ${tool} compare
    ${example}/own_values.baseline.json ${WORK_DIR}/bug/baseline/own_csv_values_baseline.results.json)
if(NOT out MATCHES "REGRESSION error grew: spec/eval/own_csv_values_baseline")
  message(FATAL_ERROR "compare did not name OWN_BUG's grown error:\n${out}")
endif()
