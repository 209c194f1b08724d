// The optical sheets `polariser` and `retarder` (optical_sheet.h, docs/polarisation.md,
// "Optical sheets"): their readers and registrations. Their axes are world directions, which
// the polarised mode turns into each hit's shading frame (orient).
#include "lamina/bsdf/material_kind.h"
#include "lamina/bsdf/optical_sheet.h"
#include "lamina/core/json_reader.h"
#include "material_readers.h"

namespace lamina {

namespace {

// A world direction; only its line matters (a polariser's axis and its opposite are the same).
Vec3d readAxis(const JsonReader& r) {
    if (!r.has("axis")) r.failAt("axis", "missing; expected a direction [x, y, z] in the world");
    const auto a = r.requiredArray<3>("axis", {-1e6, 1e6});
    const Vec3d axis(a[0], a[1], a[2]);
    if (!(glm::length(axis) > 0)) r.failAt("axis", "expected a non-zero direction");
    return glm::normalize(axis);
}

MaterialModel readPolariser(const JsonReader& r) {
    PolariserMaterial p;
    p.axis = readAxis(r);
    p.transmittance = r.number("transmittance", 1.0, Range::unit());
    return p;
}

MaterialModel readRetarder(const JsonReader& r) {
    RetarderMaterial t;
    t.axis = readAxis(r);
    t.retardanceDegrees = r.number("retardance", 90.0, {-360.0, 360.0});
    return t;
}

// The shading frame's coordinates of a world axis (a frame's rows are its axes).
Vec3d toFrame(const Vec3d& axis, const Frame<double>& frame) {
    return frame.toLocal(axis);
}

void orientPolariser(MaterialModel& model, const Frame<double>& frame) {
    auto& p = model.as<PolariserMaterial>();
    p.axis = toFrame(p.axis, frame);
}

void orientRetarder(MaterialModel& model, const Frame<double>& frame) {
    auto& t = model.as<RetarderMaterial>();
    t.axis = toFrame(t.axis, frame);
}

}  // namespace

extern const MaterialKind kPolariserMaterial{
    .name = "polariser",
    .listPosition = 140,
    .read = readPolariser,
    .schema = R"json({
  "type": "object",
  "description": "An ideal linear polariser sheet: light crosses it without turning; the polarised mode passes the component along the axis (projected perpendicular to the light), the other modes half of the light.",
  "required": ["type", "axis"],
  "additionalProperties": false,
  "properties": {
    "type": {"const": "polariser"},
    "axis": {"$ref": "#/$defs/vec3", "description": "the transmission axis, a direction in the world"},
    "transmittance": {"type": "number", "minimum": 0, "maximum": 1, "default": 1}
  },
  "examples": [{"type": "polariser", "axis": [1, 0, 0]}]
})json",
    .orient = orientPolariser,
    .polarisation = "a linear polariser at its axis",
    .transmits = [](const MaterialModel&) { return true; }};

extern const MaterialKind kRetarderMaterial{.name = "retarder",
                                            .listPosition = 150,
                                            .read = readRetarder,
                                            .schema = R"json({
  "type": "object",
  "description": "An ideal linear retarder sheet (a wave plate): light crosses it without turning; the polarised mode delays the component perpendicular to the fast axis by the retardance, the other modes see a clear sheet.",
  "required": ["type", "axis"],
  "additionalProperties": false,
  "properties": {
    "type": {"const": "retarder"},
    "axis": {"$ref": "#/$defs/vec3", "description": "the fast axis, a direction in the world"},
    "retardance": {"type": "number", "minimum": -360, "maximum": 360, "default": 90, "description": "degrees, at every wavelength (90: a quarter-wave plate)"}
  },
  "examples": [{"type": "retarder", "axis": [1, 1, 0], "retardance": 90}]
})json",
                                            .orient = orientRetarder,
                                            .polarisation = "a linear retarder at its axis",
                                            .transmits = [](const MaterialModel&) { return true; }};

}  // namespace lamina
