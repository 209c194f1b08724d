// lamina's image-pair viewer, inlined into every report page (report_page.py) and into
// `lamina compare --html`. One viewer per <section class="pair">: its two linear Rec.709
// images travel in the page as base64 little-endian float32 RGB (row-major from the top row),
// so the page needs no network and no file beside it.
//
// What a reader can do: show A, B, their signed difference A - B (a diverging map, symmetric
// limits) or the relative error |A - B| / (|B| + 0.01) (a sequential map from 0); set the
// exposure in stops (it scales the images and the maps' limits alike); zoom to single pixels
// (1x-32x, or fit the page); read the values of A, B and A - B under the cursor.
//
// For scripts (the browser test): window.laminaViewers holds one object per pair with
// show(mode), value(x, y) (the linear value of the shown quantity), setExposure(stops),
// setZoom(factor) and the fields mode, decoded, width, height.
"use strict";

(function () {
    const MODES = ["a", "b", "difference", "error"];
    const ERROR_FLOOR = 0.01;  // keeps the relative error finite where B is black

    // Anchors of matplotlib's viridis (van der Walt and Smith 2015), evenly spaced over
    // [0, 1]; the map between them is linear in sRGB.
    const VIRIDIS = [[68, 1, 84], [72, 40, 120], [62, 74, 137], [49, 104, 142], [38, 130, 142],
                     [31, 158, 137], [53, 183, 121], [110, 206, 88], [181, 222, 43],
                     [253, 231, 37]];
    // A blue-white-red diverging map (ColorBrewer RdBu ends, Brewer 2003), -1..1.
    const BLUE = [33, 102, 172], WHITE = [247, 247, 247], RED = [178, 24, 43];

    function lerp(a, b, t) { return a + (b - a) * t; }
    function ramp(anchors, t) {
        t = Math.min(1, Math.max(0, t)) * (anchors.length - 1);
        const i = Math.min(anchors.length - 2, Math.floor(t)), f = t - i;
        return [0, 1, 2].map(c => lerp(anchors[i][c], anchors[i + 1][c], f));
    }
    function diverging(t) {  // t in [-1, 1]
        t = Math.min(1, Math.max(-1, t));
        return t < 0 ? ramp([WHITE, BLUE], -t) : ramp([WHITE, RED], t);
    }
    // The sRGB transfer function (IEC 61966-2-1) of a linear value clipped to [0, 1].
    function srgb8(v) {
        v = Math.min(1, Math.max(0, v));
        const e = v <= 0.0031308 ? 12.92 * v : 1.055 * Math.pow(v, 1 / 2.4) - 0.055;
        return Math.round(255 * e);
    }
    function decode(base64, count) {
        const bytes = Uint8Array.from(atob(base64), ch => ch.charCodeAt(0));
        const values = new Float32Array(bytes.buffer);
        if (values.length !== count) throw new Error("expected " + count + " values, got " + values.length);
        return values;
    }
    // The q-quantile of |values| over the finite ones (0 if none).
    function quantileAbs(values, q) {
        const finite = [];
        for (const v of values) if (Number.isFinite(v)) finite.push(Math.abs(v));
        if (finite.length === 0) return 0;
        finite.sort((x, y) => x - y);
        return finite[Math.min(finite.length - 1, Math.floor(q * finite.length))];
    }
    function fmt(v) { return Number.isFinite(v) ? v.toPrecision(4) : "not finite"; }

    class PairViewer {
        constructor(section) {
            this.section = section;
            const data = JSON.parse(section.querySelector("script.pair-data").textContent);
            this.width = data.width;
            this.height = data.height;
            this.labels = {a: data.label_a, b: data.label_b};
            const n = data.width * data.height * 3;
            this.a = decode(data.a, n);
            this.b = decode(data.b, n);
            this.difference = new Float32Array(n / 3);
            this.error = new Float32Array(n / 3);
            for (let p = 0; p < n / 3; ++p) {
                let d = 0, e = 0;
                for (let c = 0; c < 3; ++c) {
                    const a = this.a[3 * p + c], b = this.b[3 * p + c];
                    d += a - b;
                    e += Math.abs(a - b) / (Math.abs(b) + ERROR_FLOOR);
                }
                this.difference[p] = d / 3;
                this.error[p] = e / 3;
            }
            // The maps' limits at exposure 0: the 99th percentile (the legend says so).
            this.differenceLimit = quantileAbs(this.difference, 0.99) || 1;
            this.errorLimit = quantileAbs(this.error, 0.99) || 1;
            this.canvas = section.querySelector("canvas");
            this.canvas.width = this.width;
            this.canvas.height = this.height;
            this.context = this.canvas.getContext("2d");
            this.pixels = this.context.createImageData(this.width, this.height);
            this.readout = section.querySelector(".readout");
            this.legend = section.querySelector(".legend");
            this.exposureLabel = section.querySelector(".exposure-value");
            this.buttons = {};
            for (const button of section.querySelectorAll("button[data-mode]")) {
                this.buttons[button.dataset.mode] = button;
                button.addEventListener("click", () => this.show(button.dataset.mode));
            }
            const exposure = section.querySelector("input.exposure");
            exposure.addEventListener("input", () => this.setExposure(Number(exposure.value)));
            this.exposureInput = exposure;
            const zoom = section.querySelector("select.zoom");
            zoom.addEventListener("change", () => this.setZoom(zoom.value));
            this.canvas.addEventListener("mousemove", event => this.describe(event));
            this.canvas.addEventListener("mouseleave", () => { this.readout.textContent = "\u00a0"; });
            this.exposure = 0;
            this.mode = "a";
            this.setZoom(zoom.value);
            this.show("a");
            this.decoded = true;
        }

        show(mode) {
            if (!MODES.includes(mode)) throw new Error("no view named " + mode);
            this.mode = mode;
            for (const [name, button] of Object.entries(this.buttons))
                button.classList.toggle("active", name === mode);
            this.draw();
        }

        setExposure(stops) {
            this.exposure = stops;
            this.exposureInput.value = stops;
            this.exposureLabel.textContent = (stops >= 0 ? "+" : "") + stops.toFixed(1) + " EV";
            this.draw();
        }

        setZoom(factor) {
            // "fit": the page's width, but at least 640 pixels wide where the image is smaller.
            const shown = factor === "fit"
                ? Math.min(this.section.clientWidth || this.width, Math.max(this.width, 640))
                : this.width * Number(factor);
            this.canvas.style.width = shown + "px";
        }

        // The linear value of the shown quantity at pixel (x, y): [r, g, b] for an image, one
        // number for a map.
        value(x, y) {
            const p = y * this.width + x;
            if (this.mode === "a" || this.mode === "b") {
                const image = this[this.mode];
                return [image[3 * p], image[3 * p + 1], image[3 * p + 2]];
            }
            return this[this.mode][p];
        }

        draw() {
            const scale = Math.pow(2, this.exposure), out = this.pixels.data;
            const pixels = this.width * this.height;
            for (let p = 0; p < pixels; ++p) {
                let rgb;
                if (this.mode === "a" || this.mode === "b") {
                    const image = this[this.mode];
                    rgb = [0, 1, 2].map(c => srgb8(image[3 * p + c] * scale));
                } else if (this.mode === "difference") {
                    rgb = diverging(this.difference[p] * scale / this.differenceLimit);
                } else {
                    rgb = ramp(VIRIDIS, this.error[p] * scale / this.errorLimit);
                }
                out[4 * p] = rgb[0];
                out[4 * p + 1] = rgb[1];
                out[4 * p + 2] = rgb[2];
                out[4 * p + 3] = 255;
            }
            this.context.putImageData(this.pixels, 0, 0);
            this.legend.textContent = this.legendText(scale);
        }

        legendText(scale) {
            if (this.mode === "a" || this.mode === "b")
                return this.labels[this.mode] + ": linear Rec.709, sRGB-encoded for display, " +
                       "values above 1 after the exposure clipped";
            if (this.mode === "difference")
                return "A - B, mean of the channels: blue -" + fmt(this.differenceLimit / scale) +
                       ", white 0, red +" + fmt(this.differenceLimit / scale) +
                       " (99th percentile of |A - B| at 0 EV)";
            return "|A - B| / (|B| + " + ERROR_FLOOR + "), mean of the channels: 0 (dark) to " +
                   fmt(this.errorLimit / scale) + " (yellow; 99th percentile at 0 EV)";
        }

        describe(event) {
            const box = this.canvas.getBoundingClientRect();
            const x = Math.floor((event.clientX - box.left) / box.width * this.width);
            const y = Math.floor((event.clientY - box.top) / box.height * this.height);
            if (x < 0 || y < 0 || x >= this.width || y >= this.height) return;
            const p = y * this.width + x;
            const triple = image => "(" + [0, 1, 2].map(c => fmt(image[3 * p + c])).join(", ") + ")";
            this.readout.textContent = "pixel (" + x + ", " + y + ")   A " + triple(this.a) +
                "   B " + triple(this.b) + "   A - B " + fmt(this.difference[p]) +
                "   relative error " + fmt(this.error[p]);
        }
    }

    function start() {
        window.laminaViewers = [];
        for (const section of document.querySelectorAll("section.pair")) {
            try {
                window.laminaViewers.push(new PairViewer(section));
            } catch (error) {
                section.querySelector(".readout").textContent = "this pair cannot be shown: " + error.message;
                console.error("lamina viewer: " + error.message);
            }
        }
    }
    if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
    else start();
})();
