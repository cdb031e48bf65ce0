# covsim_add_module(NAME SOURCES ... DEPS ...)
# One library per module folder (a top-level folder, or one of analysis/'s rooms), aliased
# covsim::NAME (exported under the same name). Includes are rooted at the repository
# (installed: at include/covsim), so code says #include "core/kernel.hpp" or
# #include "analysis/sweep/sweep_runner.hpp" and the folder names the module.
function(covsim_add_module name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_library(covsim_${name} STATIC ${ARG_SOURCES})
  target_include_directories(covsim_${name} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
    $<BUILD_INTERFACE:${PROJECT_BINARY_DIR}/generated>
    $<INSTALL_INTERFACE:include/covsim>)
  target_link_libraries(covsim_${name} PUBLIC covsim::flags ${ARG_DEPS})
  if(COVSIM_FUZZ)  # coverage feedback from the modules' code for libFuzzer (not the tests')
    target_compile_options(covsim_${name} PRIVATE -fsanitize=fuzzer-no-link)
  endif()
  set_target_properties(covsim_${name} PROPERTIES EXPORT_NAME ${name}
                                                  POSITION_INDEPENDENT_CODE ON)
  add_library(covsim::${name} ALIAS covsim_${name})
  set_property(GLOBAL APPEND PROPERTY COVSIM_MODULES covsim_${name})
  file(RELATIVE_PATH folder ${PROJECT_SOURCE_DIR} ${CMAKE_CURRENT_SOURCE_DIR})
  install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/ DESTINATION include/covsim/${folder}
          FILES_MATCHING PATTERN "*.hpp")
endfunction()

# covsim_precompile(TARGET HEADER...): the heavy third-party headers a target's translation
# units all include (nlohmann/json through scenarios/scenario.hpp, CLI11, Catch2, pybind11),
# parsed once per target instead of once per file. Off with -DCOVSIM_PCH=OFF. ccache caches
# such compilations with the sloppiness scripts/build sets.
# What every module from scenarios/ up includes through scenarios/scenario.hpp.
set(COVSIM_JSON_HEADERS <nlohmann/json.hpp> <fmt/format.h>)
function(covsim_precompile target)
  if(NOT COVSIM_PCH)
    return()
  endif()
  target_precompile_headers(${target} PRIVATE ${ARGN})
  if(CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    # Without it clang stamps the header's time into the PCH, and ccache cannot reuse it.
    target_compile_options(${target} PRIVATE -Xclang -fno-pch-timestamp)
  endif()
endfunction()
