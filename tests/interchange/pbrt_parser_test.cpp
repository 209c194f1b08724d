// The pbrt-v4 tokenizer and parser (renderer/interchange/src/pbrt_tokenizer.h,
// pbrt_parser.h): tokens and their lines, the transform directives against matrices worked
// out by hand, the graphics-state stack, includes, and every error naming file and line.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "pbrt_parser.h"
#include "pbrt_tokenizer.h"
#include "scratch_directory.h"

namespace lamina::render::pbrt {
namespace {

using lamina::testing::errorOf;
using PbrtIncludes = lamina::testing::ScratchDirectoryTest;

ParsedScene parse(const std::string& text) {
    return parseText(text, "s.pbrt", ".");
}

std::string parseError(const std::string& text) {
    return errorOf([&] { parse(text); });
}

void expectMatrix(const glm::dmat4& actual, const glm::dmat4& expected) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            EXPECT_NEAR(actual[c][r], expected[c][r], 1e-12) << "row " << r << " column " << c;
}

TEST(PbrtTokenizer, TokensCarryTheirLines) {
    Tokenizer t("Shape # a comment \"not a string\"\n  \"sphere\" [ 1 -2.5e1 ]\n\"a\\\"b\\n\" +3",
                "f.pbrt");
    const std::vector<std::pair<Token::Kind, std::string>> expected = {
        {Token::Kind::Word, "Shape"},    {Token::Kind::String, "sphere"},
        {Token::Kind::OpenBracket, "["}, {Token::Kind::Number, "1"},
        {Token::Kind::Number, "-2.5e1"}, {Token::Kind::CloseBracket, "]"},
        {Token::Kind::String, "a\"b\n"}, {Token::Kind::Number, "+3"}};
    const int lines[] = {1, 2, 2, 2, 2, 2, 3, 3};
    for (std::size_t i = 0; i < expected.size(); ++i) {
        const auto token = t.next();
        ASSERT_TRUE(token);
        EXPECT_EQ(token->kind, expected[i].first) << i;
        EXPECT_EQ(token->text, expected[i].second) << i;
        EXPECT_EQ(token->line, lines[i]) << i;
    }
    EXPECT_FALSE(t.next());
}

TEST(PbrtTokenizer, NumbersAreParsedExactly) {
    Tokenizer t("-2.5e1 .5 +3", "f.pbrt");
    EXPECT_EQ(t.next()->number, -25.0);
    EXPECT_EQ(t.next()->number, 0.5);
    EXPECT_EQ(t.next()->number, 3.0);
}

TEST(PbrtTokenizer, BadInputIsRefusedWithItsLine) {
    auto error = [](const std::string& text) {
        return errorOf([&] {
            Tokenizer t(text, "f.pbrt");
            while (t.next()) {
            }
        });
    };
    EXPECT_EQ(error("Shape\n\"sphere"), "f.pbrt:2: a string is not closed (missing '\"')");
    EXPECT_EQ(error("\"a\nb\""), "f.pbrt:1: a string is not closed before the end of the line");
    EXPECT_EQ(error("\n\n1.2.3"), "f.pbrt:3: \"1.2.3\" is not a number");
    EXPECT_EQ(error("1e999"), "f.pbrt:1: \"1e999\" is not a number");
    EXPECT_EQ(error("Shape\x01\x02"), "f.pbrt:1: unexpected byte 0x01");
    EXPECT_EQ(error("\"\\q\""), "f.pbrt:1: unknown escape \\q in a string");
}

TEST(PbrtParser, TransformDirectivesComposeAsPbrtDoes) {
    // The current transform is post-multiplied by each directive (pbrt-v4 scene.cpp):
    // a point is scaled first, then rotated, then translated.
    const ParsedScene s = parse(
        "Translate 1 2 3\nRotate 90 0 0 1\nScale 2 2 2\nShape \"sphere\"\n"
        "Transform [1 0 0 0  0 1 0 0  0 0 1 0  4 5 6 1]\nShape \"sphere\"\n"
        "ConcatTransform 2 0 0 0  0 3 0 0  0 0 4 0  0 0 0 1\nShape \"sphere\"\n");
    ASSERT_EQ(s.shapes.size(), 3u);
    glm::dmat4 expected(1.0);
    expected = glm::translate(expected, glm::dvec3(1, 2, 3));
    expected = glm::rotate(expected, glm::radians(90.0), glm::dvec3(0, 0, 1));
    expected = glm::scale(expected, glm::dvec3(2));
    expectMatrix(s.shapes[0].entity.transform, expected);
    // The point (1, 0, 0): scaled to (2, 0, 0), turned to (0, 2, 0), moved to (1, 4, 3).
    const glm::dvec4 p = s.shapes[0].entity.transform * glm::dvec4(1, 0, 0, 1);
    EXPECT_NEAR(p.x, 1, 1e-12);
    EXPECT_NEAR(p.y, 4, 1e-12);
    EXPECT_NEAR(p.z, 3, 1e-12);
    // Transform's 16 numbers are the matrix column by column: the last four translate.
    expectMatrix(s.shapes[1].entity.transform, glm::translate(glm::dmat4(1.0), {4, 5, 6}));
    expectMatrix(s.shapes[2].entity.transform,
                 glm::scale(glm::translate(glm::dmat4(1.0), {4, 5, 6}), {2, 3, 4}));
}

// Identity resets the current transform (pbrt-v4 scene.cpp), as published scenes use it
// between a camera and the world.
TEST(PbrtParser, IdentityResetsTheTransform) {
    const ParsedScene s = parse(
        "Translate 1 2 3\nScale 2 2 2\nIdentity\nShape \"sphere\"\nIdentity\n"
        "Rotate 90 0 0 1\nShape \"sphere\"\n");
    ASSERT_EQ(s.shapes.size(), 2u);
    expectMatrix(s.shapes[0].entity.transform, glm::dmat4(1.0));
    expectMatrix(s.shapes[1].entity.transform,
                 glm::rotate(glm::dmat4(1.0), glm::radians(90.0), glm::dvec3(0, 0, 1)));
}

TEST(PbrtParser, LookAtIsCameraFromWorld) {
    const ParsedScene s = parse("LookAt 1 2 3  1 2 4  0 1 0\nCamera \"perspective\"\n");
    ASSERT_TRUE(s.camera);
    // The eye goes to the origin, the viewing direction (+z here) to +z, and pbrt's camera
    // +x is cross(up, dir) = (1, 0, 0).
    const glm::dmat4 worldFromCamera = glm::inverse(s.camera->transform);
    expectMatrix(worldFromCamera, glm::translate(glm::dmat4(1.0), {1, 2, 3}));
    EXPECT_EQ(parseError("LookAt 0 0 0  0 1 0  0 1 0\n"),
              "s.pbrt:1: LookAt: the up vector is parallel to the viewing direction");
}

TEST(PbrtParser, AttributesAndCoordinateSystemsRestoreTheState) {
    const ParsedScene s = parse(
        "Translate 1 0 0\nCoordinateSystem \"here\"\nAttributeBegin\n  Translate 0 1 0\n"
        "  ReverseOrientation\n  Material \"conductor\"\n  Shape \"sphere\"\nAttributeEnd\n"
        "Shape \"disk\"\nTranslate 5 5 5\nCoordSysTransform \"here\"\nShape \"sphere\"\n"
        "TransformBegin\nScale 2 2 2\nTransformEnd\nShape \"sphere\"\n");
    ASSERT_EQ(s.shapes.size(), 4u);
    expectMatrix(s.shapes[0].entity.transform, glm::translate(glm::dmat4(1.0), {1, 1, 0}));
    EXPECT_TRUE(s.shapes[0].reverseOrientation);
    EXPECT_EQ(s.shapes[0].material, "pbrt_material_1");
    expectMatrix(s.shapes[1].entity.transform, glm::translate(glm::dmat4(1.0), {1, 0, 0}));
    EXPECT_FALSE(s.shapes[1].reverseOrientation);
    EXPECT_EQ(s.shapes[1].material, "");
    expectMatrix(s.shapes[2].entity.transform, glm::translate(glm::dmat4(1.0), {1, 0, 0}));
    expectMatrix(s.shapes[3].entity.transform, glm::translate(glm::dmat4(1.0), {1, 0, 0}));
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_EQ(s.warnings[0],
              "s.pbrt:13: TransformBegin (deprecated in pbrt-v4) read as saving the transform");
}

TEST(PbrtParser, CameraCoordinateSystemIsTheCamerasFrame) {
    const ParsedScene s = parse(
        "LookAt 0 0 5  0 0 0  0 1 0\nCamera \"perspective\"\nWorldBegin\n"
        "CoordSysTransform \"camera\"\nShape \"sphere\"\n");
    const glm::dvec4 p = s.shapes[0].entity.transform * glm::dvec4(0, 0, 0, 1);
    EXPECT_NEAR(p.z, 5, 1e-12);
}

TEST(PbrtParser, ParametersAreTyped) {
    const ParsedScene s = parse(
        "Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"integer indices\" [0 1 2]\n"
        "  \"string name\" \"x\" \"bool flag\" true \"bool other\" \"false\"\n"
        "  \"spectrum s\" \"metal-Cu-eta\" \"texture t\" \"checks\"\n");
    const ParamList& p = s.shapes[0].entity.params;
    EXPECT_EQ(p.numbers("P", {"point3"}, 3)->size(), 9u);
    EXPECT_EQ(p.string("name", ""), "x");
    EXPECT_TRUE(p.boolean("flag", false));
    EXPECT_FALSE(p.boolean("other", true));
    EXPECT_EQ(p.find("s")->strings[0], "metal-Cu-eta");
    EXPECT_EQ(p.find("t")->strings[0], "checks");
    EXPECT_EQ(errorOf([&] { p.number("name", 0); }),
              "s.pbrt:2: Shape \"trianglemesh\": parameter \"string name\" has the wrong type: "
              "expected float");
    EXPECT_EQ(errorOf([&] { p.integer("indices", 0); }),
              "s.pbrt:1: Shape \"trianglemesh\": parameter \"integer indices\" expected one "
              "value, got 3");
}

// White space around a declaration's type and name is allowed, as pbrt-v4 allows it: published
// hair scenes write " float beta_n".
TEST(PbrtParser, ParameterDeclarationsMayHaveWhiteSpaceAround) {
    const ParsedScene s = parse("Shape \"sphere\" \" float radius\" 2 \"float zmin \" -1\n");
    const ParamList& p = s.shapes[0].entity.params;
    EXPECT_EQ(p.number("radius", 0), 2);
    EXPECT_EQ(p.number("zmin", 0), -1);
}

TEST(PbrtParser, ParameterErrorsNameFileAndLine) {
    EXPECT_EQ(parseError("Shape \"sphere\"\n  \"radius\" 1"),
              "s.pbrt:2: Shape \"sphere\": expected a parameter \"type name\", got \"radius\"");
    EXPECT_EQ(parseError("Shape \"sphere\" \"real radius\" 1"),
              "s.pbrt:1: Shape \"sphere\": parameter \"real radius\" has an unknown type \"real\"");
    EXPECT_EQ(parseError("Shape \"sphere\" \"float radius\" [ 1\n"),
              "s.pbrt:1: Shape \"sphere\": parameter \"float radius\": '[' is not closed");
    EXPECT_EQ(parseError("Shape \"sphere\" \"string name\" 3"),
              "s.pbrt:1: Shape \"sphere\": parameter \"string name\" expects strings, got 3");
    EXPECT_EQ(parseError("Shape \"sphere\" \"float radius\" 1 \"float radius\" 2"),
              "s.pbrt:1: Shape \"sphere\": parameter \"radius\" is given twice");
}

TEST(PbrtParser, DirectiveErrorsNameFileAndLine) {
    EXPECT_EQ(parseError("WorldBegin\n\nFooBar 1 2\n"), "s.pbrt:3: unknown directive \"FooBar\"");
    EXPECT_EQ(parseError("Translate 1 2\n"),
              "s.pbrt:1: expected 3 numbers after Translate, got the end of the file");
    EXPECT_EQ(parseError("\"sphere\"\n"), "s.pbrt:1: expected a directive, got \"sphere\"");
    EXPECT_EQ(parseError("AttributeEnd\n"),
              "s.pbrt:1: AttributeEnd without a matching AttributeBegin");
    EXPECT_EQ(parseError("AttributeBegin\nShape \"sphere\"\n"),
              "s.pbrt:1: AttributeBegin is not closed before the end of s.pbrt (line 3)");
    EXPECT_EQ(parseError("CoordSysTransform \"nowhere\""),
              "s.pbrt:1: CoordSysTransform: no coordinate system \"nowhere\" was defined");
    EXPECT_EQ(parseError("MakeNamedMedium \"fog\" \"float g\" 0.5"),
              "s.pbrt:1: MakeNamedMedium \"fog\": no \"string type\" parameter");
    EXPECT_EQ(parseError("MakeNamedMedium \"fog\" \"string type\" \"homogeneous\"\n"
                         "MakeNamedMedium \"fog\" \"string type\" \"homogeneous\""),
              "s.pbrt:2: MakeNamedMedium \"fog\": defined again (first at s.pbrt:1)");
    EXPECT_EQ(parseError("ActiveTransform Sometimes"),
              "s.pbrt:1: ActiveTransform Sometimes: expected All, StartTime or EndTime");
    EXPECT_EQ(parseError("TransformTimes 1 1"),
              "s.pbrt:1: TransformTimes: expected a start time before the end time, both in "
              "[-1e6, 1e6] and at least 1e-6 apart");
    EXPECT_EQ(parseError("ColorSpace \"aces2065-1\""),
              "s.pbrt:1: ColorSpace \"aces2065-1\" is not supported (lamina's colours are sRGB / "
              "Rec.709, pbrt-v4's default \"srgb\")");
}

// MediumInterface is an attribute (saved by AttributeBegin); one name is both sides; the
// camera sits in the outside medium in effect when Camera is read.
TEST(PbrtParser, MediumInterfaceIsAnAttribute) {
    const ParsedScene s = parse(
        "MediumInterface \"\" \"fog\"\nCamera \"perspective\"\nWorldBegin\n"
        "MakeNamedMedium \"ink\" \"string type\" \"homogeneous\" \"float g\" 0.3\n"
        "AttributeBegin\nMediumInterface \"ink\" \"fog\"\nShape \"sphere\"\nAttributeEnd\n"
        "Shape \"disk\"\nMediumInterface \"ink\"\nShape \"disk\"\n");
    EXPECT_EQ(s.cameraMedia.outside, "fog");
    EXPECT_EQ(s.cameraMedia.inside, "");
    ASSERT_EQ(s.media.size(), 1u);
    EXPECT_EQ(s.media[0].name, "ink");
    EXPECT_EQ(s.media[0].entity.type, "homogeneous");
    EXPECT_EQ(s.media[0].entity.location.line, 4);
    ASSERT_EQ(s.shapes.size(), 3u);
    EXPECT_EQ(s.shapes[0].media.inside, "ink");
    EXPECT_EQ(s.shapes[0].media.outside, "fog");
    EXPECT_EQ(s.shapes[0].media.location.line, 6);
    EXPECT_TRUE(s.shapes[0].media.isTransition());
    // Restored by AttributeEnd: the state before it, vacuum inside and fog outside.
    EXPECT_EQ(s.shapes[1].media.inside, "");
    EXPECT_EQ(s.shapes[1].media.outside, "fog");
    EXPECT_EQ(s.shapes[2].media.inside, "ink");
    EXPECT_EQ(s.shapes[2].media.outside, "ink");
    EXPECT_FALSE(s.shapes[2].media.isTransition());
}

TEST(PbrtParser, ObjectsAndInstances) {
    const ParsedScene s = parse(
        "ObjectBegin \"leaf\"\n  Translate 1 0 0\n  Shape \"sphere\"\nObjectEnd\n"
        "Translate 0 2 0\nObjectInstance \"leaf\"\nShape \"disk\"\n");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(s.objects[0].name, "leaf");
    ASSERT_EQ(s.objects[0].shapes.size(), 1u);
    expectMatrix(s.objects[0].shapes[0].entity.transform,
                 glm::translate(glm::dmat4(1.0), {1, 0, 0}));
    ASSERT_EQ(s.instances.size(), 1u);
    expectMatrix(s.instances[0].transform, glm::translate(glm::dmat4(1.0), {0, 2, 0}));
    // ObjectEnd restored the transform of ObjectBegin; the disk is not in the object.
    ASSERT_EQ(s.shapes.size(), 1u);
    expectMatrix(s.shapes[0].entity.transform, glm::translate(glm::dmat4(1.0), {0, 2, 0}));
    EXPECT_EQ(parseError("ObjectBegin \"a\"\nAreaLightSource \"diffuse\"\nShape \"sphere\"\n"),
              "s.pbrt:3: an area light inside ObjectBegin is not supported (pbrt-v4 refuses it "
              "too: instances cannot emit)");
    EXPECT_EQ(parseError("ObjectBegin \"a\"\nObjectBegin \"b\"\n"),
              "s.pbrt:2: ObjectBegin \"b\" inside ObjectBegin \"a\"");
}

TEST_F(PbrtIncludes, IncludeAndImportReadFilesBesideTheScene) {
    write("part.pbrt", "Shape \"sphere\"\nInclude \"deeper.pbrt\"\n");
    write("deeper.pbrt", "Shape \"disk\"\n");
    const auto main = write("main.pbrt",
                            "Translate 1 0 0\nInclude \"part.pbrt\"\nImport "
                            "\"deeper.pbrt\"\n");
    const ParsedScene s = parseFile(main);
    ASSERT_EQ(s.shapes.size(), 3u);
    EXPECT_EQ(s.shapes[0].entity.location.str(), (dir_ / "part.pbrt").string() + ":1");
    EXPECT_EQ(s.shapes[1].entity.location.str(), (dir_ / "deeper.pbrt").string() + ":1");
    expectMatrix(s.shapes[1].entity.transform, glm::translate(glm::dmat4(1.0), {1, 0, 0}));
    EXPECT_EQ(s.files.size(), 4u);
    const auto missing = write("missing.pbrt", "\nInclude \"absent.pbrt\"\n");
    EXPECT_EQ(errorOf([&] { parseFile(missing); }),
              missing.string() + ":2: Include \"absent.pbrt\": no such file");
    const auto loop = write("loop.pbrt", "Include \"loop.pbrt\"\n");
    EXPECT_NE(errorOf([&] { parseFile(loop); }).find("nested includes"), std::string::npos);
}

}  // namespace
}  // namespace lamina::render::pbrt
