"""lamina from Python: the BSDF lab, spectra and colour, rendering and the experiments.

NumPy arrays in and out; the same materials, scenes, validation and one-line errors as the
``lamina`` command line (errors are ValueError with the file and the JSON path). See
docs/python.md.
"""

from ._lamina import (  # noqa: F401
    Image,
    Material,
    blackbody,
    cie_cmf,
    compare,
    conductor_f0_f82,
    convergence,
    fresnel,
    glasses,
    illuminant,
    illuminants,
    ior,
    layering,
    material_kinds,
    metals,
    random_numbers,
    read_image,
    reciprocity,
    rgb_to_spectrum,
    rgb_to_xyz,
    stability,
    xyz_to_rgb,
)
from . import _lamina


class RenderInterrupted(KeyboardInterrupt):
    """Ctrl-C during lamina.render: raised after the pass in flight; ``image`` is the partial
    render (an Image, ``image.partial`` is True)."""

    def __init__(self, message, image):
        super().__init__(message)
        self.image = image


def render(scene, **overrides):
    """Renders ``scene`` (a dict in the scene format, or a path to a scene file) and returns
    an Image (``.rgb``, ``.aovs``, ``.metadata``, ``.save(path)``).

    The overrides are the command line's: spp, time, mode, integrator, mis, sampler, seed,
    threads, max_depth, resolution ((w, h) or "WxH"), aovs; ``progress=callable`` is called
    after every pass with a dict of fraction, seconds, passes and spp. The GIL is released
    while rendering. Ctrl-C stops the render after the pass in flight and raises
    RenderInterrupted (a KeyboardInterrupt) carrying the partial image; an exception raised by
    the progress callback stops it the same way and is re-raised with the image as its
    ``image`` attribute.
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
