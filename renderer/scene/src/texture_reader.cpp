// A scene file's texture definitions (docs/scene-format.md, "textures"): the patterns, the
// operations on textures, pbrt-v4's noise textures, and the mappings that place them.
#include <algorithm>

#include "lamina/core/json_reader.h"
#include "lamina/scene/material_textures.h"
#include "lamina/scene/procedural_textures.h"
#include "lamina/scene/scene_readers.h"

namespace lamina::render {

namespace {

// An operand of a texture operation: the name of a texture, or a constant (a number or
// [r, g, b]; `colour` false: a number only).
std::shared_ptr<const Texture> readOperand(
    const JsonReader& t, const std::string& key, double fallback, bool colour, Range range,
    const TextureLookup& textureIndex,
    const std::vector<std::shared_ptr<const Texture>>& textures) {
    if (t.has(key) && t.value()[key].is_string())
        return textures[std::size_t(textureIndex(t, key, t.requiredString(key)))];
    if (colour) {
        const auto c = t.triple(key, {fallback, fallback, fallback}, range);
        return std::make_shared<ConstantTexture>(Rgb<float>(float(c[0]), float(c[1]), float(c[2])));
    }
    return std::make_shared<ConstantTexture>(Rgb<float>(float(t.number(key, fallback, range))));
}

/// Texture coordinates and the vectors that make them: large enough for any scene, small
/// enough that float keeps them finite.
constexpr Range kCoordinateRange{-1e6, 1e6};

Vec2<float> readPair(const JsonReader& r, const std::string& key, Vec2<float> fallback) {
    if (!r.has(key)) return fallback;
    const auto a = r.requiredArray<2>(key, kCoordinateRange);
    return Vec2<float>(float(a[0]), float(a[1]));
}

Vec3<float> readVector(const JsonReader& r, const std::string& key, Vec3<float> fallback) {
    if (!r.has(key)) return fallback;
    const auto a = r.requiredArray<3>(key, kCoordinateRange);
    return Vec3<float>(float(a[0]), float(a[1]), float(a[2]));
}

// The mapping of a 2D texture: the uv mapping of the texture's own `scale` (`defaultScale`
// when absent; negative mirrors, 0 is refused) and `offset`, or a `mapping` object that
// projects the point: {"type": "planar", "v1", "v2", "offset", "transform"}, {"type":
// "spherical" | "cylindrical", "transform"} ({"type": "uv"} is the default).
TextureMapping2D readMapping2D(const JsonReader& t, Vec2<float> defaultScale) {
    TextureMapping2D m;
    m.scale = readPair(t, "scale", defaultScale);
    if (m.scale.x == 0 || m.scale.y == 0)
        t.failAt("scale", "a scale of 0 maps every point to one texel (a negative one mirrors)");
    m.offset = readPair(t, "offset", Vec2<float>(0.0f));
    const auto mapping = t.optionalChild("mapping");
    if (!mapping) return m;
    mapping->expectObject();
    m.kind = mapping->choice("type", TextureMappingKind::Uv, kTextureMappingKindNames);
    if (m.kind == TextureMappingKind::Point)
        mapping->failAt("type",
                        "a 2D texture takes a uv, planar, spherical or cylindrical mapping "
                        "(point is for the solid textures and the checkerboard)");
    if (m.kind != TextureMappingKind::Uv) {
        for (const char* key : {"scale", "offset"})
            if (t.has(key))
                t.failAt(key, std::string("belongs to the uv mapping; a ") +
                                  std::string(kTextureMappingKindNames.name(m.kind)) +
                                  " mapping takes its own keys");
        m.scale = Vec2<float>(1.0f);
        if (m.kind == TextureMappingKind::Planar) {
            m.v1 = readVector(*mapping, "v1", m.v1);
            m.v2 = readVector(*mapping, "v2", m.v2);
            m.offset = readPair(*mapping, "offset", Vec2<float>(0.0f));
        }
        m.space = TextureSpace::fromTransform(readTransform(*mapping, "transform"));
    }
    mapping->finish();
    return m;
}

// The texture space of a solid texture: its {"type": "point", "transform": [...]} mapping
// (the identity without one).
TextureSpace readPointMapping(const JsonReader& t) {
    const auto mapping = t.optionalChild("mapping");
    if (!mapping) return {};
    mapping->expectObject();
    if (mapping->choice("type", TextureMappingKind::Point, kTextureMappingKindNames) !=
        TextureMappingKind::Point)
        mapping->failAt("type", "a solid texture takes the point mapping");
    const TextureSpace space = TextureSpace::fromTransform(readTransform(*mapping, "transform"));
    mapping->finish();
    return space;
}

// The noise textures (procedural_textures.h) with pbrt-v4's defaults.
std::shared_ptr<const Texture> readNoiseTexture(const JsonReader& t, TextureKind kind) {
    const TextureSpace space = readPointMapping(t);
    if (kind == TextureKind::Windy) return std::make_shared<WindyTexture>(space);
    const int octaves = t.integer("octaves", 8, 1, kMaxNoiseOctaves);
    const float roughness = float(t.number("roughness", 0.5, {0.0, 4.0}));
    if (kind == TextureKind::Fbm) return std::make_shared<FbmTexture>(space, octaves, roughness);
    if (kind == TextureKind::Wrinkled)
        return std::make_shared<WrinkledTexture>(space, octaves, roughness);
    const float scale = float(t.number("scale", 1.0, kCoordinateRange));
    const float variation = float(t.number("variation", 0.2, kCoordinateRange));
    return std::make_shared<MarbleTexture>(space, octaves, roughness, scale, variation);
}

}  // namespace

std::shared_ptr<const Texture> readTexture(
    const JsonReader& t, const TextureLookup& textureIndex,
    const std::vector<std::shared_ptr<const Texture>>& textures) {
    t.expectObject();
    t.noteNames("type", kTextureKindNames.names());
    const std::string type = t.requiredString("type");
    const auto kind = kTextureKindNames.find(type);
    if (!kind)
        t.failAt("type", "expected " + kTextureKindNames.list(" or ") + ", got \"" + type + "\"");
    std::shared_ptr<const Texture> texture;
    switch (*kind) {
        case TextureKind::Checkerboard: {
            const auto a = t.triple("a", {0.8, 0.8, 0.8}, Range::nonNegative());
            const auto b = t.triple("b", {0.2, 0.2, 0.2}, Range::nonNegative());
            const Rgb<float> ca{float(a[0]), float(a[1]), float(a[2])};
            const Rgb<float> cb{float(b[0]), float(b[1]), float(b[2])};
            // A point mapping makes it pbrt-v4's 3D checkerboard, cells of the texture's space.
            const Json* mapping = t.value().contains("mapping") ? &t.value()["mapping"] : nullptr;
            if (mapping && mapping->is_object() && mapping->value("type", Json()) == "point")
                texture = std::make_shared<SolidCheckerboardTexture>(ca, cb, readPointMapping(t));
            else
                texture = std::make_shared<CheckerboardTexture>(
                    ca, cb, readMapping2D(t, Vec2<float>(8.0f)));
            break;
        }
        case TextureKind::Image: {
            const std::filesystem::path file = t.filePath("file");
            const bool srgb = t.choice("color_space", TextureColorSpace::Srgb,
                                       kTextureColorSpaceNames) == TextureColorSpace::Srgb;
            const bool invert = t.boolean("invert", false);
            const TextureMapping2D mapping = readMapping2D(t, Vec2<float>(1.0f));
            try {
                texture = std::make_shared<ImageTexture>(file, mapping, srgb, invert);
            } catch (const InputError& e) {
                t.failAt("file", e.what());
            }
            break;
        }
        case TextureKind::Scale:
        case TextureKind::Power: {
            if (!t.has("texture") || !t.value()["texture"].is_string())
                t.failAt("texture", "expected the name of a texture");
            const auto source =
                textures[std::size_t(textureIndex(t, "texture", t.requiredString("texture")))];
            if (*kind == TextureKind::Scale)
                texture = std::make_shared<ScaleTexture>(
                    source, float(t.requiredNumber("scale", {0.0, 1e6})));
            else
                texture = std::make_shared<PowerTexture>(
                    source, float(t.requiredNumber("exponent", {0.0625, 16.0})));
            break;
        }
        case TextureKind::Mix: {
            // pbrt-v4's defaults: tex1 0, tex2 1, amount 0.5.
            auto a = readOperand(t, "a", 0.0, true, Range::nonNegative(), textureIndex, textures);
            auto b = readOperand(t, "b", 1.0, true, Range::nonNegative(), textureIndex, textures);
            auto amount =
                readOperand(t, "amount", 0.5, false, Range::unit(), textureIndex, textures);
            texture = std::make_shared<MixTexture>(std::move(a), std::move(b), std::move(amount));
            break;
        }
        case TextureKind::DirectionMix: {
            // pbrt-v4's defaults: tex1 0, tex2 1, dir (0, 1, 0).
            auto a = readOperand(t, "a", 0.0, true, Range::nonNegative(), textureIndex, textures);
            auto b = readOperand(t, "b", 1.0, true, Range::nonNegative(), textureIndex, textures);
            const Vec3<float> d = readVector(t, "direction", Vec3<float>(0, 1, 0));
            const float length = glm::length(d);
            if (!(length > 0.0f) || !std::isfinite(length))
                t.failAt("direction", "expected a non-zero vector");
            texture = std::make_shared<DirectionMixTexture>(std::move(a), std::move(b), d / length);
            break;
        }
        case TextureKind::Fbm:
        case TextureKind::Wrinkled:
        case TextureKind::Windy:
        case TextureKind::Marble:
            texture = readNoiseTexture(t, *kind);
            break;
        case TextureKind::Dots: {
            // pbrt-v4's defaults: inside 1, outside 0.
            auto inside =
                readOperand(t, "inside", 1.0, true, Range::nonNegative(), textureIndex, textures);
            auto outside =
                readOperand(t, "outside", 0.0, true, Range::nonNegative(), textureIndex, textures);
            texture = std::make_shared<DotsTexture>(readMapping2D(t, Vec2<float>(1.0f)),
                                                    std::move(inside), std::move(outside));
            break;
        }
    }
    t.finish();
    return texture;
}

}  // namespace lamina::render
