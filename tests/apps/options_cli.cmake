# `covsim run --seed/--set`, the default output folder, robots drawn per seed, `covsim
# describe`, `covsim --version` and a replay's warning about another build, as a user runs
# them. -DCOVSIM=<program> -DSOURCE=<source dir> -DWORK=<scratch>
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
set(u ${SOURCE}/scenarios/u_shape.json)

include(${CMAKE_CURRENT_LIST_DIR}/run_ok.cmake)
function(fingerprint var dir)
  file(READ ${dir}/final.json final)
  string(JSON fp GET "${final}" fingerprint)
  set(${var} ${fp} PARENT_SCOPE)
endfunction()
function(bad what expected)  # bad(WHAT REGEX ARGS...): exit 2 and the message
  execute_process(COMMAND ${COVSIM} ${ARGN} WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc
                  OUTPUT_QUIET ERROR_VARIABLE err)
  if(NOT rc EQUAL 2 OR NOT err MATCHES "${expected}")
    message(FATAL_ERROR "${what}: expected exit 2 and '${expected}', got ${rc}: ${err}")
  endif()
endfunction()

# --set and --seed equal editing the file, fingerprint for fingerprint.
run_ok(set run ${u} --seed 4 --set network.loss.model=bernoulli --set network.loss.p=0.3
       --out ${WORK}/set)
file(READ ${u} base)
string(JSON edited SET "${base}" seed 4)
string(JSON edited SET "${edited}" network "{\"loss\": {\"model\": \"bernoulli\", \"p\": 0.3}}")
file(WRITE ${WORK}/edited.json "${edited}")
run_ok(edit run ${WORK}/edited.json --out ${WORK}/edited)
fingerprint(a ${WORK}/set)
fingerprint(b ${WORK}/edited)
if(NOT a STREQUAL b)
  message(FATAL_ERROR "--set gave ${a}, the edited file ${b}")
endif()
file(READ ${WORK}/set/scenario.json kept)
string(JSON p GET "${kept}" network loss p)
if(NOT p EQUAL 0.3)
  message(FATAL_ERROR "scenario.json does not hold the --set value: ${kept}")
endif()

# The default output folder: out/<scenario name>-<seed>.
run_ok(default run ${u} --seed 3)
if(NOT EXISTS ${WORK}/out/u_shape-3/final.json)
  message(FATAL_ERROR "no out/u_shape-3/final.json: ${default_out}")
endif()

# Bad options: exit 2, naming the option, nothing written.
bad("--set with a bad value" "--set network.loss.p=2: .*u_shape.json: \\$\\.network\\.loss\\.p: expected"
    run ${u} --set network.loss.model=bernoulli --set network.loss.p=2 --out ${WORK}/no1)
bad("--set without =" "--set network.loss: expected PATH=VALUE" run ${u} --set network.loss
    --out ${WORK}/no2)
bad("--set with a bad path" "--set a..b=1: \"a..b\" is not a dotted path" run ${u} --set a..b=1
    --out ${WORK}/no3)
bad("planner-contract of a planner through walls" "planner \"none\" does not avoid obstacles"
    planner-contract --planner none --cases 1)
bad("--seed -1" "--seed: expected a whole number" run ${u} --seed -1 --out ${WORK}/no4)
bad("--seed 2^64" "--seed: expected a whole number" run ${u} --seed 18446744073709551616
    --out ${WORK}/no5)
foreach(d no1 no2 no3 no4 no5)
  if(EXISTS ${WORK}/${d})
    message(FATAL_ERROR "a rejected run left ${d}")
  endif()
endforeach()

# Robots drawn per seed: seeds deploy differently, and the run folder replays without the
# generator (their body and speed kept beside the positions drawn).
string(JSON drawn SET "${base}" robots "{\"count\": 6, \"start\": {\"cluster\": {\"center\": [0.15, 0.85], \"radius\": 0.12}}, \"radius\": 0.004, \"max_speed\": 0.12}")
file(WRITE ${WORK}/drawn.json "${drawn}")
run_ok(d1 run ${WORK}/drawn.json --seed 1 --out ${WORK}/d1)
run_ok(d2 run ${WORK}/drawn.json --seed 2 --out ${WORK}/d2)
file(READ ${WORK}/d1/scenario.json s1)
file(READ ${WORK}/d2/scenario.json s2)
string(JSON r1 GET "${s1}" robots positions)
string(JSON r2 GET "${s2}" robots positions)
string(JSON n1 LENGTH "${s1}" robots positions)
if(r1 STREQUAL r2 OR NOT n1 EQUAL 6)
  message(FATAL_ERROR "seeds 1 and 2 drew the same robots, or not 6: ${r1}")
endif()
run_ok(again run ${WORK}/d1/scenario.json --out ${WORK}/d1-again)
fingerprint(f1 ${WORK}/d1)
fingerprint(f1b ${WORK}/d1-again)
if(NOT f1 STREQUAL f1b)
  message(FATAL_ERROR "the run folder's scenario.json ran to ${f1b}, the run to ${f1}")
endif()

# describe: the scenario as it will run; it runs to the same fingerprint.
run_ok(describe describe ${WORK}/drawn.json --seed 1)
file(WRITE ${WORK}/described.json "${describe_out}")
string(JSON tol GET "${describe_out}" convergence position_tolerance)
if(NOT tol GREATER 0)
  message(FATAL_ERROR "describe left the derived tolerance out: ${describe_out}")
endif()
run_ok(described run ${WORK}/described.json --out ${WORK}/described)
fingerprint(f2 ${WORK}/described)
if(NOT f1 STREQUAL f2)
  message(FATAL_ERROR "the described scenario ran to ${f2}, the scenario to ${f1}")
endif()

# --version names the version and the commit.
run_ok(version --version)
if(NOT version_out MATCHES "^covsim [0-9]+\\.[0-9]+\\.[0-9]+ \\(commit ")
  message(FATAL_ERROR "covsim --version: ${version_out}")
endif()

# A trace from another build replays with a warning naming what differs.
run_ok(traced run ${u} --out ${WORK}/t --trace ${WORK}/t.trace)
file(READ ${WORK}/t.trace trace)
string(REGEX REPLACE "build\\.commit [0-9a-f]+" "build.commit 0123456789abcdef" trace "${trace}")
file(WRITE ${WORK}/other.trace "${trace}")
run_ok(replay replay ${WORK}/other.trace)
if(NOT replay_err MATCHES "written by a different build" OR NOT replay_err MATCHES
   "commit: 0123456789abcdef then" OR NOT replay_out MATCHES "replay matches")
  message(FATAL_ERROR "replay of another build's trace: ${replay_out} ${replay_err}")
endif()
run_ok(same replay ${WORK}/t.trace)
if(same_err MATCHES "different build")
  message(FATAL_ERROR "a trace of this build warned: ${same_err}")
endif()
# A run's folder is not its trace: said so, exit 2.
bad("replay of a run folder" "t: is a directory, not a trace" replay ${WORK}/t)

# `list planners --reads-range`: the planners a sensor-range study varies (the registry's
# flag), and only for planners.
run_ok(ranged list planners --names --reads-range)
run_ok(every list planners --names)
if(NOT ranged_out STREQUAL "tangent_bug\npotential_field\n" OR NOT every_out MATCHES
   "straight_line")
  message(FATAL_ERROR "list planners --reads-range: '${ranged_out}' of '${every_out}'")
endif()
bad("--reads-range on laws" "applies to planners only" list laws --reads-range)
# `list laws --autonomous`: the laws a comparison runs, without the one a program drives.
run_ok(own list laws --names --autonomous)
run_ok(laws list laws --names)
if(NOT own_out STREQUAL "virtual_generators\neuclidean_lloyd\ngeodesic_lloyd\n" OR NOT laws_out
   MATCHES "external")
  message(FATAL_ERROR "list laws --autonomous: '${own_out}' of '${laws_out}'")
endif()
bad("--autonomous on planners" "applies to laws only" list planners --autonomous)

# random-env's seed is read strictly, as run's is.
bad("random-env --seed -1" "--seed: expected a whole number" random-env --seed -1)
bad("random-env --seed 1.5" "--seed: expected a whole number" random-env --seed 1.5)

# `list sensor`, `list sections`: each fixed section's keys with kind, default, unit, bounds
# and help, from the same schemas the loader reads.
run_ok(sensor list sensor)
if(NOT sensor_out MATCHES "range +number +default null \\[m\\], >= 0, null allowed +sensing range")
  message(FATAL_ERROR "list sensor does not show sensor.range: ${sensor_out}")
endif()
run_ok(all list)
if(NOT all_out MATCHES "section sensor:" OR NOT all_out MATCHES "planners \\(\"planner\": {\"type\"}\\)")
  message(FATAL_ERROR "list shows not both components and sections: ${all_out}")
endif()
run_ok(keys list sections --names)
foreach(key robots.max_speed sensor.range sensor.noise.sigma loops.loop1_period
            network.acquire_timeout limits.trajectory_rows)
  if(NOT keys_out MATCHES "(^|\n)${key}\n")
    message(FATAL_ERROR "list sections --names lacks ${key}: ${keys_out}")
  endif()
endforeach()
run_ok(md list sections --markdown)
if(NOT md_out MATCHES "<!-- begin sensor -->\n\\| key \\| kind \\|.*\\| `range` \\| number \\| m \\|")
  message(FATAL_ERROR "list sections --markdown: ${md_out}")
endif()
bad("--markdown on planners" "applies to sections only" list planners --markdown)
# The documentation's tables written from the schemas are the ones checked in.
configure_file(${SOURCE}/docs/scenario-format.md ${WORK}/scenario-format.md COPYONLY)
run_ok(update list --update-docs ${WORK}/scenario-format.md)
file(READ ${SOURCE}/docs/scenario-format.md checked_in)
file(READ ${WORK}/scenario-format.md regenerated)
if(NOT checked_in STREQUAL regenerated)
  message(FATAL_ERROR "docs/scenario-format.md differs from the schemas: run covsim list "
                      "--update-docs docs/scenario-format.md")
endif()
file(WRITE ${WORK}/no-markers.md "nothing here\n")
bad("--update-docs without markers" "no-markers.md: no lines" list --update-docs
    ${WORK}/no-markers.md)

# A mistyped command or option: the error says what it most likely meant.
bad("a mistyped command" "'rnu' is no covsim command: did you mean 'run'\\?" rnu ${u})
bad("a mistyped option" "'--trac' is no option of covsim run: did you mean '--trace'\\?"
    run ${u} --trac t.trace)
bad("a mistyped option near two" "'--seeed' is no option of covsim run: did you mean '--seed' or '--speed'\\?"
    run ${u} --seeed 3)
bad("an unknown command" "the commands are cells, describe" frobnicate)
