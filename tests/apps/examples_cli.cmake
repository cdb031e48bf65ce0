# The examples build against an installed covsim, as a user's own project would, and run
# through both routes: their own program (linking covsim::covsim, registering the component,
# running the planner contract suite or a sweep) and the installed covsim with --plugin.
#   -DBUILD=<covsim build dir> -DSOURCE=<covsim source> -DWORK=<scratch> -DCXX=<compiler>
#   [-DPYTHON=<interpreter> -DPYTHON_SITE=<where the package installs, under the prefix>
#    -DPRELOAD=<sanitizer runtime to preload, for a sanitized build>]
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
set(prefix ${WORK}/prefix)

function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}):\n${out}\n${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()

run("cmake --install" ${CMAKE_COMMAND} --install ${BUILD} --prefix ${prefix})
foreach(f bin/covsim lib/cmake/covsim/covsimConfig.cmake include/covsim/core/version.hpp
          include/covsim/sim/plugin.hpp lib/libcovsim_core.a)
  if(NOT EXISTS ${prefix}/${f})
    message(FATAL_ERROR "the installation lacks ${f}")
  endif()
endforeach()

set(launcher "")
find_program(CCACHE ccache)
if(CCACHE)
  set(launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${CCACHE})
endif()
foreach(example bug2_planner damped_lloyd_law)
  # With no build type given, as the examples' own comments show: they default to Release.
  run("configuring ${example}" ${CMAKE_COMMAND} -S ${SOURCE}/examples/${example}
      -B ${WORK}/${example} -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_CXX_COMPILER=${CXX}
      ${launcher})
  file(STRINGS ${WORK}/${example}/CMakeCache.txt build_type REGEX "^CMAKE_BUILD_TYPE:")
  if(NOT build_type MATCHES "=Release$")
    message(FATAL_ERROR "${example} does not default to Release: ${build_type}")
  endif()
  run("building ${example}" ${CMAKE_COMMAND} --build ${WORK}/${example} -j 2)
endforeach()

# --help is help, and a bad argument an error with exit 2, never a crash.
foreach(program bug2_planner/bug2_demo damped_lloyd_law/damped_lloyd_demo)
  run("${program} --help" ${WORK}/${program} --help)
  if(NOT out MATCHES "^usage: ")
    message(FATAL_ERROR "${program} --help: ${out}")
  endif()
  set(rest ${WORK}/out)  # damped_lloyd_demo's OUT_DIR
  if(program MATCHES "bug2")
    set(rest 10)  # bug2_demo's CASES
  endif()
  execute_process(COMMAND ${WORK}/${program} ${WORK}/no-such.json ${rest} RESULT_VARIABLE rc
                  ERROR_VARIABLE err OUTPUT_QUIET)
  if(NOT rc EQUAL 2 OR NOT err MATCHES "no-such.json")
    message(FATAL_ERROR "${program} on a missing scenario: expected exit 2 naming it, got ${rc}: ${err}")
  endif()
endforeach()

# Route 1: the user's own programs.
run("bug2_demo" ${WORK}/bug2_planner/bug2_demo ${SOURCE}/scenarios/u_shape.json 300)
if(NOT out MATCHES "contract: 300 cases, [0-9]+ reached, [0-9]+ projected, 0 stalled, 0 failed"
   OR NOT out MATCHES "run: converged")
  message(FATAL_ERROR "bug2_demo: ${out}")
endif()
run("damped_lloyd_demo" ${WORK}/damped_lloyd_law/damped_lloyd_demo ${SOURCE}/scenarios/u_shape.json
    ${WORK}/damped-sweep)
file(READ ${WORK}/damped-sweep/runs.csv runs)
if(NOT runs MATCHES "0.3,damped_lloyd,1,1," OR NOT runs MATCHES "1.0,damped_lloyd,1,1,")
  message(FATAL_ERROR "damped_lloyd_demo's sweep did not converge for both gains:\n${runs}")
endif()

# Route 2: the installed covsim loads the plugins; scenarios select them by name.
file(READ ${SOURCE}/scenarios/u_shape.json base)
string(REPLACE "\"seed\": 1" "\"seed\": 1, \"planner\": {\"type\": \"bug2\"}" bug2 "${base}")
file(WRITE ${WORK}/u_bug2.json "${bug2}")
string(REPLACE "\"seed\": 1" "\"seed\": 1, \"controller\": {\"type\": \"damped_lloyd\", \"gain\": 0.5}"
       damped "${base}")
file(WRITE ${WORK}/u_damped.json "${damped}")
run("covsim list --plugin" ${prefix}/bin/covsim list planners --names
    --plugin ${WORK}/bug2_planner/libbug2_plugin.so)
if(NOT out MATCHES "bug2")
  message(FATAL_ERROR "covsim list does not show the plugin's planner: ${out}")
endif()
foreach(case "bug2;bug2_planner/libbug2_plugin.so" "damped;damped_lloyd_law/libdamped_lloyd_plugin.so")
  list(GET case 0 name)
  list(GET case 1 plugin)
  run("covsim run --plugin ${plugin}" ${prefix}/bin/covsim run ${WORK}/u_${name}.json
      --out ${WORK}/run-${name} --plugin ${WORK}/${plugin})
  file(READ ${WORK}/run-${name}/final.json final)
  # Converged; a motion out of Ω would have stopped the run with an error.
  if(NOT final MATCHES "\"converged\": true")
    message(FATAL_ERROR "the ${name} plugin's run did not converge:\n${final}")
  endif()
endforeach()
# Without the plugin, the scenario names an unknown planner: a clear error, exit 2.
execute_process(COMMAND ${prefix}/bin/covsim run ${WORK}/u_bug2.json --out ${WORK}/no-plugin
                RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
if(NOT rc EQUAL 2 OR NOT err MATCHES "\\$.planner.type: expected one of")
  message(FATAL_ERROR "a scenario naming an unloaded plugin's planner: ${rc}: ${err}")
endif()

# The installed Python package: where the system Python looks under the prefix, it runs the
# U-shaped scenario to the installed program's fingerprint.
if(PYTHON)
  if(NOT EXISTS ${prefix}/${PYTHON_SITE}/covsim/__init__.py)
    message(FATAL_ERROR "the installation lacks the Python package in ${PYTHON_SITE}")
  endif()
  run("covsim run" ${prefix}/bin/covsim run ${SOURCE}/scenarios/u_shape.json --out ${WORK}/run-u)
  file(READ ${WORK}/run-u/final.json final)
  string(REGEX MATCH "\"fingerprint\": \"([0-9a-f]+)\"" _ "${final}")
  set(expected ${CMAKE_MATCH_1})
  file(WRITE ${WORK}/probe.py "import covsim\nprint(covsim.__file__)\n"
       "s = covsim.Scenario.from_file('${SOURCE}/scenarios/u_shape.json')\n"
       "print(covsim.Simulation(s).run()['fingerprint'])\n")
  set(preload)
  if(PRELOAD)  # a sanitized build: its runtime first, the interpreter's own leaks not counted
    set(preload LD_PRELOAD=${PRELOAD} ASAN_OPTIONS=detect_leaks=0)
  endif()
  run("the installed Python package" ${CMAKE_COMMAND} -E env PYTHONPATH=${prefix}/${PYTHON_SITE}
      ${preload} ${PYTHON} ${WORK}/probe.py)
  if(NOT out MATCHES "^${prefix}/${PYTHON_SITE}/covsim/__init__.py\n${expected}\n$")
    message(FATAL_ERROR "the installed Python package: ${out} (want fingerprint ${expected})")
  endif()
endif()
message(STATUS "examples built and ran against the installed covsim")
