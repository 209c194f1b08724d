// Scene files (docs/scene-format.md) -> SceneDesc, validated, with every error naming the file
// and the JSON path. The parts of the file are read by the units of scene_readers.h.
#include <iostream>

#include "lamina/core/printable.h"
#include "lamina/interchange/scene_import.h"
#include "lamina/scene/scene_readers.h"

namespace lamina::render {

namespace {

SceneDesc readScene(const Json& json, const JsonSource& source) {
    const JsonReader root(json, "", source);
    root.expectObject();
    SceneDesc scene;
    scene.file = source.name;
    // Media first: the camera and the shapes name them.
    if (const auto m = root.optionalChild("media")) readMedia(*m, scene);
    if (const auto c = root.optionalChild("camera"))
        scene.camera = readCamera(*c, scene.media, scene.importWarnings);
    if (const auto f = root.optionalChild("film")) scene.film = readFilm(*f);
    if (const auto i = root.optionalChild("integrator")) readIntegrator(*i, scene.settings);
    if (const auto s = root.optionalChild("sampler")) readSampler(*s, scene.settings);
    SceneMaterials materials(scene);
    if (const auto t = root.optionalChild("textures")) materials.defineTextures(*t);
    if (const auto m = root.optionalChild("materials")) materials.define(*m);
    SceneObjects objects(scene, materials);
    if (const auto o = root.optionalChild("objects")) objects.define(*o);
    if (const auto s = root.optionalChild("shapes")) {
        if (!s->value().is_array()) s->fail("expected an array of shapes");
        for (std::size_t i = 0; i < s->value().size(); ++i)
            readShape(JsonReader(s->value()[i], s->indexPath(i), source), materials, objects,
                      scene);
        orderShapesByKind(scene.shapes);
    }
    if (const auto l = root.optionalChild("lights")) {
        if (!l->value().is_array()) l->fail("expected an array of lights");
        for (std::size_t i = 0; i < l->value().size(); ++i)
            scene.lights.push_back(readLight(JsonReader(l->value()[i], l->indexPath(i), source)));
    }
    root.finish();
    materials.recordUnused();
    objects.recordUnused();
    bool emitter = !scene.lights.empty();
    for (const ShapeDesc& shape : scene.shapes)
        emitter |= surface(shape).emission.has_value();
    // An emitting medium lights a scene too (every integrator renders it: docs/media.md).
    for (const MediumDesc& m : scene.media)
        emitter |= m.emits();
    if (!emitter)
        root.fail("the scene has no light: add an emitting shape, a light or an emitting medium");
    return scene;
}

void printWarnings(const SceneDesc& scene) {
    for (const std::string& warning : scene.importWarnings)
        std::cerr << "lamina: warning: " << escapeControl(warning) << "\n";
}

}  // namespace

SceneDesc parseScene(const std::string& text, const JsonSource& source) {
    const Json root = parseJsonText(text, source);
    std::vector<std::filesystem::path> read;
    JsonSource recording = source;
    recording.readFiles = &read;
    SceneDesc scene = readScene(root, recording);
    scene.inputFiles = std::move(read);
    return scene;
}

SceneDesc loadScene(const std::filesystem::path& file, bool print) {
    if (detectSceneFormat(file) != SceneFormat::Lamina) {
        // A scene named without a directory ("scene.pbrt") is relative to the working one.
        const std::filesystem::path directory =
            file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
        ImportedScene imported = importScene(file, directory);
        std::vector<std::filesystem::path> read = std::move(imported.inputFiles);
        // Errors in the translated document name the file and the path in the document that
        // `lamina convert` writes, which is where a user can look them up.
        const JsonSource source{file.string() + " (translated)", directory, &read};
        SceneDesc scene = readScene(imported.scene, source);
        scene.file = file;
        scene.format = imported.format;
        scene.inputFiles = std::move(read);
        // The translation's warnings first, then the loader's own (an OBJ's MTL library).
        scene.importWarnings.insert(scene.importWarnings.begin(), imported.warnings.begin(),
                                    imported.warnings.end());
        if (print) printWarnings(scene);
        return scene;
    }
    const Json root = readJsonFile(file);
    std::vector<std::filesystem::path> read{file};
    const JsonSource source{file.string(), file.parent_path(), &read};
    SceneDesc scene = readScene(root, source);
    scene.inputFiles = std::move(read);
    if (print) printWarnings(scene);
    return scene;
}

}  // namespace lamina::render
