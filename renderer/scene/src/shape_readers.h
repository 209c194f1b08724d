// The readers of an entry of "shapes", private to lamina_scene: shape_reader.cpp reads the
// type, instances and objects; analytic_shape_reader.cpp the spheres, disks and cylinders;
// mesh_shape_reader.cpp the triangle meshes.
#pragma once

#include <string>
#include <vector>

#include "lamina/scene/scene_readers.h"

namespace lamina::render {

/// Where a shape's descriptions go: the scene's shapes or an object's (in reading order;
/// the loader orders them by kind at the end, orderShapesByKind), and where what a reader
/// maps to something else is said (SceneDesc::importWarnings).
struct ShapeDestination {
    std::vector<ShapeDesc>& shapes;
    std::vector<std::string>& warnings;
};

/// A shape's "alpha": a number in [0, 1] or {"texture": "name"} (its first channel).
AlphaDesc readAlpha(const JsonReader& r, SceneMaterials& materials);

/// A `sphere`, `disk` or `cylinder` named `name`: a SphereDesc or DiskDesc when whole, else a
/// QuadricDesc (every cylinder).
ShapeDesc readSphere(const JsonReader& r, const std::string& name, SceneMaterials& materials);
ShapeDesc readDisk(const JsonReader& r, const std::string& name, SceneMaterials& materials);
ShapeDesc readCylinder(const JsonReader& r, const std::string& name, SceneMaterials& materials);

/// A `curves` shape named `name` (curves_shape_reader.cpp).
ShapeDesc readCurves(const JsonReader& r, const std::string& name, SceneMaterials& materials);

/// A triangle-mesh shape (`mesh`, `rectangle`, `obj`, `ply`) named `name`: one MeshDesc, or
/// for an `obj` without a `material` one per usemtl group (obj_materials.h).
void readMeshShape(const JsonReader& r, ShapeKind kind, const std::string& name,
                   SceneMaterials& materials, const ShapeDestination& to);

}  // namespace lamina::render
