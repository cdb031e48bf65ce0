# run_ok(NAME ARGS...): runs ${COVSIM} ARGS in ${WORK}; fails the test unless it exits 0, and
# leaves its stdout in ${NAME}_out and its stderr in ${NAME}_err.
function(run_ok name)
  execute_process(COMMAND ${COVSIM} ${ARGN} WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc
                  OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "covsim ${ARGN}: exit ${rc}: ${err}")
  endif()
  set(${name}_out "${out}" PARENT_SCOPE)
  set(${name}_err "${err}" PARENT_SCOPE)
endfunction()
