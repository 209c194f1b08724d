// pbrt-v4's motion blur in lamina's scene document (docs/interchange.md, "Directives"):
// ActiveTransform changes the start or end transform alone, a moving shape becomes an object
// placed by a moving instance, a moving ObjectInstance a moving instance, and the shutter is
// written in lamina's time (TransformTimes' start 0, end 1) only when something moves. The
// document is compared exactly, and the loaded scene moves the way pbrt-v4 would: the
// interpolated transform at each end is the shape's own.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "lamina/interchange/scene_import.h"
#include "lamina/scene/scene_description.h"
#include "scratch_directory.h"

namespace lamina::render {
namespace {

using lamina::testing::errorOf;

class PbrtMotion : public lamina::testing::ScratchDirectoryTest {
  protected:
    ImportedScene import(const std::string& text) {
        file_ = write("s.pbrt", text);
        return importScene(file_, dir_);
    }
    std::string at(int line) const {
        return (dir_ / "s.pbrt").string() + ":" + std::to_string(line);
    }
    std::filesystem::path file_;
};

constexpr const char* kLight = "LightSource \"point\" \"rgb I\" [1 1 1]\n";

TEST_F(PbrtMotion, AMovingShapeIsAnObjectPlacedByAMovingInstance) {
    const ImportedScene s = import(std::string("TransformTimes 2 4\n"
                                               "Camera \"perspective\" \"float shutteropen\" 2.5 "
                                               "\"float shutterclose\" 3\n"
                                               "WorldBegin\n") +
                                   kLight + "Shape \"sphere\"\n" +
                                   "AttributeBegin\n"
                                   "  Translate 1 0 0\n"
                                   "  ActiveTransform EndTime\n"
                                   "  Translate 0 2 0\n"
                                   "  ActiveTransform All\n"
                                   "  Shape \"sphere\" \"float radius\" 0.5\n"
                                   "AttributeEnd\n");
    const Json& doc = s.scene;
    ASSERT_EQ(doc["shapes"].size(), 2u);
    // The still sphere stays a shape; the moving one is an instance of its own object.
    EXPECT_EQ(doc["shapes"][0]["type"], "sphere");
    const Json& instance = doc["shapes"][1];
    EXPECT_EQ(instance["type"], "instance");
    const std::string object = instance["object"];
    EXPECT_EQ(doc["objects"][object][0]["center"], Json::parse("[1, 0, 0]"));
    EXPECT_EQ(instance["transform"][0]["matrix"],
              Json::parse("[1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]"));
    EXPECT_EQ(instance["transform_end"][0]["matrix"],
              Json::parse("[1,0,0,0, 0,1,0,2, 0,0,1,0, 0,0,0,1]"));
    // pbrt's times 2.5 and 3 of TransformTimes [2, 4].
    EXPECT_EQ(doc["camera"]["shutter"], Json::parse("[0.25, 0.5]"));
    EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
    const SceneDesc scene = loadScene(file_);
    ASSERT_EQ(scene.instances.size(), 1u);
    EXPECT_TRUE(scene.hasMotion());
    EXPECT_EQ(scene.camera.shutter, (std::array<double, 2>{0.25, 0.5}));
}

TEST_F(PbrtMotion, AMovingInstanceMovesAndAStillSceneHasNoShutter) {
    const ImportedScene s = import(std::string("WorldBegin\n") + kLight +
                                   "ObjectBegin \"o\"\nShape \"sphere\"\nObjectEnd\n"
                                   "ActiveTransform StartTime\nTranslate -1 0 0\n"
                                   "ActiveTransform All\nObjectInstance \"o\"\n");
    const Json& instance = s.scene["shapes"][0];
    EXPECT_EQ(instance["transform"][0]["matrix"],
              Json::parse("[1,0,0,-1, 0,1,0,0, 0,0,1,0, 0,0,0,1]"));
    EXPECT_EQ(instance["transform_end"][0]["matrix"],
              Json::parse("[1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]"));
    EXPECT_EQ(s.scene["camera"]["shutter"], Json::parse("[0, 1]"));
    const ImportedScene still = import(std::string("WorldBegin\n") + kLight + "Shape \"sphere\"\n");
    EXPECT_FALSE(still.scene["camera"].contains("shutter"));
}

TEST_F(PbrtMotion, WhatLaminaCannotMoveIsSaidOrRefused) {
    const ImportedScene s = import(
        "ActiveTransform EndTime\nTranslate 0 0 1\n"
        "ActiveTransform All\nCamera \"perspective\"\n"
        "WorldBegin\nActiveTransform EndTime\nRotate 30 0 1 0\n"
        "ActiveTransform All\n"
        "LightSource \"point\" \"rgb I\" [1 1 1]\n"
        "Shape \"sphere\"\n");
    ASSERT_EQ(s.warnings.size(), 3u);
    EXPECT_EQ(s.warnings[0], at(4) +
                                 ": the camera moves (ActiveTransform): lamina keeps it at "
                                 "its start transform (only shapes and instances move)");
    EXPECT_THAT(s.warnings[1], ::testing::StartsWith(at(10) + ": a turning motion"));
    EXPECT_THAT(s.warnings[2], ::testing::StartsWith(at(9) + ": LightSource \"point\" moves"));
    EXPECT_EQ(errorOf([&] {
                  import(std::string("WorldBegin\n") + kLight +
                         "ActiveTransform EndTime\nTranslate 1 0 0\nActiveTransform All\n"
                         "AreaLightSource \"diffuse\"\nShape \"sphere\"\n");
              }),
              at(7) +
                  ": a moving area light (ActiveTransform) is not supported (pbrt-v4 "
                  "refuses it too): give the emitting shape one transform");
}

}  // namespace
}  // namespace lamina::render
