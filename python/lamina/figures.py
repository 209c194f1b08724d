"""lamina's figures, drawn with matplotlib from the spec files the experiments write.

An experiment (experiments/, `Report::addFigure`) writes each figure's data as NAME.figure.json
(and, for a map, its values as NAME.f32: little-endian float32, row-major from the top row,
NaN where there is no value) and, at the end of the run, runs this file as a script on its
directory: ``python3 figures.py DIR`` draws every spec found there into NAME.png and NAME.pdf.

Three kinds of figure:

- ``lines``: series against x, each optionally with standard errors drawn as a band around it
  (never as a series of its own); logarithmic axes where the data span decades; one panel,
  several side by side sharing the y axis, or a grid of them sharing both axes (``columns``).
- ``map``: a false-colour map. Unsigned quantities use a sequential perceptual map (viridis),
  signed ones a diverging map with limits symmetric about zero; a logarithmic colour scale
  where the values span decades. The limits come from the data's percentiles and the caption
  printed under the map says which, and how many pixels lie beyond them. A cyclic quantity (an
  angle) uses a cyclic map (twilight) over its whole period.
- ``swatches``: a grid of true colours (what models look like side by side).

``problems(figure)`` lists what a reader of a drawn figure could be misled by (too many
pixels clipped, colour-bar limits that cut into the data's 1st-99th percentiles, text that
overlaps or leaves the figure, a legend outside its axes, an unlabelled axis or colour bar);
the tests hold every experiment's figures to an empty list. The module uses matplotlib's
object interface only (no pyplot), so importing it changes no backend.
"""

import json
import os
import sys
import textwrap

try:
    import matplotlib
    import numpy as np
    from matplotlib import colors
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure
    from matplotlib.image import AxesImage
    from matplotlib.legend import Legend
    from matplotlib.text import Text
except ImportError:
    if __name__ == "__main__":
        sys.exit(3)  # NO_MATPLOTLIB: the caller says so in one line and keeps the data
    raise

SPEC_SUFFIX = ".figure.json"
SPEC_VERSION = 1

#: The share of a map's pixels that may lie beyond its colour limits without a reason given.
MAX_CLIPPED = 0.05
#: A log axis or colour scale is chosen when the positive data span at least this ratio.
DECADES_RATIO = 100.0

_WIDTH_IN = 6.4
_LINE_HEIGHT_IN = 4.4
_CAPTION_POINTS = 7.5
_TITLE_POINTS = 10.5


class SpecError(ValueError):
    """A figure spec that cannot be drawn: names the file and what was expected."""


# --------------------------------------------------------------------------- reading specs


def load(path):
    """The spec at `path` as a dict; a map's values are read into spec["values"] (a 2-D float
    array, NaN where there is none)."""
    try:
        with open(path) as f:
            spec = json.load(f)
    except (OSError, ValueError) as e:
        raise SpecError(f"{path}: expected a JSON figure spec ({e})") from None
    if spec.get("lamina_figure") != SPEC_VERSION:
        raise SpecError(f"{path}: lamina_figure: expected {SPEC_VERSION}")
    if spec.get("kind") not in ("lines", "map", "swatches"):
        raise SpecError(f"{path}: kind: expected \"lines\", \"map\" or \"swatches\"")
    if spec["kind"] == "map":
        data = os.path.join(os.path.dirname(path), spec["data"])
        w, h = int(spec["width"]), int(spec["height"])
        values = np.fromfile(data, dtype="<f4")
        if values.size != w * h:
            raise SpecError(f"{data}: expected {w} x {h} float32 values, found {values.size}")
        spec["values"] = values.reshape(h, w).astype(np.float64)
    return spec


# --------------------------------------------------------------------------- scales


def spans_decades(values):
    """Whether the positive finite values span DECADES_RATIO or more (and there are no
    others): what makes a log axis the readable one."""
    v = np.asarray(values, dtype=np.float64)
    v = v[np.isfinite(v)]
    if v.size < 2 or np.any(v <= 0):
        return False
    return v.max() / v.min() >= DECADES_RATIO


def _axis_is_log(setting, values):
    """A spec's log_x / log_y: "auto" (log where the data span decades), "log" or "linear"."""
    if setting == "auto":
        return spans_decades(values)
    return setting in ("log", True)


def map_scale(values, signed, from_zero=False, percentile=99.0, scale="auto", upper=None,
              cycle=None):
    """The colour scale of a map: (norm, colour map name, caption sentence).

    Cyclic (`cycle`, the quantity's period [lo, hi], an angle): twilight over the whole period,
    whose ends meet in one colour, as the quantity's do.

    Unsigned: viridis from 0 (`from_zero`) or the data's (100 - percentile)th percentile to its
    `percentile`th; logarithmic when `scale` is "log", or "auto" and the values are positive
    and span decades. Signed: RdBu_r from -L to L, L the `percentile`th percentile of |values|
    (symmetric log when they span decades). A given `upper` replaces the upper percentile (and
    L): a limit the user fixed."""
    v = values[np.isfinite(values)]
    if v.size == 0:
        return colors.Normalize(0, 1), "viridis", "No finite values."
    lo_p = 100.0 - percentile
    if cycle is not None:
        lo, hi = float(cycle[0]), float(cycle[1])
        p1, p99 = np.percentile(v, [1, 99])
        return colors.Normalize(lo, hi), "twilight", (
            f"Cyclic colour scale (twilight) over the whole period {lo:g} to {hi:g}, whose ends "
            f"are one colour (the values' 1st-99th percentiles: {p1:.3g} to {p99:.3g})")
    if signed:
        mag = np.abs(v)
        limit = float(upper) if upper is not None else float(np.percentile(mag, percentile))
        if limit <= 0:
            limit = float(mag.max()) or 1.0
        small = float(np.percentile(mag[mag > 0], 50)) if np.any(mag > 0) else limit
        log = scale == "log" or (scale == "auto" and limit / max(small, 1e-300) >= DECADES_RATIO)
        if log:
            linthresh = max(small, limit / 1e4)
            norm = colors.SymLogNorm(linthresh=linthresh, vmin=-limit, vmax=limit, base=10)
            how = (f"symmetric log scale (linear within +-{linthresh:.3g}), "
                   f"limits +-{limit:.3g}")
        else:
            norm = colors.Normalize(-limit, limit)
            how = f"limits +-{limit:.3g}"
        source = ("fixed (the 99th percentile of |value| is "
                  f"{np.percentile(mag, 99):.3g})" if upper is not None
                  else f"the {percentile:g}th percentile of |value|")
        return norm, "RdBu_r", f"Diverging colour scale, {how}: {source}"
    positive = v[v > 0]
    log = not from_zero and (scale == "log" or (scale == "auto" and spans_decades(v)))
    if log and positive.size:
        lo = float(np.percentile(positive, lo_p))
        hi = float(upper) if upper is not None else float(np.percentile(positive, percentile))
        if hi <= lo:
            hi = lo * 10
        top = "fixed" if upper is not None else f"the {percentile:g}th percentile"
        return colors.LogNorm(lo, hi), "viridis", (
            f"Log colour scale from {lo:.3g} (the {lo_p:g}th percentile of the values) to "
            f"{hi:.3g} ({top})")
    lo = 0.0 if from_zero else float(np.percentile(v, lo_p))
    hi = float(upper) if upper is not None else float(np.percentile(v, percentile))
    if hi <= lo:
        hi = lo + (abs(lo) if lo else 1.0)
    where = "0" if from_zero else f"the {lo_p:g}th percentile ({lo:.3g})"
    to = (f"{hi:.3g} (fixed; the values' 99th percentile is {np.percentile(v, 99):.3g})"
          if upper is not None else f"the {percentile:g}th percentile of the values ({hi:.3g})")
    return colors.Normalize(lo, hi), "viridis", f"Colour scale from {where} to {to}"


def clipped_fraction(values, norm):
    """The share of the finite values that lie beyond the norm's limits (drawn in its end
    colours), with a relative tolerance of 1e-6 of the range."""
    v = np.asarray(values, dtype=np.float64)
    v = v[np.isfinite(v)]
    if v.size == 0:
        return 0.0
    lo, hi = float(norm.vmin), float(norm.vmax)
    tol = 1e-6 * max(abs(hi - lo), abs(hi), abs(lo), 1e-300)
    return float(np.mean((v < lo - tol) | (v > hi + tol)))


# --------------------------------------------------------------------------- drawing


def _wrap(text, points, width_in=_WIDTH_IN):
    # Characters per line for the figure's width at this font size (about 0.5 em a glyph).
    chars = max(20, int(width_in * 72 / (0.52 * points)) - 4)
    return "\n".join(textwrap.wrap(text, chars)) if text else ""


def _finish(fig, spec, caption):
    """Title, caption under the axes, layout with room for both."""
    caption = _wrap(caption, _CAPTION_POINTS, fig.get_figwidth())
    lines = caption.count("\n") + 1 if caption else 0
    bottom = (lines * _CAPTION_POINTS * 1.3 + 8) / (72 * fig.get_figheight()) if lines else 0
    if caption:
        fig.text(0.012, 0.008, caption, fontsize=_CAPTION_POINTS, va="bottom", ha="left")
    fig.suptitle(_wrap(spec.get("title", ""), _TITLE_POINTS, fig.get_figwidth()),
                 fontsize=_TITLE_POINTS)
    fig.tight_layout(rect=(0, bottom, 1, 1))
    fig.lamina_caption = caption.replace("\n", " ")
    fig.lamina_name = spec.get("name", "")


def _panels(spec):
    """A lines spec's panels: spec["panels"], or its "series" as the one panel."""
    if "panels" in spec:
        return spec["panels"]
    return [{"title": "", "series": spec.get("series", [])}]


def _draw_series(ax, s, log_x, log_y):
    x = np.asarray(s["x"], dtype=np.float64)
    y = np.asarray(s["y"], dtype=np.float64)
    ok = np.isfinite(x) & np.isfinite(y)
    if log_x:
        ok &= x > 0
    if log_y:
        ok &= y > 0
    style = {"dashed": "--", "dotted": ":"}.get(s.get("style", "solid"), "-")
    (line,) = ax.plot(x[ok], y[ok], style, label=s.get("name") or None, color=s.get("color"),
                      linewidth=1.4, marker="o" if s.get("markers") else None, markersize=3)
    if s.get("se") is not None:
        se = np.asarray(s["se"], dtype=np.float64)[ok]
        low, high = y[ok] - se, y[ok] + se
        if log_y:  # a band below zero cannot be drawn on a log axis: cut it at y / 10
            low = np.maximum(low, y[ok] / 10)
        ax.fill_between(x[ok], low, high, color=line.get_color(), alpha=0.25, linewidth=0)


def draw_lines(spec):
    """Line plots, one per panel side by side (a shared y axis), every series with its
    standard-error band (series["se"])."""
    panels = _panels(spec)
    every = [s for p in panels for s in p["series"]]

    def values(key):
        v = [np.asarray(s[key], dtype=np.float64) for s in every]
        return np.concatenate(v) if v else np.zeros(0)

    log_x = _axis_is_log(spec.get("log_x", "auto"), values("x"))
    log_y = _axis_is_log(spec.get("log_y", "auto"), values("y"))
    # A grid of `columns` panels a row shares both axes: the bottom row carries the x label,
    # the first column the y label.
    columns = max(1, min(int(spec.get("columns") or len(panels)), len(panels)))
    rows = -(-len(panels) // columns)
    width = _WIDTH_IN if len(panels) == 1 else min(10.0, 3.3 * columns)
    height = spec.get("height_in", _LINE_HEIGHT_IN if rows == 1 else 1.2 + 2.0 * rows)
    fig = Figure(figsize=(width, height))
    FigureCanvasAgg(fig)
    grid = fig.subplots(rows, columns, sharex=rows > 1, sharey=True, squeeze=False)
    axes = list(grid.ravel())
    for unused in axes[len(panels):]:
        fig.delaxes(unused)
    for i, (ax, panel) in enumerate(zip(axes, panels)):
        bottom = i + columns >= len(panels)
        for s in panel["series"]:
            _draw_series(ax, s, log_x, log_y)
        if log_x:
            ax.set_xscale("log")
        if log_y:
            ax.set_yscale("log")
        if panel.get("title"):
            ax.set_title(panel["title"], fontsize="medium")
        ax.set_xlabel(panel.get("x_label", spec["x_label"]) if bottom else "")
        ax.set_ylabel(spec["y_label"] if i % columns == 0 else "")
        ax.lamina_shares_x_label = not bottom
        ax.lamina_shares_y_label = i % columns != 0
        ax.grid(True, which="major", alpha=0.3)
        # One legend (the first panel's) names what every panel shows.
        named = [s for s in panel["series"] if s.get("name")]
        if named and i == 0:
            ax.legend(loc=spec.get("legend", "best"), fontsize="small" if len(panels) == 1
                      else "x-small", ncol=2 if len(named) > 5 and len(panels) == 1 else 1,
                      framealpha=0.85)
    caption = spec.get("caption", "")
    if any(s.get("se") is not None for s in every):
        caption = (caption + " " if caption else "") + "Bands: +-1 standard error."
    _finish(fig, spec, caption)
    return fig


def draw_swatches(spec):
    """A grid of true colours (linear Rec.709, shown sRGB-encoded), rows and columns named."""
    rows, columns = spec["rows"], spec["columns"]
    rgb = np.asarray([[np.nan if c is None else c for c in colour] for colour in spec["colours"]],
                     dtype=np.float64).reshape(len(rows), len(columns), 3)
    rgb = np.clip(np.nan_to_num(rgb, nan=0.0), 0.0, 1.0)
    srgb = np.where(rgb <= 0.0031308, 12.92 * rgb, 1.055 * rgb ** (1 / 2.4) - 0.055)
    height = min(7.0, 1.6 + 0.45 * len(rows))
    fig = Figure(figsize=(_WIDTH_IN, height))
    FigureCanvasAgg(fig)
    ax = fig.add_subplot()
    ax.imshow(srgb, interpolation="nearest", aspect="auto")
    ax.set_xticks(range(len(columns)), columns)
    ax.set_yticks(range(len(rows)), rows, fontsize="small")
    ax.set_xlabel(spec["x_label"])
    ax.set_ylabel(spec["y_label"])
    _finish(fig, spec, spec.get("caption", ""))
    return fig


def _map_extent(spec, w, h):
    """imshow's extent and whether the axes are the image's pixels."""
    xa, ya = spec.get("x_axis"), spec.get("y_axis")
    if not xa or not ya:
        return None, True

    def edges(axis, n):
        if axis.get("categories"):
            return -0.5, n - 0.5
        first, last = float(axis["first"]), float(axis["last"])
        step = (last - first) / (n - 1) if n > 1 else 1.0
        return first - step / 2, last + step / 2

    x0, x1 = edges(xa, w)
    y0, y1 = edges(ya, h)
    return (x0, x1, y1, y0), False  # rows run from the top: the first row at the top


def draw_map(spec):
    """A false-colour map with its colour bar (spec["quantity"], spec["unit"])."""
    values = spec["values"]
    h, w = values.shape
    signed = bool(spec.get("signed", False))
    norm, cmap_name, how = map_scale(values, signed, bool(spec.get("from_zero", False)),
                                     float(spec.get("percentile", 99.0)),
                                     spec.get("scale", "auto"), spec.get("upper"),
                                     spec.get("cycle"))
    extent, pixels = _map_extent(spec, w, h)
    # Pixels, and axes of one quantity (direction cosines), keep their shape; others fill.
    equal = pixels or bool(spec.get("equal_aspect", False))
    aspect_ratio = h / w if equal else 0.75
    fig = Figure(figsize=(_WIDTH_IN, min(7.5, max(3.4, _WIDTH_IN * 0.78 * aspect_ratio + 1.4))))
    FigureCanvasAgg(fig)
    ax = fig.add_subplot()
    cmap = matplotlib.colormaps[cmap_name].copy()
    cmap.set_bad("0.6")
    im = ax.imshow(np.ma.masked_invalid(values), cmap=cmap, norm=norm, interpolation="nearest",
                   extent=extent, aspect="equal" if equal else "auto")
    clipped = clipped_fraction(values, norm)
    v = values[np.isfinite(values)]
    below = v.size and np.any(v < norm.vmin)
    above = v.size and np.any(v > norm.vmax)
    extend = {(True, True): "both", (True, False): "min", (False, True): "max"}.get(
        (bool(below), bool(above)), "neither")
    unit = spec.get("unit", "")
    label = spec["quantity"] + (f" ({unit})" if unit else "")
    bar = fig.colorbar(im, ax=ax, extend=extend, fraction=0.05, pad=0.03)
    bar.set_label(label)
    if pixels:
        ax.set_xlabel("x (pixels)")
        ax.set_ylabel("y (pixels)")
    else:
        for axis, setter, ticks, n in ((spec["x_axis"], ax.set_xlabel, ax.set_xticks, w),
                                       (spec["y_axis"], ax.set_ylabel, ax.set_yticks, h)):
            setter(axis["label"])
            if axis.get("categories"):
                is_x = axis is spec["x_axis"]
                # x labels: slanted when many, ending under their tick; y labels end at theirs.
                ticks(range(n), axis["categories"], rotation=30 if is_x and n > 4 else 0,
                      ha=("right" if n > 4 else "center") if is_x else "right",
                      fontsize="small")
    nan = int(np.sum(~np.isfinite(values)))
    caption = how + f"; {100 * clipped:.1f}% of the values lie beyond the limits."
    if nan:
        caption += f" Grey: {nan} cells without a value."
    if spec.get("clip_reason"):
        caption += " " + spec["clip_reason"]
    if spec.get("caption"):
        caption = spec["caption"] + " " + caption
    _finish(fig, spec, caption)
    fig.lamina_clip_reason = spec.get("clip_reason", "")
    return fig


def draw(spec):
    """The figure of a spec (a dict from load())."""
    return {"map": draw_map, "lines": draw_lines, "swatches": draw_swatches}[spec["kind"]](spec)


def write(fig, stem):
    """NAME.png (150 dpi) and NAME.pdf (vector) for the path stem NAME."""
    for ext, kwargs in ((".png", {"dpi": 150}), (".pdf", {})):
        tmp = stem + ".tmp" + ext
        fig.savefig(tmp, **kwargs, metadata={"Software": None} if ext == ".png" else
                    {"Creator": "lamina", "Producer": None, "CreationDate": None})
        os.replace(tmp, stem + ext)


# --------------------------------------------------------------------------- checks


def _tick_labels(fig):
    """(every tick label, the ones drawn): a tick outside the view keeps its Text, undrawn."""
    every, drawn = set(), []
    for ax in fig.axes:
        for axis in (ax.xaxis, ax.yaxis):
            lo, hi = sorted(axis.get_view_interval())
            eps = 1e-9 * max(abs(hi - lo), abs(hi), 1e-300)
            for tick in axis.get_major_ticks() + axis.get_minor_ticks():
                loc = tick.get_loc()
                for label in (tick.label1, tick.label2):
                    every.add(id(label))
                    if loc is not None and lo - eps <= loc <= hi + eps:
                        drawn.append(label)
    return every, drawn


def _texts(fig):
    """The texts a reader sees."""
    every, drawn = _tick_labels(fig)
    seen = set()
    for t in [t for t in fig.findobj(Text) if id(t) not in every] + drawn:
        if id(t) in seen or not t.get_visible() or not t.get_text().strip():
            continue
        seen.add(id(t))
        yield t


def _overlap(a, b, slack=1.0):
    return (min(a.x1, b.x1) - max(a.x0, b.x0) > slack
            and min(a.y1, b.y1) - max(a.y0, b.y0) > slack)


def _inside(inner, outer, slack=1.0):
    return (inner.x0 >= outer.x0 - slack and inner.y0 >= outer.y0 - slack
            and inner.x1 <= outer.x1 + slack and inner.y1 <= outer.y1 + slack)


def problems(fig):
    """What a reader of the drawn figure could be misled by, as sentences (empty: none)."""
    found = []
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    name = getattr(fig, "lamina_name", "") or "figure"
    caption = getattr(fig, "lamina_caption", "")

    for im in fig.findobj(AxesImage):
        if im.get_array().ndim == 3:
            continue  # true colours (swatches): no colour scale to mislead
        data = np.ma.filled(im.get_array().astype(np.float64), np.nan)
        v = data[np.isfinite(data)]
        if v.size == 0:
            continue
        norm = im.norm
        clipped = clipped_fraction(v, norm)
        if clipped > MAX_CLIPPED and not getattr(fig, "lamina_clip_reason", ""):
            found.append(f"{name}: {100 * clipped:.1f}% of the map's values lie beyond its "
                         f"colour limits [{norm.vmin:.3g}, {norm.vmax:.3g}] and the caption "
                         f"gives no reason")
        considered = v[v > 0] if isinstance(norm, colors.LogNorm) else v
        if considered.size:
            p1, p99 = np.percentile(considered, [1, 99])
            tol = 1e-6 * max(abs(norm.vmax - norm.vmin), 1e-300)
            if norm.vmin > p1 + tol or norm.vmax < p99 - tol:
                found.append(f"{name}: colour limits [{norm.vmin:.3g}, {norm.vmax:.3g}] do not "
                             f"contain the data's 1st-99th percentiles [{p1:.3g}, {p99:.3g}]")
        if im.colorbar is None or not im.colorbar.ax.get_ylabel().strip():
            found.append(f"{name}: a map without a labelled colour bar")

    for ax in fig.axes:
        if any(ax is im.colorbar.ax for im in fig.findobj(AxesImage) if im.colorbar):
            continue
        shared_x = getattr(ax, "lamina_shares_x_label", False)
        shared_y = getattr(ax, "lamina_shares_y_label", False)
        if not (shared_x or ax.get_xlabel().strip()) or not (shared_y or ax.get_ylabel().strip()):
            found.append(f"{name}: axes without a label on x or y")

    # A tick label over its own axes' plot area hides data and reads as part of it.
    _, drawn = _tick_labels(fig)
    drawn = {id(t) for t in drawn}
    for ax in fig.axes:
        for label in ax.get_xticklabels() + ax.get_yticklabels():
            if id(label) not in drawn or not label.get_visible() or not label.get_text().strip():
                continue
            if _overlap(label.get_window_extent(renderer), ax.bbox, slack=2.0):
                found.append(f"{name}: the tick label \"{label.get_text()[:40]}\" lies over "
                             f"its axes' plot")

    texts = list(_texts(fig))
    boxes = [t.get_window_extent(renderer) for t in texts]
    page = fig.bbox
    for t, b in zip(texts, boxes):
        if not _inside(b, page):
            found.append(f"{name}: text \"{t.get_text()[:40]}\" runs outside the figure")
    for i in range(len(texts)):
        for j in range(i + 1, len(texts)):
            if _overlap(boxes[i], boxes[j]):
                found.append(f"{name}: text \"{texts[i].get_text()[:40]}\" overlaps "
                             f"\"{texts[j].get_text()[:40]}\"")

    for legend in fig.findobj(Legend):
        box = legend.get_window_extent(renderer)
        holder = legend.axes.bbox if legend.axes is not None else page
        if not _inside(box, holder):
            found.append(f"{name}: the legend is not inside its axes")
        mine = {id(t) for t in legend.get_texts()} | {id(legend.get_title())}
        for t, b in zip(texts, boxes):
            if id(t) not in mine and _overlap(box, b):
                found.append(f"{name}: the legend covers \"{t.get_text()[:40]}\"")
    if caption and "percentile" not in caption and fig.findobj(AxesImage):
        found.append(f"{name}: a map whose caption does not state its limits' percentile")
    return found


# --------------------------------------------------------------------------- the script


def specs_in(paths):
    """Every spec file named, or found directly inside a directory named, sorted."""
    found = []
    for p in paths:
        if os.path.isdir(p):
            found += sorted(os.path.join(p, f) for f in os.listdir(p) if f.endswith(SPEC_SUFFIX))
        else:
            found.append(p)
    return found


def draw_all(paths, check=True):
    """Draws every spec of `paths`; returns the problems found (with check)."""
    found = []
    for path in specs_in(paths):
        spec = load(path)
        spec.setdefault("name", os.path.basename(path)[: -len(SPEC_SUFFIX)])
        fig = draw(spec)
        write(fig, path[: -len(SPEC_SUFFIX)])
        if check:
            found += problems(fig)
    return found


def main(argv):
    if len(argv) < 2 or argv[1] in ("-h", "--help"):
        print("usage: figures.py DIR_OR_SPEC...   (draws NAME.figure.json into NAME.png, "
              "NAME.pdf)", file=sys.stderr)
        return 2
    try:
        found = draw_all(argv[1:])
    except SpecError as e:
        print(f"lamina: error: {e}", file=sys.stderr)
        return 1
    for p in found:
        print(f"lamina: note: {p}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
