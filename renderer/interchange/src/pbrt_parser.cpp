#include "pbrt_parser.h"

#include <algorithm>
#include <map>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "lamina/core/error.h"
#include "lamina/core/gzip_file.h"
#include "lamina/core/input_file.h"
#include "pbrt_tokenizer.h"

namespace lamina::render::pbrt {

namespace {

// A scene file's text: pbrt-v4 reads a gzip-compressed file (.pbrt.gz), the one it was started
// on or an included one, as the text it holds (Tokenizer::CreateFromFile, parser.cpp).
std::string readSceneText(const std::filesystem::path& file) {
    if (isGzipPath(file)) return readGzipFile(file, kMaxTextFileBytes, kMaxTextFileBytes, "scene");
    return readInputFile(file, kMaxTextFileBytes);
}

// Include and Import may nest, but not without end (a file including itself).
constexpr int kMaxIncludeDepth = 32;

struct GraphicsState {
    glm::dmat4 transform{1.0};
    bool reverseOrientation = false;
    std::string material;
    Location materialLocation;
    std::optional<Entity> areaLight;
    MediumSides media;
};

// The part of the graphics state that TransformBegin/End saves (deprecated in pbrt-v4, still
// read by it).
struct Frame {
    GraphicsState state;
    bool transformOnly = false;
    bool object = false;  // pushed by ObjectBegin
    Location location;
};

class Parser {
  public:
    Parser(ParsedScene& scene) : scene_(scene) {}

    void parse(Tokenizer& tokens, int depth) {
        while (auto token = tokens.next()) {
            if (token->kind != Token::Kind::Word)
                tokens.fail(token->line, "expected a directive, got \"" + token->text + "\"");
            directive(tokens, *token, depth);
        }
    }

    void finish(const std::string& fileName, int line) {
        if (!stack_.empty())
            throw InputError(stack_.back().location.str() + ": " +
                             (stack_.back().object ? "ObjectBegin" : "AttributeBegin") +
                             " is not closed before the end of " + fileName + " (line " +
                             std::to_string(line) + ")");
    }

  private:
    Location where(const Tokenizer& tokens, int line) const { return {tokens.fileName(), line}; }

    void warn(const Location& at, const std::string& message) {
        scene_.warnings.push_back(at.str() + ": " + message);
    }

    Token expect(Tokenizer& tokens, Token::Kind kind, const std::string& what, int line) {
        auto t = tokens.next();
        if (!t) tokens.fail(line, "expected " + what + ", got the end of the file");
        if (t->kind != kind) tokens.fail(t->line, "expected " + what + ", got \"" + t->text + "\"");
        return *t;
    }
    std::string string(Tokenizer& tokens, const Token& directive) {
        return expect(tokens, Token::Kind::String, "a quoted string after " + directive.text,
                      directive.line)
            .text;
    }
    std::vector<double> numbers(Tokenizer& tokens, const Token& directive, std::size_t count,
                                bool bracketsAllowed) {
        bool bracketed = false;
        if (bracketsAllowed && tokens.peek() && tokens.peek()->kind == Token::Kind::OpenBracket) {
            tokens.next();
            bracketed = true;
        }
        std::vector<double> v;
        for (std::size_t i = 0; i < count; ++i)
            v.push_back(expect(tokens, Token::Kind::Number,
                               std::to_string(count) + " numbers after " + directive.text,
                               directive.line)
                            .number);
        if (bracketed)
            expect(tokens, Token::Kind::CloseBracket,
                   "']' after " + std::to_string(count) + " numbers of " + directive.text,
                   directive.line);
        return v;
    }

    Entity entity(Tokenizer& tokens, const Token& directive, const std::string& type) {
        Entity e;
        e.type = type;
        e.location = where(tokens, directive.line);
        e.params = readParamList(tokens, directive.text + " \"" + type + "\"");
        e.transform = state_.transform;
        return e;
    }

    void setOnce(std::optional<Entity>& slot, Entity e, const std::string& directive) {
        if (slot)
            warn(e.location, directive + " given again: this one replaces the one of line " +
                                 std::to_string(slot->location.line));
        slot = std::move(e);
    }

    void addShape(Entity e) {
        ShapeDef s;
        s.entity = std::move(e);
        s.material = state_.material;
        s.materialLocation = state_.materialLocation;
        s.areaLight = state_.areaLight;
        s.reverseOrientation = state_.reverseOrientation;
        s.media = state_.media;
        if (currentObject_) {
            if (s.areaLight)
                throw InputError(s.entity.location.str() +
                                 ": an area light inside ObjectBegin is not supported (pbrt-v4 "
                                 "refuses it too: instances cannot emit)");
            currentObject_->shapes.push_back(std::move(s));
        } else {
            scene_.shapes.push_back(std::move(s));
        }
    }

    void include(Tokenizer& tokens, const Token& directive, int depth) {
        const std::string name = string(tokens, directive);
        if (depth + 1 > kMaxIncludeDepth)
            tokens.fail(directive.line, directive.text + " \"" + name + "\": more than " +
                                            std::to_string(kMaxIncludeDepth) +
                                            " nested includes (does a file include itself?)");
        std::filesystem::path path(name);
        // pbrt-v4 resolves every relative name against the directory of the scene file it
        // was started on (SetSearchDirectory in pbrt.cpp), including those in included files.
        if (path.is_relative()) path = scene_.directory / path;
        const std::string why = notARegularFile(path);
        if (!why.empty()) tokens.fail(directive.line, directive.text + " \"" + name + "\": " + why);
        scene_.files.push_back(path);
        std::string text;
        try {
            text = readSceneText(path);
        } catch (const InputError& e) {
            // A broken gzip stream's error names no line: the directive that read it does.
            if (!isGzipPath(path)) throw;
            tokens.fail(directive.line, directive.text + " \"" + name + "\": " + e.what());
        }
        Tokenizer inner(std::move(text), path.string());
        parse(inner, depth + 1);
    }

    void directive(Tokenizer& tokens, const Token& d, int depth) {
        const std::string& name = d.text;
        const Location at = where(tokens, d.line);
        glm::dmat4& ctm = state_.transform;
        if (name == "Identity") {
            ctm = glm::dmat4(1.0);
        } else if (name == "Translate") {
            const auto v = numbers(tokens, d, 3, false);
            ctm = glm::translate(ctm, glm::dvec3(v[0], v[1], v[2]));
        } else if (name == "Scale") {
            const auto v = numbers(tokens, d, 3, false);
            ctm = glm::scale(ctm, glm::dvec3(v[0], v[1], v[2]));
        } else if (name == "Rotate") {
            const auto v = numbers(tokens, d, 4, false);
            const glm::dvec3 axis(v[1], v[2], v[3]);
            if (glm::length(axis) == 0) tokens.fail(d.line, "Rotate: the axis is zero");
            // pbrt-v4's Rotate (transform.cpp) is the right-handed rotation about the axis,
            // as glm::rotate.
            ctm = glm::rotate(ctm, glm::radians(v[0]), glm::normalize(axis));
        } else if (name == "LookAt") {
            const auto v = numbers(tokens, d, 9, false);
            ctm = ctm * lookAt(tokens, d, glm::dvec3(v[0], v[1], v[2]),
                               glm::dvec3(v[3], v[4], v[5]), glm::dvec3(v[6], v[7], v[8]));
        } else if (name == "Transform" || name == "ConcatTransform") {
            const auto v = numbers(tokens, d, 16, true);
            // pbrt-v4 transposes the 16 numbers (parser.cpp, Transform): they are the matrix
            // column by column, which is glm's storage order.
            const glm::dmat4 m = glm::make_mat4(v.data());
            ctm = name == "Transform" ? m : ctm * m;
        } else if (name == "CoordinateSystem") {
            coordinateSystems_[string(tokens, d)] = ctm;
        } else if (name == "CoordSysTransform") {
            const std::string system = string(tokens, d);
            const auto it = coordinateSystems_.find(system);
            if (it == coordinateSystems_.end())
                tokens.fail(d.line, "CoordSysTransform: no coordinate system \"" + system +
                                        "\" was defined");
            ctm = it->second;
        } else if (name == "ActiveTransform") {
            const auto t = expect(tokens, Token::Kind::Word, "All, StartTime or EndTime", d.line);
            if (t.text != "All")
                tokens.fail(d.line,
                            "ActiveTransform " + t.text +
                                ": motion blur is not supported (only ActiveTransform All)");
        } else if (name == "TransformTimes") {
            numbers(tokens, d, 2, false);
            warn(at, "TransformTimes ignored: lamina renders one instant (no motion blur)");
        } else if (name == "ReverseOrientation") {
            state_.reverseOrientation = !state_.reverseOrientation;
        } else if (name == "AttributeBegin" || name == "TransformBegin") {
            if (name == "TransformBegin")
                warn(at, "TransformBegin (deprecated in pbrt-v4) read as saving the transform");
            stack_.push_back({state_, name == "TransformBegin", false, at});
        } else if (name == "AttributeEnd" || name == "TransformEnd") {
            if (stack_.empty() || stack_.back().object ||
                stack_.back().transformOnly != (name == "TransformEnd"))
                tokens.fail(d.line,
                            name + " without a matching " +
                                (name == "AttributeEnd" ? "AttributeBegin" : "TransformBegin"));
            if (stack_.back().transformOnly)
                state_.transform = stack_.back().state.transform;
            else
                state_ = stack_.back().state;
            stack_.pop_back();
        } else if (name == "WorldBegin") {
            ctm = glm::dmat4(1.0);
            coordinateSystems_["world"] = ctm;
        } else if (name == "Camera") {
            Entity e = entity(tokens, d, string(tokens, d));
            // pbrt-v4 names the camera's frame "camera" (scene.cpp, BasicSceneBuilder::Camera).
            coordinateSystems_["camera"] = glm::inverse(e.transform);
            // The camera sits in the current outside medium (BasicSceneBuilder::Camera).
            scene_.cameraMedia = state_.media;
            setOnce(scene_.camera, std::move(e), "Camera");
        } else if (name == "Film") {
            setOnce(scene_.film, entity(tokens, d, string(tokens, d)), "Film");
        } else if (name == "Sampler") {
            setOnce(scene_.sampler, entity(tokens, d, string(tokens, d)), "Sampler");
        } else if (name == "Integrator") {
            setOnce(scene_.integrator, entity(tokens, d, string(tokens, d)), "Integrator");
        } else if (name == "PixelFilter") {
            setOnce(scene_.filter, entity(tokens, d, string(tokens, d)), "PixelFilter");
        } else if (name == "Accelerator") {
            entity(tokens, d, string(tokens, d));
            warn(at, "Accelerator ignored: lamina always uses Embree's BVH");
        } else if (name == "ColorSpace") {
            const std::string space = string(tokens, d);
            if (space != "srgb")
                tokens.fail(d.line, "ColorSpace \"" + space +
                                        "\" is not supported (lamina's colours are sRGB / "
                                        "Rec.709, pbrt-v4's default \"srgb\")");
        } else if (name == "Option") {
            const ParamList p = readParamList(tokens, "Option");
            warn(at, "Option ignored: pbrt's rendering options do not change lamina's scene");
            (void)p;
        } else if (name == "Include" || name == "Import") {
            include(tokens, d, depth);
        } else if (name == "Material") {
            Entity e = entity(tokens, d, string(tokens, d));
            MaterialDef m{"pbrt_material_" + std::to_string(++anonymousMaterials_), std::move(e)};
            state_.material = m.name;
            state_.materialLocation = at;
            scene_.materials.push_back(std::move(m));
        } else if (name == "MakeNamedMaterial") {
            const std::string materialName = string(tokens, d);
            Entity e;
            e.location = at;
            e.transform = ctm;
            e.params = readParamList(tokens, "MakeNamedMaterial \"" + materialName + "\"");
            if (!e.params.has("type"))
                tokens.fail(d.line, "MakeNamedMaterial \"" + materialName +
                                        "\": no \"string type\" parameter");
            e.type = e.params.string("type", "");
            for (const MaterialDef& m : scene_.materials)
                if (m.name == materialName)
                    tokens.fail(d.line, "MakeNamedMaterial \"" + materialName +
                                            "\": defined again (first at " +
                                            m.entity.location.str() + ")");
            scene_.materials.push_back({materialName, std::move(e)});
        } else if (name == "NamedMaterial") {
            state_.material = string(tokens, d);
            state_.materialLocation = at;
        } else if (name == "Texture") {
            const std::string textureName = string(tokens, d);
            const std::string valueType = string(tokens, d);
            if (valueType != "float" && valueType != "spectrum")
                tokens.fail(d.line,
                            "Texture \"" + textureName +
                                "\": expected the type \"float\" or \"spectrum\", got \"" +
                                valueType + "\"" +
                                (valueType == "color" || valueType == "rgb"
                                     ? " (pbrt-v3's name: convert the file with pbrt-v4's `pbrt "
                                       "--upgrade FILE > NEW.pbrt`)"
                                     : ""));
            Entity e = entity(tokens, d, string(tokens, d));
            for (const TextureDef& t : scene_.textures)
                if (t.name == textureName && t.valueType == valueType)
                    tokens.fail(d.line, "Texture \"" + textureName +
                                            "\": defined again (first at " +
                                            t.entity.location.str() + ")");
            scene_.textures.push_back({textureName, valueType, std::move(e)});
        } else if (name == "Shape") {
            addShape(entity(tokens, d, string(tokens, d)));
        } else if (name == "AreaLightSource") {
            state_.areaLight = entity(tokens, d, string(tokens, d));
        } else if (name == "LightSource") {
            if (currentObject_)
                tokens.fail(d.line, "LightSource inside ObjectBegin is not supported");
            scene_.lights.push_back(entity(tokens, d, string(tokens, d)));
        } else if (name == "ObjectBegin") {
            const std::string objectName = string(tokens, d);
            if (currentObject_)
                tokens.fail(d.line, "ObjectBegin \"" + objectName + "\" inside ObjectBegin \"" +
                                        currentObject_->name + "\"");
            for (const ObjectDef& o : scene_.objects)
                if (o.name == objectName)
                    tokens.fail(d.line, "ObjectBegin \"" + objectName +
                                            "\": defined again (first at " + o.location.str() +
                                            ")");
            // pbrt-v4's ObjectBegin also begins an attribute block (scene.cpp).
            stack_.push_back({state_, false, true, at});
            scene_.objects.push_back({objectName, at, {}});
            currentObject_ = &scene_.objects.back();
        } else if (name == "ObjectEnd") {
            if (!currentObject_ || stack_.empty() || !stack_.back().object)
                tokens.fail(d.line, "ObjectEnd without a matching ObjectBegin");
            state_ = stack_.back().state;
            stack_.pop_back();
            currentObject_ = nullptr;
        } else if (name == "ObjectInstance") {
            const std::string objectName = string(tokens, d);
            if (currentObject_)
                tokens.fail(d.line, "ObjectInstance inside ObjectBegin is not supported");
            scene_.instances.push_back({objectName, at, ctm});
        } else if (name == "MakeNamedMedium") {
            const std::string mediumName = string(tokens, d);
            Entity e;
            e.location = at;
            e.transform = ctm;
            e.params = readParamList(tokens, "MakeNamedMedium \"" + mediumName + "\"");
            if (!e.params.has("type"))
                tokens.fail(d.line,
                            "MakeNamedMedium \"" + mediumName + "\": no \"string type\" parameter");
            e.type = e.params.string("type", "");
            for (const MediumDef& m : scene_.media)
                if (m.name == mediumName)
                    tokens.fail(d.line, "MakeNamedMedium \"" + mediumName +
                                            "\": defined again (first at " +
                                            m.entity.location.str() + ")");
            scene_.media.push_back({mediumName, std::move(e)});
        } else if (name == "MediumInterface") {
            // One name is both sides (pbrt-v4's parser); the state is an attribute, saved by
            // AttributeBegin.
            state_.media.inside = string(tokens, d);
            state_.media.outside = state_.media.inside;
            if (tokens.peek() && tokens.peek()->kind == Token::Kind::String)
                state_.media.outside = tokens.next()->text;
            state_.media.location = at;
        } else if (name == "Attribute") {
            tokens.fail(d.line,
                        "Attribute (default parameters for a kind of directive) is "
                        "not supported");
        } else if (name == "WorldEnd") {
            warn(at, "WorldEnd (pbrt-v3) ignored: pbrt-v4 files end without it");
        } else {
            tokens.fail(d.line, "unknown directive \"" + name + "\"");
        }
    }

    // pbrt-v4's LookAt (transform.cpp): camera space has x = normalize(cross(up, dir)),
    // y = cross(dir, x), z = dir; the transform returned is cameraFromWorld.
    glm::dmat4 lookAt(Tokenizer& tokens, const Token& d, const glm::dvec3& eye,
                      const glm::dvec3& look, const glm::dvec3& up) {
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

    ParsedScene& scene_;
    GraphicsState state_;
    std::vector<Frame> stack_;
    std::map<std::string, glm::dmat4> coordinateSystems_;
    ObjectDef* currentObject_ = nullptr;
    int anonymousMaterials_ = 0;
};

}  // namespace

ParsedScene parseText(const std::string& text, const std::string& fileName,
                      const std::filesystem::path& directory) {
    ParsedScene scene;
    scene.directory = directory;
    Parser parser(scene);
    Tokenizer tokens(text, fileName);
    parser.parse(tokens, 0);
    parser.finish(fileName, tokens.line());
    return scene;
}

ParsedScene parseFile(const std::filesystem::path& file) {
    const std::string text = readSceneText(file);
    ParsedScene scene = parseText(text, file.string(), file.parent_path());
    scene.files.insert(scene.files.begin(), file);
    return scene;
}

}  // namespace lamina::render::pbrt
