# Runs `covsim cells` as a user would: analytic output, and exit code 2 with a clear
# message for bad input.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
file(WRITE ${WORK}/ring.json [=[{"environment": {"outer": [[-2, -2], [2, -2], [2, 2], [-2, 2]], "holes": [[[-1, -1], [1, -1], [1, 1], [-1, 1]]]}, "density": {"type": "uniform"}}]=])
file(WRITE ${WORK}/gens.json "[[-1.5, 0], [1.5, 0]]")
execute_process(COMMAND ${COVSIM} cells ${WORK}/ring.json --generators ${WORK}/gens.json
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cells failed (${rc}): ${err}")
endif()
# Each half of the ring has mass 6 and centroid x = ±7/6; the order of keys is as documented.
string(JSON mass0 GET "${out}" cells 0 mass)
string(JSON cx1 GET "${out}" cells 1 centroid 0)
string(JSON total GET "${out}" total_cost)
if(NOT mass0 MATCHES "^(6|6\\.0|6\\.000000000000[0-9]*|5\\.999999999999[0-9]*)$" OR NOT cx1 MATCHES "^1\\.16666666666")
  message(FATAL_ERROR "unexpected cells output: ${out}")
endif()
if(NOT out MATCHES "^\\{\"cells\":\\[\\{\"mass\":")
  message(FATAL_ERROR "keys out of order: ${out}")
endif()

file(WRITE ${WORK}/bad.json [=[{"environment": {"outer": [[0, 0], [1, 0], [1, 1]]}, "density": {"type": "uniform"}, "robotz": 1}]=])
execute_process(COMMAND ${COVSIM} cells ${WORK}/bad.json --generators ${WORK}/gens.json
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "bad.json: \\$\\.robotz: unknown key" OR NOT out STREQUAL "")
  message(FATAL_ERROR "bad scenario: expected exit 2 naming the key and no output, got ${rc}: ${err} ${out}")
endif()
file(WRITE ${WORK}/same.json "[[0.5, 0.5], [0.5, 0.5]]")
execute_process(COMMAND ${COVSIM} cells ${WORK}/ring.json --generators ${WORK}/same.json
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "coincide")
  message(FATAL_ERROR "coincident generators: expected exit 2, got ${rc}: ${err}")
endif()
file(WRITE ${WORK}/nan.json "[[0.5, 0.5], [1, \"x\"]]")
execute_process(COMMAND ${COVSIM} cells ${WORK}/ring.json --generators ${WORK}/nan.json
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "nan.json: \\$\\[1\\]\\[1\\]: expected a number")
  message(FATAL_ERROR "bad generators: expected exit 2 with the JSON path, got ${rc}: ${err}")
endif()
execute_process(COMMAND ${COVSIM} cells ${WORK}/missing.json --generators ${WORK}/gens.json
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "missing.json: cannot open")
  message(FATAL_ERROR "missing scenario: expected exit 2, got ${rc}: ${err}")
endif()
# A generator so far from Ω that its cell's moments would lose their digits: refused, not a
# mass larger than Ω's.
file(WRITE ${WORK}/far.json "[[1e7, 1e7]]")
execute_process(COMMAND ${COVSIM} cells ${WORK}/ring.json --generators ${WORK}/far.json
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "far.json: \\$: generator 0 at \\(1e\\+07, 1e\\+07\\) is more than"
   OR NOT out STREQUAL "")
  message(FATAL_ERROR "a far generator: expected exit 2 naming it, got ${rc}: ${err} ${out}")
endif()
# Output that cannot be written (a full disk) is a failure naming standard output.
if(EXISTS /dev/full)
  execute_process(COMMAND ${COVSIM} cells ${WORK}/ring.json --generators ${WORK}/gens.json
                  OUTPUT_FILE /dev/full RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 1 OR NOT err MATCHES "cannot write to standard output")
    message(FATAL_ERROR "cells > /dev/full: expected exit 1 naming standard output, got ${rc}: ${err}")
  endif()
endif()
