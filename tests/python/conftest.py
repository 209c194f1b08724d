"""Shared fixtures of the Python module's tests: the lamina executable the module is checked
against and the source tree (tests/CMakeLists.txt sets both in the environment)."""

import json
import os
import re
import subprocess

import pytest


@pytest.fixture(scope="session")
def lamina_exe():
    return os.environ["LAMINA_EXECUTABLE"]


@pytest.fixture(scope="session")
def source_dir():
    return os.environ["LAMINA_SOURCE_DIR"]


def run_cli(exe, *args, stdin=None):
    """Runs the lamina command; returns (exit status, stdout, stderr)."""
    p = subprocess.run([exe, *args], input=stdin, capture_output=True, text=True)
    return p.returncode, p.stdout, p.stderr


def load_scene_dict(path):
    """A scene file as a dict: its whole-line // comments removed (lamina's JSON allows
    comments, Python's does not)."""
    with open(path) as f:
        text = "\n".join(line for line in f if not re.match(r"\s*//", line))
    return json.loads(text)
