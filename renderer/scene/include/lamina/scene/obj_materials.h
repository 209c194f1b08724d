// The materials of an OBJ file: its `usemtl` groups and the MTL libraries its `mtllib` lines
// name (docs/scene-format.md, "OBJ materials"). An `obj` shape without a `material` reads
// them; each group becomes a mesh of its own with the material its MTL entry maps to:
//   Kd                       lambert (reflectance Kd)
//   Ks, Ns (Ks not black)    standard, specular workflow: base_color Kd, specular_color Ks,
//                            GGX alpha = sqrt(2 / (Ns + 2)) (the Blinn-Phong exponent whose
//                            lobe matches a Beckmann one of that alpha, Walter et al. 2007,
//                            "Microfacet Models for Refraction", section 5.2; used for GGX)
//   illum 4-7 or d < 1       dielectric (ior Ni, 1.5 when Ni is absent or 1)
//   map_Kd                   an image texture (relative to the MTL file) as the reflectance
//                            or base_color (Kd itself is then not applied)
//   Ke (not black)           emission Ke
// Other MTL keys are ignored with one warning per key naming the file and line.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "lamina/core/json_reader.h"
#include "lamina/scene/scene_description.h"

namespace lamina::render {

/// One `newmtl` entry, mapped to a lamina material.
struct MtlMaterial {
    std::string mtlName;         ///< as written after newmtl
    std::string name;            ///< "MTLFILE:NAME": the scene material's name
    std::filesystem::path file;  ///< the MTL file it is defined in
    int line = 0;                ///< the line of its newmtl
    Json material;               ///< a lamina material object
    /// map_Kd as written (relative to `file`'s directory), read as the texture `textureName`
    /// that `material` names.
    std::optional<std::string> diffuseMap;
    std::string textureName;
    std::optional<Rgb<double>> emission;  ///< Ke
};

/// An OBJ file's faces split by material, in the order the groups first appear.
struct ObjGroups {
    struct Group {
        int material = -1;  ///< index into `materials`; -1: the face names no known material
        MeshDesc mesh;
    };
    std::vector<Group> groups;
    std::vector<MtlMaterial> materials;
    std::vector<std::filesystem::path> libraries;  ///< the MTL files read
    std::vector<std::string> warnings;             ///< "FILE:LINE: ..." each
};

/// The materials of one MTL library's text (mtl_materials.cpp); what it ignores is appended to
/// `warnings`. InputErrors name `file` and the line.
std::vector<MtlMaterial> readMtlLibrary(const std::filesystem::path& file, const std::string& text,
                                        std::vector<std::string>& warnings);

/// Reads `file` with its MTL libraries. InputErrors name the file (OBJ or MTL), and for MTL
/// values the line: a missing library, a value out of range. An OBJ without `mtllib` is an
/// error (the shape must then name a material).
ObjGroups readObjGroups(const std::filesystem::path& file);

}  // namespace lamina::render
