# Precompiled headers for lamina's targets: the standard library, glm (through
# lamina/core/vector.h) and a target's own heavy third-party headers. Parsing them was most of the
# compile time of a typical file (renderer/lights/src/point_lights.cpp: 2.3 s without, 0.7 s
# with), and a clean build is what CI pays for on every run.
#
# Off by default when a compiler launcher (ccache) is set: ccache caches nothing that uses a
# precompiled header unless its sloppiness settings are changed, and a developer's build with
# it stays the one that catches a file's missing #include.
if(CMAKE_CXX_COMPILER_LAUNCHER)
  set(lamina_pch_default OFF)
else()
  set(lamina_pch_default ON)
endif()
option(LAMINA_PRECOMPILE_HEADERS "Precompile the standard library, glm, GoogleTest and CLI11 headers"
       ${lamina_pch_default})

set(LAMINA_PCH_HEADERS
    <algorithm> <array> <cmath> <cstddef> <cstdint> <filesystem> <functional> <limits> <map>
    <memory> <optional> <ostream> <set> <sstream> <string> <string_view> <utility> <variant>
    <vector> "${PROJECT_SOURCE_DIR}/core/include/lamina/core/vector.h")

# lamina_precompile_headers(target [HEADERS header...] [REUSE_FROM owner]): the common set plus
# the target's own heavy third-party headers (GoogleTest for the tests, CLI11 for the command);
# or the header precompiled for owner, a target compiled with the same flags and definitions
# (the static libraries share lamina_core's, the test binaries lamina_unit_tests'): building a
# header once per target cost as much as a dozen source files each time.
function(lamina_precompile_headers target)
  if(NOT LAMINA_PRECOMPILE_HEADERS)
    return()
  endif()
  cmake_parse_arguments(arg "" "REUSE_FROM" "HEADERS" ${ARGN})
  if(arg_REUSE_FROM)
    target_precompile_headers(${target} REUSE_FROM ${arg_REUSE_FROM})
  else()
    target_precompile_headers(${target} PRIVATE ${LAMINA_PCH_HEADERS} ${arg_HEADERS})
  endif()
endfunction()
