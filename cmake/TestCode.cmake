# How the GoogleTest executables' own sources are compiled: faster to build, with the same checks.
# Only the tests' own files: the library, the platform, the tools and the tests' reference code
# (tests/support, the long-double oracle) keep the flags they ship or run with.
#
# - -O1 in the optimised builds (Release, and the sanitizer build's RelWithDebInfo): the test
#   bodies set up inputs and compare answers; most of the work they check runs in the libraries
#   (header-only kernels a test includes, such as kernel/segment_hits.h, are compiled at -O1 here
#   and at the library's level where the library uses them). -O1 took a third off each test file's
#   compile (GCC 12: hard_cases_test.cpp 4.9 s -> 3.2 s, lidar_test.cpp 6.7 s -> 4.7 s). It changes
#   no answer: without -ffast-math and with -ffp-contract=off (set here as in revolve_internal)
#   every optimisation level computes the same IEEE results.
# - A precompiled <gtest/gtest.h> (and <gmock/gmock.h> where every file includes it) in targets of
#   three or more files: parsing GoogleTest cost about 1.4 s a file. Only files that include
#   GoogleTest themselves get it. It is included before a file's first line, so a project header
#   the file includes first sees GoogleTest's standard headers: the sanitizer build of
#   scripts/test.sh turns precompiled headers off (CMAKE_DISABLE_PRECOMPILE_HEADERS), so that a
#   header missing an #include still fails to compile there.
# The choice of files reads their #include lines when CMake configures; editing them configures again.
function(revolve_test_code target)
  target_compile_options(${target} PRIVATE $<$<CONFIG:Release,RelWithDebInfo,MinSizeRel>:-O1> -ffp-contract=off)

  get_target_property(sources ${target} SOURCES)
  get_target_property(source_dir ${target} SOURCE_DIR)
  set(with_gtest "")
  set(all_gmock TRUE)
  foreach(source ${sources})
    cmake_path(ABSOLUTE_PATH source BASE_DIRECTORY ${source_dir})
    if(NOT source MATCHES "\\.cpp$")
      continue()
    endif()
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${source})
    file(STRINGS ${source} includes REGEX "^#include <g(test/gtest|mock/gmock)\\.h>")
    if(includes)
      list(APPEND with_gtest ${source})
      if(NOT includes MATCHES "gmock/gmock.h")
        set(all_gmock FALSE)
      endif()
    else()
      set_source_files_properties(${source} TARGET_DIRECTORY ${target} PROPERTIES SKIP_PRECOMPILE_HEADERS ON)
    endif()
  endforeach()
  list(LENGTH with_gtest files)
  if(files GREATER_EQUAL 3)
    if(all_gmock)
      target_precompile_headers(${target} PRIVATE <gmock/gmock.h> <gtest/gtest.h>)
    else()
      target_precompile_headers(${target} PRIVATE <gtest/gtest.h>)
    endif()
  endif()
endfunction()
