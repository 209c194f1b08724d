// The scene file formats lamina reads, by name. On its own so that the scene description can
// say which format a scene came from without the importers' header, which brings in the JSON
// library (the costliest header of the build).
#pragma once

#include <array>

#include "lamina/core/name_table.h"

namespace lamina::render {

/// The formats `lamina render`, `info` and `convert` read.
enum class SceneFormat { Lamina, Pbrt, Mitsuba };
inline constexpr NameTable kSceneFormatNames{
    std::array{NameEntry{SceneFormat::Lamina, "lamina"}, NameEntry{SceneFormat::Pbrt, "pbrt-v4"},
               NameEntry{SceneFormat::Mitsuba, "mitsuba"}}};

}  // namespace lamina::render
