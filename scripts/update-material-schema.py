#!/usr/bin/env python3
"""Writes the material part of docs/scene.schema.json from the material registrations.

Each material type's registration (bsdf/src/*_reader.cpp, MaterialKind) carries its branch of the
schema; the schema test (tests/scene/scene_schema_test.cpp) fails when the file and the
registrations differ. After adding or changing a material type, build the Python module and run

    PYTHONPATH=build/python python3 scripts/update-material-schema.py

which replaces $defs.material's "type" enum and "oneOf" branches (in the registrations' order) and
writes the file in its compact layout. --check only reports whether the file is up to date.
"""
import argparse
import json
import pathlib
import sys

WIDTH = 100


def compact(value, indent=0, prefix=0):
    """JSON in the file's layout: an array or object on one line where it fits in WIDTH columns
    (with the key before it and a comma after), else one member per line."""
    flat = json.dumps(value, ensure_ascii=False, separators=(", ", ": "))
    if not isinstance(value, (dict, list)) or not value or indent + prefix + len(flat) + 1 <= WIDTH:
        return flat
    pad = " " * (indent + 2)
    if isinstance(value, dict):
        items = []
        for k, v in value.items():
            key = json.dumps(k, ensure_ascii=False) + ": "
            items.append(pad + key + compact(v, indent + 2, len(key)))
        return "{\n" + ",\n".join(items) + "\n" + " " * indent + "}"
    items = [pad + compact(v, indent + 2) for v in value]
    return "[\n" + ",\n".join(items) + "\n" + " " * indent + "]"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true", help="only report whether it is up to date")
    parser.add_argument("--schema", default=str(pathlib.Path(__file__).resolve().parent.parent /
                                                "docs" / "scene.schema.json"))
    args = parser.parse_args()
    path = pathlib.Path(args.schema)
    schema = json.loads(path.read_text(encoding="utf-8"))
    try:
        import lamina
    except ImportError:
        sys.exit("update-material-schema: the lamina Python module is needed: "
                 "PYTHONPATH=build/python python3 scripts/update-material-schema.py")
    kinds = lamina.material_kinds()
    material = schema["$defs"]["material"]
    material["properties"]["type"]["enum"] = [k["name"] for k in kinds]
    material["oneOf"] = [k["schema"] for k in kinds]
    text = compact(schema) + "\n"
    if args.check:
        if text != path.read_text(encoding="utf-8"):
            sys.exit(f"update-material-schema: {path} differs from the material registrations")
        print(f"update-material-schema: {path} is up to date")
        return
    path.write_text(text, encoding="utf-8")
    print(f"update-material-schema: wrote {path} ({len(kinds)} material types)")


if __name__ == "__main__":
    main()
