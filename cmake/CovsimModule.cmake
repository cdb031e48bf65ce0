# covsim_add_module(NAME SOURCES ... DEPS ...)
# One library per top-level folder, aliased covsim::NAME. Includes are rooted at the
# repository, so code says #include "core/kernel.hpp" and the folder names the module.
function(covsim_add_module name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  if(ARG_SOURCES)
    add_library(covsim_${name} STATIC ${ARG_SOURCES})
    target_include_directories(covsim_${name} PUBLIC ${PROJECT_SOURCE_DIR})
    target_link_libraries(covsim_${name} PUBLIC covsim::flags ${ARG_DEPS})
  else()
    # A module with no sources yet still carries its place in the dependency order.
    add_library(covsim_${name} INTERFACE)
    target_include_directories(covsim_${name} INTERFACE ${PROJECT_SOURCE_DIR})
    target_link_libraries(covsim_${name} INTERFACE covsim::flags ${ARG_DEPS})
  endif()
  add_library(covsim::${name} ALIAS covsim_${name})
endfunction()
