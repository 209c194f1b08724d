// pbrt-v4's motion blur (ActiveTransform StartTime / EndTime, TransformTimes, the camera's
// shutteropen and shutterclose) -> lamina's moving instances and camera shutter
// (docs/scene-format.md, "Motion blur"; pbrt_motion.cpp).
#pragma once

#include "pbrt_translation.h"

namespace lamina::render::pbrt {

/// A shape whose transform moves: an object of its own (the shape at its start transform),
/// placed by an instance that moves from the identity to end x start^-1, into `doc`'s
/// "objects" and "shapes". pbrt-v4 refuses a moving area light; so does this.
void translateMovingShape(TranslationContext& context, const ShapeDef& shape, Json& doc);
/// An ObjectInstance: a lamina instance, moving (`transform_end`) if its transform does.
Json translateInstance(TranslationContext& context, const InstanceDef& instance);
/// Warns of `what` (the camera, a light, a medium) whose transform moves: lamina keeps it at
/// its start transform, as pbrt-v4 does for lights and media.
void warnStandsStill(TranslationContext& context, const Entity& entity, const std::string& what);
/// The camera's `shutter` in lamina's time (TransformTimes' start 0, its end 1), written only
/// when something moves (a still scene's document is unchanged).
void translateShutter(TranslationContext& context, const Entity& camera, Json& doc);

}  // namespace lamina::render::pbrt
