// A realistic camera's optics (Kolb, Mitchell and Hanrahan 1995): rays traced through the
// spherical interfaces and the aperture stop of a lens system (lens_file.h), refracted by
// Snell's law, blocked where they miss an interface's aperture or are totally reflected.
//
// Lens space: the film in the plane z = 0, centred on the axis, the lens in front of it along
// +z (towards the scene), metres. The rear vertex stands at filmDistance(), found by focusing:
// the distance at which a paraxial ray from the axis point at focus_distance in front of the
// film (pbrt-v4 measures it from the film too) crosses the axis on the film.
//
// Rays leave a film point towards the exit pupil, the part of the rear interface's plane
// through which light reaches the scene: bounded once per ring of film points (32 rings out to
// half the film's diagonal, 16384 trial rays each) by a rectangle, grown by the trials'
// spacing, that is sampled uniformly and turned to the film point's angle (as pbrt-v4 does;
// a sliver of the pupil the trials miss is lost, which they make rare).
#pragma once

#include <optional>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "lamina/scene/lens_file.h"

namespace lamina::render {

struct LensRay {
    glm::dvec3 origin, direction;  ///< direction unit
};

/// A point of the exit pupil's rectangle and its density per unit area.
struct PupilSample {
    glm::dvec3 point;  ///< on the plane of the rear vertex
    double pdf;
};

class LensSystem {
  public:
    /// `apertureDiameter` (metres; 0: the file's) sets the stop's; larger than the file's it is
    /// clamped to it (`clamped` says so). Throws InputError (no location: the caller names the
    /// key) when the focus distance is too short for the lens or no ray passes.
    LensSystem(std::vector<LensInterface> interfaces, double apertureDiameter, double focusDistance,
               double filmDiagonal, bool* clamped = nullptr);

    /// The ray leaving the front interface for a ray from the film side (towards +z), or
    /// nullopt if the lens blocks it.
    std::optional<LensRay> traceFromFilm(LensRay ray) const;
    /// The ray leaving the rear interface for a ray from the scene (towards -z), or nullopt.
    std::optional<LensRay> traceFromScene(LensRay ray) const;

    /// A point of the exit pupil seen from film point `film` (z = 0) for `u` in [0, 1)^2, or
    /// nullopt where no light reaches that part of the film.
    std::optional<PupilSample> sampleExitPupil(const glm::dvec2& film, const glm::dvec2& u) const;

    double filmDistance() const { return interfaces_.back().thickness; }
    double frontZ() const { return frontZ_; }
    double filmDiagonal() const { return filmDiagonal_; }
    const std::vector<LensInterface>& interfaces() const { return interfaces_; }

  private:
    struct Bounds {
        glm::dvec2 lo{1e300}, hi{-1e300};
        bool empty() const { return !(lo.x <= hi.x && lo.y <= hi.y); }
    };
    /// The axis position where a paraxial ray from the scene's axis point at `distance` in
    /// front of the film crosses the axis behind the lens (the image; 0 is the film).
    std::optional<double> imageZ(double distance) const;
    void focus(double focusDistance);
    Bounds boundExitPupil(double r0, double r1) const;

    std::vector<LensInterface>
        interfaces_;  ///< front to rear; the last one's thickness: to the film
    double frontZ_ = 0;
    double filmDiagonal_;
    std::vector<Bounds> pupil_;  ///< by ring of film points
};

}  // namespace lamina::render
