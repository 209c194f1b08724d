// The pbrt-v4 camera and its film: Camera "perspective" / "orthographic" and Film "rgb" with
// pbrt-v4's sensor (film.cpp, PixelSensor: ISO, exposure time, white balance, the cie1931
// curves), its clamp and its crop, as the lamina camera and film (docs/interchange.md).
#include <algorithm>
#include <cmath>
#include <sstream>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "pbrt_translation.h"
#include "rounded_rotation.h"

namespace lamina::render::pbrt {

namespace {

constexpr double kPi = 3.14159265358979323846;

std::string number(double v) {
    std::ostringstream out;
    out << v;
    return out.str();
}

Json vec(const glm::dvec3& v) {
    return Json::array({v.x, v.y, v.z});
}

// The film's pixel bounds, as pbrt-v4's FilmBaseParameters computes them: `cropwindow` (in
// [0, 1] of the image, each pair sorted and clamped) wins over `pixelbounds` (clamped to the
// image); an empty result is an error.
void translateCrop(TranslationContext& ctx, const Entity& e, int width, int height, Json& film) {
    const ParamList& p = e.params;
    const auto window = p.numbers("cropwindow", {"float"}, 4);
    const auto bounds = p.numbers("pixelbounds", {"integer"}, 4);
    if (window && window->size() != 4)
        p.fail(*p.find("cropwindow"), "expected four numbers x0 x1 y0 y1");
    if (bounds && bounds->size() != 4)
        p.fail(*p.find("pixelbounds"), "expected four integers x0 x1 y0 y1");
    if (!window && !bounds) return;
    int x0 = 0, x1 = width, y0 = 0, y1 = height;
    if (window) {
        if (bounds) ctx.warn(e.location, "both cropwindow and pixelbounds: the cropwindow is used");
        const auto& w = *window;
        const auto edge = [](double a, double b, bool upper, int size) {
            const double v = std::clamp(upper ? std::max(a, b) : std::min(a, b), 0.0, 1.0);
            return int(std::ceil(size * v));
        };
        x0 = edge(w[0], w[1], false, width);
        x1 = edge(w[0], w[1], true, width);
        y0 = edge(w[2], w[3], false, height);
        y1 = edge(w[2], w[3], true, height);
    } else {
        const auto& b = *bounds;
        const auto clampTo = [](double v, int size) {
            return int(std::clamp(v, 0.0, double(size)));
        };
        x0 = clampTo(b[0], width);
        x1 = clampTo(b[1], width);
        y0 = clampTo(b[2], height);
        y1 = clampTo(b[3], height);
        if (x0 != int(b[0]) || x1 != int(b[1]) || y0 != int(b[2]) || y1 != int(b[3]))
            ctx.warn(e.location, "pixelbounds extend beyond the image: clamped to it");
    }
    if (!(x0 < x1 && y0 < y1))
        ctx.fail(e.location, "the film's crop holds no pixel (pixel bounds [" + std::to_string(x0) +
                                 ", " + std::to_string(x1) + ") x [" + std::to_string(y0) + ", " +
                                 std::to_string(y1) + "))");
    if (x0 != 0 || y0 != 0 || x1 != width || y1 != height) film["crop"] = {x0, x1, y0, y1};
}

}  // namespace

// pbrt-v4's film (film.cpp, RGBFilm and PixelSensor): resolution 1280 x 720; the imaging
// ratio exposure time x ISO / 100, the exposure time being the camera's shutterclose -
// shutteropen (pbrt-v4's scene.cpp); `scale` is pbrt-v3's film scale, kept by exporters.
Json translateFilm(TranslationContext& ctx, const Entity& e, const Entity& camera, int& width,
                   int& height) {
    const ParamList& p = e.params;
    if (e.type != "rgb") {
        if (e.type == "image")
            ctx.fail(e.location,
                     "Film \"image\" is pbrt-v3's film: this is a pbrt-v3 file, which pbrt-v4 "
                     "refuses too; convert it with pbrt-v4's `pbrt --upgrade FILE > NEW.pbrt`");
        if (e.type != "gbuffer" && e.type != "spectral")
            ctx.fail(e.location, "Film \"" + e.type + "\" is not supported (rgb)");
        ctx.warn(e.location, "Film \"" + e.type + "\" became lamina's RGB film (linear Rec.709)");
    }
    width = p.integer("xresolution", 1280);
    height = p.integer("yresolution", 720);
    if (p.has("filename")) {
        p.string("filename", "");
        ctx.warn(e.location, "the film's filename ignored: lamina writes the image named by -o");
    }
    if (p.has("savefp16")) {
        p.boolean("savefp16", false);
        ctx.warn(e.location, "savefp16 ignored: lamina writes float EXR");
    }
    if (camera.type == "realistic") {
        ctx.filmDiagonal = p.number("diagonal", 35);
        if (!(ctx.filmDiagonal > 0 && ctx.filmDiagonal < 1e5))
            ctx.fail(e.location, "Film: diagonal must be in (0, 1e5) mm");
    } else if (p.has("diagonal")) {
        p.number("diagonal", 35);
        ctx.warn(e.location,
                 "diagonal ignored: only pbrt-v4's realistic camera reads the film's size");
    }
    Json film{{"resolution", {width, height}}};
    const std::string sensor = p.string("sensor", "cie1931");
    if (sensor != "cie1931")
        ctx.fail(p.find("sensor")->location,
                 "Film: sensor \"" + sensor +
                     "\" is not supported: lamina has pbrt-v4's \"cie1931\" sensor only (the CIE "
                     "1931 observer), not its measured camera curves; remove the parameter");
    const double iso = p.number("iso", 100);
    if (!(iso > 0)) ctx.fail(p.find("iso")->location, "Film: iso must be positive");
    if (iso != 100) film["iso"] = iso;
    const ParamList& c = camera.params;
    const double open = c.number("shutteropen", 0), close = c.number("shutterclose", 1);
    if (!(close > open))
        ctx.fail(camera.location,
                 "the camera's shutterclose must be later than its shutteropen "
                 "(their difference is the film's exposure time)");
    if (close - open != 1) film["exposure_time"] = close - open;
    const double scale = p.number("scale", 1);
    if (!(scale > 0)) ctx.fail(p.find("scale")->location, "Film: scale must be positive");
    if (scale != 1) film["scale"] = scale;
    if (p.has("whitebalance")) {
        const double kelvin = p.number("whitebalance", 0);
        if (kelvin != 0 && !(kelvin >= 4000 && kelvin <= 25000))
            ctx.fail(p.find("whitebalance")->location,
                     "Film: whitebalance " + number(kelvin) +
                         " is not supported: lamina balances to the CIE daylight locus, 4000 to "
                         "25000 K (or 0: none)");
        if (kelvin != 0) film["white_balance"] = kelvin;
    }
    if (p.has("maxcomponentvalue")) {
        const double m = p.number("maxcomponentvalue", 0);
        if (!(m > 0))
            ctx.fail(p.find("maxcomponentvalue")->location,
                     "Film: maxcomponentvalue must be positive");
        if (std::isfinite(m)) film["max_component_value"] = m;
    }
    translateCrop(ctx, e, width, height, film);
    p.refuseUnused();
    return film;
}

// pbrt-v4's cameras (cameras.cpp): camera space x = cross(up, dir) maps to raster +x. The
// perspective camera's `fov` (90) spans the shorter image axis; the orthographic camera's
// `screenwindow` (the shorter axis [-1, 1]) is in camera-space units.
Json translateCamera(TranslationContext& ctx, const Entity& e, int width, int height) {
    const ParamList& p = e.params;
    const bool orthographic = e.type == "orthographic";
    if (e.type != "perspective" && !orthographic && e.type != "realistic")
        ctx.fail(e.location, "Camera \"" + e.type +
                                 "\" is not supported (perspective, orthographic, realistic); "
                                 "the spherical camera has no lamina equivalent");
    if (!(std::abs(glm::determinant(e.transform)) > 0))
        ctx.fail(e.location, "the camera transform is singular (it flattens the view)");
    const glm::dmat4 worldFromCamera = glm::inverse(e.transform);
    const glm::dvec3 x(worldFromCamera[0]), y(worldFromCamera[1]), z(worldFromCamera[2]);
    const glm::dvec3 position(worldFromCamera[3]);
    const glm::dmat3 axes(worldFromCamera);
    // A rotation with a uniform scale, rounded as exporters write it (rounded_rotation.h), and a
    // scale of the viewing axis alone, which pbrt-v4 turns into a narrower or wider view (its
    // rays are camera-space directions mapped by the transform and normalised). Camera x and y
    // of different lengths would make pixels that are not square.
    const double skew = columnSkew(axes);
    const double lx = glm::length(x), ly = glm::length(y), lz = glm::length(z);
    if (skew > kRoundedRotationTolerance || std::abs(lx - ly) > kRoundedRotationTolerance * ly)
        ctx.fail(e.location,
                 "the camera transform shears the view or scales its x and y axes differently "
                 "(pixels would not be square); lamina's camera takes rotations, mirrors, "
                 "uniform scales and a scale along the viewing axis");
    if (skew > 1e-9 || std::abs(lx - ly) > 1e-9 * ly)
        ctx.warn(e.location, "the camera transform is a rotation to within " +
                                 deviationText(std::max(skew, std::abs(lx - ly) / ly)) +
                                 " (rounded digits): its nearest rotation is used");
    const double s = ly;
    // camera x = cross(y, z) (det > 0) is pbrt's left-handed frame: image right = up x
    // forward. A mirroring transform (Scale -1 1 1, common in exported files) makes it
    // right-handed.
    const bool left = glm::dot(x, glm::cross(y, z)) > 0;
    Json camera{{"position", vec(position)},
                {"look_at", vec(position + glm::normalize(z))},
                {"up", vec(glm::normalize(y))}};
    if (e.type == "realistic") {
        // pbrt-v4's RealisticCamera (cameras.cpp): its lens file in millimetres, the stop's
        // `aperturediameter` (1 mm) and `focusdistance` (10) in the scene's metres, from the
        // film: a camera transform that scales would scale them, which lamina does not.
        if (std::abs(s - 1) > 1e-6 || std::abs(lz - 1) > 1e-6)
            ctx.fail(e.location,
                     "a realistic camera's transform must not scale (its lens is "
                     "in metres of the scene)");
        const Param* lensFile = p.find("lensfile");
        if (!lensFile) ctx.fail(e.location, "Camera \"realistic\": no \"string lensfile\"");
        p.string("lensfile", "");
        camera["type"] = "realistic";
        camera["lens_file"] = ctx.filePath(p, *lensFile);
        camera["aperture_diameter"] = p.number("aperturediameter", 1.0);
        camera["focus_distance"] = p.number("focusdistance", 10.0);
        camera["film_diagonal"] = ctx.filmDiagonal;
    } else if (orthographic) {
        camera["type"] = "orthographic";
        const double aspect = double(width) / double(height);
        std::vector<double> window = aspect > 1 ? std::vector{-aspect, aspect, -1.0, 1.0}
                                                : std::vector{-1.0, 1.0, -1 / aspect, 1 / aspect};
        if (const auto w = p.numbers("screenwindow", {"float"}, 4)) {
            if (w->size() != 4 || !((*w)[0] < (*w)[1] && (*w)[2] < (*w)[3]))
                p.fail(*p.find("screenwindow"), "expected x0 < x1 and y0 < y1");
            window = *w;
        }
        for (double& v : window)
            v *= s;  // camera-space units, scaled by the transform into the scene's
        camera["screen_window"] = window;
        if (p.number("lensradius", 0.0) > 0)
            ctx.fail(e.location,
                     "an orthographic camera with a lens (lensradius) is not "
                     "supported: remove lensradius for a sharp orthographic view");
        p.number("focaldistance", 1e6);
    } else {
        const double fov = p.number("fov", 90.0);
        if (!(fov > 0 && fov < 180)) ctx.fail(e.location, "fov must be in (0, 180) degrees");
        // The image plane's half-height at unit distance, scaled by a stretch of the viewing
        // axis (y / z lengths: a longer z narrows the view).
        const double stretch = ly / lz;
        double vertical = fov;
        if (width < height || std::abs(stretch - 1) > 1e-9) {
            double t = std::tan(0.5 * fov * kPi / 180) * stretch;
            if (width < height) t *= double(height) / double(width);
            vertical = 2 * std::atan(t) * 180 / kPi;
        }
        camera["fov"] = vertical;
        const double lensRadius = p.number("lensradius", 0.0);
        const double focus = p.number("focaldistance", 1e6);
        if (lensRadius > 0) {
            camera["type"] = "thin_lens";
            camera["aperture_radius"] = lensRadius * s;
            camera["focus_distance"] = focus * lz;
        }
    }
    camera["handedness"] = left ? "left" : "right";
    p.refuseUnused();
    return camera;
}

}  // namespace lamina::render::pbrt
