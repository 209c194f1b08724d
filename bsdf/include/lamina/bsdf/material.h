// Material descriptions: the JSON objects of docs/bsdf.md ("Materials"), parsed and validated
// once, independent of the rendering mode. A description is a value of its type's struct, which
// lives in that type's BSDF header beside the function that builds its BSDF (`buildModel`, for
// every variant); `MaterialModel` holds one of any type, so that no central list names them
// (docs/architecture.md, "A new material"). Colours are linear Rec.709 triples; what a colour
// means in spectral mode is decided by the builder's SpectrumContext (material_builder.h).
#pragma once

#include <concepts>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "lamina/bsdf/bxdf.h"
#include "lamina/bsdf/material_inputs.h"

namespace lamina {

// Declared only: the JSON library is the costliest header of the build, and most files that
// use materials never parse one (bsdf/src/*_reader.cpp include core/json_reader.h).
class JsonReader;

template <SpectrumType S>
class MaterialBuilder;

/// One material description of any type. A type `M` is a description when its BSDF header
/// declares `template <SpectrumType S> std::unique_ptr<Bxdf<S>> buildModel(const M&, const
/// MaterialBuilder<S>&)` and marks it with LAMINA_MATERIAL_MODEL(M) (material_builder.h), which
/// the build instantiates for the four variants in one optimised file.
class MaterialModel {
  public:
    MaterialModel() = default;
    template <typename M>
    requires(!std::same_as<std::remove_cvref_t<M>, MaterialModel>)
        MaterialModel(M model)  // NOLINT(google-explicit-constructor): a description is a model
        : holder_(std::make_unique<Holder<M>>(std::move(model))) {}
    MaterialModel(const MaterialModel& other)
        : holder_(other.holder_ ? other.holder_->clone() : nullptr) {}
    MaterialModel(MaterialModel&&) noexcept = default;
    MaterialModel& operator=(const MaterialModel& other) {
        if (this != &other) holder_ = other.holder_ ? other.holder_->clone() : nullptr;
        return *this;
    }
    MaterialModel& operator=(MaterialModel&&) noexcept = default;
    ~MaterialModel() = default;

    /// The description if it is of type M, else nullptr.
    template <typename M>
    const M* get() const {
        const auto* h = dynamic_cast<const Holder<M>*>(holder_.get());
        return h ? &h->model : nullptr;
    }
    template <typename M>
    M* get() {
        auto* h = dynamic_cast<Holder<M>*>(holder_.get());
        return h ? &h->model : nullptr;
    }
    template <typename M>
    bool holds() const {
        return get<M>() != nullptr;
    }
    /// The description, which must be of type M (std::logic_error otherwise).
    template <typename M>
    const M& as() const {
        if (const M* m = get<M>()) return *m;
        throw std::logic_error("a material description of another type");
    }
    template <typename M>
    M& as() {
        if (M* m = get<M>()) return *m;
        throw std::logic_error("a material description of another type");
    }

    /// The BSDF of this description in the builder's variant.
    template <SpectrumType S>
    std::unique_ptr<Bxdf<S>> build(const MaterialBuilder<S>& builder) const {
        if (!holder_) throw std::logic_error("a material description without a model");
        return holder_->build(builder);
    }

  private:
    struct Concept {
        virtual ~Concept() = default;
        virtual std::unique_ptr<Concept> clone() const = 0;
        virtual std::unique_ptr<Bxdf<Rgb<float>>> build(
            const MaterialBuilder<Rgb<float>>&) const = 0;
        virtual std::unique_ptr<Bxdf<Rgb<double>>> build(
            const MaterialBuilder<Rgb<double>>&) const = 0;
        virtual std::unique_ptr<Bxdf<SampledSpectrum<float>>> build(
            const MaterialBuilder<SampledSpectrum<float>>&) const = 0;
        virtual std::unique_ptr<Bxdf<SampledSpectrum<double>>> build(
            const MaterialBuilder<SampledSpectrum<double>>&) const = 0;
    };

    // buildModel is found by argument-dependent lookup in M's BSDF header.
    template <typename M>
    struct Holder final : Concept {
        M model;
        explicit Holder(M m) : model(std::move(m)) {}
        std::unique_ptr<Concept> clone() const override { return std::make_unique<Holder>(model); }
        std::unique_ptr<Bxdf<Rgb<float>>> build(
            const MaterialBuilder<Rgb<float>>& b) const override {
            return buildModel(model, b);
        }
        std::unique_ptr<Bxdf<Rgb<double>>> build(
            const MaterialBuilder<Rgb<double>>& b) const override {
            return buildModel(model, b);
        }
        std::unique_ptr<Bxdf<SampledSpectrum<float>>> build(
            const MaterialBuilder<SampledSpectrum<float>>& b) const override {
            return buildModel(model, b);
        }
        std::unique_ptr<Bxdf<SampledSpectrum<double>>> build(
            const MaterialBuilder<SampledSpectrum<double>>& b) const override {
            return buildModel(model, b);
        }
    };

    std::unique_ptr<Concept> holder_;
};

struct MaterialDesc {
    std::string type;  ///< the JSON "type", for messages and `lamina info`
    MaterialModel model;
};

/// The material types parseMaterial accepts, in the order its messages list them.
std::vector<std::string> materialTypeNames();

/// Parses and validates one material object ({"type": ..., ...}); unknown types, unknown keys
/// and out-of-range values are InputErrors naming the JSON path.
MaterialDesc parseMaterial(const JsonReader& reader);

/// Parses a material given on a command line: a JSON object literal or "@file.json".
MaterialDesc parseMaterialArgument(const std::string& argument);

}  // namespace lamina
