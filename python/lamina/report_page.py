"""A report as a web page: index.html beside an experiment's summary.md, self-contained.

An experiment (experiments/, ``Report``) writes summary.md, its figures (NAME.png) and, for every
pair of images it compared, NAME.pair.json with the two images' pixels beside it
(NAME.a.f32, NAME.b.f32: little-endian float32 RGB, linear Rec.709, row-major from the top
row). At the end of the run it runs this file as a script on its directory: ``python3
report_page.py DIR`` writes DIR/index.html with the summary's text and tables, its figures
inlined, and an image viewer per pair (report_viewer.js: A/B, exposure, zoom to pixels, the
difference and the relative error, the values under the cursor). ``python3 report_page.py
--pair SPEC --out PAGE`` writes the viewer of one pair alone (``lamina compare --html``).

The page loads nothing from the network or from beside it: images are data URIs and the pixel
data base64 in the page, so it can be mailed or archived as one file. Only the standard library
is used (no matplotlib needed). The summary's Markdown is the subset lamina writes: headings,
paragraphs, pipe tables, lists, images, fenced code, `code`, **bold** and *emphasis*.
"""

import base64
import html
import json
import os
import re
import sys

PAIR_SUFFIX = ".pair.json"
PAIR_VERSION = 1
_HERE = os.path.dirname(os.path.abspath(__file__))


class PageError(ValueError):
    """A pair spec or its data that cannot be shown: names the file and what was expected."""


def _read(name):
    with open(os.path.join(_HERE, name), encoding="utf-8") as f:
        return f.read()


# ------------------------------------------------------------------------- Markdown subset

def _inline(text, directory):
    """One line of Markdown text as HTML: images (inlined), code, bold, emphasis, links."""
    out, pos = [], 0
    pattern = re.compile(r"!\[([^\]]*)\]\(([^)]+)\)|`([^`]+)`|\[([^\]]+)\]\(([^)]+)\)")
    for m in pattern.finditer(text):
        out.append(_emphasis(html.escape(text[pos:m.start()])))
        if m.group(2) is not None:
            out.append(_image(m.group(1), m.group(2), directory))
        elif m.group(3) is not None:
            out.append("<code>" + html.escape(m.group(3)) + "</code>")
        else:
            target = m.group(5)
            # A link to a file of the report works beside the page; anything else is text.
            out.append('<a href="%s">%s</a>' % (html.escape(target, quote=True),
                                               _emphasis(html.escape(m.group(4)))))
        pos = m.end()
    out.append(_emphasis(html.escape(text[pos:])))
    return "".join(out)


def _emphasis(escaped):
    escaped = re.sub(r"\*\*([^*]+)\*\*", r"<strong>\1</strong>", escaped)
    return re.sub(r"(?<![\w*])\*([^*\s][^*]*)\*(?![\w*])", r"<em>\1</em>", escaped)


_IMAGE_TYPES = {".png": "image/png", ".svg": "image/svg+xml", ".jpg": "image/jpeg",
                ".jpeg": "image/jpeg"}


def _image(alt, target, directory):
    path = os.path.join(directory, target)
    kind = _IMAGE_TYPES.get(os.path.splitext(target)[1].lower())
    if kind is None or not os.path.isfile(path):
        # Not drawn (no matplotlib) or not an image: say so where the figure would be.
        return '<span class="missing">[%s: %s not available]</span>' % (
            html.escape(alt), html.escape(target))
    with open(path, "rb") as f:
        data = base64.b64encode(f.read()).decode("ascii")
    return '<img alt="%s" src="data:%s;base64,%s">' % (html.escape(alt, quote=True), kind, data)


def _table(rows, directory):
    cells = [[c.strip() for c in r.strip().strip("|").split("|")] for r in rows]
    head, body = cells[0], cells[2:]  # cells[1] is the --- separator
    out = ["<table><thead><tr>"]
    out += ["<th>%s</th>" % _inline(c, directory) for c in head]
    out.append("</tr></thead><tbody>")
    for r in body:
        out.append("<tr>" + "".join("<td>%s</td>" % _inline(c, directory) for c in r) + "</tr>")
    out.append("</tbody></table>")
    return "".join(out)


def markdown_to_html(text, directory):
    """The Markdown lamina's summaries use, as HTML (figures inlined from `directory`)."""
    lines, out, i = text.splitlines(), [], 0
    while i < len(lines):
        line = lines[i]
        if not line.strip():
            i += 1
        elif line.startswith("```"):
            j = i + 1
            while j < len(lines) and not lines[j].startswith("```"):
                j += 1
            out.append("<pre><code>%s</code></pre>" % html.escape("\n".join(lines[i + 1:j])))
            i = j + 1
        elif re.match(r"#{1,6} ", line):
            level = len(line) - len(line.lstrip("#"))
            out.append("<h%d>%s</h%d>" % (level, _inline(line[level + 1:], directory), level))
            i += 1
        elif line.lstrip().startswith("|") and i + 1 < len(lines) and \
                re.match(r"\s*\|[\s:|-]+\|\s*$", lines[i + 1]):
            j = i
            while j < len(lines) and lines[j].lstrip().startswith("|"):
                j += 1
            out.append(_table(lines[i:j], directory))
            i = j
        elif re.match(r"\s*([-*]|\d+\.) ", line):
            ordered = bool(re.match(r"\s*\d+\. ", line))
            items = []
            while i < len(lines) and lines[i].strip():
                m = re.match(r"\s*(?:[-*]|\d+\.) (.*)", lines[i])
                if m:
                    items.append(m.group(1))
                elif items:
                    items[-1] += " " + lines[i].strip()  # a continued item
                i += 1
            tag = "ol" if ordered else "ul"
            out.append("<%s>%s</%s>" % (tag, "".join(
                "<li>%s</li>" % _inline(item, directory) for item in items), tag))
        else:
            j = i
            while j < len(lines) and lines[j].strip() and not re.match(
                    r"#{1,6} |```|\s*\||\s*([-*]|\d+\.) ", lines[j]):
                j += 1
            j = max(j, i + 1)
            out.append("<p>%s</p>" % _inline(" ".join(l.strip() for l in lines[i:j]), directory))
            i = j
    return "\n".join(out)


# ------------------------------------------------------------------------- image pairs

def load_pair(path):
    """A pair spec with its two images' data as base64; PageError if it cannot be shown."""
    try:
        with open(path, encoding="utf-8") as f:
            spec = json.load(f)
    except (OSError, ValueError) as e:
        raise PageError("%s: %s" % (path, e)) from e
    if not isinstance(spec, dict) or spec.get("lamina_pair") != PAIR_VERSION:
        raise PageError("%s: lamina_pair: expected %d" % (path, PAIR_VERSION))
    width, height = spec.get("width"), spec.get("height")
    if not (isinstance(width, int) and isinstance(height, int) and width > 0 and height > 0):
        raise PageError("%s: width, height: expected positive integers" % path)
    directory = os.path.dirname(path)
    out = {"width": width, "height": height, "title": str(spec.get("title", "")),
           "caption": str(spec.get("caption", "")),
           "label_a": str(spec.get("label_a", "A")), "label_b": str(spec.get("label_b", "B"))}
    for side in ("a", "b"):
        name = spec.get(side)
        if not isinstance(name, str):
            raise PageError("%s: %s: expected the name of a .f32 file" % (path, side))
        try:
            with open(os.path.join(directory, name), "rb") as f:
                data = f.read()
        except OSError as e:
            raise PageError("%s: %s: %s" % (path, side, e)) from e
        if len(data) != width * height * 3 * 4:
            raise PageError("%s: %s: expected %d float32 RGB values (%dx%d), the file holds %d bytes"
                            % (path, side, width * height * 3, width, height, len(data)))
        out[side] = base64.b64encode(data).decode("ascii")
    return out


_ZOOMS = ["fit", "1", "2", "4", "8", "16", "32"]


def pair_section(pair):
    """The HTML of one viewer (report_viewer.js brings it to life)."""
    data = json.dumps({k: pair[k] for k in ("width", "height", "label_a", "label_b", "a", "b")})
    buttons = "".join('<button type="button" data-mode="%s">%s</button>' % (m, html.escape(t))
                      for m, t in (("a", "A: " + pair["label_a"]), ("b", "B: " + pair["label_b"]),
                                   ("difference", "A - B"), ("error", "relative error")))
    zooms = "".join('<option value="%s"%s>%s</option>' % (
        z, " selected" if z == "fit" else "", "fit" if z == "fit" else z + "x") for z in _ZOOMS)
    return (
        '<section class="pair">'
        + ("<h3>%s</h3>" % html.escape(pair["title"]) if pair["title"] else "")
        + '<div class="controls">%s' % buttons
        + '<label>exposure <input class="exposure" type="range" min="-10" max="10" step="0.5"'
          ' value="0"> <span class="exposure-value">+0.0 EV</span></label>'
        + '<label>zoom <select class="zoom">%s</select></label></div>' % zooms
        + '<div class="frame"><canvas></canvas></div>'
        + '<div class="legend"></div><div class="readout">&nbsp;</div>'
        + ("<p class=\"caption\">%s</p>" % html.escape(pair["caption"]) if pair["caption"] else "")
        + '<script type="application/json" class="pair-data">%s</script>' % data.replace("</", "<\\/")
        + "</section>")


# ------------------------------------------------------------------------- pages

def page(title, body):
    """A whole self-contained page around `body`."""
    return ("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
            "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">"
            "<title>%s</title><style>%s</style></head><body>\n%s\n<script>%s</script>"
            "</body></html>\n") % (html.escape(title), _read("report_page.css"), body,
                                  _read("report_viewer.js"))


def _write_atomically(path, text):
    # Nothing half-written: the page appears whole or not at all.
    temporary = path + ".partial"
    with open(temporary, "w", encoding="utf-8") as f:
        f.write(text)
    os.replace(temporary, path)


def write_report_page(directory):
    """DIRECTORY/index.html from its summary.md, figures and pair specs; returns its path."""
    summary_path = os.path.join(directory, "summary.md")
    with open(summary_path, encoding="utf-8") as f:
        summary = f.read()
    m = re.search(r"^# (.+)$", summary, re.M)
    title = m.group(1).strip() if m else os.path.basename(os.path.abspath(directory))
    parts = [markdown_to_html(summary, directory)]
    pairs = sorted(n for n in os.listdir(directory) if n.endswith(PAIR_SUFFIX))
    if pairs:
        parts.append("<h2>Images compared</h2>")
        parts += [pair_section(load_pair(os.path.join(directory, n))) for n in pairs]
    path = os.path.join(directory, "index.html")
    _write_atomically(path, page(title, "\n".join(parts)))
    return path


def write_pair_page(spec, out):
    """The viewer of one pair alone, at `out`."""
    pair = load_pair(spec)
    title = pair["title"] or "%s against %s" % (pair["label_a"], pair["label_b"])
    body = "<h1>%s</h1>\n%s" % (html.escape(title), pair_section(dict(pair, title="")))
    _write_atomically(out, page(title, body))
    return out


def main(argv):
    usage = ("usage: report_page.py DIR  (DIR/index.html from DIR/summary.md)\n"
             "       report_page.py --pair SPEC.pair.json --out PAGE.html")
    try:
        if len(argv) == 2 and argv[1] not in ("-h", "--help"):
            write_report_page(argv[1])
        elif len(argv) == 5 and argv[1] == "--pair" and argv[3] == "--out":
            write_pair_page(argv[2], argv[4])
        else:
            print(usage, file=sys.stderr)
            return 0 if len(argv) == 2 else 2
    except (OSError, PageError) as e:
        print("lamina: error: %s" % e, file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
