#include "pbrt_motion.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "pbrt_shapes.h"

namespace lamina::render::pbrt {

namespace {

// lamina interpolates an instance's matrices element by element (Embree's motion blur);
// pbrt-v4's AnimatedTransform decomposes them and turns the rotation by slerp. The two agree
// where the linear part stays put (translations) or only scales; a turning one is
// approximated, which is said once per moving entity.
void warnIfTurning(TranslationContext& ctx, const Location& at, const glm::dmat4& start,
                   const glm::dmat4& end) {
    const glm::dmat3 a(start), b(end);
    double change = 0, size = 0;
    for (int c = 0; c < 3; ++c) {
        const glm::dvec3 na = glm::normalize(a[c]), nb = glm::normalize(b[c]);
        change = std::max(change, glm::length(na - nb));
        size = std::max(size, glm::length(a[c]));
    }
    if (change > 1e-9)
        ctx.warn(at,
                 "a turning motion: lamina interpolates the start and end matrices element "
                 "by element, pbrt-v4 turns the rotation at constant speed (halfway through "
                 "a turn by A the object is scaled by cos(A / 2))");
}

Json instanceJson(const std::string& object, const glm::dmat4& start,
                  const std::optional<glm::dmat4>& end) {
    Json instance = {{"type", "instance"},
                     {"object", object},
                     {"transform", Json::array({Json{{"matrix", rowMajor(start)}}})}};
    if (end) instance["transform_end"] = Json::array({Json{{"matrix", rowMajor(*end)}}});
    return instance;
}

}  // namespace

void translateMovingShape(TranslationContext& ctx, const ShapeDef& s, Json& doc) {
    const Entity& e = s.entity;
    // pbrt-v4 (scene.cpp, CreatePrimitivesForAnimatedShapes): "Animated area lights are not
    // supported."
    if (s.areaLight)
        ctx.fail(e.location,
                 "a moving area light (ActiveTransform) is not supported (pbrt-v4 refuses it "
                 "too): give the emitting shape one transform");
    auto shape = translateShape(ctx, s, true);  // it becomes an object of its own
    if (!shape) return;
    warnIfTurning(ctx, e.location, e.transform, *e.transformEnd);
    // The object is the shape where it stands at the start; the instance carries it from
    // there: lerp(I, end start^-1) start = lerp(start, end), the same motion.
    const std::string name = "pbrt_moving_shape_" + std::to_string(e.location.line) + "_" +
                             std::to_string(doc.contains("objects") ? doc["objects"].size() : 0);
    doc["objects"][name] = Json::array({std::move(*shape)});
    doc["shapes"].push_back(
        instanceJson(name, glm::dmat4(1.0), *e.transformEnd * glm::inverse(e.transform)));
}

Json translateInstance(TranslationContext& ctx, const InstanceDef& i) {
    if (i.transformEnd) warnIfTurning(ctx, i.location, i.transform, *i.transformEnd);
    return instanceJson(i.object, i.transform, i.transformEnd);
}

void warnStandsStill(TranslationContext& ctx, const Entity& e, const std::string& what) {
    if (e.transformEnd)
        ctx.warn(e.location, what +
                                 " moves (ActiveTransform): lamina keeps it at its start "
                                 "transform (only shapes and instances move)");
}

void translateShutter(TranslationContext& ctx, const Entity& camera, Json& doc) {
    bool moves = false;
    for (const Json& shape : doc["shapes"])
        moves = moves || shape.contains("transform_end");
    if (!moves) return;
    const TransformTimes& t = ctx.scene.transformTimes;
    const double open = camera.params.number("shutteropen", 0),
                 close = camera.params.number("shutterclose", 1);
    // TransformTimes' start is lamina's time 0, its end time 1.
    const auto lamina = [&](double time) { return (time - t.start) / (t.end - t.start); };
    if (!(std::abs(lamina(open)) <= 1e6 && std::abs(lamina(close)) <= 1e6))
        ctx.fail(camera.location,
                 "the shutter times are too far from TransformTimes (at most "
                 "1e6 times its interval)");
    doc["camera"]["shutter"] = Json::array({lamina(open), lamina(close)});
}

}  // namespace lamina::render::pbrt
