// `lamina info SCENE`: what a scene needs before it is rendered: geometry counts, materials
// with their active lobes, lights, spectral data, and the memory the geometry takes.
#include <CLI/CLI.hpp>
#include <cstdio>

#include "lamina/bsdf/material_builder.h"
#include "lamina/render/render_memory.h"
#include "lamina/scene/scene_description.h"

namespace lamina::app {

namespace {

void collectSpectral(const MaterialDesc& m, std::vector<std::string>& out) {
    if (const auto* c = std::get_if<ConductorMaterial>(&m.model))
        if (c->optics.spectrum) out.push_back(c->optics.spectrum->name() + " (n, k)");
    if (const auto* d = std::get_if<DielectricMaterial>(&m.model))
        if (d->spectrum) out.push_back(d->spectrum->name() + " (dispersion)");
    if (const auto* t = std::get_if<ThinDielectricMaterial>(&m.model))
        if (t->spectrum) out.push_back(t->spectrum->name() + " (index per wavelength)");
    if (const auto* x = std::get_if<MixMaterial>(&m.model)) {
        collectSpectral(*x->a, out);
        collectSpectral(*x->b, out);
    }
    if (const auto* c = std::get_if<CoatedMaterial>(&m.model)) collectSpectral(*c->base, out);
}

void run(const std::string& file) {
    const render::SceneDesc scene = render::loadScene(file);
    std::size_t triangles = 0, vertices = 0, bytes = 0, emitters = 0;
    std::vector<bool> used(scene.materials.size(), false);
    for (const auto& shape : scene.shapes) {
        const render::SurfaceDesc& surface = render::surface(shape);
        used[std::size_t(surface.material)] = true;
        if (const auto* m = std::get_if<render::MeshDesc>(&shape)) {
            triangles += m->triangles.size();
            vertices += m->positions.size();
            bytes += m->positions.size() * sizeof(m->positions[0]) + m->normals.size() * 12 +
                     m->uvs.size() * 8 + m->triangles.size() * 12;
            if (m->emission) emitters += m->triangles.size();
        } else if (surface.emission) {
            ++emitters;
        }
    }
    const std::size_t meshes = render::countShapes<render::MeshDesc>(scene.shapes),
                      spheres = render::countShapes<render::SphereDesc>(scene.shapes),
                      disks = render::countShapes<render::DiskDesc>(scene.shapes);
    // An object's shapes are stored once; its instances reference them (no copies).
    std::size_t objectTriangles = 0, objectPrimitives = 0, instancedTriangles = 0;
    std::vector<std::size_t> trianglesOf(scene.objects.size(), 0);
    for (std::size_t o = 0; o < scene.objects.size(); ++o) {
        const render::ObjectDesc& object = scene.objects[o];
        for (const auto& shape : object.shapes) {
            used[std::size_t(render::surface(shape).material)] = true;
            if (const auto* m = std::get_if<render::MeshDesc>(&shape)) {
                trianglesOf[o] += m->triangles.size();
                bytes += m->positions.size() * sizeof(m->positions[0]) + m->normals.size() * 12 +
                         m->uvs.size() * 8 + m->triangles.size() * 12;
            }
        }
        objectTriangles += trianglesOf[o];
        objectPrimitives += trianglesOf[o] +
                            render::countShapes<render::SphereDesc>(object.shapes) +
                            render::countShapes<render::DiskDesc>(object.shapes);
    }
    for (const auto& inst : scene.instances)
        instancedTriangles += trianglesOf[std::size_t(inst.object)];
    // Embree's BVH over triangles takes roughly 64 bytes per primitive (a rough guide), and
    // an instance about as much as one primitive.
    bytes += (triangles + spheres + objectPrimitives + scene.instances.size()) * 64;
    std::printf("scene: %s\n", file.c_str());
    // The loader has printed each warning on stderr already ("lamina: warning: ..."); the
    // listing counts them rather than repeating them.
    if (scene.format != render::SceneFormat::Lamina)
        std::printf(
            "format: %s, translated with %zu warnings (`lamina convert` writes the "
            "translation)\n",
            std::string(render::kSceneFormatNames.name(scene.format)).c_str(),
            scene.importWarnings.size());
    else if (!scene.importWarnings.empty())
        std::printf("warnings: %zu (an OBJ's materials: what was mapped or ignored)\n",
                    scene.importWarnings.size());
    std::printf("image: %dx%d, %d spp, max depth %d, %s sampler, seed %llu\n", scene.film.width,
                scene.film.height, scene.settings.spp, scene.settings.maxDepth,
                std::string(render::kSamplerNames.name(scene.settings.sampler)).c_str(),
                static_cast<unsigned long long>(scene.settings.seed));
    std::printf(
        "geometry: %zu meshes (%zu triangles, %zu vertices), %zu spheres, %zu disks, "
        "~%.1f MiB\n",
        meshes, triangles, vertices, spheres, disks, double(bytes) / (1 << 20));
    if (!scene.objects.empty() || !scene.unusedObjectNames.empty()) {
        std::printf(
            "instances: %zu of %zu objects, referencing %zu triangles (%zu stored once in the "
            "objects)",
            scene.instances.size(), scene.objects.size(), instancedTriangles, objectTriangles);
        for (const auto& name : scene.unusedObjectNames)
            std::printf(", %s unused (never loaded)", name.c_str());
        std::printf("\n");
    }
    const auto film =
        render::estimateRenderMemory(scene.film.width, scene.film.height, false, false);
    std::printf(
        "render memory: ~%s (film %s, image %s); with --aovs ~%s, bdpt --strategies ~%s\n",
        render::formatBytes(film.total()).c_str(), render::formatBytes(film.film).c_str(),
        render::formatBytes(film.output).c_str(),
        render::formatBytes(
            render::estimateRenderMemory(scene.film.width, scene.film.height, true, false).total())
            .c_str(),
        render::formatBytes(
            render::estimateRenderMemory(scene.film.width, scene.film.height, false, true).total())
            .c_str());
    std::printf("lights: %zu emitting primitives, %zu other lights\n", emitters,
                scene.lights.size());
    std::printf("materials:\n");
    std::vector<std::string> spectral;
    const SpectrumContext<Rgb<float>> context;
    for (std::size_t i = 0; i < scene.materials.size(); ++i) {
        const auto bsdf = buildBxdf(scene.materials[i], context);
        std::printf("  %s: %s; lobes: %s%s\n", scene.materialNames[i].c_str(),
                    scene.materials[i].type.c_str(), describeLobes(bsdf->flags()).c_str(),
                    used[i] ? "" : " (unused)");
        if (used[i]) collectSpectral(scene.materials[i], spectral);
    }
    for (const auto& name : scene.unusedMaterialNames)
        std::printf("  %s: unused (never loaded)\n", name.c_str());
    std::printf("textures: %zu loaded", scene.textures.size());
    for (const auto& name : scene.unusedTextureNames)
        std::printf(", %s unused (never loaded)", name.c_str());
    std::printf("\n");
    std::printf("spectral data: %s\n", spectral.empty() ? "none" : "");
    for (const auto& s : spectral)
        std::printf("  %s\n", s.c_str());
}

}  // namespace

void registerInfoCommand(CLI::App& app) {
    auto file = std::make_shared<std::string>();
    CLI::App* cmd = app.add_subcommand("info",
                                       "Print what a scene needs: geometry, materials "
                                       "and their lobes, lights, spectral data, memory");
    cmd->add_option("scene", *file, "Scene file")->required()->check(CLI::ExistingFile);
    cmd->callback([file] { run(*file); });
}

}  // namespace lamina::app
