# `covsim plot DIR` as a user would run it: the redrawn scene.svg and cost.svg equal the
# ones `covsim run` drew, and replay.html is self-contained and works in headless Chromium:
# the page moves its slider (an input event, as a user's drag sends), draws, and reports
# what it drew; an error in the page is reported. A screenshot is taken.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
execute_process(COMMAND ${COVSIM} run ${SOURCE}/scenarios/u_shape.json --out ${WORK}/run
                RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "run failed (${rc}): ${err}")
endif()
foreach(f scene.svg cost.svg)
  file(RENAME ${WORK}/run/${f} ${WORK}/${f})
endforeach()
execute_process(COMMAND ${COVSIM} plot ${WORK}/run RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "plot failed (${rc}): ${err}")
endif()
foreach(f scene.svg cost.svg)
  file(READ ${WORK}/${f} drawn)
  file(READ ${WORK}/run/${f} redrawn)
  if(NOT drawn STREQUAL redrawn)
    message(FATAL_ERROR "covsim plot drew a different ${f}")
  endif()
endforeach()
file(READ ${WORK}/run/replay.html page)
if(page MATCHES "<script src|<link|https?://|@import")
  message(FATAL_ERROR "replay.html refers to other files or the network")
endif()

# A missing output file is bad input: exit 2, naming it.
file(MAKE_DIRECTORY ${WORK}/empty)
execute_process(COMMAND ${COVSIM} plot ${WORK}/empty RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "final.json")
  message(FATAL_ERROR "plot of an empty folder: expected exit 2 naming final.json, got ${rc}: ${err}")
endif()

if(NOT CHROMIUM)
  message(FATAL_ERROR "chromium not found (scripts/install-deps installs it)")
endif()
set(flags --headless --no-sandbox --disable-gpu --enable-logging=stderr --v=0)
function(load page out_var err_var)
  execute_process(COMMAND ${CHROMIUM} ${flags} --dump-dom "file://${page}?selftest"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE dom ERROR_VARIABLE err TIMEOUT 120)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "chromium failed on ${page} (${rc}): ${err}")
  endif()
  set(${out_var} "${dom}" PARENT_SCOPE)
  set(${err_var} "${err}" PARENT_SCOPE)
endfunction()

load(${WORK}/run/replay.html dom err)
# u_shape converges after 268 motion steps: 269 frames; the slider moves to frame 134.
if(NOT dom MATCHES "<pre id=\"status\">selftest ok: frame 134 of 269, t=13.4, robots 5, cells 5, cost cursor t=13.4, keys ok, png ok<")
  string(REGEX MATCH "<pre id=\"status\">[^<]*<" status "${dom}")
  message(FATAL_ERROR "the replay did not draw the frame the slider moved to: ${status}")
endif()
if(err MATCHES "Uncaught")
  message(FATAL_ERROR "the replay page reported errors: ${err}")
endif()
execute_process(COMMAND ${CHROMIUM} ${flags} --window-size=840,760
                        --screenshot=${WORK}/replay.png "file://${WORK}/run/replay.html?selftest"
                RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET TIMEOUT 120)
file(SIZE ${WORK}/replay.png png_size)
if(NOT rc EQUAL 0 OR png_size LESS 10000)
  message(FATAL_ERROR "no screenshot of the replay (${rc}, ${png_size} bytes): ${err}")
endif()

# The check can fail: a page that throws is reported as such.
string(REPLACE "\ndraw(0);\n" "\ndraw(0); notDefined();\n" broken "${page}")
file(WRITE ${WORK}/broken.html "${broken}")
load(${WORK}/broken.html dom err)
if(dom MATCHES "<pre id=\"status\">selftest ok" OR NOT dom MATCHES "<pre id=\"status\">errors: Uncaught ReferenceError")
  message(FATAL_ERROR "an error in the page went unreported: ${dom}")
endif()
