#include "lamina/render/scene_statistics.h"

#include "lamina/bsdf/material_builder.h"
#include "lamina/bsdf/material_kind.h"
#include "lamina/lights/area_lights.h"

namespace lamina::render {

namespace {

template <typename Mesh>
std::size_t meshBytes(const Mesh& m) {
    return m.positions.size() * sizeof(m.positions[0]) + m.normals.size() * 12 + m.uvs.size() * 8 +
           m.triangles.size() * 12;
}

}  // namespace

SceneStatistics sceneStatistics(const SceneDesc& scene) {
    SceneStatistics s;
    s.meshes = countShapes<MeshDesc>(scene.shapes);
    s.spheres = countShapes<SphereDesc>(scene.shapes);
    s.disks = countShapes<DiskDesc>(scene.shapes);
    std::vector<bool> used(scene.materials.size(), false);
    for (const auto& shape : scene.shapes) {
        const SurfaceDesc& surface = render::surface(shape);
        if (!surface.isInterface()) used[std::size_t(surface.material)] = true;
        if (const auto* q = std::get_if<QuadricDesc>(&shape))
            ++(q->kind == Quadric::Sphere     ? s.partialSpheres
               : q->kind == Quadric::Cylinder ? s.cylinders
                                              : s.partialDisks);
        if (const auto* c = std::get_if<CurvesDesc>(&shape)) {
            ++s.curves;
            s.curveSegments += c->segments.size();
            s.curvePoints += c->points.size();
            s.geometryBytes += c->points.size() * 20 + c->segments.size() * 4;
        }
        if (const auto* m = std::get_if<MeshDesc>(&shape)) {
            s.triangles += m->triangles.size();
            s.vertices += m->positions.size();
            s.geometryBytes += meshBytes(*m);
            if (m->emission) {
                ++s.emitters;
                s.areaLights += RectangleLight::isRectangle(*m) ? 1 : m->triangles.size();
            }
        } else if (surface.emission) {
            ++s.emitters;
            ++s.areaLights;
        }
    }
    std::size_t objectPrimitives = 0;
    std::vector<std::size_t> trianglesOf(scene.objects.size(), 0);
    for (std::size_t o = 0; o < scene.objects.size(); ++o) {
        const ObjectDesc& object = scene.objects[o];
        for (const auto& shape : object.shapes) {
            if (!render::surface(shape).isInterface())
                used[std::size_t(render::surface(shape).material)] = true;
            if (const auto* m = std::get_if<MeshDesc>(&shape)) {
                trianglesOf[o] += m->triangles.size();
                s.geometryBytes += meshBytes(*m);
            }
        }
        s.objectTriangles += trianglesOf[o];
        objectPrimitives += trianglesOf[o] + countShapes<SphereDesc>(object.shapes) +
                            countShapes<DiskDesc>(object.shapes) +
                            countShapes<QuadricDesc>(object.shapes) +
                            countShapes<CurvesDesc>(object.shapes);
    }
    s.objects = scene.objects.size();
    s.instances = scene.instances.size();
    for (const auto& inst : scene.instances)
        s.instancedTriangles += trianglesOf[std::size_t(inst.object)];
    // Embree's BVH over triangles takes roughly 64 bytes per primitive (a rough guide), and
    // an instance about as much as one primitive.
    s.geometryBytes += (s.triangles + s.spheres + s.partialSpheres + s.cylinders + s.partialDisks +
                        s.curveSegments + objectPrimitives + scene.instances.size()) *
                       64;
    // A crop is the film that is allocated and written.
    const int w = scene.film.crop ? scene.film.crop->width() : scene.film.width;
    const int h = scene.film.crop ? scene.film.crop->height() : scene.film.height;
    s.film = estimateRenderMemory(w, h, false, false);
    s.filmWithAovs = estimateRenderMemory(w, h, true, false).total();
    s.filmWithStrategies = estimateRenderMemory(w, h, false, true).total();
    s.lights = scene.lights.size();
    const SpectrumContext<Rgb<float>> context;
    for (std::size_t i = 0; i < scene.materials.size(); ++i) {
        const auto bsdf = buildBxdf(scene.materials[i], context);
        const MaterialKind* kind = findMaterialKind(scene.materials[i].type);
        s.materials.push_back({scene.materialNames[i], scene.materials[i].type,
                               describeLobes(bsdf->flags()), used[i],
                               kind ? std::string(kind->polarisation) : std::string()});
        if (used[i]) collectSpectralData(scene.materials[i], s.spectralData);
    }
    return s;
}

}  // namespace lamina::render
