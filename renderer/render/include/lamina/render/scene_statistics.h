// What a scene needs before it is rendered (`lamina info`): geometry counts and the memory the
// geometry takes, instancing, the film's memory, lights, the materials with their active lobes,
// and the spectral data the used materials read. Counted here; the command prints it.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "lamina/render/render_memory.h"
#include "lamina/scene/scene_description.h"

namespace lamina::render {

struct SceneStatistics {
    std::size_t meshes = 0, triangles = 0, vertices = 0, spheres = 0, disks = 0;
    /// pbrt-v4's clipped quadrics (QuadricDesc), by kind.
    std::size_t partialSpheres = 0, cylinders = 0, partialDisks = 0;
    /// Curves shapes, their strands' segments and control points.
    std::size_t curves = 0, curveSegments = 0, curvePoints = 0;
    /// The meshes' arrays (the scene's and the objects') and Embree's BVH, roughly.
    std::size_t geometryBytes = 0;
    /// Instancing: an object's shapes are stored once and its instances reference them.
    std::size_t instances = 0, objects = 0;
    std::size_t instancedTriangles = 0;                      ///< referenced by the instances
    std::size_t objectTriangles = 0;                         ///< stored in the objects
    RenderMemory film;                                       ///< the film at the scene's resolution
    std::uint64_t filmWithAovs = 0, filmWithStrategies = 0;  ///< totals
    /// Emitting shapes as the scene wrote them (a rectangle, a mesh, a sphere, a disk, a
    /// quadric: one each).
    std::size_t emitters = 0;
    /// The area lights the renderer samples for them: one per triangle of an emitting mesh,
    /// one for a rectangle (also a mesh of two triangles that form one), a sphere, a disk or a
    /// quadric.
    std::size_t areaLights = 0;
    std::size_t lights = 0;  ///< the other lights
    struct Material {
        std::string name;
        std::string type;
        std::string lobes;  ///< describeLobes of its BSDF built in RGB mode
        bool used = false;
        std::string polarisation;  ///< what the polarised mode makes of it (MaterialKind)
    };
    std::vector<Material> materials;
    /// The spectral data of the used materials: "Au (n, k)", "bk7 (dispersion)", ...
    std::vector<std::string> spectralData;
};

SceneStatistics sceneStatistics(const SceneDesc& scene);

}  // namespace lamina::render
