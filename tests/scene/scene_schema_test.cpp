// docs/scene.schema.json held to the readers, so that the two cannot drift apart: the readers
// log every key they ask for (JsonKeyLog), on every shipped scene and on every example the
// schema gives, and
//   - every key a reader asks for is named by the schema where it is asked,
//   - every key the schema names is asked for by a reader (on some scene or example),
//   - a key read as a name has the reader's table of names as its enum, exactly,
//   - the material types are the loader's table of types, each with examples it accepts, and
//     each type's branch is the one its registration carries (material_kind.h).
// That the shipped scenes and the examples are valid by the schema's own rules (ranges,
// required keys) is checked with a JSON Schema validator (tests/app/validate_scene_schema.py).
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <deque>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "json_schema_map.h"
#include "lamina/bsdf/material.h"
#include "lamina/bsdf/material_kind.h"
#include "lamina/core/input_file.h"
#include "lamina/output/image_output.h"
#include "lamina/scene/scene_description.h"

namespace lamina::render {
namespace {

namespace fs = std::filesystem;
using testing::JsonSchemaMap;

const fs::path kSource = LAMINA_SOURCE_DIR;

Json schemaJson() {
    std::ifstream in(kSource / "docs" / "scene.schema.json");
    return Json::parse(in);
}

std::vector<fs::path> shippedScenes() {
    std::vector<fs::path> scenes;
    for (const auto& e : fs::recursive_directory_iterator(kSource / "scenes"))
        if (e.is_regular_file() && e.path().extension() == ".json") scenes.push_back(e.path());
    std::sort(scenes.begin(), scenes.end());
    return scenes;
}

// One document the readers read, with what they asked of it and the schema's map of it.
struct ReadDocument {
    std::string name;
    Json value;
    JsonKeyLog log;
    std::shared_ptr<JsonSchemaMap> map;
};

// The material branches of the schema, by type.
std::map<std::string, const Json*> materialBranches(const Json& schema) {
    std::map<std::string, const Json*> branches;
    for (const auto& b : schema["$defs"]["material"]["oneOf"])
        branches[b["properties"]["type"]["const"].get<std::string>()] = &b;
    return branches;
}

// The shipped scenes and the schema's examples (scenes, and materials by type), read once for all
// the tests below.
class SceneSchema : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        schema_ = schemaJson();
        for (const fs::path& file : shippedScenes()) {
            const std::string name = file.lexically_relative(kSource).string();
            const std::string text = readInputFile(file, kMaxTextFileBytes);
            ReadDocument& d = add(name, parseJsonText(text, JsonSource{name}));
            JsonSource source{name, file.parent_path()};
            source.keyLog = &d.log;
            (void)parseScene(text, source);
            d.map->walk(schema_, d.value, "");
        }
        // The files the schema's scene examples name, written for them.
        const fs::path dir =
            fs::temp_directory_path() / ("lamina-schema-" + std::to_string(::getpid()));
        fs::create_directories(dir);
        const std::vector<float> grey(2 * 2 * 3, 0.5f);  // 2 x 2 grey images
        render::writeRgb8(dir / "photo.png", 2, 2, grey);
        render::writeFloatExr(dir / "sky.exr", 2, 2, {"R", "G", "B"}, grey);
        // Two quads in Mitsuba's serialized format (the seed of its fuzz target).
        fs::copy_file(kSource / "tests/fuzz/corpus/serialized_reader/two-quads-v4.serialized",
                      dir / "quads.serialized");
        // A realistic camera's lens system.
        fs::copy_file(kSource / "scenes/lenses/dgauss.50mm.dat", dir / "dgauss.50mm.dat");
        int sceneIndex = 0;
        for (const auto& example : schema_["examples"]) {
            ReadDocument& d =
                add("the schema's scene example [" + std::to_string(sceneIndex++) + "]", example);
            JsonSource source{d.name, dir};
            source.keyLog = &d.log;
            (void)parseScene(example.dump(), source);
            d.map->walk(schema_, d.value, "");
        }
        fs::remove_all(dir);
        for (const auto& [type, branch] : materialBranches(schema_)) {
            int index = 0;
            for (const auto& example : (*branch)["examples"]) {
                ReadDocument& d = add(
                    "the schema's example " + type + "[" + std::to_string(index++) + "]", example);
                JsonSource source{d.name, kSource / "docs"};
                source.keyLog = &d.log;
                (void)parseMaterial(JsonReader(d.value, "", source));
                d.map->walk(schema_["$defs"]["material"], d.value, "");
            }
        }
        for (const auto& d : documents_)
            visited_.insert(d.map->visited().begin(), d.map->visited().end());
    }

    static ReadDocument& add(std::string name, Json value) {
        documents_.push_back(
            {std::move(name), std::move(value), {}, std::make_shared<JsonSchemaMap>(schema_)});
        return documents_.back();
    }

    static inline Json schema_;
    static inline std::deque<ReadDocument> documents_;  // add() keeps earlier references valid
    static inline std::set<const Json*> visited_;
};

std::set<std::string> asSet(const std::vector<std::string>& v) {
    return {v.begin(), v.end()};
}

TEST_F(SceneSchema, EveryKeyAReaderAsksForIsNamedWhereItIsAsked) {
    for (const auto& d : documents_)
        for (const auto& k : d.log.keys) {
            const auto& schemas = d.map->at(k.objectPath);
            ASSERT_FALSE(schemas.empty())
                << d.name << ": the schema describes no object at " << k.objectPath;
            const bool named = std::any_of(schemas.begin(), schemas.end(), [&](const Json* s) {
                return (s->contains("properties") && (*s)["properties"].contains(k.key)) ||
                       (s->contains("additionalProperties") &&
                        (*s)["additionalProperties"].is_object());
            });
            EXPECT_TRUE(named) << d.name << ": a reader asks for \"" << k.key << "\" at "
                               << (k.objectPath.empty() ? "(top level)" : k.objectPath)
                               << ", which the schema does not name there";
        }
}

TEST_F(SceneSchema, EveryKeyTheSchemaNamesIsAskedForByAReader) {
    // Per subschema, the keys the readers asked of the objects it describes.
    std::map<const Json*, std::set<std::string>> asked;
    for (const auto& d : documents_)
        for (const auto& k : d.log.keys)
            for (const Json* s : d.map->at(k.objectPath))
                asked[s].insert(k.key);
    for (const Json* s : visited_) {
        if (!s->contains("properties")) continue;
        for (const auto& [key, property] : (*s)["properties"].items())
            EXPECT_TRUE(asked[s].count(key))
                << "the schema names \"" << key << "\" in " << s->dump().substr(0, 120)
                << "... but no reader asks for it (on any shipped scene or schema example)";
    }
}

TEST_F(SceneSchema, EverySubschemaWithKeysIsReachedByASceneOrAnExample) {
    // Otherwise the two tests above would say nothing of it.
    std::vector<const Json*> withKeys;
    const auto collect = [&](const auto& self, const Json& s) -> void {
        if (s.is_object() && s.contains("properties")) withKeys.push_back(&s);
        if (s.is_structured())
            for (const auto& child : s)
                self(self, child);
    };
    collect(collect, schema_);
    for (const Json* s : withKeys)
        EXPECT_TRUE(visited_.count(s))
            << "no shipped scene or schema example reaches " << s->dump().substr(0, 160);
}

TEST_F(SceneSchema, AKeyReadAsANameHasTheReadersNamesAsItsEnum) {
    int checked = 0;
    for (const auto& d : documents_)
        for (const auto& k : d.log.keys) {
            if (k.names.empty()) continue;
            bool found = false;
            for (const Json* s : d.map->at(k.objectPath)) {
                if (!s->contains("properties") || !(*s)["properties"].contains(k.key)) continue;
                const Json& property = d.map->resolve((*s)["properties"][k.key]);
                if (!property.contains("enum")) continue;  // a oneOf branch's const
                found = true;
                ++checked;
                EXPECT_EQ(asSet(property["enum"].get<std::vector<std::string>>()), asSet(k.names))
                    << d.name << ": " << k.objectPath << "." << k.key;
            }
            EXPECT_TRUE(found) << d.name << ": the schema gives no enum for \"" << k.key << "\" at "
                               << k.objectPath;
        }
    EXPECT_GT(checked, 100);
}

TEST_F(SceneSchema, TheMaterialTypesAreTheLoadersWithExamplesItAccepts) {
    const auto branches = materialBranches(schema_);
    std::vector<std::string> schemaTypes;
    for (const auto& [type, branch] : branches) {
        schemaTypes.push_back(type);
        EXPECT_FALSE((*branch)["examples"].empty()) << type << " has no example";
    }
    EXPECT_EQ(asSet(schemaTypes), asSet(materialTypeNames()));
    EXPECT_EQ(asSet(schema_["$defs"]["material"]["properties"]["type"]["enum"]
                        .get<std::vector<std::string>>()),
              asSet(materialTypeNames()));
}

// The material part of the schema is written from the registrations
// (scripts/update-material-schema.py): in their order, each branch the one its type carries.
TEST_F(SceneSchema, EachMaterialBranchIsItsRegistrations) {
    const Json& material = schema_["$defs"]["material"];
    const auto kinds = materialKinds();
    ASSERT_EQ(material["oneOf"].size(), kinds.size())
        << "run scripts/update-material-schema.py after changing a material type";
    for (std::size_t i = 0; i < kinds.size(); ++i) {
        EXPECT_EQ(material["oneOf"][i], Json::parse(kinds[i]->schema))
            << kinds[i]->name << ": docs/scene.schema.json differs from its registration; run "
            << "scripts/update-material-schema.py";
        EXPECT_EQ(material["properties"]["type"]["enum"][i], std::string(kinds[i]->name));
    }
}

// A type's texturable keys are exactly the keys its branch of the schema lets name a texture.
TEST_F(SceneSchema, TexturableKeysTakeATextureInTheSchema) {
    int checked = 0;
    for (const MaterialKind* kind : materialKinds()) {
        const Json branch = Json::parse(kind->schema);
        for (const TexturableKey& t : kind->texturable) {
            const std::string key(t.key);
            ASSERT_TRUE(branch["properties"].contains(key)) << kind->name << "." << key;
            const std::string ref = branch["properties"][key].value("$ref", "");
            EXPECT_TRUE(ref == "#/$defs/textured_reflectance" ||
                        ref == "#/$defs/textured_roughness")
                << kind->name << "." << key << " is texturable but its schema says " << ref;
            ++checked;
        }
        for (const auto& [key, property] : branch["properties"].items()) {
            if (property.value("$ref", "").starts_with("#/$defs/textured_")) {
                EXPECT_TRUE(kind->texturedParameter(key))
                    << kind->name << "." << key << " takes a texture in the schema, not in lamina";
            }
        }
    }
    EXPECT_GT(checked, 10);
}

}  // namespace
}  // namespace lamina::render
