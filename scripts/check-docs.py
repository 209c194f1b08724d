#!/usr/bin/env python3
"""The docs as a reference, checked against the tree:

- docs/architecture.md names only files and folders that exist;
- no doc speaks of this project's issue numbers (the history is in git; another project's
  tracker, "pbrt-v4 issue 30", may be cited);
- no file of the repository cites a document that is not in it (DESIGN.md, PITFALLS.md and
  PEERS.md of the shared folder beside the clone).

For docs/architecture.md:

A name with a slash is a path from the repository's root (or from docs/, for links); a bare file
name (`geometry.h`) must be the name of some file in the repository. Placeholders in capitals
(`NAME_integrator.h`, `FORMAT_*`) name what a new thing adds and are not checked. Run by ctest
(label unit); exits 1 naming each name that points nowhere.
"""
import pathlib
import re
import sys

root = pathlib.Path(__file__).resolve().parent.parent
doc = root / "docs" / "architecture.md"
text = doc.read_text(encoding="utf-8")
files = {p.name for p in root.rglob("*") if p.is_file() and "build" not in p.parts[len(root.parts):][:1]
         and ".git" not in p.parts}
SUFFIXES = (".h", ".cpp", ".md", ".sh", ".py", ".cmake", ".json", ".txt")
missing = []
for match in re.finditer(r"`([^`\s]+)`", text):
    name = match.group(1).rstrip(",.:;")
    name = re.sub(r"\(.*$", "", name)  # a call: `loadScene(...)`
    if re.search(r"[A-Z]{3,}", name.replace("CMakeLists", "").replace("README", "")):
        continue  # NAME_integrator.h, FORMAT_*, ...
    if "/" in name:
        if name.startswith(("lamina/", "-", "<", "$")) or "://" in name or "<room>" in name:
            continue  # an include path, an option, a variable
        path = name.rstrip("/")
        if not ((root / path).exists() or (doc.parent / path).exists()):
            missing.append(name)
    elif name.endswith(SUFFIXES) and name not in files:
        missing.append(name)
for line_no, line in enumerate(text.splitlines(), 1):
    for link in re.findall(r"\]\(([^)#\s]+)", line):
        if "://" not in link and not (doc.parent / link).exists():
            missing.append(f"{link} (link, line {line_no})")
problems = [f"docs/architecture.md names {name}, which is not in the tree" for name in missing]

# Issue numbers in the docs, unless the line cites another project's tracker.
OTHER_PROJECTS = re.compile(r"pbrt|mitsuba|cycles|blender|falcor|embree|openimageio|tev|#\d", re.I)
docs = [root / "README.md", *sorted((root / "docs").rglob("*.md"))]
for path in docs:
    for line_no, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        if re.search(r"\bissues? \d+", line, re.I) and not OTHER_PROJECTS.search(line):
            problems.append(f"{path.relative_to(root)}:{line_no}: names an issue number: {line.strip()}")

# Documents outside the repository.
OUTSIDE = re.compile(r"\b(DESIGN|PITFALLS|PEERS)\.md\b")
for path in sorted(root.rglob("*")):
    rel = path.relative_to(root)
    if not path.is_file() or rel.parts[0].startswith(("build", ".git")) or path == pathlib.Path(__file__).resolve():
        continue
    try:
        lines = path.read_text(encoding="utf-8").splitlines()
    except (UnicodeDecodeError, OSError):
        continue
    for line_no, line in enumerate(lines, 1):
        if OUTSIDE.search(line):
            problems.append(f"{rel}:{line_no}: cites a document outside the repository: {line.strip()}")

for problem in problems:
    print(f"check-docs: {problem}")
if problems:
    sys.exit(1)
print("check-docs: architecture.md matches the tree; no issue numbers; no outside documents cited")
