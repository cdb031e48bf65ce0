# Compiler flags shared by every covsim target.
# -ffp-contract=off keeps a*b+c from being fused differently by different builds, so
# results and fingerprints are bit-identical across optimisation levels; never -ffast-math.
find_program(CCACHE_PROGRAM ccache)
if(CCACHE_PROGRAM)
  set(CMAKE_CXX_COMPILER_LAUNCHER "${CCACHE_PROGRAM}")
endif()

set(CMAKE_CXX_FLAGS_RELEASE "-O2 -DNDEBUG")
set(CMAKE_CXX_FLAGS_RELWITHDEBINFO "-O2 -g")
if(COVSIM_SANITIZE)
  # Sanitizer reports need file and line, not variables: line tables and -O1 compile in about
  # half the time of -O2 -g, and -O1 is what the sanitizers' own documentation recommends.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    set(CMAKE_CXX_FLAGS_RELWITHDEBINFO "-O1 -gline-tables-only")
  else()
    set(CMAKE_CXX_FLAGS_RELWITHDEBINFO "-O1 -g1")
  endif()
endif()

add_library(covsim_flags INTERFACE)
add_library(covsim::flags ALIAS covsim_flags)
set_target_properties(covsim_flags PROPERTIES EXPORT_NAME flags)
target_compile_features(covsim_flags INTERFACE cxx_std_20)
# Warnings are for covsim's own code: a user building against the installed package gets
# only what determinism needs.
target_compile_options(covsim_flags INTERFACE
  $<BUILD_INTERFACE:-Wall -Wextra -Wpedantic> -ffp-contract=off -fno-fast-math)
if(COVSIM_SANITIZE)
  target_compile_options(covsim_flags INTERFACE -fsanitize=address,undefined
                                                -fno-sanitize-recover=all -fno-omit-frame-pointer)
  # One shared sanitizer runtime for the programs, the tests and the Python module: the
  # interpreter, not built with the sanitizers, loads it first (LD_PRELOAD, COVSIM_ASAN_RUNTIME)
  # and the programs that Python tests start use the same one. GCC links it shared already.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    # The runtime's name: per architecture (clang 14), or in a per-target folder (newer).
    foreach(name libclang_rt.asan-${CMAKE_SYSTEM_PROCESSOR}.so libclang_rt.asan.so)
      execute_process(COMMAND ${CMAKE_CXX_COMPILER} -print-file-name=${name}
                      OUTPUT_VARIABLE COVSIM_ASAN_RUNTIME OUTPUT_STRIP_TRAILING_WHITESPACE)
      if(IS_ABSOLUTE "${COVSIM_ASAN_RUNTIME}" AND EXISTS "${COVSIM_ASAN_RUNTIME}")
        break()
      endif()
    endforeach()
    if(NOT IS_ABSOLUTE "${COVSIM_ASAN_RUNTIME}" OR NOT EXISTS "${COVSIM_ASAN_RUNTIME}")
      message(FATAL_ERROR "COVSIM_SANITIZE: ${CMAKE_CXX_COMPILER} names no shared ASan runtime "
                          "(libclang_rt.asan*.so), which the Python module and the programs share")
    endif()
    get_filename_component(covsim_asan_dir ${COVSIM_ASAN_RUNTIME} DIRECTORY)
    # A target with COVSIM_STATIC_ASAN (the libFuzzer targets, whose runtime must come first)
    # keeps clang's static runtime.
    set(covsim_shared_asan "$<NOT:$<BOOL:$<TARGET_PROPERTY:COVSIM_STATIC_ASAN>>>")
    target_link_options(covsim_flags INTERFACE -fsanitize=address,undefined
                        "$<${covsim_shared_asan}:-shared-libasan;-Wl,-rpath,${covsim_asan_dir}>")
  else()
    execute_process(COMMAND ${CMAKE_CXX_COMPILER} -print-file-name=libasan.so
                    OUTPUT_VARIABLE COVSIM_ASAN_RUNTIME OUTPUT_STRIP_TRAILING_WHITESPACE)
    target_link_options(covsim_flags INTERFACE -fsanitize=address,undefined)
  endif()
endif()
