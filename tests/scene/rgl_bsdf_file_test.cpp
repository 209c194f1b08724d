// RGL material files (rgl_bsdf_file.h) and the `measured` material in scenes:
// - a file written in the RGL layout (rgl_file_writer.h) reads back into the table the fields
//   make in memory, value for value;
// - hostile files (truncated, wrong magic or version, an unknown type, data beyond the end,
//   shapes larger than the file, a field twice or missing, a wrong type or shape, NaN, a
//   decreasing grid) are refused with one InputError line naming the file, never a crash;
// - a scene's measured material reads its file when the scene loads, and a file named twice is
//   read once;
// - pbrt-v4's `Material "measured"` and Mitsuba 3's `<bsdf type="measured">` become it.
#include <gtest/gtest.h>

#include <limits>

#include "lamina/bsdf/conductor.h"
#include "lamina/bsdf/measured.h"
#include "lamina/bsdf/mix.h"
#include "lamina/interchange/scene_import.h"
#include "lamina/scene/rgl_bsdf_file.h"
#include "lamina/scene/scene_description.h"
#include "rgl_file_writer.h"
#include "scratch_directory.h"

namespace lamina::render {
namespace {

using testing::errorOf;
using testing::TensorField;

using Spec = Rgb<double>;

std::vector<TensorField> conductorFields(bool spectral = false) {
    const MicrofacetDistribution<double> d(NdfKind::Ggx, 0.3, 0.3);
    const ConductorBxdf<Spec> c(MicrofacetReflectionLobe<Spec>(
        d, Fresnel<Spec>::conductor(Spec(0.18, 0.42, 1.37), Spec(3.42, 2.35, 1.77))));
    testing::RglTabulation t;
    t.thetaCount = 6;
    t.ndfSize = 16;
    t.vndfSize = 12;
    t.valueSize = 8;
    t.spectral = spectral;
    return testing::rglFields(c, d, t);
}

TensorField* find(std::vector<TensorField>& fields, const std::string& name) {
    for (TensorField& f : fields)
        if (f.name == name) return &f;
    return nullptr;
}

class RglBsdfFile : public testing::ScratchDirectoryTest {
  protected:
    std::filesystem::path file(const std::vector<TensorField>& fields,
                               const std::string& name = "m.bsdf") {
        return write(name, testing::tensorFileBytes(fields));
    }
    std::string refusal(const std::vector<TensorField>& fields) {
        const auto path = file(fields);
        return errorOf([&] { readRglBsdfFile(path); });
    }
    std::string refusalOfBytes(const std::string& bytes) {
        const auto path = write("m.bsdf", bytes);
        return errorOf([&] { readRglBsdfFile(path); });
    }
    std::string name() const { return (dir_ / "m.bsdf").string(); }
};

TEST_F(RglBsdfFile, ReadsBackTheTableItsFieldsMake) {
    for (bool spectral : {false, true}) {
        const auto fields = conductorFields(spectral);
        const MeasuredBsdfTable read = readRglBsdfFile(file(fields));
        const MeasuredBsdfTable made(testing::measuredFields(fields));
        EXPECT_EQ(read.description(), "lamina test: a microfacet BSDF tabulated");
        EXPECT_EQ(read.spectral(), spectral);
        EXPECT_EQ(read.valueShape(), (std::vector<std::size_t>{1, 6, 3, 8, 8}));
        int checked = 0;
        for (double a = 0.1; a < 1.4; a += 0.23)
            for (double b = 0.05; b < 6.2; b += 0.61) {
                const Vec3d wo(std::sin(a), 0.2, std::cos(a));
                const Vec3d wi(std::sin(b) * 0.7, std::cos(b) * 0.7, 0.714);
                const auto r = read.lookup(glm::normalize(wo), wi),
                           m = made.lookup(glm::normalize(wo), wi);
                ASSERT_TRUE(r && m);
                EXPECT_EQ(r->pdf, m->pdf);
                for (int c = 0; c < 3; ++c)
                    EXPECT_EQ(read.rgbValue(*r, c), made.rgbValue(*m, c));
                ++checked;
            }
        EXPECT_GT(checked, 40);
    }
}

TEST_F(RglBsdfFile, BrokenContainersAreRefusedWithOneLine) {
    const std::string good = testing::tensorFileBytes(conductorFields());
    EXPECT_EQ(refusalOfBytes(""), name() + ": the file ends inside the header");
    EXPECT_EQ(refusalOfBytes(good.substr(0, 13)), name() + ": the file ends inside the version");
    EXPECT_EQ(refusalOfBytes(good.substr(0, 15)),
              name() + ": the file ends inside the field count");
    EXPECT_EQ(refusalOfBytes("tensor_filX" + good.substr(11)),
              name() +
                  ": expected a tensor file (an RGL .bsdf file): it starts with "
                  "\"tensor_file\"");
    std::string version = good;
    version[12] = 2;
    EXPECT_EQ(refusalOfBytes(version), name() + ": expected a tensor file of version 1.0, got 2.0");
    // Every cut inside the header or the data is refused, never read past the end.
    for (std::size_t cut = 18; cut < good.size(); cut += 97) {
        const std::string message = refusalOfBytes(good.substr(0, cut));
        EXPECT_EQ(message.rfind(name() + ": ", 0), 0u) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos);
    }
}

TEST_F(RglBsdfFile, HostileHeadersAllocateNothing) {
    auto fields = conductorFields();
    find(fields, "vndf")->shape = {1, 6, std::uint64_t(1) << 40, std::uint64_t(1) << 40};
    EXPECT_EQ(refusal(fields),
              name() + ": field \"vndf\": its shape holds more data than the file");
    fields = conductorFields();
    find(fields, "ndf")->shape = {std::numeric_limits<std::uint64_t>::max(), 3};
    EXPECT_EQ(refusal(fields), name() + ": field \"ndf\": its shape holds more data than the file");
    // A field count of four billion: the file ends long before.
    std::string bytes = testing::tensorFileBytes(conductorFields());
    for (int i = 14; i < 18; ++i)
        bytes[std::size_t(i)] = char(0xff);
    EXPECT_EQ(refusalOfBytes(bytes).rfind(name() + ": ", 0), 0u);
    fields = conductorFields();
    find(fields, "sigma")->type = 12;
    EXPECT_EQ(refusal(fields), name() + ": field \"sigma\": unknown type 12");
}

TEST_F(RglBsdfFile, WrongFieldsAreRefusedByName) {
    auto without = [](const std::string& name) {
        auto fields = conductorFields();
        fields.erase(std::find_if(fields.begin(), fields.end(),
                                  [&](const TensorField& f) { return f.name == name; }));
        return fields;
    };
    EXPECT_EQ(refusal(without("vndf")), name() + ": the field \"vndf\" is missing");
    EXPECT_EQ(refusal(without("rgb")),
              name() + ": expected the field \"spectra\" (with \"wavelengths\") or \"rgb\"");
    auto twice = conductorFields();
    twice.push_back(twice[2]);
    EXPECT_EQ(refusal(twice), name() + ": field \"theta_i\" appears twice");
    auto type = conductorFields();
    find(type, "ndf")->type = 11;
    EXPECT_EQ(refusal(type), name() + ": field \"ndf\": expected float32 values, got type 11");
    auto shape = conductorFields();
    find(shape, "luminance")->shape = {1, 5, 8, 8};
    find(shape, "luminance")->data.resize(5 * 64 * 4);
    EXPECT_EQ(refusal(shape),
              name() +
                  ": field \"luminance\": expected the shape [1, 6, >= 2, >= 2], got "
                  "[1, 5, 8, 8]");
    auto nan = conductorFields();
    const float bad = std::numeric_limits<float>::quiet_NaN();
    std::memcpy(find(nan, "rgb")->data.data() + 40, &bad, 4);
    EXPECT_EQ(refusal(nan), name() + ": field \"rgb\": holds a value that is not a finite number");
    auto order = conductorFields();
    *find(order, "theta_i") =
        TensorField::floats("theta_i", {6}, {0.0f, 0.1f, 0.3f, 0.2f, 0.4f, 0.5f});
    EXPECT_EQ(refusal(order), name() + ": field \"theta_i\": expected increasing values");
    auto phi = conductorFields();
    const std::vector<float> angles{-1.0f, 0.0f, 0.3f};
    *find(phi, "phi_i") = TensorField::floats("phi_i", {3}, angles);
    EXPECT_EQ(refusal(phi), name() +
                                ": field \"vndf\": expected the shape [3, 6, >= 2, >= 2], "
                                "got [1, 6, 12, 12]");
}

TEST_F(RglBsdfFile, ASceneReadsItsMeasuredFilesOnce) {
    file(conductorFields());
    const auto scene = write("scene.json", R"({
  "camera": {"position": [0, 0, 3], "look_at": [0, 0, 0], "fov": 40},
  "film": {"resolution": [8, 8]},
  "materials": {"gold": {"type": "measured", "filename": "m.bsdf"},
                "mixed": {"type": "mix", "a": {"type": "measured", "filename": "m.bsdf"},
                          "b": {"type": "lambert"}}},
  "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "gold"},
             {"type": "sphere", "center": [2, 0, 0], "radius": 1, "material": "mixed"}],
  "lights": [{"type": "point", "position": [0, 2, 2], "intensity": 10}]
})");
    const SceneDesc s = loadScene(scene, false);
    ASSERT_EQ(s.materials.size(), 2u);
    const auto& gold = s.materials[0].model.as<MeasuredMaterial>();
    const auto& mix = s.materials[1].model.as<MixMaterial>();
    const auto& inner = mix.a->model.as<MeasuredMaterial>();
    ASSERT_TRUE(gold.slot->table);
    EXPECT_EQ(gold.slot->table, inner.slot->table);
    // A broken file: one line naming it.
    write("m.bsdf", "tensor_file");
    const std::string message = errorOf([&] { loadScene(scene, false); });
    EXPECT_EQ(message, name() + ": the file ends inside the header");
}

TEST_F(RglBsdfFile, PbrtAndMitsubaMeasuredMaterialsBecomeIt) {
    file(conductorFields());
    const auto pbrt = write("s.pbrt",
                            "LookAt 0 0 0  0 0 1  0 1 0\nCamera \"perspective\"\nWorldBegin\n"
                            "LightSource \"point\" \"rgb I\" [1 1 1]\n"
                            "Material \"measured\" \"string filename\" \"m.bsdf\"\n"
                            "Shape \"sphere\"\n");
    const ImportedScene p = importScene(pbrt, dir_);
    EXPECT_EQ(p.scene["materials"]["pbrt_material_1"],
              Json::parse(R"({"type": "measured", "filename": "m.bsdf"})"));
    EXPECT_NO_THROW(loadScene(pbrt, false));
    EXPECT_EQ(errorOf([&] {
                  importScene(
                      write("t.pbrt", "WorldBegin\nMaterial \"measured\"\nShape \"sphere\"\n"),
                      dir_);
              }),
              (dir_ / "t.pbrt").string() + ":2: measured: no \"string filename\" parameter");

    const auto xml = write("scene.xml",
                           "<scene version=\"3.0.0\">\n<bsdf type=\"measured\" id=\"m\">"
                           "<string name=\"filename\" value=\"m.bsdf\"/></bsdf>\n"
                           "<shape type=\"sphere\"><ref id=\"m\"/>"
                           "<emitter type=\"area\"/></shape>\n</scene>\n");
    const ImportedScene m = importScene(xml, dir_);
    const Json expected{{"type", "measured"},
                        {"filename", std::filesystem::absolute(dir_ / "m.bsdf").string()}};
    EXPECT_EQ(m.scene["materials"]["m"], expected);
    EXPECT_NO_THROW(loadScene(xml, false));
}

}  // namespace
}  // namespace lamina::render
