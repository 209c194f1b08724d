// Mitsuba 3 textures -> lamina textures (mitsuba_textures.h). Mitsuba's conventions are those of
// mitsuba3 src/textures/bitmap.cpp and checkerboard.cpp; `to_uv` is an affine map of the plane,
// uv' = A uv + t, taken from a <transform>'s 4x4 matrix as Mitsuba's Properties do (its upper
// left 2 x 2 block and the first two rows of its last column: AffineTransform::extract).
#include "mitsuba_textures.h"

#include <cmath>

#include "lamina/core/error.h"

namespace lamina::render::mitsuba {

namespace {

// to_uv as uv' = (scale.x u, scale.y v) + offset, or refused when it rotates or shears.
struct UvMap {
    double scaleU = 1, scaleV = 1, offsetU = 0, offsetV = 0;
};

UvMap readUvMap(Plugin& p) {
    const auto transform = p.transform("to_uv");
    if (!transform) return {};
    const glm::dmat4& m = transform->matrix;  // m[column][row]
    if (m[1][0] != 0 || m[0][1] != 0)
        p.fail(
            "a to_uv that rotates or shears uv is not supported (lamina's textures scale "
            "and offset u and v)");
    return {m[0][0], m[1][1], m[3][0], m[3][1]};
}

// The name of the lamina texture of a Mitsuba texture: its id, else what it is and where (the
// line, and the file when it is an included one: lines of two files may coincide).
std::string baseName(const Plugin& p, const std::string& what) {
    const Element& texture = p.element();
    if (const std::string* id = texture.attribute("id")) return *id;
    const auto& files = p.document().files;
    const std::string file = !files.empty() && texture.file == files.front()
                                 ? ""
                                 : texture.file.filename().string() + " ";
    return what + " (" + file + "line " + std::to_string(texture.line) + ")";
}

// Whether `use` evaluates the texture as one number (Texture::eval_1).
bool singleValued(TextureUse use) {
    return use == TextureUse::Alpha || use == TextureUse::Scalar || use == TextureUse::Opacity;
}

// A checkerboard's colour as a lamina colour (a number or [r, g, b]); as an alpha, one number
// in [0, 1], whose square root lamina's textured roughness squares back; as a scalar, one
// number in [0, 1].
Json checkerColor(Plugin& p, const char* name, double fallback, TextureUse use) {
    const Json c = p.color(name).value_or(Json(fallback));
    if (!singleValued(use)) {
        if (c.is_object())
            p.fail(std::string("parameter \"") + name +
                   "\": a spectrum in a checkerboard is not supported (give an rgb)");
        return c;
    }
    const std::string what = use == TextureUse::Alpha     ? "an alpha"
                             : use == TextureUse::Opacity ? "an opacity"
                                                          : "a roughness";
    if (!c.is_number())
        p.fail(std::string("parameter \"") + name + "\": " + what + " must be one number");
    const double v = c.get<double>();
    if (!(v >= 0 && v <= 1))
        p.fail(std::string("parameter \"") + name + "\": " + what +
               " must be in [0, 1] for lamina");
    return use == TextureUse::Alpha ? std::sqrt(v) : v;
}

// Whether 2 x is an integer: a checkerboard shifted by it keeps its cells' edges.
bool onHalfCells(double x) {
    return std::abs(2 * x - std::round(2 * x)) < 1e-9;
}

// mitsuba3 checkerboard.cpp: with uv' = to_uv(uv), eval gives color0 where
// frac(u') > 1/2 and frac(v') > 1/2 agree, that is where floor(2 u') + floor(2 v') is even
// (edges aside), and color1 elsewhere; eval_1, which one-number parameters (alpha, roughness)
// use, swaps the two.
// Lamina's checkerboard gives `a` where floor(u su) + floor(v sv) is even, so su = 2 |sx|,
// sv = 2 |sy|, and the colours swap once for each of: an odd 2 tx + 2 ty, a negative sx, a
// negative sy (floor(-x) = -floor(x) - 1 off the edges), the eval_1 use.
std::string checkerboard(Plugin& p, TextureUse use, std::vector<TranslatedTexture>& out) {
    if (use == TextureUse::Map)
        p.fail("a bumpmap's or normalmap's texture must be a bitmap (lamina reads image files)");
    Json color0 = checkerColor(p, "color0", 0.4, use);
    Json color1 = checkerColor(p, "color1", 0.2, use);
    const UvMap uv = readUvMap(p);
    if (uv.scaleU == 0 || uv.scaleV == 0)
        p.fail("a to_uv that scales u or v by 0 is not supported");
    if (!onHalfCells(uv.offsetU) || !onHalfCells(uv.offsetV))
        p.fail(
            "a to_uv translation that is not a multiple of 1/2 is not supported on a "
            "checkerboard (lamina's has no offset)");
    const long shift = std::lround(2 * uv.offsetU) + std::lround(2 * uv.offsetV);
    const bool swap =
        ((shift % 2 != 0) != (uv.scaleU < 0)) != ((uv.scaleV < 0) != singleValued(use));
    if (swap) std::swap(color0, color1);
    p.finish();
    const std::string name =
        baseName(p, "checkerboard") + (singleValued(use) ? " as roughness" : "");
    out.push_back({name,
                   {{"type", "checkerboard"},
                    {"a", color0},
                    {"b", color1},
                    {"scale", {2 * std::abs(uv.scaleU), 2 * std::abs(uv.scaleV)}}},
                   {}});
    return name;
}

// mitsuba3 bitmap.cpp: `raw` false decodes 8-bit sRGB, bilinear and repeating by default; looked
// up at to_uv(uv) with the pixel centres at (i + 1/2) / width, as lamina's image texture.
std::string bitmap(Plugin& p, std::vector<TranslatedTexture>& out, bool* rawOut) {
    const auto file = p.file("filename");
    if (!file) p.fail("a bitmap needs \"filename\"");
    const bool raw = p.boolean("raw", false);
    if (rawOut) *rawOut = raw;
    const std::string filter = p.string("filter_type").value_or("bilinear");
    if (filter != "bilinear" && filter != "nearest")
        p.fail("filter_type \"" + filter + "\" is not supported (bilinear or nearest)");
    if (filter == "nearest") p.warn("filter_type nearest became lamina's bilinear lookup");
    const std::string wrap = p.string("wrap_mode").value_or("repeat");
    if (wrap != "repeat")
        p.fail("wrap_mode \"" + wrap + "\" is not supported (lamina's images repeat)");
    const UvMap uv = readUvMap(p);
    if (!(uv.scaleU > 0 && uv.scaleV > 0))
        p.fail(
            "a to_uv that mirrors or collapses a bitmap is not supported (lamina's image "
            "scale is positive)");
    if (p.has("format")) p.ignore("format", "lamina stores textures as float");
    // Changes only how Mitsuba stores the texture for lookups.
    p.boolean("accel", true);
    p.warn(
        "bitmap became an image texture: Mitsuba reads v = 0 at the image's top row, lamina "
        "at its bottom row (the same on OBJ meshes, whose v Mitsuba flips when reading them; "
        "elsewhere the image lands mirrored in v)");
    p.finish();
    Json texture{{"type", "image"}, {"color_space", raw ? "linear" : "srgb"}};
    if (uv.scaleU != 1 || uv.scaleV != 1) texture["scale"] = {uv.scaleU, uv.scaleV};
    if (uv.offsetU != 0 || uv.offsetV != 0) texture["offset"] = {uv.offsetU, uv.offsetV};
    const std::string name = baseName(p, "bitmap " + file->filename().string());
    out.push_back({name, texture, *file});
    return name;
}

}  // namespace

std::string translateTexture(const Element& texture, TextureUse use,
                             const MitsubaDocument& document, Diagnostics& diagnostics,
                             std::vector<TranslatedTexture>& out, bool* raw) {
    Plugin p(texture, document, diagnostics);
    if (raw) *raw = false;
    if (p.type() == "checkerboard") return checkerboard(p, use, out);
    if (p.type() == "bitmap" && use == TextureUse::Alpha) {
        // Lamina's textured roughness is sqrt(alpha): the square root of Mitsuba's bilinear
        // lookup, taken after it (a power texture), as Mitsuba takes alpha = the lookup.
        p.warn(
            "a bitmap as alpha: lamina reads its first channel where Mitsuba reads the "
            "luminance of an RGB image (the same for a grey one)");
        const std::string name = bitmap(p, out, raw);
        const std::string root = name + " as roughness";
        out.push_back({root, {{"type", "power"}, {"texture", name}, {"exponent", 0.5}}, {}});
        return root;
    }
    if (p.type() == "bitmap" && (use == TextureUse::Scalar || use == TextureUse::Opacity))
        p.warn(std::string("a bitmap as ") +
               (use == TextureUse::Opacity ? "a mask's opacity" : "roughness") +
               ": lamina reads its first channel where Mitsuba reads the luminance of an RGB "
               "image (the same for a grey one)");
    if (p.type() == "bitmap") return bitmap(p, out, raw);
    if (use == TextureUse::Map)
        p.fail("a bumpmap's or normalmap's texture must be a bitmap (lamina reads image files)");
    p.fail("the texture plugin \"" + p.type() + "\" is not supported (bitmap, checkerboard)");
}

std::optional<Json> colorOrTexture(Plugin& p, const std::string& name,
                                   std::vector<TranslatedTexture>& out) {
    if (const auto t = p.texture(name))
        return Json{{"texture", translateTexture(*t->texture, TextureUse::Color, p.document(),
                                                 p.diagnostics(), out)}};
    return p.color(name);
}

}  // namespace lamina::render::mitsuba
