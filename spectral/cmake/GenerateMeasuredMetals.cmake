# Writes OUTPUT, a C++ source with the n, k tables of the measured metals (spectral/data/nk,
# one CSV per metal: "# comment" lines, a header "lambda_nm,n,k", then nm,n,k rows), for
# measured_metals.h. Run by the build (cmake -P) whenever a CSV changes.
# Arguments: -DDATA_DIR=... -DOUTPUT=...
file(GLOB csvs ${DATA_DIR}/*.csv)
list(SORT csvs)
set(body "")
set(entries "")
foreach(csv IN LISTS csvs)
  get_filename_component(stem ${csv} NAME_WE)      # Cu_JohnsonChristy1972
  string(REGEX REPLACE "_.*" "" metal ${stem})       # Cu
  string(REGEX REPLACE "^[^_]*_" "" source ${stem})  # JohnsonChristy1972
  file(STRINGS ${csv} lines)
  set(rows "")
  set(count 0)
  foreach(line IN LISTS lines)
    if(line MATCHES "^#" OR line MATCHES "^lambda" OR line STREQUAL "")
      continue()
    endif()
    if(NOT line MATCHES "^[0-9.eE+-]+,[0-9.eE+-]+,[0-9.eE+-]+$")
      message(FATAL_ERROR "${csv}: expected nm,n,k, found \"${line}\"")
    endif()
    string(REPLACE "," ", " row "${line}")
    string(APPEND rows "    {${row}},\n")
    math(EXPR count "${count} + 1")
  endforeach()
  string(APPEND body "constexpr MeasuredNk k${stem}[] = {\n${rows}};\n\n")
  string(APPEND entries "    {\"${metal}\", \"${source}\", k${stem}},\n")
endforeach()
file(WRITE ${OUTPUT}.tmp "// Generated from spectral/data/nk by spectral/cmake/GenerateMeasuredMetals.cmake.
#include \"measured_metals.h\"

namespace lamina {

namespace {

${body}const MeasuredMetal kMeasuredMetals[] = {
${entries}};

}  // namespace

std::span<const MeasuredMetal> measuredMetals() {
    return kMeasuredMetals;
}

}  // namespace lamina
")
execute_process(COMMAND ${CMAKE_COMMAND} -E copy_if_different ${OUTPUT}.tmp ${OUTPUT})
