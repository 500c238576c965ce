# expect_run(CODE ARGS...): runs the CLI (${CLI}, from the repository root ${SOURCE_DIR}) with ARGS, fails the
# test unless it exits with CODE, and leaves its stdout in OUT and its stderr in ERR. Shared by the CLI tests.
function(expect_run expected_code)
  execute_process(COMMAND ${CLI} ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err
                  WORKING_DIRECTORY ${SOURCE_DIR})
  if(NOT code STREQUAL "${expected_code}")
    message(FATAL_ERROR "straightest ${ARGN}: exit ${code}, expected ${expected_code}\nstdout: ${out}\nstderr: ${err}")
  endif()
  set(OUT "${out}" PARENT_SCOPE)
  set(ERR "${err}" PARENT_SCOPE)
endfunction()
