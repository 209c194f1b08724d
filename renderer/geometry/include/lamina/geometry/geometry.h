// The scene's geometry in Embree 3: triangle meshes, analytic spheres and disks, pbrt-v4's
// clipped quadrics (Embree user geometry, quadric.h), one Embree geometry per shape, and the
// surface interaction at a hit (position recomputed from the primitive for accuracy, geometric and
// shading normals, uv; where the shape's material has a bump or normal map, the uv derivatives and
// the shading normal that map makes, shading_normal_maps.h). Objects (SceneDesc::objects) are
// Embree scenes of their own, built once and placed by Embree instance geometries, never copied.
// Shapes with an alpha cut-out carry Embree filter functions, so closest-hit and shadow rays alike
// pass through their holes (alpha_filter.h). Which shapes emit is the light set's business
// (lights.h).
#pragma once

#include <embree3/rtcore.h>

#include <memory>
#include <optional>
#include <vector>

#include "lamina/core/frame.h"
#include "lamina/core/ray.h"
#include "lamina/geometry/alpha_filter.h"
#include "lamina/scene/scene_description.h"
#include "lamina/scene/shading_normal_maps.h"

namespace lamina::render {

using Vec3f = Vec3<float>;
using Vec2f = Vec2<float>;

struct QuadricGeometry;  // quadric_geometry.h

/// A point on a surface hit by a ray.
struct SurfaceHit {
    Vec3f p;   ///< on the surface (recomputed from the primitive, not o + t d)
    Vec3f ng;  ///< geometric normal, unit, outward (winding / sphere orientation)
    Vec3f ns;  ///< shading normal, unit, on the same side as ng (a material's map applied)
    Vec2f uv{0.0f};
    /// Unit, along a curve (the hair BSDF's fibre axis, the shading frame's x); zero on every
    /// other shape, whose shading frame follows the normal alone.
    Vec3f tangent{0.0f};
    /// In the world; only where the shape's material turns the shading normal (ShapeInfo),
    /// zero elsewhere.
    SurfaceDerivatives derivatives;
    float t = 0;
    int shape = -1;  ///< index into Geometry::shapes()
    std::uint32_t primitive = 0;
    int instance = -1;  ///< into SceneDesc::instances; -1: a shape of "shapes"
};

/// What the geometry knows about each shape.
struct ShapeInfo {
    const ShapeDesc* desc = nullptr;  ///< in SceneDesc::shapes or in its object's shapes
    int material = -1;
    int object = -1;  ///< into SceneDesc::objects; -1: a shape of the scene's own list
    /// Its material has a bump or normal map (MaterialTextures::perturbsNormal).
    bool turnsNormal = false;
};

/// What the Embree scenes hold: triangles stored once, and those instances make visible.
struct GeometryCounts {
    std::size_t trianglesStored = 0;      ///< in the shapes and the built objects
    std::size_t trianglesReferenced = 0;  ///< the shapes' plus every instance's object's
    std::size_t instances = 0;
    std::size_t objectsBuilt = 0;  ///< objects some instance places (each one Embree scene)
};

/// An instance's transform as Embree applies it (float), in double for the hit. A moving
/// instance (InstanceDesc::toWorldEnd) has a second one at time 1, and Embree interpolates the
/// two matrices element by element at the ray's time (instance_motion.cpp).
struct InstanceTransform {
    glm::dmat4 toWorld{1.0}, toObject{1.0};
    glm::dmat3 normalMatrix{1.0};
    bool mirrors = false;
    std::optional<glm::dmat4> toWorldEnd;  ///< at time 1; unset: it does not move

    /// From Embree's 3 x 4 column-major matrix.
    static InstanceTransform fromEmbree(const float xfm[12]);
    /// The transform at `time` in [0, 1], as Embree interpolates it (a moving one's).
    InstanceTransform at(float time) const;
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

    /// The scene's shapes (indexed by Embree geometry id), then each built object's.
    const std::vector<ShapeInfo>& shapes() const { return shapes_; }
    const GeometryCounts& counts() const { return counts_; }
    /// The axis-aligned box of everything, instances included.
    Vec3f boundsLo() const { return boundsLo_; }
    Vec3f boundsHi() const { return boundsHi_; }
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
    /// Every shape of `shapes` into `target`, geometry id = index (the scene's shapes, or
    /// those of the object `object`).
    void addShapes(RTCScene target, const std::vector<ShapeDesc>& shapes, int object);
    /// One shape's Embree geometry, one function per kind of ShapeDesc.
    RTCGeometry newGeometry(const MeshDesc& m, int object);
    RTCGeometry newGeometry(const SphereDesc& s, int object);
    RTCGeometry newGeometry(const DiskDesc& d, int object);
    RTCGeometry newGeometry(const QuadricDesc& q, int object);
    RTCGeometry newGeometry(const CurvesDesc& c, int object);
    void addAlphaFilter(RTCGeometry g, const AlphaDesc& alpha, const MeshDesc* mesh);
    void addInstances(Vec3<double>& lo, Vec3<double>& hi);

    const SceneDesc& scene_;
    RTCDevice device_ = nullptr;
    RTCScene scene3_ = nullptr;
    std::vector<RTCScene> objectScenes_;  ///< by object; null: placed by no instance
    std::vector<int> objectFirstShape_;   ///< by object: its first entry in shapes_
    std::vector<InstanceTransform> instanceTransforms_;
    std::vector<std::unique_ptr<AlphaTest>> alphaTests_;      ///< the filters' user data
    std::vector<std::unique_ptr<QuadricGeometry>> quadrics_;  ///< the user geometries' data
    std::vector<ShapeInfo> shapes_;
    unsigned sceneShapes_ = 0;  ///< shapes of the scene's own list: the instances' ids follow
    GeometryCounts counts_;
    Vec3f boundsLo_{0.0f}, boundsHi_{0.0f};
    Vec3f boundsCenter_{0.0f};
    float boundsRadius_ = 1;
    float rayOffsetScale_ = 1;
};

}  // namespace lamina::render
