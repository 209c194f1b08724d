#include "pbrt_transform_directives.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "pbrt_parser.h"

namespace lamina::render::pbrt {

Token expectToken(Tokenizer& tokens, Token::Kind kind, const std::string& what, int line) {
    auto t = tokens.next();
    if (!t) tokens.fail(line, "expected " + what + ", got the end of the file");
    if (t->kind != kind) tokens.fail(t->line, "expected " + what + ", got \"" + t->text + "\"");
    return *t;
}

std::string quotedString(Tokenizer& tokens, const Token& directive) {
    return expectToken(tokens, Token::Kind::String, "a quoted string after " + directive.text,
                       directive.line)
        .text;
}

std::vector<double> directiveNumbers(Tokenizer& tokens, const Token& directive, std::size_t count,
                                     bool bracketsAllowed) {
    bool bracketed = false;
    if (bracketsAllowed && tokens.peek() && tokens.peek()->kind == Token::Kind::OpenBracket) {
        tokens.next();
        bracketed = true;
    }
    std::vector<double> v;
    for (std::size_t i = 0; i < count; ++i)
        v.push_back(expectToken(tokens, Token::Kind::Number,
                                std::to_string(count) + " numbers after " + directive.text,
                                directive.line)
                        .number);
    if (bracketed)
        expectToken(tokens, Token::Kind::CloseBracket,
                    "']' after " + std::to_string(count) + " numbers of " + directive.text,
                    directive.line);
    return v;
}

namespace {

// pbrt-v4's LookAt (transform.cpp): camera space has x = normalize(cross(up, dir)),
// y = cross(dir, x), z = dir; the transform returned is cameraFromWorld.
glm::dmat4 lookAt(Tokenizer& tokens, const Token& d, const glm::dvec3& eye, const glm::dvec3& look,
                  const glm::dvec3& up) {
    const glm::dvec3 dir = look - eye;
    if (glm::length(dir) == 0) tokens.fail(d.line, "LookAt: the eye and the target coincide");
    if (glm::length(up) == 0) tokens.fail(d.line, "LookAt: the up vector is zero");
    const glm::dvec3 z = glm::normalize(dir);
    const glm::dvec3 c = glm::cross(glm::normalize(up), z);
    if (glm::length(c) < 1e-12)
        tokens.fail(d.line, "LookAt: the up vector is parallel to the viewing direction");
    const glm::dvec3 x = glm::normalize(c);
    const glm::dvec3 y = glm::cross(z, x);
    glm::dmat4 worldFromCamera(1.0);
    worldFromCamera[0] = glm::dvec4(x, 0);
    worldFromCamera[1] = glm::dvec4(y, 0);
    worldFromCamera[2] = glm::dvec4(z, 0);
    worldFromCamera[3] = glm::dvec4(eye, 1);
    return glm::inverse(worldFromCamera);
}

}  // namespace

bool readTransformDirective(Tokenizer& tokens, const Token& d, CurrentTransform& ctm,
                            std::map<std::string, CurrentTransform>& coordinateSystems,
                            TransformTimes& times) {
    const std::string& name = d.text;
    // pbrt-v4's ForActiveTransforms: each directive changes the active ones of the two.
    const auto apply = [&](const auto& change) {
        if (ctm.startActive) ctm.start = change(ctm.start);
        if (ctm.endActive) ctm.end = change(ctm.end);
    };
    if (name == "Identity") {
        apply([](const glm::dmat4&) { return glm::dmat4(1.0); });
    } else if (name == "Translate") {
        const auto v = directiveNumbers(tokens, d, 3, false);
        apply([&](const glm::dmat4& m) { return glm::translate(m, glm::dvec3(v[0], v[1], v[2])); });
    } else if (name == "Scale") {
        const auto v = directiveNumbers(tokens, d, 3, false);
        apply([&](const glm::dmat4& m) { return glm::scale(m, glm::dvec3(v[0], v[1], v[2])); });
    } else if (name == "Rotate") {
        const auto v = directiveNumbers(tokens, d, 4, false);
        const glm::dvec3 axis(v[1], v[2], v[3]);
        if (glm::length(axis) == 0) tokens.fail(d.line, "Rotate: the axis is zero");
        // pbrt-v4's Rotate (transform.cpp) is the right-handed rotation about the axis, as
        // glm::rotate.
        apply([&](const glm::dmat4& m) {
            return glm::rotate(m, glm::radians(v[0]), glm::normalize(axis));
        });
    } else if (name == "LookAt") {
        const auto v = directiveNumbers(tokens, d, 9, false);
        const glm::dmat4 look = lookAt(tokens, d, glm::dvec3(v[0], v[1], v[2]),
                                       glm::dvec3(v[3], v[4], v[5]), glm::dvec3(v[6], v[7], v[8]));
        apply([&](const glm::dmat4& m) { return m * look; });
    } else if (name == "Transform" || name == "ConcatTransform") {
        const auto v = directiveNumbers(tokens, d, 16, true);
        // pbrt-v4 transposes the 16 numbers (parser.cpp, Transform): they are the matrix column
        // by column, which is glm's storage order.
        const glm::dmat4 t = glm::make_mat4(v.data());
        apply([&](const glm::dmat4& m) { return name == "Transform" ? t : m * t; });
    } else if (name == "CoordinateSystem") {
        coordinateSystems[quotedString(tokens, d)] = ctm;
    } else if (name == "CoordSysTransform") {
        const std::string system = quotedString(tokens, d);
        const auto it = coordinateSystems.find(system);
        if (it == coordinateSystems.end())
            tokens.fail(d.line,
                        "CoordSysTransform: no coordinate system \"" + system + "\" was defined");
        // Both transforms, whichever are active (pbrt-v4 assigns the whole set).
        ctm.start = it->second.start;
        ctm.end = it->second.end;
    } else if (name == "ActiveTransform") {
        const auto t = expectToken(tokens, Token::Kind::Word, "All, StartTime or EndTime", d.line);
        if (t.text != "All" && t.text != "StartTime" && t.text != "EndTime")
            tokens.fail(t.line,
                        "ActiveTransform " + t.text + ": expected All, StartTime or EndTime");
        ctm.startActive = t.text != "EndTime";
        ctm.endActive = t.text != "StartTime";
    } else if (name == "TransformTimes") {
        const auto v = directiveNumbers(tokens, d, 2, false);
        // lamina's scene times are these mapped to [0, 1]: their difference divides.
        if (!(v[0] < v[1]) || !(std::abs(v[0]) <= 1e6 && std::abs(v[1]) <= 1e6) ||
            !(v[1] - v[0] >= 1e-6))
            tokens.fail(d.line,
                        "TransformTimes: expected a start time before the end time, both "
                        "in [-1e6, 1e6] and at least 1e-6 apart");
        times = {v[0], v[1]};
    } else {
        return false;
    }
    return true;
}

}  // namespace lamina::render::pbrt
