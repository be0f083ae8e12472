# Precompiled headers. Nearly every TideSPH source includes Eigen and a common set of standard
# headers; parsing them took about 3 s of the 4-5 s that a small source costs at -O3 (about 1.4
# of them for <Eigen/Core> alone), times some 130 sources, in each of the three builds of CI.
# Only headers from outside the project are precompiled, so that editing a TideSPH header does
# not rebuild more than it did without them. TIDE_PRECOMPILE_HEADERS=OFF turns them off, e.g. to
# check that every source includes what it uses.
option(TIDE_PRECOMPILE_HEADERS "Precompile the external headers every target includes" ON)
# The test executables alone (GoogleTest's header is the largest they parse): CI's single-precision
# build keeps the libraries, apps and tools without precompiled headers, so that they are checked
# for what they include, and the tests with them.
option(TIDE_PRECOMPILE_TEST_HEADERS "Precompile them for the test executables (default: TIDE_PRECOMPILE_HEADERS)"
       ${TIDE_PRECOMPILE_HEADERS})

set(TIDE_PRECOMPILED_HEADERS
  <Eigen/Core>
  <algorithm>
  <array>
  <cmath>
  <cstddef>
  <cstdint>
  <filesystem>
  <functional>
  <memory>
  <optional>
  <span>
  <string>
  <string_view>
  <utility>
  <variant>
  <vector>)

# tide_precompile_headers(target [TEST] [REUSE_FROM other] [EXTRA headers...]): gives target the
# precompiled headers (with EXTRA ones, e.g. GoogleTest's), its own or those of `other`, which
# must be compiled with the same flags (the test executables share one). TEST: a test executable,
# which follows TIDE_PRECOMPILE_TEST_HEADERS.
function(tide_precompile_headers target)
  cmake_parse_arguments(PARSE_ARGV 1 pch "TEST" "REUSE_FROM" "EXTRA")
  if(pch_TEST)
    if(NOT TIDE_PRECOMPILE_TEST_HEADERS)
      return()
    endif()
    if(NOT TIDE_PRECOMPILE_HEADERS)
      target_link_libraries(${target} PRIVATE tide_precompiled_header_warnings)
    endif()
  elseif(NOT TIDE_PRECOMPILE_HEADERS)
    return()
  endif()
  if(pch_REUSE_FROM)
    target_precompile_headers(${target} REUSE_FROM ${pch_REUSE_FROM})
  else()
    target_precompile_headers(${target} PRIVATE ${TIDE_PRECOMPILED_HEADERS} ${pch_EXTRA})
  endif()
endfunction()

# GCC 12 reads its own std::string code from a precompiled header as if it were not a system
# header when it warns after inlining: -Warray-bounds and -Wstringop-overread then report the
# library's known false positives (a memcpy "out of the bounds" of a moved std::string, e.g. in
# push_back of a scene::Obstacle), which the same file compiled without the precompiled header
# does not. The targets with precompiled headers leave those two warnings out; CI's
# single-precision build compiles every file but the tests' without them and keeps them
# (scripts/check.sh).
add_library(tide_precompiled_header_warnings INTERFACE)
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  target_compile_options(tide_precompiled_header_warnings INTERFACE -Wno-array-bounds -Wno-stringop-overread)
endif()
if(TIDE_PRECOMPILE_HEADERS)
  target_link_libraries(tide_warnings INTERFACE tide_precompiled_header_warnings)
endif()
