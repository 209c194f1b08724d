// The emitting media of a scene as sources of light particles (light tracing, BDPT's light
// subpaths; docs/media.md, "Emitting media in light tracing and BDPT"). A medium emits
// sigma_a(x) Le per unit length and solid angle, isotropically; a particle of that emission
// starts at a point x of the medium with a density per unit volume, leaves in a direction
// uniform on the sphere, and carries sigma_a(x) Le 4 pi / (P p(x)), P the probability of
// choosing the medium. Where x is sampled:
//   homogeneous  uniform in the box of the shapes that bound the medium (every bounded region
//                lies in the convex hull of its boundary); a point outside the medium (found
//                from the camera, as a particle's medium is) carries nothing: one try, so the
//                density stays 1 / volume of the box, which BDPT's weights can evaluate;
//   grid         a cell of the majorant grid chosen in proportion to its maximum density (the
//                emission sigma_a Le follows the density, and no density in a cell exceeds
//                its maximum), then uniform in the cell, in the medium's space and carried to
//                the scene by the medium's transform (an affine map: a constant Jacobian).
// The sources join the lights' point-independent selection (LightSet::chooseEmitter) by power:
// the media take the share P_media / (P_media + P_lights) (at least 1% for either, as the light
// set gives every light), the lights keep their distribution among themselves. A scene without
// emitting media chooses exactly as before (the light set's own numbers, bit for bit).
#pragma once

#include <optional>
#include <vector>

#include "lamina/integrators/integrator.h"

namespace lamina::render {

class MediumEmitters {
  public:
    /// The emitting media of the context's scene when `media` (the mode renders media and the
    /// scene has some), else none. Throws InputError (refuseUnboundedEmission) for a
    /// homogeneous emitting medium that reaches infinity: its volume cannot be sampled.
    MediumEmitters(const SceneContext& context, bool media);

    bool empty() const { return sources_.empty(); }

    /// What a particle starts from: light `light`, or the volume of SceneDesc::media[medium],
    /// chosen with `probability`.
    struct Choice {
        int light = -1, medium = -1;
        float probability = 0;
    };
    /// Only when the scene has lights or emitting media.
    Choice choose(float u) const;
    /// The probability that a particle starts from light i: the light set's own without
    /// emitting media, else scaled by the lights' share.
    float lightProbability(std::size_t i) const;
    /// The probability that a particle starts in medium `medium`'s volume (0: it emits nothing).
    float mediumProbability(int medium) const;

    /// A point of medium `medium`'s emitting region from u in [0, 1)^3 and its density per
    /// unit volume; none where nothing can be sampled.
    struct VolumePoint {
        Vec3f p;
        float pdf;
    };
    std::optional<VolumePoint> samplePoint(int medium, const Vec3f& u) const;
    /// The density per unit volume with which samplePoint produces `p` (0 outside the region
    /// it samples).
    float pointDensity(int medium, const Vec3f& p) const;

  private:
    struct Source {
        int medium = -1;
        float probability = 0;  ///< of a particle starting here (the media's share included)
        /// The box points are sampled in: the scene's (homogeneous), the grid's in medium space.
        Vec3f lo{0.0f}, hi{0.0f};
        float boxDensity = 0;  ///< homogeneous: 1 / the box's volume
        // A grid: its majorant cells' distribution and the density per unit volume of the
        // scene of a uniform point in a cell chosen with probability 1.
        const GridDensity* grid = nullptr;
        int nx = 0, ny = 0, nz = 0;
        std::vector<float> cellPmf, cellCdf;
        float cellDensity = 0;
        glm::mat3 toWorld{1.0f};  ///< medium -> scene (the inverse of GridDensity's map)
        Vec3f toWorldOffset{0.0f};
    };
    /// Adds medium `index`'s source, with its power (for the selection) in `power`.
    bool addHomogeneous(const SceneContext& context, int index, double& power);
    bool addGrid(const SceneContext& context, int index, double& power);

    const LightSet* lights_ = nullptr;
    std::vector<Source> sources_;
    std::vector<int> sourceOf_;  ///< by medium: its index in sources_, or -1
    std::vector<float> cdf_;     ///< over sources_, of the media's share
    float mediaShare_ = 0;       ///< the probability that a particle starts in a medium
};

/// The one-line refusal of a homogeneous emitting medium that reaches infinity (for light
/// tracing and BDPT, which would have to sample its volume).
[[noreturn]] void refuseUnboundedEmission(const SceneDesc& scene, int medium);

/// Whether a medium of the scene is, by its description alone, a homogeneous emitting medium
/// that fills space: the camera's medium, named by no shape.
bool emissionFillsSpace(const SceneDesc& scene, int medium);

}  // namespace lamina::render
