// Names the lamina scene document reserves (docs/media.md), which both translators write. The
// translators know nothing of lamina_scene's types, so they name the document's words here.
#pragma once

namespace lamina::render {

/// A shape's `"material": "interface"`: an index-matched boundary between two media.
inline constexpr const char* kDocumentInterfaceMaterial = "interface";
/// The medium name that means no medium (`"interior": "vacuum"`).
inline constexpr const char* kDocumentVacuum = "vacuum";

}  // namespace lamina::render
