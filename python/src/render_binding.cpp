// lamina.render: a scene (a dict or a file) rendered with the command line's overrides, the
// GIL released. After every pass the calling thread takes the GIL back to look for a pending
// Ctrl-C (PyErr_CheckSignals) and to call the progress callback; either one stopping the
// render raises the renderer's interruption flag, so the render ends after the pass in flight
// exactly as `lamina render` does on SIGINT, and the partial image is returned with the
// exception (the Python layer raises it, lamina/__init__.py).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <filesystem>
#include <map>
#include <vector>

#include "arrays.h"
#include "bindings.h"
#include "declared_keywords.h"
#include "lamina/core/error.h"
#include "lamina/core/json_reader.h"
#include "lamina/experiments/command_options.h"
#include "lamina/output/image_output.h"
#include "lamina/output/render_metadata.h"
#include "lamina/render/renderer.h"
#include "lamina/version.h"

namespace lamina::python {

namespace {

using render::RenderOptions;

/// A finished (or interrupted) render: the film, what the EXR's metadata says, and the
/// images as NumPy arrays (float32, as the EXR stores them).
class RenderedImage {
  public:
    RenderedImage(render::RenderResult result, render::ImageMetadata metadata, bool aovs)
        : result_(std::make_shared<render::RenderResult>(std::move(result))),
          metadata_(std::move(metadata)),
          aovs_(aovs) {}

    py::array_t<float> rgb() const {
        const render::Film& film = *result_->film;
        const py::ssize_t w = film.width(), h = film.height();
        py::array_t<float> out({h, w, py::ssize_t(3)});
        float* p = out.mutable_data();
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const Rgb<double> v = film.pixel(x, y);
                for (int c = 0; c < 3; ++c)
                    *p++ = float(v[c]);
            }
        return out;
    }

    /// Albedo (H, W, 3), N (H, W, 3), Z (H, W) and Variance.Y (H, W) with aovs=True;
    /// Variance.Y (the variance of each pixel's mean luminance) always.
    py::dict aovs() const {
        const render::Film& film = *result_->film;
        const py::ssize_t w = film.width(), h = film.height();
        py::dict d;
        py::array_t<float> variance({h, w});
        float* v = variance.mutable_data();
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                *v++ = float(film.varianceOfMean(x, y));
        d["variance"] = variance;
        if (!aovs_) return d;
        py::array_t<float> albedo({h, w, py::ssize_t(3)}), normal({h, w, py::ssize_t(3)}),
            depth({h, w});
        float *a = albedo.mutable_data(), *n = normal.mutable_data(), *z = depth.mutable_data();
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const render::PixelAovs p = film.aovs(x, y);
                for (int c = 0; c < 3; ++c) {
                    *a++ = float(p.albedo[c]);
                    *n++ = float(p.normal[c]);
                }
                *z++ = float(p.depth);
            }
        d["albedo"] = albedo;
        d["normal"] = normal;
        d["depth"] = depth;
        return d;
    }

    /// The Stokes layers of a polarised render, (4, H, W, 3): S0..S3 in linear Rec.709, in the
    /// image frame (docs/polarisation.md, "Stokes images"); None for the other modes.
    py::object stokes() const {
        const render::Film& film = *result_->film;
        if (!film.hasStokes()) return py::none();
        const py::ssize_t w = film.width(), h = film.height();
        py::array_t<float> out({py::ssize_t(4), h, w, py::ssize_t(3)});
        float* p = out.mutable_data();
        const std::size_t layer = std::size_t(w) * std::size_t(h) * 3;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const std::array<Rgb<double>, 4> s = film.stokes(x, y);
                const std::size_t at = (std::size_t(y) * std::size_t(w) + std::size_t(x)) * 3;
                for (std::size_t i = 0; i < 4; ++i)
                    for (int c = 0; c < 3; ++c)
                        p[i * layer + at + std::size_t(c)] = float(s[i][c]);
            }
        return out;
    }

    /// The spectral film (spectral_film=N), (C, N, H, W): each pixel's mean spectral radiance
    /// (per nm) in N bins over 360-830 nm, C = 1 (S0) in spectral mode and 4 (S0..S3, in the
    /// image frame) in polarised mode: the EXR's S<c>.<nm>nm layers; None without one.
    py::object spectralFilm() const {
        const render::Film& film = *result_->film;
        const render::SpectralFilm* s = film.spectralFilm();
        if (!s) return py::none();
        const py::ssize_t w = film.width(), h = film.height(), n = s->bins().count,
                          components = s->components();
        py::array_t<float> out({components, n, h, w});
        float* p = out.mutable_data();
        std::vector<double> bins(s->valuesPerPixel());
        const std::size_t plane = std::size_t(w) * std::size_t(h);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                film.spectralMean(x, y, bins.data());
                const std::size_t at = std::size_t(y) * std::size_t(w) + std::size_t(x);
                for (std::size_t i = 0; i < bins.size(); ++i)
                    p[i * plane + at] = float(bins[i]);
            }
        return out;
    }

    /// The centres of the spectral film's bins in nm, (N,); None without one.
    py::object spectralFilmNm() const {
        const render::SpectralFilm* s = result_->film->spectralFilm();
        if (!s) return py::none();
        py::array_t<double> out(py::ssize_t(s->bins().count));
        for (int b = 0; b < s->bins().count; ++b)
            out.mutable_data()[b] = s->bins().centre(b);
        return out;
    }

    /// Every "lamina:<key>" of the EXR, by key.
    py::dict metadata() const {
        py::dict d;
        for (const auto& [k, v] : metadata_.strings)
            d[py::str(k)] = v;
        for (const auto& [k, v] : metadata_.floats)
            d[py::str(k)] = v;
        for (const auto& [k, v] : metadata_.ints)
            d[py::str(k)] = v;
        for (const auto& [k, v] : metadata_.matrices) {
            py::array_t<float> m({py::ssize_t(4), py::ssize_t(4)});
            std::copy(v.begin(), v.end(), m.mutable_data());
            d[py::str(k)] = m;
        }
        return d;
    }

    /// The EXR `lamina render` writes (with the AOV layers when rendered with aovs=True), or
    /// its PNG preview for a .png name.
    void save(const std::string& path, double exposure) const {
        const std::filesystem::path p = path;
        render::checkOutputPath(p);
        py::gil_scoped_release release;
        if (p.extension() == ".png")
            render::writePngPreview(p, *result_->film, exposure);
        else if (p.extension() == ".exr")
            render::writeExr(p, *result_->film, aovs_, metadata_);
        else
            throw InputError(path + ": expected a .exr or .png name");
    }

    int spp() const { return result_->spp; }
    double seconds() const { return result_->seconds; }
    bool partial() const { return result_->partial; }
    std::uint64_t rejected() const { return result_->film->rejectedSamples(); }

  private:
    std::shared_ptr<render::RenderResult> result_;
    render::ImageMetadata metadata_;
    bool aovs_;
};

/// The command line's overrides (`lamina render --spp --time --mode ...`) as keywords: those
/// the declaration of `render` gives Python (experiments/src/render_declaration.cpp), read as
/// the command line reads them; `progress`, a callable, is Python's own.
RenderOptions optionsOf(const py::kwargs& kwargs, py::object& progress) {
    std::map<std::string, py::object> callbacks;
    const experiments::OptionValues values =
        keywordValues(experiments::commandDeclaration("render"), kwargs, "render", &callbacks);
    if (const auto it = callbacks.find("progress"); it != callbacks.end()) progress = it->second;
    return experiments::renderOptionsFrom(values);
}

render::SceneDesc sceneOf(const py::object& scene) {
    if (py::isinstance<py::dict>(scene)) {
        // Relative file names in a dict resolve against the working directory.
        const JsonSource source{"<scene dict>", std::filesystem::current_path()};
        return render::parseScene(jsonText(scene, source.name), source);
    }
    const py::object path = py::module_::import("os").attr("fspath")(scene);
    return render::loadScene(path.cast<std::string>());
}

/// Returns (image, exception or None): the exception that stopped the render (a
/// KeyboardInterrupt, or what the progress callback raised).
py::tuple renderScene(const py::object& sceneArgument, const py::kwargs& kwargs) {
    py::object progress = py::none();
    const RenderOptions o = optionsOf(kwargs, progress);
    const render::SceneDesc scene = sceneOf(sceneArgument);
    std::atomic<bool>& interrupt = render::renderInterruptFlag();
    interrupt.store(false);
    py::object stoppedBy = py::none();
    const auto onPass = [&](const render::RenderProgress& p) {
        py::gil_scoped_acquire acquire;
        if (!stoppedBy.is_none()) return;
        try {
            if (PyErr_CheckSignals() != 0) throw py::error_already_set();
            if (!progress.is_none()) {
                py::dict d;
                d["fraction"] = p.fraction;
                d["seconds"] = p.seconds;
                d["passes"] = p.passesDone;
                d["spp"] = p.sppDone;
                progress(d);
            }
        } catch (py::error_already_set& e) {
            stoppedBy = e.value();
            interrupt.store(true);
        }
    };
    render::RenderResult r;
    {
        py::gil_scoped_release release;
        try {
            r = render::renderScene(scene, o, onPass);
        } catch (...) {
            interrupt.store(false);
            throw;
        }
        interrupt.store(false);
    }
    render::ImageMetadata meta =
        render::renderMetadata(scene, o, r, {LAMINA_VERSION_STRING, LAMINA_GIT_COMMIT});
    return py::make_tuple(RenderedImage(std::move(r), std::move(meta), o.aovs), stoppedBy);
}

}  // namespace

void bindRender(py::module_& m) {
    py::class_<RenderedImage>(m, "Image", "A render: rgb, aovs, metadata, save(path)")
        .def_property_readonly("rgb", &RenderedImage::rgb, "Linear Rec.709, (H, W, 3) float32")
        .def_property_readonly("aovs", &RenderedImage::aovs)
        .def_property_readonly("stokes", &RenderedImage::stokes,
                               "Polarised mode: S0..S3, (4, H, W, 3) float32 in the image frame; "
                               "else None")
        .def_property_readonly("spectral_film", &RenderedImage::spectralFilm,
                               "With spectral_film=N: (C, N, H, W) float32, each pixel's mean "
                               "spectral radiance per bin (C = 1: S0; polarised mode C = 4: "
                               "S0..S3); else None")
        .def_property_readonly("spectral_film_nm", &RenderedImage::spectralFilmNm,
                               "The bins' centres in nm, (N,); else None")
        .def_property_readonly("metadata", &RenderedImage::metadata)
        .def_property_readonly("spp", &RenderedImage::spp)
        .def_property_readonly("seconds", &RenderedImage::seconds)
        .def_property_readonly("partial", &RenderedImage::partial)
        .def_property_readonly("rejected_samples", &RenderedImage::rejected)
        .def("save", &RenderedImage::save, py::arg("path"), py::arg("exposure") = 0.0,
             "Writes the EXR lamina render writes (.exr) or its PNG preview (.png)");
    m.def("_render", &renderScene, py::arg("scene"));
    m.def(
        "read_image",
        [](const std::string& path) {
            const render::RgbImage img = render::readRgbImage(path);
            py::array_t<float> out(
                {py::ssize_t(img.height), py::ssize_t(img.width), py::ssize_t(3)});
            std::copy(img.pixels.begin(), img.pixels.end(), out.mutable_data());
            py::dict meta;
            for (const auto& [k, v] : img.metadata)
                meta[py::str(k)] = v;
            return py::make_tuple(out, meta);
        },
        py::arg("path"), "An image's R, G, B as (H, W, 3) float32, and its metadata");
}

}  // namespace lamina::python
