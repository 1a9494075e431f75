# Precompiled headers (option STC_PRECOMPILED_HEADERS): the third-party and standard headers that
# most translation units parse, Eigen's dense and sparse cores above all, compiled once per target
# instead of once per file. The code compiled is the same; a clean Release build takes 15 % less
# wall time on 2 cores (docs/changelog.md, "Unreleased"). The project's own headers stay out, so that
# editing one recompiles only the files that include it.
#
# GCC 12 loses the system-header status of what comes from a precompiled header, and then reports
# its known false positives in libstdc++'s string code (-Warray-bounds, -Wstringop-overflow,
# -Wstringop-overread, which a plain build keeps quiet as coming from a system header); with
# precompiled headers these three are off. The warnings-as-errors build, which is where warnings
# are checked, compiles without precompiled headers and keeps them.
if(STC_WARNINGS_AS_ERRORS)
  set(stc_pch_default OFF)
else()
  set(stc_pch_default ON)
endif()
option(STC_PRECOMPILED_HEADERS "Precompile Eigen's and the standard library's common headers"
       ${stc_pch_default})

set(STC_PCH_HEADERS <Eigen/Core> <Eigen/SparseCore> <algorithm> <cmath> <limits> <map> <memory>
                    <optional> <sstream> <stdexcept> <string> <utility> <vector>)

# stc_pch_warning_options(TARGET): the three warnings above off for GCC.
function(stc_pch_warning_options target)
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    target_compile_options(${target} PRIVATE -Wno-array-bounds -Wno-stringop-overflow
                         -Wno-stringop-overread)
  endif()
endfunction()

# stc_precompile_headers(TARGET): TARGET's files start from STC_PCH_HEADERS. The libraries and the
# program compile with one set of flags, so they share the core's precompiled header (a header of
# their own cost each library, strategies' one file included, about 8 s of one core before its
# first file); the Python module, compiled position-independent and with hidden symbols, precompiles
# its own.
function(stc_precompile_headers target)
  if(NOT STC_PRECOMPILED_HEADERS)
    return()
  endif()
  if(target STREQUAL "stcontact_core" OR target STREQUAL "stcontact_python")
    target_precompile_headers(${target} PRIVATE ${STC_PCH_HEADERS})
  else()
    target_precompile_headers(${target} REUSE_FROM stcontact_core)
  endif()
  stc_pch_warning_options(${target})
endfunction()

# stc_precompile_test_headers(TARGET...): the same with GoogleTest added, for the test programs;
# they share one compile line, so the first one's header serves the others.
function(stc_precompile_test_headers first)
  if(NOT STC_PRECOMPILED_HEADERS)
    return()
  endif()
  target_precompile_headers(${first} PRIVATE ${STC_PCH_HEADERS} <gtest/gtest.h>)
  foreach(target IN LISTS first ARGN)
    if(NOT target STREQUAL first)
      target_precompile_headers(${target} REUSE_FROM ${first})
    endif()
    stc_pch_warning_options(${target})
  endforeach()
endfunction()
