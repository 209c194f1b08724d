# Writes what would otherwise be central lists of lamina_bsdf, from marks in the files of each
# material type (docs/architecture.md, "A new material"), so that a new type edits no list:
#  - INSTANTIATIONS: a source file that compiles, once and optimised, every BSDF class template
#    a header marks with LAMINA_EXTERN_BSDF_VARIANTS(Class) and the builder of every description a
#    header marks with LAMINA_MATERIAL_MODEL(Model), in the four variants;
#  - KIND_LIST: the registrations (`extern const MaterialKind kName{...}`) of the reader files,
#    for material_kinds.cpp.
# Run as `cmake -P` at build time with HEADERS, READERS (;-separated lists, passed with | in place
# of ;), INSTANTIATIONS and KIND_LIST. A file is rewritten only when its text changes.

string(REPLACE "|" ";" headers "${HEADERS}")
string(REPLACE "|" ";" readers "${READERS}")
list(SORT headers)
list(SORT readers)

function(write_if_changed path text)
  if(EXISTS "${path}")
    file(READ "${path}" old)
    if(old STREQUAL text)
      return()
    endif()
  endif()
  file(WRITE "${path}" "${text}")
endfunction()

set(includes "")
set(classes "")
set(models "")
foreach(header IN LISTS headers)
  file(STRINGS "${header}" marks REGEX "^LAMINA_(EXTERN_BSDF_VARIANTS|MATERIAL_MODEL)\\([A-Za-z0-9_]+\\)$")
  if(marks)
    get_filename_component(name "${header}" NAME)
    string(APPEND includes "#include \"lamina/bsdf/${name}\"\n")
  endif()
  foreach(mark IN LISTS marks)
    string(REGEX REPLACE "^LAMINA_([A-Z_]+)\\(([A-Za-z0-9_]+)\\)$" "\\1;\\2" parts "${mark}")
    list(GET parts 0 kind)
    list(GET parts 1 type)
    if(kind STREQUAL "EXTERN_BSDF_VARIANTS")
      string(APPEND classes "LAMINA_INSTANTIATE_BSDF(${type})\n")
    else()
      string(APPEND models "LAMINA_INSTANTIATE_MATERIAL_MODEL(${type})\n")
    endif()
  endforeach()
endforeach()

write_if_changed("${INSTANTIATIONS}" "// Written by cmake/GenerateBsdfRegistry.cmake from the marks in bsdf/include: do not edit.
${includes}
namespace lamina {

#define LAMINA_INSTANTIATE_BSDF(Class)            \\
    template class Class<Rgb<float>>;             \\
    template class Class<Rgb<double>>;            \\
    template class Class<SampledSpectrum<float>>; \\
    template class Class<SampledSpectrum<double>>;

#define LAMINA_INSTANTIATE_MATERIAL_MODEL(Model)                                              \\
    template std::unique_ptr<Bxdf<Rgb<float>>> buildModel(const Model&,                        \\
                                                         const MaterialBuilder<Rgb<float>>&); \\
    template std::unique_ptr<Bxdf<Rgb<double>>> buildModel(const Model&,                       \\
                                                          const MaterialBuilder<Rgb<double>>&); \\
    template std::unique_ptr<Bxdf<SampledSpectrum<float>>> buildModel(                          \\
        const Model&, const MaterialBuilder<SampledSpectrum<float>>&);                          \\
    template std::unique_ptr<Bxdf<SampledSpectrum<double>>> buildModel(                         \\
        const Model&, const MaterialBuilder<SampledSpectrum<double>>&);

${classes}${models}
}  // namespace lamina
")

set(declarations "")
set(entries "")
foreach(reader IN LISTS readers)
  file(STRINGS "${reader}" lines REGEX "^extern const MaterialKind k[A-Za-z0-9_]+")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "^extern const MaterialKind (k[A-Za-z0-9_]+).*$" "\\1" kind "${line}")
    string(APPEND declarations "extern const MaterialKind ${kind};\n")
    string(APPEND entries "    &${kind},\n")
  endforeach()
endforeach()

write_if_changed("${KIND_LIST}" "// Written by cmake/GenerateBsdfRegistry.cmake from the reader files: do not edit.
${declarations}
namespace {

// In the order of the reader files' names; materialKinds() orders them by listPosition.
const MaterialKind* const kRegisteredMaterialKinds[] = {
${entries}};

}  // namespace
")
