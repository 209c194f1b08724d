// Which parts of a JSON Schema describe each object of a JSON document: the map the scene
// schema test uses to hold docs/scene.schema.json to the readers' own keys. It follows the
// keywords the scene schema uses ($ref into $defs, oneOf/anyOf, properties,
// additionalProperties, items, prefixItems) and picks a oneOf branch by the shallow checks a
// reader's choice depends on: the JSON type, `const`, the `required` keys and the const of a
// `type` property. Paths are spelt as JsonReader::path() spells them ("shapes[2].material").
#pragma once

#include <map>
#include <set>
#include <string>
#include <vector>

#include "lamina/core/json_reader.h"

namespace lamina::testing {

class JsonSchemaMap {
  public:
    explicit JsonSchemaMap(const Json& root) : root_(root) {}

    /// `schema` after following any "$ref": "#/$defs/NAME".
    const Json& resolve(const Json& schema) const {
        const Json* s = &schema;
        while (s->is_object() && s->contains("$ref")) {
            const std::string ref = (*s)["$ref"].get<std::string>();
            const std::string prefix = "#/$defs/";
            if (ref.rfind(prefix, 0) != 0) throw std::runtime_error("unsupported $ref " + ref);
            s = &root_["$defs"].at(ref.substr(prefix.size()));
        }
        return *s;
    }

    /// Adds the subschemas that describe `value` (at `path`) and every value inside it.
    void walk(const Json& schema, const Json& value, const std::string& path) {
        std::vector<const Json*> found;
        candidates(schema, value, found);
        auto& at = schemasAt_[path];
        at.insert(at.end(), found.begin(), found.end());
        for (const Json* s : found)
            visited_.insert(s);
        if (value.is_object()) {
            for (const auto& [key, child] : value.items()) {
                const std::string childPath = path.empty() ? key : path + "." + key;
                for (const Json* s : found) {
                    if (s->contains("properties") && (*s)["properties"].contains(key))
                        walk((*s)["properties"][key], child, childPath);
                    else if (s->contains("additionalProperties") &&
                             (*s)["additionalProperties"].is_object())
                        walk((*s)["additionalProperties"], child, childPath);
                }
            }
        } else if (value.is_array()) {
            for (std::size_t i = 0; i < value.size(); ++i) {
                const std::string childPath = path + "[" + std::to_string(i) + "]";
                for (const Json* s : found) {
                    if (s->contains("prefixItems") && i < (*s)["prefixItems"].size())
                        walk((*s)["prefixItems"][i], value[i], childPath);
                    else if (s->contains("items") && (*s)["items"].is_object())
                        walk((*s)["items"], value[i], childPath);
                }
            }
        }
    }

    /// The subschemas found for the object at `path` (empty when the walk never got there).
    const std::vector<const Json*>& at(const std::string& path) const {
        static const std::vector<const Json*> none;
        const auto it = schemasAt_.find(path);
        return it == schemasAt_.end() ? none : it->second;
    }

    /// Every subschema some walk reached.
    const std::set<const Json*>& visited() const { return visited_; }

  private:
    static bool hasJsonType(const Json& value, const std::string& type) {
        if (type == "object") return value.is_object();
        if (type == "array") return value.is_array();
        if (type == "string") return value.is_string();
        if (type == "boolean") return value.is_boolean();
        if (type == "integer") return value.is_number_integer();
        if (type == "number") return value.is_number();
        return type == "null" && value.is_null();
    }

    // The shallow checks that choose between oneOf branches.
    bool admits(const Json& s, const Json& value) const {
        if (s.contains("type") && !hasJsonType(value, s["type"].get<std::string>())) return false;
        if (s.contains("const") && s["const"] != value) return false;
        if (!value.is_object()) return true;
        if (s.contains("required"))
            for (const auto& key : s["required"])
                if (!value.contains(key.get<std::string>())) return false;
        if (s.contains("properties") && s["properties"].contains("type") &&
            value.contains("type")) {
            const Json& typeSchema = resolve(s["properties"]["type"]);
            if (typeSchema.contains("const") && typeSchema["const"] != value["type"]) return false;
        }
        return true;
    }

    void candidates(const Json& schema, const Json& value, std::vector<const Json*>& out) const {
        const Json& s = resolve(schema);
        if (!s.is_object() || !admits(s, value)) return;
        if (s.contains("properties") || s.contains("items") || s.contains("prefixItems") ||
            s.contains("additionalProperties"))
            out.push_back(&s);
        for (const char* keyword : {"oneOf", "anyOf"})
            if (s.contains(keyword))
                for (const auto& branch : s[keyword])
                    candidates(branch, value, out);
    }

    const Json& root_;
    std::map<std::string, std::vector<const Json*>> schemasAt_;
    std::set<const Json*> visited_;
};

}  // namespace lamina::testing
