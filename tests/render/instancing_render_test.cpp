// Instances and alpha cut-outs in renders, for the path, light and bdpt integrators:
// - scenes/reciprocity/cutouts.json without its cut-outs renders the same image with its
//   object instanced as with the object's shapes written out at each instance (within float
//   rounding: Embree intersects an instance in object space and a copy in world space, so
//   hit points differ by a few ULPs and an occasional path takes another turn; not bit for bit);
// - a shape of alpha 0 leaves the image bit for bit as it is without the shape;
// - an alpha 0.5 screen between a lamp and a floor halves the floor's irradiance, and so the
//   image of the floor (analytic; four standard errors of the two images' means).
// The integrators' agreement on the scene with its cut-outs is in integrator_agreement_test.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "render_helpers.h"
#include "source_files.h"

namespace lamina::render {
namespace {

Json cutoutsSceneWithout(const std::vector<std::string>& names) {
    std::ifstream in(testing::sourceFile("scenes/reciprocity/cutouts.json"));
    std::stringstream text;
    text << in.rdbuf();
    Json j = parseJsonText(text.str(), {"cutouts.json", "."});
    Json kept = Json::array();
    for (const Json& s : j["shapes"])
        if (std::find(names.begin(), names.end(), s.value("name", "")) == names.end())
            kept.push_back(s);
    j["shapes"] = kept;
    return j;
}

// The object's shapes placed by each instance's transform, as shapes (the object's shapes
// have no transform of their own here).
Json writtenOut(const Json& scene) {
    Json j = scene;
    Json shapes = Json::array();
    for (const Json& s : scene["shapes"]) {
        if (s["type"] != "instance") {
            shapes.push_back(s);
            continue;
        }
        for (Json shape : scene["objects"][s["object"].get<std::string>()]) {
            EXPECT_FALSE(shape.contains("transform"));
            shape["transform"] = s["transform"];
            shapes.push_back(shape);
        }
    }
    j["shapes"] = shapes;
    j.erase("objects");
    return j;
}

RenderResult renderWith(const SceneDesc& scene, IntegratorKind integrator, int spp) {
    RenderOptions o;
    o.integrator = integrator;
    o.spp = spp;
    o.seed = 7;
    o.resolution = std::make_pair(32, 32);
    o.threads = 2;
    return renderScene(scene, o);
}

const IntegratorKind kIntegrators[] = {IntegratorKind::Path, IntegratorKind::Light,
                                       IntegratorKind::Bdpt};

TEST(InstancingRender, InstancesRenderLikeTheirCopiesWrittenOut) {
    const Json instancedJson = cutoutsSceneWithout({"screen", "panel"});
    const SceneDesc instanced = testing::sceneFromText(instancedJson.dump());
    const SceneDesc copies = testing::sceneFromText(writtenOut(instancedJson).dump());
    ASSERT_EQ(instanced.instances.size(), 3u);
    ASSERT_TRUE(copies.instances.empty());
    for (const IntegratorKind integrator : kIntegrators) {
        const auto a = renderWith(instanced, integrator, 16);
        const auto b = renderWith(copies, integrator, 16);
        double sumA = 0, sumB = 0;
        int close = 0, equal = 0;
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 32; ++x) {
                const double pa = luminance(a.film->pixel(x, y));
                const double pb = luminance(b.film->pixel(x, y));
                sumA += pa;
                sumB += pb;
                close += std::abs(pa - pb) <= 1e-3 * std::max(pb, 1e-3);
                equal += pa == pb;
            }
        const std::string name(kIntegratorNames.name(integrator));
        std::printf("  %-5s %d of 1024 pixels equal, %d within 1e-3; mean ratio %.6f\n",
                    name.c_str(), equal, close, sumA / sumB);
        ASSERT_GT(sumB, 0.0) << name;
        // Float rounding moves hit points by ULPs; a few paths (an edge, a roulette decision
        // at its threshold) turn elsewhere and change their pixel by a sample's worth.
        // Measured: every pixel within 1e-3, a fifth to two thirds of them bit for bit.
        EXPECT_GE(close, 1024 * 99 / 100) << name;
        EXPECT_NEAR(sumA / sumB, 1.0, 1e-3) << name;
    }
}

TEST(AlphaRender, AShapeOfAlphaZeroLeavesTheImageAsWithoutIt) {
    Json with = cutoutsSceneWithout({"screen", "panel"});
    const SceneDesc without = testing::sceneFromText(with.dump());
    with["shapes"].push_back(Json::parse(
        R"({"type": "sphere", "material": "clay", "center": [0, 0.8, -1], "radius": 0.5,
            "alpha": 0})"));
    const SceneDesc invisible = testing::sceneFromText(with.dump());
    for (const IntegratorKind integrator : kIntegrators) {
        const auto a = renderWith(invisible, integrator, 4);
        const auto b = renderWith(without, integrator, 4);
        int equal = 0;
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 32; ++x)
                equal += a.film->pixel(x, y) == b.film->pixel(x, y);
        EXPECT_EQ(equal, 1024) << kIntegratorNames.name(integrator);
    }
}

// A floor (reflectance 0.5) under a black lamp of radiance 1, and between them a black screen
// of alpha `alpha` covering the lamp's whole view of the floor; the camera sits below the
// screen. Every path from the floor to the lamp crosses the screen once, and nothing else
// reflects: the floor's image is alpha-times-nothing plus (1 - alpha) times the open image.
std::string halfScreenScene(const std::string& screenAlpha) {
    return std::string(R"({
      "camera": {"position": [0, 0.4, -1.5], "look_at": [0, 0, 0], "fov": 40},
      "materials": {"floor": {"type": "lambert", "reflectance": 0.5},
                    "black": {"type": "lambert", "reflectance": 0}},
      "shapes": [
        {"type": "rectangle", "material": "floor",
         "transform": [{"rotate": {"axis": [1, 0, 0], "angle": -90}}, {"scale": 3}]},
        {"type": "rectangle", "material": "black", "alpha": )") +
           screenAlpha + R"(,
         "transform": [{"rotate": {"axis": [1, 0, 0], "angle": 90}}, {"scale": 50},
                       {"translate": [0, 0.8, 0]}]},
        {"type": "rectangle", "material": "black", "emission": {"radiance": 1},
         "transform": [{"rotate": {"axis": [1, 0, 0], "angle": 90}}, {"scale": 2},
                       {"translate": [0, 1.2, 0]}]}
      ]})";
}

TEST(AlphaRender, AHalfTransparentScreenHalvesTheIrradianceItPasses) {
    const SceneDesc open = testing::sceneFromText(halfScreenScene("0"));
    const SceneDesc half = testing::sceneFromText(halfScreenScene("0.5"));
    for (const IntegratorKind integrator : kIntegrators) {
        const int spp = integrator == IntegratorKind::Light ? 64 : 32;
        const auto a = testing::imageMean(*renderWith(half, integrator, spp).film, 1);
        const auto b = testing::imageMean(*renderWith(open, integrator, spp).film, 1);
        ASSERT_GT(b.mean, 0.0);
        // Ratio's standard error from the two independent means (first-order propagation).
        const double ratio = a.mean / b.mean;
        const double se = ratio * std::hypot(a.standardError / a.mean, b.standardError / b.mean);
        EXPECT_NEAR(ratio, 0.5, 4 * se + 1e-9) << kIntegratorNames.name(integrator) << " se " << se;
        EXPECT_LT(se, 0.02) << kIntegratorNames.name(integrator);
    }
}

}  // namespace
}  // namespace lamina::render
