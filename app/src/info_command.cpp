// `lamina info SCENE`: what a scene needs before it is rendered (render/scene_statistics.h
// counts it): geometry counts, materials with their active lobes, lights, spectral data, and
// the memory the geometry and the film take.
#include <CLI/CLI.hpp>
#include <cstdio>

#include "lamina/render/render_memory.h"
#include "lamina/render/scene_statistics.h"
#include "lamina/scene/cloud_density.h"
#include "lamina/scene/colour_grid.h"
#include "lamina/scene/scene_description.h"

namespace lamina::app {

namespace {

// The sensor and the crop, where they differ from the defaults (film_response.h).
void printFilm(const render::FilmDesc& f) {
    if (f.crop)
        std::printf("crop: pixels [%d, %d) x [%d, %d) of the image (%dx%d written)\n", f.crop->x0,
                    f.crop->x1, f.crop->y0, f.crop->y1, f.crop->width(), f.crop->height());
    if (f.imagingRatio() != 1)
        std::printf("sensor: imaging ratio %g (exposure_time %g x iso %g / 100 x scale %g)\n",
                    f.imagingRatio(), f.exposureTime, f.iso, f.scale);
    if (f.whiteBalance > 0)
        std::printf("sensor: white balance %g K (daylight white -> Rec.709 white, Bradford)\n",
                    f.whiteBalance);
    if (f.maxComponentValue)
        std::printf(
            "sensor: clamp on (biased): every sample's CIE XYZ scaled to a largest "
            "component of at most %g\n",
            *f.maxComponentValue);
}

void run(const std::string& file) {
    const render::SceneDesc scene = render::loadScene(file);
    const render::SceneStatistics s = render::sceneStatistics(scene);
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
    printFilm(scene.film);
    std::printf("geometry: %zu meshes (%zu triangles, %zu vertices), %zu spheres, %zu disks, ",
                s.meshes, s.triangles, s.vertices, s.spheres, s.disks);
    // pbrt-v4's clipped quadrics, where the scene has any.
    if (s.partialSpheres + s.cylinders + s.partialDisks > 0)
        std::printf("%zu partial spheres, %zu cylinders, %zu partial disks, ", s.partialSpheres,
                    s.cylinders, s.partialDisks);
    if (s.curves > 0)
        std::printf("%zu curves (%zu segments, %zu control points), ", s.curves, s.curveSegments,
                    s.curvePoints);
    std::printf("~%.1f MiB\n", double(s.geometryBytes) / (1 << 20));
    if (!scene.objects.empty() || !scene.unusedObjectNames.empty()) {
        std::printf(
            "instances: %zu of %zu objects, referencing %zu triangles (%zu stored once in the "
            "objects)",
            s.instances, s.objects, s.instancedTriangles, s.objectTriangles);
        for (const auto& name : scene.unusedObjectNames)
            std::printf(", %s unused (never loaded)", name.c_str());
        std::printf("\n");
    }
    std::printf(
        "render memory: ~%s (film %s, image %s); with --aovs ~%s, bdpt --strategies ~%s\n",
        render::formatBytes(s.film.total()).c_str(), render::formatBytes(s.film.film).c_str(),
        render::formatBytes(s.film.output).c_str(), render::formatBytes(s.filmWithAovs).c_str(),
        render::formatBytes(s.filmWithStrategies).c_str());
    std::printf("lights: %zu emitting shape%s (sampled as %zu area light%s), %zu other light%s\n",
                s.emitters, s.emitters == 1 ? "" : "s", s.areaLights, s.areaLights == 1 ? "" : "s",
                s.lights, s.lights == 1 ? "" : "s");
    std::printf("materials:\n");
    for (const auto& m : s.materials)
        std::printf("  %s: %s; lobes: %s; polarised mode: %s%s\n", m.name.c_str(), m.type.c_str(),
                    m.lobes.c_str(), m.polarisation.c_str(), m.used ? "" : " (unused)");
    for (const auto& name : scene.unusedMaterialNames)
        std::printf("  %s: unused (never loaded)\n", name.c_str());
    std::printf("textures: %zu loaded", scene.textures.size());
    for (const auto& name : scene.unusedTextureNames)
        std::printf(", %s unused (never loaded)", name.c_str());
    std::printf("\n");
    // Only a scene with media prints the line: other scenes' output is as it was.
    if (scene.hasMedia()) {
        std::printf("media: %zu (docs/media.md)\n", scene.media.size());
        for (const render::MediumDesc& m : scene.media) {
            std::printf("  %s: %s, sigma_a [%g, %g, %g], sigma_s [%g, %g, %g], g %g%s",
                        m.name.c_str(), std::string(render::kMediumKindNames.name(m.kind)).c_str(),
                        m.sigmaA[0], m.sigmaA[1], m.sigmaA[2], m.sigmaS[0], m.sigmaS[1],
                        m.sigmaS[2], m.g, m.emits() ? ", emits" : "");
            if (m.grid && m.grid->colours)
                std::printf(
                    ", RGB grids sigma_a %d x %d x %d, sigma_s %d x %d x %d, majorants "
                    "%d x %d x %d",
                    m.grid->colours->sigmaA.nx, m.grid->colours->sigmaA.ny,
                    m.grid->colours->sigmaA.nz, m.grid->colours->sigmaS.nx,
                    m.grid->colours->sigmaS.ny, m.grid->colours->sigmaS.nz, m.grid->majorants.nx,
                    m.grid->majorants.ny, m.grid->majorants.nz);
            else if (m.grid && m.grid->cloud)
                std::printf(
                    ", procedural cloud (density %g, wispiness %g, frequency %g), "
                    "majorants %d x %d x %d",
                    double(m.grid->cloud->density), double(m.grid->cloud->wispiness),
                    double(m.grid->cloud->frequency), m.grid->majorants.nx, m.grid->majorants.ny,
                    m.grid->majorants.nz);
            else if (m.grid)
                std::printf(", density grid %d x %d x %d, majorants %d x %d x %d",
                            m.grid->density.nx, m.grid->density.ny, m.grid->density.nz,
                            m.grid->majorants.nx, m.grid->majorants.ny, m.grid->majorants.nz);
            std::printf("\n");
        }
    }
    std::printf("spectral data: %s\n", s.spectralData.empty() ? "none" : "");
    for (const auto& data : s.spectralData)
        std::printf("  %s\n", data.c_str());
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
