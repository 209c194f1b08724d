// lamina's OpenImageIO module (src/oiio), loaded the first time an image needs it: reading
// anything but EXR, writing anything but EXR and PNG. Found at $LAMINA_OIIO_MODULE if set, else
// where the build put it (compiled in), else beside the executable.
#pragma once

#include <filesystem>
#include <string>

#include "lamina/image/oiio_images_api.h"

namespace lamina::render {

/// The module's functions, loaded once (thread-safe). `action` ("reading", "writing") and
/// `file` name the work in the InputError "FILE: reading .jpg images needs lamina's
/// OpenImageIO module (PATH): REASON" if it cannot be loaded.
const oiio_images::Functions& oiioModule(const std::filesystem::path& file,
                                         const std::string& action);

}  // namespace lamina::render
