// The `measured` material: a BSDF measured by the RGL goniophotometer and stored in the adaptive
// parameterisation of Dupuy and Jakob 2018 (measured_table.h has the tables and the formulas).
// One glossy reflection lobe, two-sided (below the surface wo and wi are mirrored to above, as
// pbrt-v4's MeasuredBxDF does):
//   eval    fr(ui) D(wm) / (4 sigma(wo)) = f(wo, wi) |cos theta_i| (section 5 of the paper;
//           `ui` is the inverse of the visible-normal warp at u(wm)).
//   sample  the luminance warp draws ui, the visible-normal warp takes it to u(wm), wi is wo
//           reflected about wm; pdf is the product of the two warps' densities over the
//           Jacobian of u(wm) -> wi. weight = eval / pdf, both computed from wi as eval and
//           pdf compute them, so that the three agree exactly.
// What each mode reads: spectral mode a spectral file's values at the path's wavelengths (an
// RGB file's values upsampled as unbounded spectra); RGB mode an RGB file's values, or a
// spectral file's spectra reduced to linear Rec.709 under D65 when the table was built. The
// polarised mode sees an ideal depolariser (the files hold no polarisation). Measured data are
// not reciprocal: f(wo, wi) and f(wi, wo) differ by the measurement's noise and by the
// parameterisation's interpolation, which is built around wo; importance transport (light
// tracing) therefore evaluates the adjoint, the table read from wi.
#pragma once

#include <array>
#include <filesystem>
#include <memory>

#include "lamina/bsdf/bxdf.h"
#include "lamina/bsdf/material_builder.h"
#include "lamina/bsdf/measured_table.h"
#include "lamina/core/error.h"

namespace lamina {

template <SpectrumType S>
class MeasuredBxdf final : public Bxdf<S> {
  public:
    using typename Bxdf<S>::Float;
    using typename Bxdf<S>::V3;
    using typename Bxdf<S>::V2;

    /// `wavelengths`: the path's, in spectral variants (unused in RGB ones).
    MeasuredBxdf(std::shared_ptr<const MeasuredBsdfTable> table,
                 const std::array<double, S::kSize>& wavelengths)
        : table_(std::move(table)), wavelengths_(wavelengths) {}

    S eval(const V3& wo, const V3& wi, TransportMode mode) const override {
        if (mode == TransportMode::Importance) return adjoint(wo, wi);
        const auto l = table_->lookup(Vec3d(wo), Vec3d(wi));
        return l ? values(*l) : S(Float(0));
    }

    Float pdf(const V3& wo, const V3& wi) const override {
        const auto l = table_->lookup(Vec3d(wo), Vec3d(wi));
        return l ? finite(l->pdf) : Float(0);
    }

    std::optional<BsdfSample<S>> sample(const V3& wo, Float, const V2& u,
                                        TransportMode mode) const override {
        const auto wiD = table_->sample(Vec3d(wo), Vec2d(u));
        if (!wiD) return std::nullopt;
        const V3 wi(*wiD);
        const auto l = table_->lookup(Vec3d(wo), Vec3d(wi));
        if (!l || !(l->pdf > 0)) return std::nullopt;
        const S value = mode == TransportMode::Importance ? adjoint(wo, wi) : values(*l);
        const Float pdf = finite(l->pdf);
        const S weight = value / pdf;
        // A hostile table's extremes may overflow the variant's float: absorbed, never Inf.
        if (value.isZero() || !(pdf > Float(0)) || !weight.isFinite()) return std::nullopt;
        return BsdfSample<S>{wi, weight, pdf, kLobeGlossyReflection, Float(1)};
    }

    std::uint32_t flags() const override { return kLobeGlossyReflection; }
    bool usesLobeChoice() const override { return false; }

  private:
    // Importance carries the adjoint BSDF f*(wo, wi) = f(wi, wo) (Veach 1997, eq. 5.14): the
    // table read with the roles of the directions swapped, its cosine (of wo) exchanged for
    // wi's. Measured data are not reciprocal, so without it light tracing would render
    // another material than camera tracing.
    S adjoint(const V3& wo, const V3& wi) const {
        const auto l = table_->lookup(Vec3d(wi), Vec3d(wo));
        if (!l) return S(Float(0));
        const S v = values(*l) * Float(std::abs(double(wi.z)) / std::abs(double(wo.z)));
        return v.isFinite() ? v : S(Float(0));
    }

    // A value in the variant's float, 0 where it does not fit.
    static Float finite(double v) {
        const Float f = Float(v);
        return std::isfinite(f) ? f : Float(0);
    }

    S values(const MeasuredBsdfTable::Lookup& l) const {
        S out;
        if constexpr (SpectrumContext<S>::kSpectral) {
            if (table_->spectral()) {
                for (int i = 0; i < S::kSize; ++i)
                    out[i] = finite(table_->value(l, wavelengths_[std::size_t(i)]));
            } else {
                const RgbSpectrum s(Rgb<double>(table_->rgbValue(l, 0), table_->rgbValue(l, 1),
                                                table_->rgbValue(l, 2)),
                                    RgbSpectrumKind::Unbounded);
                for (int i = 0; i < S::kSize; ++i)
                    out[i] = finite(s(wavelengths_[std::size_t(i)]));
            }
        } else {
            for (int c = 0; c < 3; ++c)
                out[c] = finite(table_->rgbValue(l, c));
        }
        return out;
    }

    std::shared_ptr<const MeasuredBsdfTable> table_;
    std::array<double, S::kSize> wavelengths_;
};

LAMINA_EXTERN_BSDF_VARIANTS(MeasuredBxdf)

/// Where a measured material's table is: the bsdf library reads no files, so the scene library
/// reads the file after the material is parsed (loadMeasuredTables, rgl_bsdf_file.h) and sets
/// `table` here, which every copy of the description shares.
struct MeasuredTableSlot {
    std::filesystem::path file;
    std::shared_ptr<const MeasuredBsdfTable> table;
};

/// `measured`: {"type": "measured", "filename": path of an RGL .bsdf file}.
struct MeasuredMaterial {
    std::shared_ptr<MeasuredTableSlot> slot = std::make_shared<MeasuredTableSlot>();
};

template <SpectrumType S>
std::unique_ptr<Bxdf<S>> buildModel(const MeasuredMaterial& m, const MaterialBuilder<S>& b) {
    if (!m.slot->table)
        throw InputError(m.slot->file.string() +
                         ": the measured BSDF file was not read (the scene library reads it: "
                         "loadMeasuredTables)");
    std::array<double, S::kSize> wavelengths{};
    if constexpr (SpectrumContext<S>::kSpectral)
        for (int i = 0; i < S::kSize; ++i)
            wavelengths[std::size_t(i)] = double(b.context().wavelength(i));
    return std::make_unique<MeasuredBxdf<S>>(m.slot->table, wavelengths);
}
LAMINA_MATERIAL_MODEL(MeasuredMaterial)

}  // namespace lamina
