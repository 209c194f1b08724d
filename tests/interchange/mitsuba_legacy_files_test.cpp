// Mitsuba 0.6 scene files, as Bitterli's rendering resources and other collections publish
// them: camelCase parameter names (mitsuba3 src/core/parser.cpp upgrades files of version < 2
// the same way), the `ldrfilm`, the quasi-random samplers `sobol`, `halton` and `hammersley`,
// the path integrator's `strictNormals`, and a conductor's `extEta`. Each is compared with
// what Mitsuba 0.6 documents for it (its plugin documentation, named at each test).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "lamina/interchange/scene_import.h"
#include "lamina/scene/scene_description.h"
#include "scratch_directory.h"

namespace lamina::render {
namespace {

using lamina::testing::errorOf;

// A Cornell-box header in the style of the Mitsuba 0.6 ports of Bitterli's scenes.
constexpr const char* kHeader = R"(<scene version="0.6.0">
<integrator type="path">
  <integer name="maxDepth" value="65"/>
  <boolean name="strictNormals" value="true"/>
</integrator>
<sensor type="perspective">
  <float name="fov" value="19.5"/>
  <transform name="toWorld"><lookat origin="0, 1, 6.8" target="0, 1, 0" up="0, 1, 0"/></transform>
  <sampler type="sobol"><integer name="sampleCount" value="64"/></sampler>
  <film type="ldrfilm">
    <integer name="width" value="64"/><integer name="height" value="48"/>
    <string name="fileFormat" value="png"/><string name="pixelFormat" value="rgb"/>
    <float name="gamma" value="2.2"/><float name="exposure" value="0.5"/>
    <boolean name="banner" value="false"/>
    <rfilter type="tent"/>
  </film>
</sensor>
<shape type="rectangle">
  <emitter type="area"><rgb name="radiance" value="17, 12, 4"/></emitter>
</shape>
)";

class MitsubaLegacyFiles : public lamina::testing::ScratchDirectoryTest {
  protected:
    ImportedScene import(const std::string& body) {
        file_ = write("legacy.xml", std::string(kHeader) + body + "</scene>\n");
        return importScene(file_, dir_);
    }
    std::string where(int line) const { return file_.string() + ":" + std::to_string(line); }
    std::filesystem::path file_;
};

// Mitsuba 0.6's ldrfilm is hdrfilm's image tonemapped into 8 bits (its documentation: gamma,
// exposure, Reinhard's key and burn); lamina keeps the linear image and says so once. sobol
// (and halton, hammersley) are quasi-random samplers with the independent sampler's
// expectation: lamina's scrambled Sobol points. maxDepth 65 counts the emitter vertex (lamina's
// 64), and strictNormals is warned about.
TEST_F(MitsubaLegacyFiles, ACornellBoxHeaderTranslates) {
    const ImportedScene s = import("");
    EXPECT_EQ(s.scene["film"]["resolution"], Json::parse("[64, 48]"));
    EXPECT_EQ(s.scene["film"]["filter"]["type"], "triangle");
    EXPECT_EQ(s.scene["sampler"], Json::parse(R"({"type": "sobol", "spp": 64})"));
    EXPECT_EQ(s.scene["integrator"]["type"], "path");
    EXPECT_EQ(s.scene["integrator"]["max_depth"], 64);
    int ldr = 0, strict = 0;
    for (const std::string& w : s.warnings) {
        ldr += w.find("ldrfilm became lamina's film") != std::string::npos;
        strict += w.find("strict_normals ignored") != std::string::npos;
    }
    EXPECT_EQ(ldr, 1) << ::testing::PrintToString(s.warnings);
    EXPECT_EQ(strict, 1);
    EXPECT_NO_THROW(loadScene(file_));
    for (const char* sampler : {"halton", "hammersley"}) {
        std::string header = kHeader;
        header.replace(header.find("\"sobol\""), 7, std::string("\"") + sampler + "\"");
        file_ = write("other.xml", header + "</scene>\n");
        EXPECT_EQ(importScene(file_, dir_).scene["sampler"]["type"], "sobol") << sampler;
    }
}

// Mitsuba 0.6's conductor and roughconductor take extEta, the index of the dielectric outside
// the metal (air by default): its Fresnel equations see (eta + i k) / extEta, which lamina's
// conductor gets as eta and k divided by it (numbers, rgb and spectra alike). A named metal
// keeps lamina's table, so extEta other than air is refused there.
TEST_F(MitsubaLegacyFiles, ConductorsExtEtaDividesEtaAndK) {
    const ImportedScene s = import(R"(<bsdf type="roughconductor" id="m">
  <rgb name="eta" value="0.2, 0.9, 1.1"/><float name="k" value="3"/>
  <float name="extEta" value="1.5"/><float name="alpha" value="0.1"/>
</bsdf>
<bsdf type="conductor" id="n"><string name="material" value="Cu"/>
  <string name="extEta" value="air"/></bsdf>
<shape type="sphere"><ref id="m"/></shape>
<shape type="sphere"><point name="center" x="3" y="0" z="0"/><ref id="n"/></shape>
)");
    const Json& m = s.scene["materials"]["m"];
    ASSERT_TRUE(m["eta"].is_array());
    EXPECT_DOUBLE_EQ(m["eta"][0].get<double>(), 0.2 / 1.5);
    EXPECT_DOUBLE_EQ(m["eta"][2].get<double>(), 1.1 / 1.5);
    EXPECT_DOUBLE_EQ(m["k"].get<double>(), 2.0);
    EXPECT_EQ(s.scene["materials"]["n"]["material"], "Cu");
    EXPECT_NO_THROW(loadScene(file_));
    const std::string e = errorOf([&] {
        import(R"(<bsdf type="conductor" id="n"><string name="material" value="Au"/>
<float name="extEta" value="1.33"/></bsdf>
<shape type="sphere"><ref id="n"/></shape>
)");
    });
    EXPECT_EQ(e, where(21) +
                     ": <bsdf type=\"conductor\">: ext_eta other than air (1.000277) or vacuum "
                     "is supported only with eta and k");
}

}  // namespace
}  // namespace lamina::render
