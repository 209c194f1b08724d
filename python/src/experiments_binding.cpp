// The experiments as functions that return their results (dicts of numbers and NumPy arrays)
// instead of writing reports: compare, convergence, reciprocity, fresnel, stability and
// layering call
// the typed runX functions of experiments/ that the commands call. Scenes are files, as the
// commands take them; render overrides are the keywords of lamina.render.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>

#include "arrays.h"
#include "bindings.h"
#include "lamina/core/error.h"
#include "lamina/experiments/convergence.h"
#include "lamina/experiments/fresnel.h"
#include "lamina/experiments/image_metrics.h"
#include "lamina/experiments/layering.h"
#include "lamina/experiments/reciprocity.h"
#include "lamina/experiments/stability.h"
#include "lamina/render/render_limits.h"
#include "lamina/version.h"

namespace lamina::python {

namespace {

namespace ex = lamina::experiments;
using render::RenderOptions;

/// NaN (a slope with too few passes, a level never reached) becomes None: no NaN leaves.
py::object number(double v) {
    if (!std::isfinite(v)) return py::none();
    return py::float_(v);
}

template <typename E, std::size_t N>
std::vector<E> namesOf(const NameTable<E, N>& table, const std::vector<std::string>& names,
                       const char* key) {
    std::vector<E> out;
    for (const auto& n : names) {
        const auto e = table.find(n);
        if (!e)
            throw py::value_error(std::string(key) + ": expected names among " + table.list() +
                                  ", got \"" + n + "\"");
        out.push_back(*e);
    }
    return out;
}

/// An (H, W, 3) array, or an Image (its .rgb), as the RgbImage the metrics take.
render::RgbImage imageOf(const py::object& value, const char* what) {
    const py::object rgb = py::hasattr(value, "rgb") ? value.attr("rgb") : value;
    const auto a = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(rgb);
    if (!a || a.ndim() != 3 || a.shape(2) != 3)
        throw py::value_error(std::string(what) + ": expected an (H, W, 3) array or an Image");
    render::RgbImage img;
    img.height = int(a.shape(0));
    img.width = int(a.shape(1));
    img.pixels.assign(a.data(), a.data() + a.size());
    return img;
}

py::dict metricsDict(const ex::ImageMetrics& m) {
    py::dict d;
    for (const auto& e : ex::kMetricNames.entries())
        d[py::str(std::string(e.name))] = ex::metricValue(m, e.value);
    return d;
}

/// The overrides every experiment applies to its renders (threads, max depth, resolution,
/// sampler).
RenderOptions overridesOf(int threads, int maxDepth,
                          const std::optional<std::pair<int, int>>& resolution) {
    RenderOptions o;
    if (threads < 0 || threads > render::kMaxThreadsOverride)
        throw py::value_error("threads: expected an integer in [1, 1024] (0: all cores)");
    o.threads = threads;
    if (maxDepth > 0) o.maxDepth = maxDepth;
    if (resolution) {
        const int max = render::kMaxResolutionOverride;
        if (resolution->first < 1 || resolution->second < 1 || resolution->first > max ||
            resolution->second > max)
            throw py::value_error("resolution: each side in [1, 65536]");
        o.resolution = resolution;
    }
    return o;
}

py::object compare(const py::object& a, const py::object& b,
                   const std::optional<std::string>& metric) {
    const render::RgbImage image = imageOf(a, "a"), reference = imageOf(b, "b");
    const ex::ImageMetrics m = ex::compareImages(image, reference);
    if (!metric) return metricsDict(m);
    const auto e = ex::kMetricNames.find(*metric);
    if (!e)
        throw py::value_error("metric: expected one of " + ex::kMetricNames.list() + ", got \"" +
                              *metric + "\"");
    return py::float_(ex::metricValue(m, *e));
}

py::dict convergence(const std::string& scene, const std::vector<std::string>& integrators,
                     const std::vector<std::string>& modes, double seconds,
                     const std::string& reference, double referenceSeconds, int threads,
                     int maxDepth, const std::optional<std::pair<int, int>>& resolution) {
    ex::ConvergenceInputs in;
    in.scene = scene;
    in.integrators = namesOf(render::kIntegratorNames, integrators, "integrators");
    in.modes = namesOf(render::kRenderModeNames, modes, "modes");
    if (!(seconds > 0) || !std::isfinite(seconds))
        throw py::value_error("seconds: expected a positive number");
    in.seconds = seconds;
    in.reference = reference;
    in.referenceSeconds = referenceSeconds;
    in.overrides = overridesOf(threads, maxDepth, resolution);
    in.build = {LAMINA_VERSION_STRING, LAMINA_GIT_COMMIT};
    ex::ConvergenceResult r;
    {
        py::gil_scoped_release release;
        r = ex::runConvergence(in);
    }
    py::list curves;
    for (const auto& c : r.curves) {
        const auto& rows = c.log.rows();
        const auto n = py::ssize_t(rows.size());
        py::array_t<double> t(n), mse(n), relmse(n), mae(n);
        py::array_t<int> spp(n);
        for (py::ssize_t i = 0; i < n; ++i) {
            const auto& row = rows[std::size_t(i)];
            t.mutable_data()[i] = row.seconds;
            spp.mutable_data()[i] = row.spp;
            mse.mutable_data()[i] = row.metrics.mse;
            relmse.mutable_data()[i] = row.metrics.relmse;
            mae.mutable_data()[i] = row.metrics.mae;
        }
        py::dict reach;
        for (const auto& level : in.levels)
            reach[py::str(level.label)] = number(ex::timeToReach(rows, level.relmse));
        py::dict d;
        d["integrator"] = std::string(render::kIntegratorNames.name(c.integrator));
        d["mode"] = std::string(render::kRenderModeNames.name(c.mode));
        d["seconds"] = t;
        d["spp"] = spp;
        d["mse"] = mse;
        d["relmse"] = relmse;
        d["mae"] = mae;
        d["slope"] = number(ex::fittedSlope(rows, ex::SlopeAxis::Seconds));
        d["slope_spp"] = number(ex::fittedSlope(rows, ex::SlopeAxis::Samples));
        d["paths_per_second"] = c.pathsPerSecond;
        d["time_to_relmse"] = reach;
        curves.append(d);
    }
    py::dict out;
    out["curves"] = curves;
    out["reference_note"] = r.referenceNote;
    return out;
}

py::dict reciprocity(const std::string& scene, const std::vector<std::string>& integrators,
                     const std::string& mode, int spp, int batches, std::uint64_t seed,
                     double alpha, int blockSize, const std::string& reference, int threads,
                     int maxDepth, const std::optional<std::pair<int, int>>& resolution) {
    ex::ReciprocityInputs in;
    in.scene = scene;
    in.integrators = namesOf(render::kIntegratorNames, integrators, "integrators");
    in.mode = namesOf(render::kRenderModeNames, {mode}, "mode")[0];
    // The command line's ranges (--spp, --batches).
    if (spp < 2 || spp > render::kMaxSppOverride)
        throw py::value_error("spp: expected an integer in [2, 16777216]");
    if (batches < 2 || batches > 4096)
        throw py::value_error("batches: expected an integer in [2, 4096]");
    if (!(alpha > 0 && alpha < 1)) throw py::value_error("alpha: expected a level in (0, 1)");
    if (blockSize < 1) throw py::value_error("block_size: expected at least 1");
    in.spp = spp;
    in.batches = batches;
    in.seed = seed;
    in.test.alpha = alpha;
    in.test.blockSize = blockSize;
    in.reference = reference;
    in.overrides = overridesOf(threads, maxDepth, resolution);
    ex::ReciprocityResult r;
    {
        py::gil_scoped_release release;
        r = ex::runReciprocity(in);
    }
    py::list pairs;
    for (const auto& p : r.pairs) {
        py::dict d;
        d["a"] = p.nameA;
        d["b"] = p.nameB;
        d["agree"] = p.agree;
        d["relative_difference"] = p.result.relativeDifference;
        d["standard_error"] = p.result.standardError;
        d["mean_a"] = p.result.meanA;
        d["mean_b"] = p.result.meanB;
        d["pixel_rejection_rate"] = p.result.pixelRejectionRate();
        d["block_rejection_rate"] = p.result.blockRejectionRate();
        d["block_rejection_p_value"] = p.result.blockRejectionPValue(alpha);
        d["pixel_test_trustworthy"] = p.pixelTest.trustworthy;
        pairs.append(d);
    }
    py::list materials;
    for (const auto& m : r.materials) {
        py::dict d;
        d["material"] = m.material;
        d["mode"] = std::string(render::kRenderModeNames.name(m.mode));
        d["max_reciprocity_error"] = m.check.maxReciprocityError;
        d["max_adjoint_error"] = m.check.maxAdjointError;
        d["pairs"] = m.check.pairs;
        materials.append(d);
    }
    py::dict out;
    out["pairs"] = pairs;
    out["materials"] = materials;
    out["agree"] = r.allAgree;
    return out;
}

py::list fresnel(const std::vector<std::string>& materials) {
    ex::FresnelInputs in;
    in.materials = materials;
    ex::FresnelResult r;
    {
        py::gil_scoped_release release;
        r = ex::runFresnel(in);
    }
    py::array_t<double> degrees(ex::kFresnelAngles);
    for (int i = 0; i < ex::kFresnelAngles; ++i)
        degrees.mutable_data()[i] = i;
    py::list out;
    for (const auto& m : r.materials) {
        py::list models;
        for (const auto& model : m.models) {
            py::array_t<double> rgb({py::ssize_t(model.rgb.size()), py::ssize_t(3)});
            for (std::size_t i = 0; i < model.rgb.size(); ++i)
                for (int c = 0; c < 3; ++c)
                    rgb.mutable_data()[i * 3 + std::size_t(c)] = model.rgb[i][c];
            py::dict d;
            d["name"] = model.name;
            d["rgb"] = rgb;
            d["max_error"] = model.maxError;
            d["mean_error"] = model.meanError;
            d["max_delta_e"] = model.maxDeltaE;
            d["mean_delta_e"] = model.meanDeltaE;
            models.append(d);
        }
        py::dict spectral;
        for (const auto& curve : m.spectral)
            spectral[py::float_(curve.nm)] = py::array_t<double>(
                py::ssize_t(curve.reflectance.size()), curve.reflectance.data());
        py::dict d;
        d["material"] = m.stem;
        d["name"] = m.name;
        d["degrees"] = degrees;
        d["models"] = models;
        d["spectral"] = spectral;
        out.append(d);
    }
    return out;
}

py::list stability(const std::vector<std::string>& materials, int samples) {
    ex::StabilityInputs in;
    in.materials = materials;
    if (samples < 1) throw py::value_error("samples: expected at least 1");
    in.samples = samples;
    ex::StabilityResult r;
    {
        py::gil_scoped_release release;
        r = ex::runStability(in);
    }
    py::list out;
    for (const auto& m : r.models) {
        const auto& a = m.audit;
        const auto na = py::ssize_t(a.alphas.size()), nc = py::ssize_t(a.cosines.size());
        py::array_t<int> issues({na, nc});
        py::array_t<double> floatError({na, nc});
        for (py::ssize_t i = 0; i < na; ++i)
            for (py::ssize_t j = 0; j < nc; ++j) {
                const auto& cell = a.at(std::size_t(i), std::size_t(j));
                issues.mutable_data()[i * nc + j] = cell.issues();
                floatError.mutable_data()[i * nc + j] = cell.worstFloatError;
            }
        const ex::StabilityCell t = a.total();
        py::dict d;
        d["material"] = m.json;
        d["alphas"] = a.alphas;
        d["cosines"] = a.cosines;
        d["issues"] = issues;
        d["worst_float_error"] = floatError;
        d["nan"] = t.nan;
        d["inf"] = t.inf;
        d["negative"] = t.negative;
        d["weight_mismatch"] = t.weightMismatch;
        d["energy_gain"] = t.energyGain;
        d["evaluations"] = t.evaluations;
        d["samples"] = t.samples;
        out.append(d);
    }
    return out;
}

/// Means and standard errors of a set of estimates as two arrays.
std::pair<py::array_t<double>, py::array_t<double>> meansOf(
    const std::vector<ex::MeanEstimate>& values) {
    py::array_t<double> mean(py::ssize_t(values.size())), se(py::ssize_t(values.size()));
    for (std::size_t i = 0; i < values.size(); ++i) {
        mean.mutable_data()[i] = values[i].mean;
        se.mutable_data()[i] = values[i].standardError;
    }
    return {mean, se};
}

py::list layering(const std::vector<std::string>& materials, int estimates, int albedoSamples,
                  std::uint64_t seed) {
    ex::LayeringInputs in;
    in.materials = materials;
    if (estimates < 2 || albedoSamples < 2)
        throw py::value_error("estimates, albedo_samples: expected at least 2");
    in.estimates = estimates;
    in.albedoSamples = albedoSamples;
    in.seed = seed;
    ex::LayeringResult r;
    {
        py::gil_scoped_release release;
        r = ex::runLayering(in);
    }
    const auto n = py::ssize_t(r.mapAngles.size());
    py::list out;
    for (const auto& m : r.materials) {
        py::dict d;
        d["material"] = m.json;
        d["note"] = m.twinNote;
        d["theta_o"] = r.albedoAngles;
        const auto [walk, walkSe] = meansOf(m.walkAlbedo.values);
        d["walk_albedo"] = walk;
        d["walk_albedo_se"] = walkSe;
        d["map_angles"] = r.mapAngles;
        py::list twins;
        for (const auto& t : m.twins) {
            py::dict td;
            td["name"] = t.name;
            td["material"] = t.json;
            const auto [albedo, albedoSe] = meansOf(t.albedo.values);
            td["albedo"] = albedo;
            td["albedo_se"] = albedoSe;
            py::array_t<double> error({n, n}), errorSe({n, n});
            py::list agreement;
            for (std::size_t i = 0; i < t.map.comparisons.size(); ++i) {
                error.mutable_data()[i] = t.map.comparisons[i].error;
                errorSe.mutable_data()[i] = t.map.comparisons[i].standardError;
            }
            for (const auto& c : t.albedo.comparisons)
                agreement.append(std::string(ex::kAgreementNames.name(c.agreement)));
            td["albedo_agreement"] = agreement;
            td["map_error"] = error;
            td["map_error_se"] = errorSe;
            twins.append(td);
        }
        d["twins"] = twins;
        out.append(d);
    }
    return out;
}

}  // namespace

void bindExperiments(py::module_& m) {
    using Resolution = std::optional<std::pair<int, int>>;
    m.def("compare", &compare, py::arg("a"), py::arg("reference"), py::arg("metric") = py::none(),
          "Error metrics of a against the reference (relMSE epsilon 1e-2): one value, or a "
          "dict of mse, rmse, relmse, mae, max");
    m.def("convergence", &convergence, py::arg("scene"),
          py::arg("integrators") = std::vector<std::string>{"path", "light", "bdpt"},
          py::arg("modes") = std::vector<std::string>{"rgb"}, py::arg("seconds") = 10.0,
          py::arg("reference") = "", py::arg("reference_seconds") = 0.0, py::arg("threads") = 0,
          py::arg("max_depth") = 0, py::arg("resolution") = Resolution{},
          "Error against time per integrator and mode: rows and fitted slopes");
    m.def("reciprocity", &reciprocity, py::arg("scene"),
          py::arg("integrators") = std::vector<std::string>{"path", "light", "bdpt"},
          py::arg("mode") = "rgb", py::arg("spp") = 256, py::arg("batches") = 16,
          py::arg("seed") = 0, py::arg("alpha") = 0.01, py::arg("block_size") = 8,
          py::arg("reference") = "", py::arg("threads") = 0, py::arg("max_depth") = 0,
          py::arg("resolution") = Resolution{},
          "Do the integrators converge to the same image? Statistics per pair and a verdict");
    m.def("fresnel", &fresnel, py::arg("materials"),
          "Exact spectral Fresnel against RGB mode's models, per material");
    m.def("stability", &stability, py::arg("materials") = std::vector<std::string>{},
          py::arg("samples") = 4096,
          "The extreme-input audit per model: issues and float error over (alpha, cos theta)");
    m.def("layering", &layering, py::arg("materials"), py::arg("estimates") = 4096,
          py::arg("albedo_samples") = 1 << 16, py::arg("seed") = 1,
          "Coated materials (random walk) against their analytic layered twins: albedo with "
          "standard errors, relative error maps over (theta_o, theta_i), agreement bands");
}

}  // namespace lamina::python
