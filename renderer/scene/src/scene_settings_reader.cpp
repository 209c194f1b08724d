#include <glm/trigonometric.hpp>

#include "lamina/core/error.h"
#include "lamina/scene/lens_system.h"
#include "lamina/scene/scene_readers.h"

namespace lamina::render {

namespace {

// An orthographic camera's own keys; a lens or a field of view is refused.
void readOrthographic(const JsonReader& r, CameraDesc& c) {
    c.orthographic = true;
    for (const char* key :
         {"fov", "focal_length", "sensor_height", "aperture_radius", "focus_distance"})
        if (r.has(key)) r.failAt(key, "an orthographic camera has no lens and no field of view");
    if (r.has("screen_window")) {
        const auto w =
            r.requiredArray<4>("screen_window", {-kMaxSceneCoordinate, kMaxSceneCoordinate});
        if (!(w[0] < w[1] && w[2] < w[3]))
            r.failAt("screen_window", "expected X0 < X1 and Y0 < Y1");
        c.screenWindow = w;
    }
    c.handedness = r.choice("handedness", Handedness::Right, kHandednessNames);
}

// A realistic camera's keys (lens_system.h): its lens file, the stop's diameter, the plane in
// focus and the film's diagonal; a field of view or a thin lens is refused.
void readRealistic(const JsonReader& r, CameraDesc& c, std::vector<std::string>& warnings) {
    for (const char* key : {"fov", "focal_length", "sensor_height", "aperture_radius"})
        if (r.has(key))
            r.failAt(key,
                     "a realistic camera's lens file sets its focal length and aperture "
                     "(use aperture_diameter and film_diagonal)");
    const std::filesystem::path file = r.filePath("lens_file");
    std::vector<LensInterface> interfaces;
    try {
        interfaces = readLensFile(file);
    } catch (const InputError& e) {
        r.failAt("lens_file", e.what());
    }
    // Millimetres, as in the lens file; the focus distance in metres (the scene's unit).
    const double aperture = r.number("aperture_diameter", 0.0, {0.0, 1e5});
    const double focus =
        r.number("focus_distance", glm::length(c.lookAt - c.position), {0.0, 1e6, true});
    const double diagonal = r.number("film_diagonal", 35.0, {0.0, 1e5, true});
    c.handedness = r.choice("handedness", Handedness::Right, kHandednessNames);
    try {
        bool clamped = false;
        c.lensSystem = std::make_shared<LensSystem>(std::move(interfaces), aperture / 1000, focus,
                                                    diagonal / 1000, &clamped);
        if (clamped)
            warnings.push_back(r.source().name + ": " + r.path() +
                               ".aperture_diameter: wider than the lens file's aperture stop: "
                               "the stop's own diameter is used");
    } catch (const InputError& e) {
        r.failAt("focus_distance", e.what());
    }
}

}  // namespace

CameraDesc readCamera(const JsonReader& r, const std::vector<MediumDesc>& media,
                      std::vector<std::string>& warnings) {
    r.expectObject();
    CameraDesc c;
    // Any angle is an axis; [-180, 180] keeps typing errors (radians times 100) out.
    c.analyserDegrees = r.optionalNumber("analyser", {-180.0, 180.0});
    if (r.has("medium")) c.medium = mediumIndex(r, "medium", media);
    if (r.has("shutter")) {
        // Times in the scene's own unit: instances move from time 0 to time 1.
        c.shutter = r.requiredArray<2>("shutter", {-1e6, 1e6});
        if (!(c.shutter[0] <= c.shutter[1]))
            r.failAt("shutter", "expected [open, close] with open <= close");
    }
    r.noteNames("type", kCameraKindNames.names());
    const std::string type = r.string("type", "perspective");
    const auto kind = kCameraKindNames.find(type);
    if (!kind)
        r.failAt("type", "expected " + kCameraKindNames.list(" or ") + ", got \"" + type + "\"");
    if (r.has("matrix")) {
        // A camera-to-world matrix (row-major): the camera sits at its origin, looks
        // along its +z and has its +y up.
        if (r.has("position") || r.has("look_at") || r.has("up"))
            r.fail("give either matrix or position / look_at / up, not both");
        const Mat4 m = requiredMatrix(r, "matrix");
        c.position = Vec3d(m * glm::dvec4(0, 0, 0, 1));
        c.lookAt = c.position + Vec3d(m * glm::dvec4(0, 0, 1, 0));
        c.up = Vec3d(m * glm::dvec4(0, 1, 0, 0));
    } else {
        c.position = readVec3(r, "position", c.position);
        c.lookAt = readVec3(r, "look_at", c.lookAt);
        c.up = readVec3(r, "up", c.up);
    }
    const bool matrix = r.has("matrix");
    checkCoordinates(r, matrix ? "matrix" : "position", c.position, matrix ? "the position" : "");
    checkCoordinates(r, matrix ? "matrix" : "look_at", c.lookAt, matrix ? "the look-at point" : "");
    if (glm::length(c.lookAt - c.position) == 0) r.failAt("look_at", "equals position");
    if (glm::length(glm::cross(c.lookAt - c.position, c.up)) == 0)
        r.failAt("up", "is parallel to the viewing direction");
    if (*kind == CameraKind::Orthographic) {
        readOrthographic(r, c);
        r.finish();
        return c;
    }
    if (*kind == CameraKind::Realistic) {
        readRealistic(r, c, warnings);
        r.finish();
        return c;
    }
    if (r.has("fov") && r.has("focal_length"))
        r.fail("give either fov or focal_length (with sensor_height), not both");
    // 180 degrees is an infinitely wide image plane (tan 90 degrees): every ray misses.
    c.verticalFovDegrees = r.number("fov", 40.0, {0.0, 180.0, true, true});
    if (r.has("focal_length")) {
        // A full-frame sensor is 24 mm high.
        const double f = r.requiredNumber("focal_length", Range::positive());
        const double h = r.number("sensor_height", 24.0, Range::positive());
        c.verticalFovDegrees = glm::degrees(2.0 * std::atan(0.5 * h / f));
        if (!(c.verticalFovDegrees < 180.0))
            r.failAt("focal_length",
                     "is too short for the sensor: the field of view is 180 degrees");
    }
    // Lens points are ray origins.
    c.apertureRadius = r.number("aperture_radius", 0.0, {0.0, kMaxSceneCoordinate});
    c.focusDistance =
        r.number("focus_distance", glm::length(c.lookAt - c.position),
                 {0.0, 2 * kMaxSceneCoordinate, true});  // the focal point is a ray's target
    c.handedness = r.choice("handedness", Handedness::Right, kHandednessNames);
    if (*kind == CameraKind::ThinLens && c.apertureRadius == 0)
        r.failAt("aperture_radius", "a thin_lens camera needs an aperture_radius > 0");
    r.finish();
    return c;
}

namespace {

// The sensor's keys (film_response.h). The white balance is the CIE daylight locus, which CIE
// 15:2004 defines from 4000 K to 25000 K.
void readSensor(const JsonReader& r, FilmDesc& film) {
    film.iso = r.number("iso", 100.0, Range::positive());
    film.exposureTime = r.number("exposure_time", 1.0, Range::positive());
    film.scale = r.number("scale", 1.0, Range::positive());
    if (!(film.imagingRatio() > 0 && film.imagingRatio() < 1e30))
        r.fail("exposure_time x iso / 100 x scale must be a positive number below 1e30");
    film.maxComponentValue = r.optionalNumber("max_component_value", Range::positive());
    film.whiteBalance = r.number("white_balance", 0.0, Range::nonNegative());
    if (film.whiteBalance != 0 && !(film.whiteBalance >= 4000 && film.whiteBalance <= 25000))
        r.failAt("white_balance",
                 "expected 0 (none) or a colour temperature in [4000, 25000] kelvin (the CIE "
                 "daylight locus)");
}

}  // namespace

FilmDesc readFilm(const JsonReader& r) {
    r.expectObject();
    FilmDesc film;
    if (r.has("resolution")) {
        const auto res = r.requiredArray<2>("resolution", {1.0, 65536.0});
        if (res[0] != std::floor(res[0]) || res[1] != std::floor(res[1]))
            r.failAt("resolution", "expected two integers");
        film.width = int(res[0]);
        film.height = int(res[1]);
    }
    if (const auto f = r.optionalChild("filter")) {
        f->expectObject();
        film.filter = f->choice("type", FilterKind::Box, kFilterNames);
        const double defaultRadius = film.filter == FilterKind::Box        ? 0.5
                                     : film.filter == FilterKind::Triangle ? 2.0
                                                                           : 1.5;
        film.filterRadius = f->number("radius", defaultRadius, {0.0, 16.0, true});
        if (f->has("sigma")) {
            if (film.filter != FilterKind::Gaussian)
                f->failAt("sigma", "only a gaussian filter takes sigma");
            // Below radius / 8 the truncated Gaussian is a spike the 512-bin sampling table
            // cannot resolve; above 4 radius, exp(-x^2 / (2 sigma^2)) minus its tail cancels
            // to float rounding.
            film.filterSigma = f->number("sigma", film.filterRadius / 3,
                                         {film.filterRadius / 8, 4 * film.filterRadius});
        }
        f->finish();
    }
    readSensor(r, film);
    if (r.has("crop")) {
        // Half-open pixel bounds [x0, x1) x [y0, y1) inside the resolution.
        const auto c = r.requiredArray<4>("crop", {0.0, 65536.0});
        for (double v : c)
            if (v != std::floor(v)) r.failAt("crop", "expected four integers X0, X1, Y0, Y1");
        const PixelBounds b{int(c[0]), int(c[1]), int(c[2]), int(c[3])};
        if (!(b.x0 < b.x1 && b.x1 <= film.width && b.y0 < b.y1 && b.y1 <= film.height))
            r.failAt("crop", "expected 0 <= X0 < X1 <= " + std::to_string(film.width) +
                                 " and 0 <= Y0 < Y1 <= " + std::to_string(film.height) +
                                 " (the resolution)");
        film.crop = b;
    }
    r.finish();
    return film;
}

void readIntegrator(const JsonReader& r, RenderSettings& settings) {
    r.expectObject();
    settings.integrator = r.choice("type", IntegratorKind::Path, kIntegratorNames);
    settings.mis = r.choice("mis", MisHeuristic::Power, kMisHeuristicNames);
    settings.maxDepth = r.integer("max_depth", 16, 1, 1024);
    settings.russianRouletteDepth = r.integer("rr_depth", 5, 1, 1024);
    settings.lightSelection =
        r.choice("light_selection", LightSelection::Bvh, kLightSelectionNames);
    if (r.has("next_event") && settings.integrator != IntegratorKind::Path)
        r.failAt("next_event", "only the path integrator takes next_event");
    settings.nextEvent = r.boolean("next_event", true);
    r.finish();
}

void readSampler(const JsonReader& r, RenderSettings& settings) {
    r.expectObject();
    settings.sampler = r.choice("type", SamplerKind::Sobol, kSamplerNames);
    settings.spp = r.integer("spp", 16, 1, 1 << 24);
    settings.seed = std::uint64_t(r.integer("seed", 0, 0, 2147483647));
    r.finish();
}

}  // namespace lamina::render
