// Lights: the interface every light implements and the scene's set of lights with the
// distribution next-event estimation and particles choose them by. The lights themselves:
//   area_lights.h      emitting shapes: mesh triangles, rectangles, disks, spheres
//   point_lights.h     point and spot lights
//   infinite_lights.h  directional light, constant and image (environment map) environments
// Every sampling routine has its density for MIS. Radiance is returned as an Emission (the
// emitter's colour in both modes times a scale); the render mode turns it into its spectrum.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "lamina/geometry/geometry.h"
#include "lamina/lights/emitter_color.h"
#include "lamina/lights/light_bounds.h"
#include "lamina/lights/light_bvh.h"

namespace lamina::render {

using Rgbf = Rgb<float>;

struct LightSample {
    Vec3f wi;           ///< unit, from the reference point towards the light
    float distance;     ///< to the sampled point; infinity for infinite lights
    Emission radiance;  ///< arriving along -wi (intensity / d^2 for a point light)
    float pdf;          ///< solid angle density at the reference point; 1 for delta lights
    bool delta;
    Vec3f point;   ///< the sampled point (finite lights), for the shadow ray's far end
    Vec3f normal;  ///< the light's surface normal there, facing the reference point
};

/// A particle leaving a light (light tracing, BDPT's light subpaths).
struct EmissionSample {
    Vec3f point;             ///< where it starts (on a disk outside the scene for infinite lights)
    Vec3f normal;            ///< the emitting side's normal (the direction itself for point lights
                             ///< and infinite lights, so that |cos| = 1)
    Vec3f direction;         ///< unit, away from the light
    Emission radiance;       ///< radiance, intensity (point, spot) or irradiance (directional)
    float pdfPosition = 1;   ///< per unit area (1 for a delta position)
    float pdfDirection = 1;  ///< per solid angle (1 for a delta direction)
    bool deltaPosition = false, deltaDirection = false;
};

/// The densities of sampleEmission producing a given particle.
struct EmissionPdf {
    float position = 0, direction = 0;
};

class Light {
  public:
    virtual ~Light() = default;
    /// Samples a direction towards the light from `ref`; nullopt if nothing can be sampled.
    virtual std::optional<LightSample> sample(const Vec3f& ref, const Vec2f& u) const = 0;
    /// Solid-angle density of sample() producing the point `onLight` (hit from `ref`).
    virtual float pdf(const Vec3f& ref, const SurfaceHit& onLight) const = 0;
    /// Emitted radiance leaving `hit` towards direction `w` (unit, away from the surface).
    virtual Emission radiance(const SurfaceHit& hit, const Vec3f& w) const = 0;
    /// Total emitted power (for light selection), in RGB luminance.
    virtual double power() const = 0;
    /// Where the light is, which way and how strongly it emits, for the light BVH; nullopt
    /// for lights at infinity.
    virtual std::optional<LightBounds> bounds() const { return std::nullopt; }
    virtual bool isDelta() const { return false; }
    virtual bool isInfinite() const { return false; }
    /// Infinite lights: radiance arriving at `origin` along -w (w points away from the scene:
    /// the direction of a ray from `origin` that escapes), and the density of sample(origin)
    /// drawing w. Only a portal's depend on the origin (portal_environment.h).
    virtual Emission environment(const Vec3f& /*origin*/, const Vec3f& /*w*/) const { return {}; }
    virtual float environmentPdf(const Vec3f& /*origin*/, const Vec3f& /*w*/) const { return 0.0f; }

    /// Samples a particle: `uPosition` chooses the point, `uDirection` the direction. Its
    /// weight is radiance |cos(normal, direction)| / (pdfPosition pdfDirection).
    virtual std::optional<EmissionSample> sampleEmission(const Vec2f& uPosition,
                                                         const Vec2f& uDirection) const = 0;
    /// Densities of sampleEmission producing a particle at `point` (surface normal `normal`,
    /// as the surface was hit) leaving along `direction`. For infinite lights `point` is any
    /// point of the particle's line (none: the zero vector, when only the direction density
    /// is asked for) and the position density is per unit area perpendicular to the direction:
    /// the disk's, or a portal's projected.
    virtual EmissionPdf emissionPdf(const Vec3f& point, const Vec3f& normal,
                                    const Vec3f& direction) const = 0;
};

/// Lights of the scene and the distributions they are chosen with (light_set.cpp). The set
/// also knows which area light each shape of the geometry carries.
///
/// Next-event estimation chooses at a shading point (choose, probability): with `bvh`
/// selection the lights with a position through the light BVH and the lights at infinity with
/// a fixed share, in proportion to their power among themselves; with `power` and `uniform`
/// the same distribution everywhere. It never chooses a constant environment when every
/// environment of the scene is constant: BSDF sampling alone finds such light at least as
/// well as a direction uniform on the sphere, and the next-event samples it would take go to
/// the other lights (Cycles 3.4 and pbrt-v4 do the same; nextEventSamples). Particles (light
/// tracing, BDPT's light subpaths) start from a light chosen independently of any point
/// (chooseEmitter, emitterProbability): by power, or uniformly under `uniform` selection.
class LightSet {
  public:
    LightSet(const SceneDesc& scene, const Geometry& geometry, LightSelection selection);

    bool empty() const { return lights_.empty(); }
    std::size_t size() const { return lights_.size(); }
    const Light& light(std::size_t i) const { return *lights_[i]; }
    /// Chooses a light for next-event estimation at `p` with surface normal `n` (the zero
    /// vector: none); nullopt when the set is empty.
    std::optional<LightChoice> choose(const Vec3f& p, const Vec3f& n, float u) const;
    /// The probability that choose(p, n, u) returns light i for a uniform u.
    float probability(std::size_t i, const Vec3f& p, const Vec3f& n) const;
    /// Whether choose() can return a light at all: false without lights or when the only ones
    /// are constant environments (nextEventSamples), such as the white furnace's.
    bool nextEventChooses() const { return nextEventChoices_ > 0; }
    /// Whether choose() reads u: false when there is at most one light it can return (the
    /// Cornell box's lamp), and the integrators then skip the sampler's dimension for it.
    bool choiceReadsNumber() const { return nextEventChoices_ > 1; }
    /// Chooses the light a particle starts from.
    LightChoice chooseEmitter(float u) const;
    /// Whether chooseEmitter() reads u: false for a scene of one light.
    bool emitterChoiceReadsNumber() const { return lights_.size() > 1; }
    float emitterProbability(std::size_t i) const { return pmf_[i]; }
    /// Under every selection, probability(i, p, n) / emitterProbability(i) is the same for
    /// all environment lights (the infinite lights that are not delta) at a given point
    /// (BDPT's MIS relies on it).
    const std::vector<std::size_t>& infiniteLights() const { return infinite_; }
    /// Whether next-event estimation ever chooses light i (probability(i, ., .) > 0
    /// somewhere): false only for constant environments in a scene whose environments are
    /// all constant.
    bool nextEventSamples(std::size_t i) const { return nextEvent_[i] != 0; }
    /// The area light of a hit primitive, or -1.
    int lightAt(const SurfaceHit& hit) const;

  private:
    /// The area lights of one shape of the geometry.
    struct ShapeLights {
        int first = -1;             ///< the light of its first primitive; -1: not emissive
        bool perPrimitive = false;  ///< one light per triangle (meshes other than rectangles)
    };

    void chooseNextEventLights();
    void buildNextEventDistribution(const std::vector<double>& weights);
    void buildBvh();

    std::vector<std::unique_ptr<Light>> lights_;
    std::vector<float> pmf_, cdf_;  ///< point-independent (power or uniform): particles
    /// Next-event estimation's point-independent distribution (`power`, `uniform`): pmf_
    /// restricted to the lights it samples (nextEvent_) and renormalised.
    std::vector<float> nextEventPmf_, nextEventCdf_;
    std::vector<char> nextEvent_;  ///< per light: sampled by next-event estimation
    std::vector<std::size_t> infinite_;
    std::vector<ShapeLights> shapeLights_;  ///< indexed like Geometry::shapes()
    std::size_t nextEventChoices_ = 0;      ///< the lights choose() can return
    // `bvh` selection: the lights with a position, and the lights at infinity with the share
    // infiniteShare_, among themselves by infiniteCdf_ (their pmf_ renormalised).
    bool useBvh_ = false;
    LightBvh bvh_;
    float infiniteShare_ = 0.0f;
    std::vector<std::size_t> nextEventInfinite_;    ///< the lights of infinite_ it samples
    std::vector<float> infinitePmf_, infiniteCdf_;  ///< indexed like nextEventInfinite_
    std::vector<int> infiniteSlot_;  ///< per light: its index in nextEventInfinite_, or -1
};

}  // namespace lamina::render
