"""The command line and the Python module against the commands' declarations
(experiments/command_declaration.h). For every declared command, the options that
`lamina COMMAND --help` lists and the keywords the Python function takes are the ones the
declaration gives that front end, with its defaults: an option added to one front end alone,
or missing from one, fails here unless the declaration lists the difference with its reason."""

import inspect
import re

import pytest

import lamina
from lamina import _lamina
from conftest import run_cli

COMMANDS = [c["name"] for c in lamina.commands()]


def cli_help(exe, command):
    """{option name: its default as the help shows it, or None} of `lamina COMMAND --help`:
    positionals by name, options by their long name without the dashes."""
    status, out, err = run_cli(exe, command, "--help")
    assert status == 0, err
    options, section = {}, None
    for line in out.splitlines():
        if line in ("Positionals:", "Options:"):
            section = line
            continue
        # An option's line starts with two spaces (its description, when pushed to the next
        # line, with thirty): its names, its type with the default after "=", then the
        # description after two or more spaces.
        if section is None or not line.startswith("  ") or line.startswith("   "):
            continue
        head = re.split(r"\s{2,}", line.strip())[0]
        names, _, kind = head.partition(" ")
        if section == "Positionals:":
            name = names
        else:
            name = [n for n in names.split(",") if n.startswith("--")][0][2:]
        default = re.search(r"=(\S+)", kind)
        options[name] = default.group(1) if default else None
    options.pop("help", None)
    return options


def python_keywords(command):
    """The keywords the Python function takes: an experiment's from its signature, render's
    from its refusal of an unknown keyword (it takes **overrides), compare's from pybind11's
    signature line."""
    if command == "render":
        with pytest.raises(TypeError) as e:
            lamina.render("no-scene.json", no_such_keyword=1)
        listed = str(e.value).split("; expected ", 1)[1].split(", ")
        return {"scene": inspect.Parameter.empty, **{k: None for k in listed}}
    if command == "compare":
        signature = lamina.compare.__doc__.splitlines()[0]
        return {name: None for name in re.findall(r"(\w+):", signature.split("->")[0])}
    return {name: p.default for name, p in inspect.signature(getattr(lamina, command)).parameters.items()}


def shown(default):
    """A declared default as the command line's help shows it."""
    if isinstance(default, list):
        return ",".join(default)
    return str(default)


@pytest.mark.parametrize("command", COMMANDS)
def test_the_command_line_has_the_declared_options(lamina_exe, command):
    declared = {o["name"]: o for o in lamina.command_options(command) if o["command_line"]}
    cli = cli_help(lamina_exe, command)
    assert set(cli) - set(declared) == set(), "on the command line, not in the declaration"
    assert set(declared) - set(cli) == set(), "declared for the command line, missing from it"
    for name, o in declared.items():
        default = o["default"]
        if default is None or o["kind"] == "flag":
            continue
        if isinstance(default, (int, float)):
            assert float(cli[name]) == pytest.approx(default), name
        else:
            assert cli[name] == shown(default), name


@pytest.mark.parametrize("command", COMMANDS)
def test_python_has_the_declared_keywords(command):
    declared = {o["python"]: o for o in lamina.command_options(command) if o["python"]}
    python = python_keywords(command)
    assert set(python) - set(declared) == set(), "in Python, not in the declaration"
    assert set(declared) - set(python) == set(), "declared for Python, missing from it"
    if command in ("render", "compare"):
        return
    for name, o in declared.items():
        default = python[name]
        if o["required"]:
            assert default is inspect.Parameter.empty, name
        else:
            assert default == o["default"], name


@pytest.mark.parametrize("command", COMMANDS)
def test_every_difference_between_the_front_ends_has_a_reason(command):
    for o in lamina.command_options(command):
        respelled = o["python"] is not None and o["python"] != o["name"].replace("-", "_")
        if o["front_end"] != "both" or respelled:
            assert o["difference"], f"{command} {o['name']}: differs without a reason"


def test_python_has_every_experiment_declared():
    experiments = [c["name"] for c in lamina.commands() if c["experiment"]]
    assert experiments == [
        "reciprocity", "convergence", "fresnel", "stability", "layering", "polarisation",
        "media"]
    for name in experiments:
        assert callable(getattr(lamina, name)) and name in lamina.__all__
        assert getattr(lamina, name).__doc__.startswith(
            next(c["help"] for c in lamina.commands() if c["name"] == name))
