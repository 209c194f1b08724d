# Cold code: code that runs once per input file or once per run (the scene and material readers,
# the importers, the reports, the command line, the Python bindings, the tests themselves), as
# opposed to the per-ray and per-sample code of the integrators, lights, BSDFs and film.
# In a Release build it compiles at -O1 instead of -O3. Optimisation was two thirds of the
# compile time of a typical reader (renderer/scene/src/shape_reader.cpp: 13.7 s of CPU at -O3,
# 8.7 s at -O1, GCC 12) and a clean build is what CI pays for on every run; a reader's run time
# is a scene's load time, which the optimisation level hardly moves. Floating-point results do
# not depend on the level (no -ffast-math, no FMA contraction without -march), so the hot code
# these files call computes the same numbers.
# Builds of other types (the sanitizer builds' RelWithDebInfo -O1, Debug) keep their own flags.

# lamina_cold_target(target): every file of target is cold.
function(lamina_cold_target target)
  target_compile_options(${target} PRIVATE $<$<CONFIG:Release>:-O1>)
endfunction()

# lamina_cold_sources(source... [TARGET target]): these files are cold; without TARGET they belong
# to a target defined in the calling directory, with it to `target` wherever it was defined (a
# room of lamina_render adds its sources from its own folder). The target's precompiled header
# stays valid (GCC and Clang accept a header built at another -O level, and -Winvalid-pch would
# say otherwise).
function(lamina_cold_sources)
  cmake_parse_arguments(arg "" "TARGET" "" ${ARGN})
  if(arg_TARGET)
    set_source_files_properties(${arg_UNPARSED_ARGUMENTS} TARGET_DIRECTORY ${arg_TARGET}
                                PROPERTIES COMPILE_OPTIONS $<$<CONFIG:Release>:-O1>)
  else()
    set_source_files_properties(${arg_UNPARSED_ARGUMENTS} DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}
                                PROPERTIES COMPILE_OPTIONS $<$<CONFIG:Release>:-O1>)
  endif()
endfunction()
