#!/usr/bin/env python3
"""Validates every shipped scene and every example in docs/scene.schema.json with a JSON
Schema validator (python3-jsonschema), and checks that the schema refuses what the loader
refuses in a few known cases. The schema's keys and names are held to the readers by
tests/scene/scene_schema_test.cpp; this test holds the shipped files to the schema's rules.

Usage: validate_scene_schema.py SOURCE_DIR. Exits 77 (skipped) when jsonschema is absent.
"""
import json
import pathlib
import sys

try:
    import jsonschema
except ImportError:
    print("skipped: python3-jsonschema is not installed (scripts/setup.sh installs it)")
    sys.exit(77)


def strip_comments(text):
    """The JSON text without // and /* */ comments (which lamina's reader allows)."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if c == '"':
            j = i + 1
            while text[j] != '"':
                j += 2 if text[j] == "\\" else 1
            out.append(text[i:j + 1])
            i = j + 1
        elif text.startswith("//", i):
            i = text.find("\n", i)
            i = n if i < 0 else i
        elif text.startswith("/*", i):
            i = text.index("*/", i) + 2
        else:
            out.append(c)
            i += 1
    return "".join(out)


def main():
    source = pathlib.Path(sys.argv[1])
    schema = json.loads((source / "docs" / "scene.schema.json").read_text())
    jsonschema.Draft202012Validator.check_schema(schema)
    validator = jsonschema.Draft202012Validator(schema)
    failures = []

    def check(name, document, valid=True):
        errors = sorted(validator.iter_errors(document), key=lambda e: list(e.absolute_path))
        if valid and errors:
            e = errors[0]
            path = ".".join(str(p) for p in e.absolute_path) or "(top level)"
            failures.append(f"{name}: {path}: {e.message[:200]}")
        if not valid and not errors:
            failures.append(f"{name}: accepted, but the loader refuses it")

    scenes = sorted((source / "scenes").rglob("*.json"))
    for f in scenes:
        check(str(f.relative_to(source)), json.loads(strip_comments(f.read_text())))
    for i, example in enumerate(schema.get("examples", [])):
        check(f"scene example [{i}]", example)
    branches = schema["$defs"]["material"].get("oneOf", [])
    for branch in branches:
        kind = branch["properties"]["type"]["const"]
        for i, example in enumerate(branch.get("examples", [])):
            check(f"{kind} example [{i}]", {"materials": {"m": example}})
    # What the loader refuses, the schema refuses too.
    for name, material in [
        ("unknown material type", {"type": "velvet"}),
        ("key of another material type", {"type": "lambert", "roughness": 0.5}),
        ("misspelt key", {"type": "phong", "shinyness": 10}),
        ("fresnel auto outside conductors", {"type": "standard", "fresnel": "auto"}),
        ("roughness out of range", {"type": "conductor", "material": "Au", "roughness": 2}),
    ]:
        check(name, {"materials": {"m": material}}, valid=False)

    for line in failures:
        print(line)
    print(f"{len(scenes)} scenes, {len(schema.get('examples', []))} scene examples and "
          f"{sum(len(b.get('examples', [])) for b in branches)} material examples: "
          f"{len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
