// The scene's geometry in Embree 3: triangle meshes, analytic spheres and disks, one Embree
// geometry per shape, and the surface interaction at a hit (position recomputed from the
// primitive for accuracy, geometric and shading normals, uv). Which shapes emit is the light
// set's business (lights.h).
#pragma once

#include <embree3/rtcore.h>

#include <memory>
#include <vector>

#include "lamina/core/frame.h"
#include "lamina/core/ray.h"
#include "lamina/render/scene_description.h"

namespace lamina::render {

using Vec3f = Vec3<float>;
using Vec2f = Vec2<float>;

/// A point on a surface hit by a ray.
struct SurfaceHit {
    Vec3f p;   ///< on the surface (recomputed from the primitive, not o + t d)
    Vec3f ng;  ///< geometric normal, unit, outward (winding / sphere orientation)
    Vec3f ns;  ///< shading normal, unit, on the same side as ng
    Vec2f uv{0.0f};
    float t = 0;
    int shape = -1;  ///< index into Geometry::shapes()
    std::uint32_t primitive = 0;
};

/// What the geometry knows about each shape.
struct ShapeInfo {
    enum class Kind { Mesh, Sphere, Disk } kind = Kind::Mesh;
    int index = -1;  ///< into SceneDesc::meshes, ::spheres or ::disks
    int material = -1;
};

class Geometry {
  public:
    explicit Geometry(const SceneDesc& scene);
    ~Geometry();
    Geometry(const Geometry&) = delete;
    Geometry& operator=(const Geometry&) = delete;

    /// The closest hit along the ray within (0, tMax), or nullopt.
    std::optional<SurfaceHit> intersect(const Vec3f& origin, const Vec3f& direction,
                                        float tMax = std::numeric_limits<float>::infinity()) const;
    /// True when something blocks the segment (0, tMax) of the ray.
    bool occluded(const Vec3f& origin, const Vec3f& direction, float tMax) const;

    const std::vector<ShapeInfo>& shapes() const { return shapes_; }
    /// Bounding sphere of everything (for environment and directional lights).
    Vec3f boundsCenter() const { return boundsCenter_; }
    float boundsRadius() const { return boundsRadius_; }
    /// The scale of the absolute ray offset near the origin (ray_offset.h): 1 for a scene
    /// whose extent is between 1 and 65536, else that extent over the nearer bound, rounded up
    /// to a power of two. The hit points' error grows with the scene's coordinates, not with
    /// a point's own: Waechter and Binder's fixed 1/65536 would carry a ray out of a scene
    /// 1e-8 times the Cornell box's size (it is 5.6e-6 across) and be lost in the rounding
    /// of one 1e8 times larger. Powers of two keep the offsets exact, and every scene of
    /// ordinary size renders as before, bit for bit.
    float rayOffsetScale() const { return rayOffsetScale_; }
    /// The committed Embree scene (for the raw ray-rate measurement, embree_limit.h).
    RTCScene embreeScene() const { return scene3_; }

  private:
    const SceneDesc& scene_;
    RTCDevice device_ = nullptr;
    RTCScene scene3_ = nullptr;
    std::vector<ShapeInfo> shapes_;
    Vec3f boundsCenter_{0.0f};
    float boundsRadius_ = 1;
    float rayOffsetScale_ = 1;
};

}  // namespace lamina::render
