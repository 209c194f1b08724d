"""lamina from Python: the BSDF lab, spectra and colour, rendering and the experiments.

NumPy arrays in and out; the same materials, scenes, validation and one-line errors as the
``lamina`` command line (errors are ValueError with the file and the JSON path). See
docs/python.md.
"""

import inspect as _inspect

from ._lamina import (  # noqa: F401
    Image,
    Material,
    blackbody,
    cie_cmf,
    command_options,
    commands,
    compare,
    conductor_f0_f82,
    glasses,
    illuminant,
    illuminants,
    ior,
    material_kinds,
    metals,
    random_numbers,
    read_image,
    rgb_to_spectrum,
    rgb_to_xyz,
    xyz_to_rgb,
)
from . import _lamina


def _experiment(command):
    """The function of a declared experiment (experiments/command_declaration.h): its
    parameters are the declaration's Python options, in order, with their defaults; it returns
    the experiment's result. A new experiment declared in experiments/ appears here."""
    name = command["name"]
    options = [o for o in _lamina.command_options(name) if o["python"] is not None]
    signature = _inspect.Signature([
        _inspect.Parameter(o["python"], _inspect.Parameter.POSITIONAL_OR_KEYWORD,
                           default=_inspect.Parameter.empty if o["required"] else o["default"])
        for o in options])

    def run(*args, **kwargs):
        # Only what the caller gave: the declaration's defaults apply to the rest.
        return _lamina._run_experiment(name, dict(signature.bind(*args, **kwargs).arguments))

    run.__name__ = run.__qualname__ = name
    run.__signature__ = signature
    run.__doc__ = "\n".join(
        [command["help"] + ".", "", "Returns " + command["returns"] + ".", ""]
        + [f"{o['python']}: {o['help']}" for o in options])
    return run


for _command in _lamina.commands():
    if _command["experiment"]:
        globals()[_command["name"]] = _experiment(_command)
del _command


class RenderInterrupted(KeyboardInterrupt):
    """Ctrl-C during lamina.render: raised after the pass in flight; ``image`` is the partial
    render (an Image, ``image.partial`` is True)."""

    def __init__(self, message, image):
        super().__init__(message)
        self.image = image


def render(scene, **overrides):
    """Renders ``scene`` (a dict in the scene format, or a path to a scene file) and returns
    an Image (``.rgb``, ``.aovs``, ``.metadata``, ``.save(path)``).

    The overrides are the command line's, as its declaration gives them to Python
    (``command_options("render")``): spp, time, mode, integrator, mis, sampler,
    light_selection, seed, threads, max_depth, resolution ((w, h) or "WxH"), aovs;
    ``progress=callable`` is called after every pass with a dict of fraction, seconds, passes
    and spp. The GIL is released while rendering. Ctrl-C stops the render after the pass in
    flight and raises RenderInterrupted (a KeyboardInterrupt) carrying the partial image; an
    exception raised by the progress callback stops it the same way and is re-raised with the
    image as its ``image`` attribute.
    """
    image, stopped_by = _lamina._render(scene, **overrides)
    if stopped_by is None:
        return image
    if isinstance(stopped_by, KeyboardInterrupt):
        raise RenderInterrupted(
            f"render interrupted after {image.spp} spp (the partial image is .image)", image
        ) from stopped_by
    stopped_by.image = image
    raise stopped_by


__all__ = [name for name in dir() if not name.startswith("_")]
