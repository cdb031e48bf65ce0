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
  set_target_properties(covsim_${name} PROPERTIES EXPORT_NAME ${name}
                                                  POSITION_INDEPENDENT_CODE ON)
  add_library(covsim::${name} ALIAS covsim_${name})
  set_property(GLOBAL APPEND PROPERTY COVSIM_MODULES covsim_${name})
  file(RELATIVE_PATH folder ${PROJECT_SOURCE_DIR} ${CMAKE_CURRENT_SOURCE_DIR})
  install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/ DESTINATION include/covsim/${folder}
          FILES_MATCHING PATTERN "*.hpp")
endfunction()
