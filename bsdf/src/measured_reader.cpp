// `measured`: an RGL measured BSDF (measured.h, docs/bsdf.md "measured"). The reader takes the
// file's path only: the scene library reads the file (rgl_bsdf_file.h, loadMeasuredTables).
#include "lamina/bsdf/material_kind.h"
#include "lamina/bsdf/measured.h"
#include "lamina/core/json_reader.h"
#include "material_readers.h"

namespace lamina {

namespace {

MaterialModel readMeasured(const JsonReader& r) {
    MeasuredMaterial m;
    m.slot->file = r.filePath("filename");
    return m;
}

void measuredData(const MaterialModel& model, std::vector<std::string>& out) {
    const MeasuredTableSlot& slot = *model.as<MeasuredMaterial>().slot;
    std::string what = "measured BSDF " + slot.file.filename().string();
    if (slot.table)
        what += slot.table->spectral()
                    ? " (" + std::to_string(slot.table->wavelengths().size()) + " wavelengths)"
                    : " (RGB)";
    out.push_back(what);
}

}  // namespace

extern const MaterialKind kMeasuredMaterial{.name = "measured",
                                            .listPosition = 160,
                                            .read = readMeasured,
                                            .schema = R"json({
  "type": "object",
  "description": "A measured BSDF of the RGL material database (Dupuy and Jakob 2018), read from its .bsdf file: glossy reflection, two-sided.",
  "required": ["type", "filename"],
  "additionalProperties": false,
  "properties": {
    "type": {"const": "measured"},
    "filename": {"type": "string", "description": "an RGL .bsdf file (spectra or rgb), relative to the scene file"}
  },
  "examples": [{"type": "measured", "filename": "../tests/fuzz/corpus/rgl_bsdf_file/isotropic_rgb.bsdf"}]
})json",
                                            .spectralData = measuredData};

}  // namespace lamina
