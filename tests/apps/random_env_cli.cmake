# Runs `covsim random-env` as a user would: the same seed writes the same file, the file
# runs as a scenario, bad arguments exit 2 and write nothing.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
foreach(name a b)
  execute_process(COMMAND ${COVSIM} random-env --seed 7 --holes 2 --robots 3 --out ${WORK}/${name}.json
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "random-env failed (${rc}): ${err}")
  endif()
endforeach()
file(READ ${WORK}/a.json a)
file(READ ${WORK}/b.json b)
if(NOT a STREQUAL b)
  message(FATAL_ERROR "the same seed gave two different environments")
endif()
execute_process(COMMAND ${COVSIM} random-env --seed 8 --holes 2 --robots 3
                RESULT_VARIABLE rc OUTPUT_VARIABLE c)
if(NOT rc EQUAL 0 OR c STREQUAL a)
  message(FATAL_ERROR "seed 8 should give another environment on stdout (${rc})")
endif()
string(JSON robots LENGTH "${a}" robots positions)
if(NOT robots EQUAL 3)
  message(FATAL_ERROR "expected 3 robots, got ${robots}")
endif()
execute_process(COMMAND ${COVSIM} run ${WORK}/a.json --out ${WORK}/run
                RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
if(NOT rc EQUAL 0 OR NOT EXISTS ${WORK}/run/final.json)
  message(FATAL_ERROR "the random scenario did not run (${rc}): ${err}")
endif()
execute_process(COMMAND ${COVSIM} random-env --seed 1 --robots 0 --out ${WORK}/none.json
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "robots" OR EXISTS ${WORK}/none.json)
  message(FATAL_ERROR "zero robots: expected exit 2 and no file, got ${rc}: ${err}")
endif()

# Asked for more holes than fit: the scenario has fewer, and the program says how many.
execute_process(COMMAND ${COVSIM} random-env --seed 1 --holes 40 --out ${WORK}/many.json
                RESULT_VARIABLE rc ERROR_VARIABLE err)
file(READ ${WORK}/many.json many)
string(JSON placed LENGTH "${many}" environment holes)
if(NOT rc EQUAL 0 OR NOT placed LESS 40 OR NOT err MATCHES "placed ${placed} of the 40 holes")
  message(FATAL_ERROR "40 holes: expected exit 0 and 'placed ${placed} of the 40 holes', got ${rc}: ${err}")
endif()
