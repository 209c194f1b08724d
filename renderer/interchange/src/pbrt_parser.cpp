#include "pbrt_parser.h"

#include <algorithm>
#include <map>

#include "lamina/core/error.h"
#include "lamina/core/gzip_file.h"
#include "lamina/core/input_file.h"
#include "pbrt_tokenizer.h"
#include "pbrt_transform_directives.h"

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
    CurrentTransform transform;
    bool reverseOrientation = false;
    std::string material;
    Location materialLocation;
    std::optional<Entity> areaLight;
    MediumSides media;
    /// pbrt-v4's `Attribute` defaults per target ("shape", "light", "material", "medium",
    /// "texture"), in the order given; saved by AttributeBegin like the rest of the state.
    std::map<std::string, std::vector<Param>> attributes;
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

    /// A directive's entity; `attributeTarget` names the Attribute defaults it takes (none
    /// for the camera, film and the other options).
    Entity entity(Tokenizer& tokens, const Token& directive, const std::string& type,
                  const char* attributeTarget = nullptr) {
        Entity e;
        e.type = type;
        e.location = where(tokens, directive.line);
        e.params = readParamList(tokens, directive.text + " \"" + type + "\"");
        if (attributeTarget) applyAttributes(e.params, attributeTarget);
        setTransform(e);
        return e;
    }

    // The entity's transform at TransformTimes' start, and at its end where that differs.
    void setTransform(Entity& e) const {
        e.transform = state_.transform.start;
        e.transformEnd.reset();
        if (state_.transform.moves()) e.transformEnd = state_.transform.end;
    }

    void applyAttributes(ParamList& params, const std::string& target) const {
        const auto found = state_.attributes.find(target);
        if (found != state_.attributes.end()) params.addDefaults(found->second);
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
        const std::string name = quotedString(tokens, directive);
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
        CurrentTransform& ctm = state_.transform;
        if (readTransformDirective(tokens, d, ctm, coordinateSystems_, scene_.transformTimes)) {
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
            // pbrt-v4's WorldBegin: both transforms the identity, both active.
            ctm = CurrentTransform{};
            coordinateSystems_["world"] = ctm;
        } else if (name == "Camera") {
            Entity e = entity(tokens, d, quotedString(tokens, d));
            // pbrt-v4 names the camera's frame "camera" (scene.cpp, BasicSceneBuilder::Camera).
            coordinateSystems_["camera"] = {glm::inverse(e.transform),
                                            glm::inverse(e.transformEnd.value_or(e.transform))};
            // The camera sits in the current outside medium (BasicSceneBuilder::Camera).
            scene_.cameraMedia = state_.media;
            setOnce(scene_.camera, std::move(e), "Camera");
        } else if (name == "Film") {
            setOnce(scene_.film, entity(tokens, d, quotedString(tokens, d)), "Film");
        } else if (name == "Sampler") {
            setOnce(scene_.sampler, entity(tokens, d, quotedString(tokens, d)), "Sampler");
        } else if (name == "Integrator") {
            setOnce(scene_.integrator, entity(tokens, d, quotedString(tokens, d)), "Integrator");
        } else if (name == "PixelFilter") {
            setOnce(scene_.filter, entity(tokens, d, quotedString(tokens, d)), "PixelFilter");
        } else if (name == "Accelerator") {
            entity(tokens, d, quotedString(tokens, d));
            warn(at, "Accelerator ignored: lamina always uses Embree's BVH");
        } else if (name == "ColorSpace") {
            const std::string space = quotedString(tokens, d);
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
            Entity e = entity(tokens, d, quotedString(tokens, d), "material");
            MaterialDef m{"pbrt_material_" + std::to_string(++anonymousMaterials_), std::move(e)};
            state_.material = m.name;
            state_.materialLocation = at;
            scene_.materials.push_back(std::move(m));
        } else if (name == "MakeNamedMaterial") {
            const std::string materialName = quotedString(tokens, d);
            Entity e;
            e.location = at;
            setTransform(e);
            e.params = readParamList(tokens, "MakeNamedMaterial \"" + materialName + "\"");
            applyAttributes(e.params, "material");
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
            state_.material = quotedString(tokens, d);
            state_.materialLocation = at;
        } else if (name == "Texture") {
            const std::string textureName = quotedString(tokens, d);
            const std::string valueType = quotedString(tokens, d);
            if (valueType != "float" && valueType != "spectrum")
                tokens.fail(d.line,
                            "Texture \"" + textureName +
                                "\": expected the type \"float\" or \"spectrum\", got \"" +
                                valueType + "\"" +
                                (valueType == "color" || valueType == "rgb"
                                     ? " (pbrt-v3's name: convert the file with pbrt-v4's `pbrt "
                                       "--upgrade FILE > NEW.pbrt`)"
                                     : ""));
            Entity e = entity(tokens, d, quotedString(tokens, d), "texture");
            for (const TextureDef& t : scene_.textures)
                if (t.name == textureName && t.valueType == valueType)
                    tokens.fail(d.line, "Texture \"" + textureName +
                                            "\": defined again (first at " +
                                            t.entity.location.str() + ")");
            scene_.textures.push_back({textureName, valueType, std::move(e)});
        } else if (name == "Shape") {
            addShape(entity(tokens, d, quotedString(tokens, d), "shape"));
        } else if (name == "AreaLightSource") {
            state_.areaLight = entity(tokens, d, quotedString(tokens, d), "light");
        } else if (name == "LightSource") {
            if (currentObject_)
                tokens.fail(d.line, "LightSource inside ObjectBegin is not supported");
            scene_.lights.push_back(entity(tokens, d, quotedString(tokens, d), "light"));
        } else if (name == "ObjectBegin") {
            const std::string objectName = quotedString(tokens, d);
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
            const std::string objectName = quotedString(tokens, d);
            if (currentObject_)
                tokens.fail(d.line, "ObjectInstance inside ObjectBegin is not supported");
            scene_.instances.push_back(
                {objectName, at, ctm.start,
                 ctm.moves() ? std::optional<glm::dmat4>(ctm.end) : std::nullopt});
        } else if (name == "MakeNamedMedium") {
            const std::string mediumName = quotedString(tokens, d);
            Entity e;
            e.location = at;
            setTransform(e);
            e.params = readParamList(tokens, "MakeNamedMedium \"" + mediumName + "\"");
            applyAttributes(e.params, "medium");
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
            state_.media.inside = quotedString(tokens, d);
            state_.media.outside = state_.media.inside;
            if (tokens.peek() && tokens.peek()->kind == Token::Kind::String)
                state_.media.outside = tokens.next()->text;
            state_.media.location = at;
        } else if (name == "Attribute") {
            // pbrt-v4's BasicSceneBuilder::Attribute: default parameters for the directives
            // of one kind until the attribute block ends.
            const std::string target = quotedString(tokens, d);
            if (target != "shape" && target != "light" && target != "material" &&
                target != "medium" && target != "texture")
                tokens.fail(d.line, "Attribute \"" + target +
                                        "\": expected the target \"shape\", \"light\", "
                                        "\"material\", \"medium\" or \"texture\"");
            const ParamList defaults = readParamList(tokens, "Attribute \"" + target + "\"");
            std::vector<Param>& list = state_.attributes[target];
            list.insert(list.end(), defaults.all().begin(), defaults.all().end());
        } else if (name == "WorldEnd") {
            warn(at, "WorldEnd (pbrt-v3) ignored: pbrt-v4 files end without it");
        } else {
            tokens.fail(d.line, "unknown directive \"" + name + "\"");
        }
    }

    ParsedScene& scene_;
    GraphicsState state_;
    std::vector<Frame> stack_;
    std::map<std::string, CurrentTransform> coordinateSystems_;
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
