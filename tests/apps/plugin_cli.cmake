# --plugin errors are bad input: exit 2 and a message naming the file and what is wrong.
#   -DCOVSIM=<covsim> -DWRONG_API=<plugin built for another API> -DTHROWING=<plugin whose
#   registering throws> -DNULL_VERSION=<plugin of another API with a null version> -DWORK=<scratch>
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
function(expect_error what pattern)
  execute_process(COMMAND ${COVSIM} list planners ${ARGN} WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc
                  ERROR_VARIABLE err OUTPUT_QUIET)
  if(NOT rc EQUAL 2 OR NOT err MATCHES "${pattern}")
    message(FATAL_ERROR "${what}: expected exit 2 and \"${pattern}\", got ${rc}: ${err}")
  endif()
endfunction()
expect_error("a missing file" "--plugin ${WORK}/none.so: no such file" --plugin ${WORK}/none.so)
# A bare name is a file in the working folder, not a library found in the system's path.
expect_error("a bare name of a system library" "--plugin libm.so.6: no such file"
             --plugin libm.so.6)
file(WRITE ${WORK}/not-a-library.so "text")
expect_error("not a shared library" "cannot load it" --plugin ${WORK}/not-a-library.so)
find_library(LIBM NAMES m)
if(LIBM)
  expect_error("a library that is no plugin" "not a covsim plugin" --plugin ${LIBM})
endif()
expect_error("another API version"
             "built for covsim plugin API [0-9]+ \\(covsim 9.9.9\\); this covsim [0-9.]+ has plugin API [0-9]+"
             --plugin ${WRONG_API})
expect_error("a registering function that throws"
             "registering its components failed \\(it threw a non-standard exception\\)"
             --plugin ${THROWING})
expect_error("a null version string" "\\(covsim of no stated version\\); this covsim"
             --plugin ${NULL_VERSION})
# The bare form docs/extending.md shows loads the file from the working folder.
get_filename_component(wrong_api_name ${WRONG_API} NAME)
file(COPY ${WRONG_API} DESTINATION ${WORK})
expect_error("a bare name in the working folder" "--plugin ${wrong_api_name}: built for covsim plugin API"
             --plugin ${wrong_api_name})
