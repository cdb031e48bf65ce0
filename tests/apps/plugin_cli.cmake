# --plugin errors are bad input: exit 2 and a message naming the file and what is wrong.
#   -DCOVSIM=<covsim> -DWRONG_API=<plugin built for another API> -DWORK=<scratch>
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
function(expect_error what pattern)
  execute_process(COMMAND ${COVSIM} list planners ${ARGN} RESULT_VARIABLE rc
                  ERROR_VARIABLE err OUTPUT_QUIET)
  if(NOT rc EQUAL 2 OR NOT err MATCHES "${pattern}")
    message(FATAL_ERROR "${what}: expected exit 2 and \"${pattern}\", got ${rc}: ${err}")
  endif()
endfunction()
expect_error("a missing file" "--plugin ${WORK}/none.so: cannot load it" --plugin ${WORK}/none.so)
file(WRITE ${WORK}/not-a-library.so "text")
expect_error("not a shared library" "cannot load it" --plugin ${WORK}/not-a-library.so)
find_library(LIBM NAMES m)
if(LIBM)
  expect_error("a library that is no plugin" "not a covsim plugin" --plugin ${LIBM})
endif()
expect_error("another API version"
             "built for covsim plugin API [0-9]+ \\(covsim 9.9.9\\); this covsim [0-9.]+ has plugin API [0-9]+"
             --plugin ${WRONG_API})
