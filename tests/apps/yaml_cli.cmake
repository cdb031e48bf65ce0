# YAML input as a user gives it: the YAML twin of u_shape runs to the fingerprint of
# u_shape.json and describes alike, the shipped YAML sweep runs, generators may be YAML, and
# bad YAML exits 2 naming the file, the line and column (and the JSON path where there is a
# value), with nothing written. -DCOVSIM=<program> -DSOURCE=<source dir> -DWORK=<scratch>
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})

include(${CMAKE_CURRENT_LIST_DIR}/run_ok.cmake)

# The twins: one run, one description, and the run folder's scenario.json stays JSON.
foreach(kind json yaml)
  run_ok(run run ${SOURCE}/scenarios/u_shape.${kind} --out ${WORK}/${kind})
  file(READ ${WORK}/${kind}/final.json final)
  string(JSON fp_${kind} GET "${final}" fingerprint)
  run_ok(describe_${kind} describe ${SOURCE}/scenarios/u_shape.${kind})
endforeach()
if(NOT fp_json STREQUAL fp_yaml OR NOT fp_yaml STREQUAL "00f6b1d36fca19df")
  message(FATAL_ERROR "u_shape.yaml ran to ${fp_yaml}, u_shape.json to ${fp_json}")
endif()
if(NOT describe_json_out STREQUAL describe_yaml_out)
  message(FATAL_ERROR "the twins describe apart:\n${describe_json_out}\n${describe_yaml_out}")
endif()
file(READ ${WORK}/yaml/scenario.json kept)
string(JSON seed ERROR_VARIABLE not_json GET "${kept}" seed)
if(not_json OR NOT seed EQUAL 1)
  message(FATAL_ERROR "the run folder's scenario.json is not JSON: ${kept}")
endif()

# The shipped YAML sweep: three loss probabilities, two seeds.
run_ok(sweep sweep ${SOURCE}/examples/sweeps/u_shape_loss.yaml --out ${WORK}/sweep --jobs 2)
file(STRINGS ${WORK}/sweep/runs.csv rows)
list(LENGTH rows n)
if(NOT n EQUAL 7 OR NOT rows MATCHES "network.loss.p")
  message(FATAL_ERROR "the YAML sweep's runs.csv: ${rows}")
endif()

# The same sweep with its progress lines going to a full disk: lost lines, not a lost sweep.
if(EXISTS /dev/full)
  execute_process(COMMAND ${COVSIM} sweep ${SOURCE}/examples/sweeps/u_shape_loss.yaml
                          --out ${WORK}/sweep-full --jobs 2
                  RESULT_VARIABLE rc OUTPUT_QUIET ERROR_FILE /dev/full)
  file(STRINGS ${WORK}/sweep-full/runs.csv full_rows)
  list(LENGTH full_rows n)
  if(NOT rc EQUAL 0 OR NOT n EQUAL 7)
    message(FATAL_ERROR "sweep with stderr on /dev/full: exit ${rc}, ${n} rows in runs.csv")
  endif()
endif()

# Generators in YAML.
file(WRITE ${WORK}/gens.yaml "# two generators\n- [0.2, 0.2]\n- [0.8, 0.2]\n")
run_ok(cells cells ${SOURCE}/scenarios/u_shape.yaml --generators ${WORK}/gens.yaml)
string(JSON ncells LENGTH "${cells_out}" cells)
if(NOT ncells EQUAL 2)
  message(FATAL_ERROR "cells of YAML generators: ${cells_out}")
endif()

# Bad input: exit 2, FILE:LINE:COLUMN (and $.path), nothing written.
set(square "environment:\n  outer: [[0, 0], [4, 0], [4, 4], [0, 4]]\ndensity: {type: uniform}\n")
function(refused name text expected)  # refused(NAME TEXT REGEX [covsim arguments])
  file(WRITE ${WORK}/${name}.yaml "${text}")
  set(args ${ARGN})
  if(NOT args)
    set(args run ${WORK}/${name}.yaml --out ${WORK}/${name}-out)
  endif()
  execute_process(COMMAND ${COVSIM} ${args} WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc
                  OUTPUT_QUIET ERROR_VARIABLE err)
  if(NOT rc EQUAL 2 OR NOT err MATCHES "${name}\\.yaml:${expected}" OR EXISTS ${WORK}/${name}-out)
    message(FATAL_ERROR "${name}: expected exit 2 and '${name}.yaml:${expected}', got ${rc}: ${err}")
  endif()
endfunction()
refused(malformed "${square}robots: {positions: [[1, 1]\nseed: 1\n" "[0-9]+:[0-9]+: malformed YAML: ")
refused(duplicate "${square}seed: 1\nseed: 2\n" "5:1: \\$: duplicate key \"seed\"")
refused(unknown "${square}robotz: 1\n" "4:9: \\$\\.robotz: unknown key \"robotz\"")
refused(wrong_type "${square}sensor:\n  range: wide\n"
        "5:10: \\$\\.sensor\\.range: expected a number, found a string")
refused(nan "${square}sensor:\n  range: .nan\n"
        "5:10: \\$\\.sensor\\.range: expected a finite number, found \\.nan")
string(REPEAT "[" 300 open)
string(REPEAT "]" 300 close)
refused(deep "${open}${close}\n" "1:257: \\$\\[0\\]\\[0\\].*: YAML nested deeper than 256 levels")
refused(alias "${square}seed: &s 1\nrobots: {count: *s}\n" "4:7: \\$\\.seed: anchors \\(&s\\)")
refused(sweep_value "scenario: ${SOURCE}/scenarios/u_shape.yaml\ngrid:\n  sensor.range: [1, -1]\nseeds: [1]\n"
        "3:21: \\$\\.grid\\.sensor\\.range\\[1\\]: sensor\\.range = -1 gives an invalid scenario"
        sweep ${WORK}/sweep_value.yaml --out ${WORK}/sweep_value-out)
refused(gens_bad "- [0.5, 0.5]\n- [1, x]\n" "2:7: \\$\\[1\\]\\[1\\]: expected a number"
        cells ${SOURCE}/scenarios/u_shape.yaml --generators ${WORK}/gens_bad.yaml)
# A value from --set is the option's, not the file's: no line and column in the file.
execute_process(COMMAND ${COVSIM} run ${SOURCE}/scenarios/u_shape.yaml --set sensor.range=-1
                        --out ${WORK}/set-out
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "--set sensor\\.range=-1: [^\n]*u_shape\\.yaml: \\$\\.sensor\\.range: ")
  message(FATAL_ERROR "--set on a YAML scenario: expected exit 2 naming the option, got ${rc}: ${err}")
endif()
