// Scene files (docs/scene-format.md) -> SceneDesc, validated, with every error naming the file
// and the JSON path.
#include <tiny_obj_loader.h>
#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>
#include <map>

#include "lamina/bsdf/phong.h"
#include "lamina/render/ply_reader.h"
#include "lamina/render/scene_description.h"

namespace lamina::render {

namespace {

using Mat4 = glm::dmat4;

Vec3d toVec(const std::array<double, 3>& a) {
    return {a[0], a[1], a[2]};
}

Vec3d readVec(const JsonReader& r, const std::string& key, Vec3d def) {
    if (!r.has(key)) return def;
    return toVec(r.requiredArray<3>(key));
}

// "transform": a list of operations applied in order (the first one first):
// {"translate": [x, y, z]}, {"scale": s | [x, y, z]}, {"rotate": {"axis": [x, y, z],
// "angle": degrees}}, {"matrix": [16 numbers, row-major]}.
Mat4 readTransform(const JsonReader& parent) {
    Mat4 m(1.0);
    const auto t = parent.optionalChild("transform");
    if (!t) return m;
    if (!t->value().is_array()) t->fail("expected an array of operations");
    for (std::size_t i = 0; i < t->value().size(); ++i) {
        const JsonReader op(t->value()[i], t->indexPath(i), t->source());
        op.expectObject();
        if (op.value().size() != 1)
            op.fail("expected one operation: translate, scale, rotate or matrix");
        Mat4 step(1.0);
        if (op.has("translate")) {
            step = glm::translate(Mat4(1.0), toVec(op.requiredArray<3>("translate")));
        } else if (op.has("scale")) {
            const auto s = op.optionalTriple("scale");
            if ((*s)[0] == 0 || (*s)[1] == 0 || (*s)[2] == 0)
                op.failAt("scale", "a scale of 0 collapses the shape");
            step = glm::scale(Mat4(1.0), toVec(*s));
        } else if (op.has("rotate")) {
            const JsonReader rot = op.child("rotate");
            const Vec3d axis = toVec(rot.requiredArray<3>("axis"));
            if (glm::length(axis) == 0) rot.failAt("axis", "expected a non-zero axis");
            const double angle = rot.requiredNumber("angle");
            rot.finish();
            step = glm::rotate(Mat4(1.0), glm::radians(angle), glm::normalize(axis));
        } else if (op.has("matrix")) {
            const auto a = op.requiredArray<16>("matrix");
            for (int row = 0; row < 4; ++row)
                for (int col = 0; col < 4; ++col)
                    step[col][row] = a[std::size_t(row * 4 + col)];  // glm is column-major
            if (std::abs(glm::determinant(step)) < 1e-300) op.failAt("matrix", "is singular");
        } else {
            op.fail("expected one of translate, scale, rotate, matrix");
        }
        op.finish();
        m = step * m;
    }
    return m;
}

class SceneParser {
  public:
    SceneParser(const Json& root, const JsonSource& source)
        : root_(root, "", source), source_(source) {}

    SceneDesc parse() {
        root_.expectObject();
        scene_.file = source_.name;
        if (const auto c = root_.optionalChild("camera")) readCamera(*c);
        if (const auto f = root_.optionalChild("film")) readFilm(*f);
        if (const auto i = root_.optionalChild("integrator")) readIntegrator(*i);
        if (const auto s = root_.optionalChild("sampler")) readSampler(*s);
        if (const auto t = root_.optionalChild("textures")) readTextures(*t);
        if (const auto m = root_.optionalChild("materials")) readMaterials(*m);
        if (const auto s = root_.optionalChild("shapes")) {
            if (!s->value().is_array()) s->fail("expected an array of shapes");
            for (std::size_t i = 0; i < s->value().size(); ++i)
                readShape(JsonReader(s->value()[i], s->indexPath(i), source_));
        }
        if (const auto l = root_.optionalChild("lights")) {
            if (!l->value().is_array()) l->fail("expected an array of lights");
            for (std::size_t i = 0; i < l->value().size(); ++i)
                readLight(JsonReader(l->value()[i], l->indexPath(i), source_));
        }
        root_.finish();
        for (const auto& [name, reader] : pendingMaterials_)
            if (std::find(scene_.materialNames.begin(), scene_.materialNames.end(), name) ==
                scene_.materialNames.end())
                scene_.unusedMaterialNames.push_back(name);
        for (const auto& [name, reader] : pendingTextures_)
            if (std::find(scene_.textureNames.begin(), scene_.textureNames.end(), name) ==
                scene_.textureNames.end())
                scene_.unusedTextureNames.push_back(name);
        bool emitter = !scene_.lights.empty();
        for (const auto& m : scene_.meshes)
            emitter |= m.emission.has_value();
        for (const auto& s : scene_.spheres)
            emitter |= s.emission.has_value();
        for (const auto& d : scene_.disks)
            emitter |= d.emission.has_value();
        if (!emitter) root_.fail("the scene has no light: add an emitting shape or a light");
        return std::move(scene_);
    }

  private:
    void readCamera(const JsonReader& r) {
        r.expectObject();
        CameraDesc& c = scene_.camera;
        const std::string type = r.string("type", "perspective");
        if (type != "perspective" && type != "thin_lens")
            r.failAt("type", "expected perspective or thin_lens, got \"" + type + "\"");
        if (r.has("matrix")) {
            // A camera-to-world matrix (row-major): the camera sits at its origin, looks
            // along its +z and has its +y up.
            if (r.has("position") || r.has("look_at") || r.has("up"))
                r.fail("give either matrix or position / look_at / up, not both");
            const auto a = r.requiredArray<16>("matrix");
            Mat4 m(1.0);
            for (int row = 0; row < 4; ++row)
                for (int col = 0; col < 4; ++col)
                    m[col][row] = a[std::size_t(row * 4 + col)];
            c.position = Vec3d(m * glm::dvec4(0, 0, 0, 1));
            c.lookAt = c.position + Vec3d(m * glm::dvec4(0, 0, 1, 0));
            c.up = Vec3d(m * glm::dvec4(0, 1, 0, 0));
        } else {
            c.position = readVec(r, "position", c.position);
            c.lookAt = readVec(r, "look_at", c.lookAt);
            c.up = readVec(r, "up", c.up);
        }
        if (glm::length(c.lookAt - c.position) == 0) r.failAt("look_at", "equals position");
        if (glm::length(glm::cross(c.lookAt - c.position, c.up)) == 0)
            r.failAt("up", "is parallel to the viewing direction");
        if (r.has("fov") && r.has("focal_length"))
            r.fail("give either fov or focal_length (with sensor_height), not both");
        c.verticalFovDegrees = r.number("fov", 40.0, {0.0, 180.0, true});
        if (r.has("focal_length")) {
            // A full-frame sensor is 24 mm high.
            const double f = r.requiredNumber("focal_length", Range::positive());
            const double h = r.number("sensor_height", 24.0, Range::positive());
            c.verticalFovDegrees = glm::degrees(2.0 * std::atan(0.5 * h / f));
        }
        c.apertureRadius = r.number("aperture_radius", 0.0, Range::nonNegative());
        c.focusDistance =
            r.number("focus_distance", glm::length(c.lookAt - c.position), Range::positive());
        if (type == "thin_lens" && c.apertureRadius == 0)
            r.failAt("aperture_radius", "a thin_lens camera needs an aperture_radius > 0");
        r.finish();
    }

    void readFilm(const JsonReader& r) {
        r.expectObject();
        if (r.has("resolution")) {
            const auto res = r.requiredArray<2>("resolution", {1.0, 65536.0});
            if (res[0] != std::floor(res[0]) || res[1] != std::floor(res[1]))
                r.failAt("resolution", "expected two integers");
            scene_.film.width = int(res[0]);
            scene_.film.height = int(res[1]);
        }
        if (const auto f = r.optionalChild("filter")) {
            f->expectObject();
            scene_.film.filter = f->choice("type", FilterKind::Box,
                                           {{"box", FilterKind::Box},
                                            {"gaussian", FilterKind::Gaussian},
                                            {"blackman_harris", FilterKind::BlackmanHarris}});
            const double defaultRadius = scene_.film.filter == FilterKind::Box ? 0.5 : 1.5;
            scene_.film.filterRadius = f->number("radius", defaultRadius, {0.0, 16.0, true});
            f->finish();
        }
        r.finish();
    }

    void readIntegrator(const JsonReader& r) {
        r.expectObject();
        scene_.settings.integrator = r.choice("type", IntegratorKind::Path,
                                              {{"path", IntegratorKind::Path},
                                               {"light", IntegratorKind::Light},
                                               {"bdpt", IntegratorKind::Bdpt}});
        scene_.settings.mis =
            r.choice("mis", MisHeuristic::Power,
                     {{"power", MisHeuristic::Power}, {"balance", MisHeuristic::Balance}});
        scene_.settings.maxDepth = r.integer("max_depth", 16, 1, 1024);
        scene_.settings.russianRouletteDepth = r.integer("rr_depth", 5, 1, 1024);
        scene_.settings.lightSelection =
            r.choice("light_selection", LightSelection::Power, kLightSelectionNames);
        r.finish();
    }

    void readSampler(const JsonReader& r) {
        r.expectObject();
        scene_.settings.sampler =
            r.choice("type", SamplerKind::Sobol,
                     {{"sobol", SamplerKind::Sobol}, {"independent", SamplerKind::Independent}});
        scene_.settings.spp = r.integer("spp", 16, 1, 1 << 24);
        scene_.settings.seed = std::uint64_t(r.integer("seed", 0, 0, 2147483647));
        r.finish();
    }

    // "textures": {"name": {"type": "checkerboard", "a": colour, "b": colour, "scale": [u, v]}
    //             | {"type": "image", "file": path, "scale": [u, v], "color_space":
    //             "srgb"|"linear"}}
    // Textures and named materials are read when a shape first refers to them, so a scene
    // never loads what it does not use (images, n/k files, albedo tables).
    void readTextures(const JsonReader& r) {
        r.expectObject();
        for (const auto& [name, value] : r.value().items())
            pendingTextures_.emplace_back(name, r.child(name));
        r.finish();
    }

    int textureIndex(const JsonReader& at, const std::string& name) {
        for (std::size_t i = 0; i < scene_.textureNames.size(); ++i)
            if (scene_.textureNames[i] == name) return int(i);
        for (const auto& [pendingName, reader] : pendingTextures_)
            if (pendingName == name) {
                loadTexture(name, reader);
                return int(scene_.textures.size() - 1);
            }
        at.failAt("texture", "unknown texture \"" + name + "\"");
    }

    void loadTexture(const std::string& name, const JsonReader& t) {
        {
            t.expectObject();
            const std::string type = t.requiredString("type");
            Vec2<float> scale(1.0f);
            if (t.has("scale")) {
                const auto sc = t.requiredArray<2>("scale", Range::positive());
                scale = Vec2<float>(float(sc[0]), float(sc[1]));
            }
            std::shared_ptr<const Texture> texture;
            if (type == "checkerboard") {
                const auto a = t.triple("a", {0.8, 0.8, 0.8}, Range::nonNegative());
                const auto b = t.triple("b", {0.2, 0.2, 0.2}, Range::nonNegative());
                if (!t.has("scale")) scale = Vec2<float>(8.0f);
                texture = std::make_shared<CheckerboardTexture>(
                    Rgb<float>(float(a[0]), float(a[1]), float(a[2])),
                    Rgb<float>(float(b[0]), float(b[1]), float(b[2])), scale);
            } else if (type == "image") {
                const std::filesystem::path file = resolve(t, "file");
                const bool srgb =
                    t.choice("color_space", true, {{"srgb", true}, {"linear", false}});
                try {
                    texture = std::make_shared<ImageTexture>(file, scale, srgb);
                } catch (const InputError& e) {
                    t.failAt("file", e.what());
                }
            } else {
                t.failAt("type", "expected checkerboard or image, got \"" + type + "\"");
            }
            t.finish();
            scene_.textureNames.push_back(name);
            scene_.textures.push_back(texture);
        }
    }

    // Replaces {"texture": name} in a material's texturable keys by a constant the material
    // parser accepts, and records the texture.
    MaterialDesc parseTexturedMaterial(const JsonReader& r) {
        if (!r.value().is_object()) return parseMaterial(r);
        Json copy = r.value();
        MaterialTextures tex;
        for (const char* key : {"base_color", "reflectance", "roughness"}) {
            if (!copy.contains(key) || !copy[key].is_object()) continue;
            const JsonReader t(r.value()[key], r.childPath(key), source_);
            const std::string name = t.requiredString("texture");
            t.finish();
            (std::string(key) == "roughness" ? tex.roughness : tex.color) = textureIndex(t, name);
            copy[key] = 0.5;
        }
        const JsonReader patched(copy, r.path(), source_);
        MaterialDesc desc = parseMaterial(patched);
        if (tex.roughness >= 0) {
            const bool energy = std::visit(
                [](const auto& m) {
                    if constexpr (requires { m.microfacet; }) return m.microfacet.multiscatter;
                    return false;
                },
                desc.model);
            const auto* st = std::get_if<StandardMaterial>(&desc.model);
            if (energy || (st && st->coupling == LayerCoupling::Albedo))
                r.failAt("roughness",
                         "a textured roughness cannot use the albedo tables of "
                         "multiscatter or the albedo coupling");
            if (copy.contains("anisotropy"))
                r.failAt("roughness", "a textured roughness is isotropic");
        }
        if (tex.any() &&
            (desc.type == "mix" || desc.type == "layered" ||
             (tex.color >= 0 && (desc.type == "conductor" || desc.type == "dielectric"))))
            r.fail(
                "textures apply to base_color / reflectance / roughness of standard, diffuse "
                "and phong materials, and to the roughness of conductors and dielectrics");
        scene_.materialTextures.push_back(tex);
        return desc;
    }

    void readMaterials(const JsonReader& r) {
        r.expectObject();
        for (const auto& [name, value] : r.value().items())
            pendingMaterials_.emplace_back(name, r.child(name));
        r.finish();
    }

    int materialOf(const JsonReader& shape) {
        if (!shape.has("material")) shape.failAt("material", "missing; every shape needs one");
        const JsonReader m = shape.child("material");
        if (m.value().is_string()) {
            const std::string name = m.value().get<std::string>();
            for (std::size_t i = 0; i < scene_.materialNames.size(); ++i)
                if (scene_.materialNames[i] == name) return int(i);
            for (const auto& [pendingName, reader] : pendingMaterials_)
                if (pendingName == name) {
                    scene_.materials.push_back(parseTexturedMaterial(reader));
                    scene_.materialNames.push_back(name);
                    return int(scene_.materials.size() - 1);
                }
            std::string known;
            for (const auto& [n, reader] : pendingMaterials_)
                known += (known.empty() ? "" : ", ") + n;
            m.fail("unknown material \"" + name + "\"" +
                   (known.empty() ? " (the scene defines no materials)" : "; defined: " + known));
        }
        scene_.materialNames.push_back(m.path());
        scene_.materials.push_back(parseTexturedMaterial(m));
        return int(scene_.materials.size() - 1);
    }

    // A radiance or intensity: a number or [r, g, b] (linear Rec.709), or a spectrum:
    // {"illuminant": "D65", "scale": Y}, {"blackbody": kelvin, "scale": Y} (both normalised
    // to luminance 1 before scaling), or {"spectrum": [[nm, value], ...], "scale": s}.
    std::pair<Rgb<double>, std::shared_ptr<const EmissionSpectrum>> readEmissionValue(
        const JsonReader& parent, const std::string& key) {
        if (!parent.has(key))
            parent.failAt(key, "missing; expected a number >= 0, [r, g, b] or a spectrum object");
        const JsonReader v = parent.child(key);
        if (!v.value().is_object()) {
            const auto rgb = *parent.optionalTriple(key, Range::nonNegative());
            return {Rgb<double>(rgb[0], rgb[1], rgb[2]), nullptr};
        }
        const double scale = v.number("scale", 1.0, Range::nonNegative());
        std::shared_ptr<const EmissionSpectrum> spectrum;
        const int forms =
            int(v.has("illuminant")) + int(v.has("blackbody")) + int(v.has("spectrum"));
        if (forms != 1) v.fail("expected exactly one of illuminant, blackbody, spectrum");
        try {
            if (v.has("illuminant")) {
                spectrum = std::make_shared<const EmissionSpectrum>(
                    EmissionSpectrum::illuminant(v.requiredString("illuminant"), scale));
            } else if (v.has("blackbody")) {
                spectrum = std::make_shared<const EmissionSpectrum>(EmissionSpectrum::blackbody(
                    v.requiredNumber("blackbody", {100.0, 1e6}), scale));
            }
        } catch (const InputError& e) {
            v.fail(e.what());
        }
        if (v.has("spectrum")) {
            const JsonReader list = v.child("spectrum");
            const auto [nm, values] = list.wavelengthTable(Range::nonNegative());
            spectrum = std::make_shared<const EmissionSpectrum>(
                EmissionSpectrum::tabulated(nm, values, scale, source_.name + ": " + list.path()));
        }
        v.finish();
        return {spectrum->rgb(), spectrum};
    }

    std::optional<EmissionDesc> emissionOf(const JsonReader& shape) {
        const auto e = shape.optionalChild("emission");
        if (!e) return std::nullopt;
        e->expectObject();
        EmissionDesc d;
        std::tie(d.radiance, d.spectrum) = readEmissionValue(*e, "radiance");
        d.twoSided = e->boolean("two_sided", false);
        e->finish();
        return d;
    }

    void finishMesh(const JsonReader& r, MeshDesc mesh, const Mat4& m) {
        const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(m)));
        for (auto& p : mesh.positions)
            p = Vec3<float>(m * glm::dvec4(Vec3d(p), 1.0));
        for (auto& n : mesh.normals)
            n = Vec3<float>(glm::normalize(normalMatrix * Vec3d(n)));
        // A negative determinant mirrors the winding; keep the geometric normal outwards.
        if (glm::determinant(glm::dmat3(m)) < 0)
            for (auto& t : mesh.triangles)
                std::swap(t[1], t[2]);
        double area = 0;
        for (const auto& t : mesh.triangles)
            area +=
                0.5 * glm::length(glm::cross(Vec3d(mesh.positions[t[1]] - mesh.positions[t[0]]),
                                             Vec3d(mesh.positions[t[2]] - mesh.positions[t[0]])));
        if (mesh.emission && !(area > 0)) r.failAt("emission", "the emitting shape has zero area");
        scene_.meshes.push_back(std::move(mesh));
    }

    void readInlineMesh(const JsonReader& r, MeshDesc& mesh) {
        const JsonReader pos = r.child("positions");
        if (!pos.value().is_array() || pos.value().size() < 3)
            pos.fail("expected an array of at least 3 [x, y, z] positions");
        for (std::size_t i = 0; i < pos.value().size(); ++i) {
            const auto& v = pos.value()[i];
            if (!v.is_array() || v.size() != 3)
                pos.fail("expected [x, y, z] at index " + std::to_string(i));
            Vec3<float> p;
            for (int c = 0; c < 3; ++c)
                p[c] = float(pos.checkNumber(v[std::size_t(c)], pos.indexPath(i), Range::any()));
            mesh.positions.push_back(p);
        }
        // Optional per-vertex shading normals and uvs, one per position.
        auto perVertex = [&](const char* key, int n, auto& out) {
            if (!r.has(key)) return;
            const JsonReader list = r.child(key);
            if (!list.value().is_array() || list.value().size() != mesh.positions.size())
                list.fail("expected one entry per position (" +
                          std::to_string(mesh.positions.size()) + ")");
            for (std::size_t i = 0; i < list.value().size(); ++i) {
                const auto& v = list.value()[i];
                if (!v.is_array() || int(v.size()) != n)
                    list.fail("expected " + std::to_string(n) + " numbers at index " +
                              std::to_string(i));
                typename std::decay_t<decltype(out)>::value_type e{};
                for (int c = 0; c < n; ++c)
                    e[c] =
                        float(list.checkNumber(v[std::size_t(c)], list.indexPath(i), Range::any()));
                out.push_back(e);
            }
        };
        perVertex("normals", 3, mesh.normals);
        perVertex("uvs", 2, mesh.uvs);
        for (const auto& n : mesh.normals)
            if (glm::length(n) == 0) r.failAt("normals", "a normal is zero");
        const JsonReader faces = r.child("faces");
        if (!faces.value().is_array() || faces.value().empty())
            faces.fail("expected an array of faces, each [i, j, k, ...] (a polygon)");
        for (std::size_t f = 0; f < faces.value().size(); ++f) {
            const auto& face = faces.value()[f];
            if (!face.is_array() || face.size() < 3)
                faces.fail("face " + std::to_string(f) + ": expected at least 3 indices");
            std::vector<std::uint32_t> idx;
            for (const auto& i : face) {
                if (!i.is_number_integer() || i.get<long long>() < 0 ||
                    i.get<long long>() >= (long long)mesh.positions.size())
                    faces.fail("face " + std::to_string(f) + ": expected vertex indices in [0, " +
                               std::to_string(mesh.positions.size() - 1) + "], got " + i.dump());
                idx.push_back(std::uint32_t(i.get<long long>()));
            }
            // Polygons (the Cornell box's quads) are split as fans: (0, 1, 2), (0, 2, 3), ...
            for (std::size_t k = 1; k + 1 < idx.size(); ++k)
                mesh.triangles.push_back({idx[0], idx[k], idx[k + 1]});
        }
    }

    void readObj(const JsonReader& r, MeshDesc& mesh) {
        const std::filesystem::path file = resolve(r, "file");
        tinyobj::ObjReaderConfig config;
        config.triangulate = true;
        config.vertex_color = false;
        tinyobj::ObjReader reader;
        if (!reader.ParseFromFile(file.string(), config))
            r.failAt("file",
                     file.string() + ": " +
                         (reader.Error().empty() ? "cannot read the OBJ file" : reader.Error()));
        const auto& attrib = reader.GetAttrib();
        std::map<std::array<int, 3>, std::uint32_t> unique;
        bool hasNormals = !attrib.normals.empty(), hasUvs = !attrib.texcoords.empty();
        for (const auto& shape : reader.GetShapes())
            for (const auto& index : shape.mesh.indices) {
                hasNormals &= index.normal_index >= 0;
                hasUvs &= index.texcoord_index >= 0;
            }
        for (const auto& shape : reader.GetShapes()) {
            const auto& idx = shape.mesh.indices;
            for (std::size_t t = 0; t + 2 < idx.size(); t += 3) {
                std::array<std::uint32_t, 3> tri{};
                for (int k = 0; k < 3; ++k) {
                    const auto& i = idx[t + std::size_t(k)];
                    const std::array<int, 3> key{i.vertex_index, hasNormals ? i.normal_index : -1,
                                                 hasUvs ? i.texcoord_index : -1};
                    auto [it, inserted] = unique.emplace(key, std::uint32_t(mesh.positions.size()));
                    if (inserted) {
                        const auto v = std::size_t(i.vertex_index) * 3;
                        mesh.positions.emplace_back(attrib.vertices[v], attrib.vertices[v + 1],
                                                    attrib.vertices[v + 2]);
                        if (hasNormals) {
                            const auto n = std::size_t(i.normal_index) * 3;
                            mesh.normals.emplace_back(attrib.normals[n], attrib.normals[n + 1],
                                                      attrib.normals[n + 2]);
                        }
                        if (hasUvs) {
                            const auto u = std::size_t(i.texcoord_index) * 2;
                            mesh.uvs.emplace_back(attrib.texcoords[u], attrib.texcoords[u + 1]);
                        }
                    }
                    tri[std::size_t(k)] = it->second;
                }
                mesh.triangles.push_back(tri);
            }
        }
        if (mesh.triangles.empty()) r.failAt("file", file.string() + ": no triangles");
    }

    std::filesystem::path resolve(const JsonReader& r, const std::string& key) {
        std::filesystem::path p = r.requiredString(key);
        if (p.is_relative()) {
            const auto beside = (source_.directory / p).lexically_normal();
            if (std::filesystem::exists(beside) || !std::filesystem::exists(p)) p = beside;
        }
        if (!std::filesystem::exists(p)) r.failAt(key, p.string() + ": no such file");
        return p;
    }

    // Analytic shapes take similarity transforms only: returns the uniform scale.
    static double uniformScale(const JsonReader& r, const Mat4& m, const std::string& what) {
        const double sx = glm::length(Vec3d(m[0])), sy = glm::length(Vec3d(m[1])),
                     sz = glm::length(Vec3d(m[2]));
        if (std::abs(sx - sy) > 1e-9 * sx || std::abs(sx - sz) > 1e-9 * sx)
            r.failAt("transform", what + " takes translate, rotate and uniform scale only");
        return sx;
    }

    void readShape(const JsonReader& r) {
        r.expectObject();
        const std::string type = r.requiredString("type");
        const std::string name = r.string("name", r.path());
        if (type == "sphere") {
            SphereDesc s;
            s.name = name;
            s.center = readVec(r, "center", Vec3d(0.0));
            s.radius = r.number("radius", 1.0, Range::positive());
            s.flipNormals = r.boolean("flip_normals", false);
            s.material = materialOf(r);
            s.emission = emissionOf(r);
            const Mat4 m = readTransform(r);
            const double sx = uniformScale(r, m, "a sphere");
            s.center = Vec3d(m * glm::dvec4(s.center, 1.0));
            s.radius *= sx;
            r.finish();
            scene_.spheres.push_back(s);
            return;
        }
        if (type == "disk") {
            // The unit disk in the plane z = 0 facing +z, or centre / normal / radius.
            DiskDesc d;
            d.name = name;
            d.center = readVec(r, "center", Vec3d(0.0));
            d.normal = readVec(r, "normal", Vec3d(0, 0, 1));
            if (glm::length(d.normal) == 0) r.failAt("normal", "expected a non-zero vector");
            d.normal = glm::normalize(d.normal);
            d.radius = r.number("radius", 1.0, Range::positive());
            d.material = materialOf(r);
            d.emission = emissionOf(r);
            const Mat4 m = readTransform(r);
            const double sx = uniformScale(r, m, "a disk");
            d.center = Vec3d(m * glm::dvec4(d.center, 1.0));
            d.normal = glm::normalize(glm::dmat3(m) * d.normal) *
                       (glm::determinant(glm::dmat3(m)) < 0 ? -1.0 : 1.0);
            d.radius *= sx;
            r.finish();
            scene_.disks.push_back(d);
            return;
        }
        MeshDesc mesh;
        mesh.name = name;
        if (type == "mesh") {
            readInlineMesh(r, mesh);
        } else if (type == "obj") {
            readObj(r, mesh);
        } else if (type == "ply") {
            const std::filesystem::path file = resolve(r, "file");
            try {
                readPly(file, mesh);
            } catch (const InputError& e) {
                r.failAt("file", e.what());
            }
        } else if (type == "rectangle") {
            // The square [-1, 1]^2 in the plane z = 0, facing +z; place it with `transform`.
            mesh.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
            mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
            mesh.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
            mesh.isRectangle = true;
        } else {
            r.failAt("type", "expected one of sphere, disk, rectangle, mesh, obj, ply; got \"" +
                                 type + "\"");
        }
        mesh.material = materialOf(r);
        mesh.emission = emissionOf(r);
        const Mat4 m = readTransform(r);
        r.finish();
        finishMesh(r, std::move(mesh), m);
    }

    void readLight(const JsonReader& r) {
        r.expectObject();
        LightDesc l;
        l.kind = r.choice("type", LightKind::Point,
                          {{"point", LightKind::Point},
                           {"spot", LightKind::Spot},
                           {"directional", LightKind::Directional},
                           {"environment", LightKind::Environment}});
        const char* key = l.kind == LightKind::Point || l.kind == LightKind::Spot ? "intensity"
                          : l.kind == LightKind::Directional                      ? "irradiance"
                                                                                  : "radiance";
        if (l.kind == LightKind::Environment && r.has("file")) {
            // An image: "scale" multiplies it, "rotate" turns it about +y.
            if (r.has("radiance")) r.fail("give either radiance or file, not both");
            l.file = resolve(r, "file");
            const double scale = r.number("scale", 1.0, Range::nonNegative());
            l.intensity = Rgb<double>(scale);
            l.rotation = r.number("rotate", 0.0);
        } else {
            std::tie(l.intensity, l.spectrum) = readEmissionValue(r, key);
        }
        if (l.kind == LightKind::Point || l.kind == LightKind::Spot)
            l.position = toVec(r.requiredArray<3>("position"));
        if (l.kind == LightKind::Spot) {
            const Vec3d target = toVec(r.requiredArray<3>("look_at"));
            if (glm::length(target - l.position) == 0) r.failAt("look_at", "equals position");
            l.direction = glm::normalize(target - l.position);
            l.coneAngle = r.number("cone_angle", 30.0, {0.0, 90.0, true});
            l.falloffStart = r.number("falloff_start", l.coneAngle * 0.8, {0.0, l.coneAngle});
        }
        if (l.kind == LightKind::Directional) {
            l.direction = toVec(r.requiredArray<3>("direction"));
            if (glm::length(l.direction) == 0) r.failAt("direction", "expected a non-zero vector");
            l.direction = glm::normalize(l.direction);
        }
        r.finish();
        scene_.lights.push_back(l);
    }

    JsonReader root_;
    const JsonSource& source_;
    SceneDesc scene_;
    std::vector<std::pair<std::string, JsonReader>> pendingMaterials_, pendingTextures_;
};

}  // namespace

MaterialDesc texturedMaterial(const SceneDesc& scene, int material, const Vec2<float>& uv) {
    MaterialDesc desc = scene.materials[std::size_t(material)];
    const MaterialTextures& t = scene.materialTextures[std::size_t(material)];
    const auto colour = [&]() {
        const Rgb<float> c = scene.textures[std::size_t(t.color)]->evaluate(uv);
        return RgbInput(std::clamp(double(c[0]), 0.0, 1.0), std::clamp(double(c[1]), 0.0, 1.0),
                        std::clamp(double(c[2]), 0.0, 1.0));
    };
    const double roughness =
        t.roughness >= 0
            ? std::clamp(double(scene.textures[std::size_t(t.roughness)]->evaluate(uv)[0]), 0.0,
                         1.0)
            : 0.0;
    const auto setRoughness = [&](MicrofacetParams& m) {
        m.alphaX = m.alphaY = roughness * roughness;
    };
    std::visit(
        [&](auto& m) {
            using M = std::decay_t<decltype(m)>;
            if constexpr (std::is_same_v<M, StandardMaterial>) {
                if (t.color >= 0) m.baseColor = colour();
                if (t.roughness >= 0) setRoughness(m.microfacet);
            } else if constexpr (std::is_same_v<M, DiffuseMaterial>) {
                if (t.color >= 0) m.reflectance = colour();
                if (t.roughness >= 0) m.roughness = roughness;
            } else if constexpr (std::is_same_v<M, PhongMaterial>) {
                if (t.color >= 0) m.reflectance = colour();
                if (t.roughness >= 0)
                    m.shininess = PhongLobe<Rgb<double>>::shininessFromAlpha(roughness * roughness);
            } else if constexpr (std::is_same_v<M, ConductorMaterial> ||
                                 std::is_same_v<M, DielectricMaterial>) {
                if (t.roughness >= 0) setRoughness(m.microfacet);
            }
        },
        desc.model);
    return desc;
}

SceneDesc parseScene(const std::string& text, const JsonSource& source) {
    const Json root = parseJsonText(text, source);
    return SceneParser(root, source).parse();
}

SceneDesc loadScene(const std::filesystem::path& file) {
    const Json root = readJsonFile(file);
    const JsonSource source{file.string(), file.parent_path()};
    return SceneParser(root, source).parse();
}

}  // namespace lamina::render
