#pragma once
// The scene model: what the scene file describes, plus the acceleration structure built
// from it. Immutable once built; renders and traces only read it.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "geometry/bvh.h"
#include "geometry/sphere.h"
#include "scene/camera_settings.h"
#include "scene/detector_settings.h"
#include "scene/lens_bench.h"
#include "scene/light.h"
#include "scene/light_sampler.h"
#include "scene/light_source.h"
#include "scene/material.h"
#include "scene/medium.h"
#include "scene/photon_targets.h"
#include "scene/render_settings.h"

namespace lenslab {

enum class ObjectType {
    Sphere,
    Triangle,
    Lens,
    Mesh,
    Implicit,
    Disc,
    Rectangle,
    Mirror
};  // Mesh: a mesh or a prism

struct SceneObject {
    std::string name;  // the user's `name`, or the JSON path "objects[i]"
    ObjectType type = ObjectType::Sphere;
    std::shared_ptr<const Shape> shape;
    int material = 0;   // index into Scene::materials
    int source = -1;    // index of the scene file's `objects` entry it came from (a lens group
                        // makes several objects)
    std::string group;  // the lens group's name, for its elements
    Vec3 group_axis;    // the axis light enters the lens group along (zero: not in a group)
    Vec3 group_vertex;  // the group's `vertex`: with group_axis, the axis as designed, which
                        // decentred and tilted elements leave
    // Set when the object is a detector (triangles, discs and rectangles only).
    std::optional<DetectorSettings> detector;
    // Whether photons are aimed at it (photon_targets.h); unset: when its material is
    // transparent or a mirror, so it makes caustics.
    std::optional<bool> photon_target;
    // What fills the solid (smoke, fog, milky water): closed shapes only; unset: clear inside.
    std::optional<Medium> medium;
};

// An emitting sphere: the report's light source.
struct SphereEmitter {
    int object;             // index into Scene::objects
    BoundingSphere sphere;  // its shape's centre and radius
    SpectrumPtr radiance;   // emitted spectral radiance
};

struct SceneHit {
    SurfaceHit surface;
    int object = -1;
};

class Scene {
public:
    CameraSettings camera;
    RenderSettings render;
    std::vector<Material> materials;
    std::vector<SceneObject> objects;
    std::vector<PointLight> point_lights;
    std::vector<BeamLight> beams;  // beams and lasers
    std::vector<SpotLight> spots;
    std::vector<LightPtr> area_lights;  // rectangle and disc lights
    // The medium filling the space outside every object (fog in the room), if any.
    std::optional<Medium> atmosphere;
    // An imported lens file's system data (wavelengths, fields, aperture), if the scene has it.
    std::optional<LensBench> bench;

    // Builds the acceleration structure and the emitter list; call after filling the fields.
    void build();
    // Sets the lights without geometry, and lights() from them; on a built scene it keeps the
    // acceleration structure (an editor's light edit).
    void set_lights(SceneLights lights);

    bool intersect(const Ray& ray, double t_min, double t_max, SceneHit& hit) const;
    // Surfaceless boundaries (a medium's edge) do not occlude.
    bool occluded(const Ray& ray, double t_min, double t_max) const;
    // The objects holding a medium, the smallest (by bounding box) first: so the first that
    // contains a point is the innermost there.
    const std::vector<int>& medium_solids() const { return m_medium_solids; }
    // Whether light may meet a medium anywhere: an atmosphere or a shape's medium.
    bool has_media() const { return atmosphere || !m_medium_solids.empty(); }

    const Material& material_of(int object) const { return materials[objects[object].material]; }
    // The transparent solid on the other side of `object`'s surface at `point` (a cemented
    // neighbour sharing that surface), or nullptr when the other side is air.
    // `outward_normal` points out of `object`.
    const Material* medium_beyond(int object, const Vec3& point, const Vec3& outward_normal) const;
    // The same as the index of that solid in `objects`, or -1.
    int solid_beyond(int object, const Vec3& point, const Vec3& outward_normal) const;
    // Objects whose material emits light: spheres (the report's lights).
    const std::vector<SphereEmitter>& emitters() const { return m_emitters; }
    // Every light: emitting spheres first, then point lights, beams, spots, area lights.
    const std::vector<LightPtr>& lights() const { return m_lights; }
    const LightSampler& light_sampler() const { return m_light_sampler; }
    // The objects photons are aimed at, and whether `object` is one of them.
    const PhotonTargets& photon_targets() const { return m_targets; }
    bool is_photon_target(int object) const {
        return m_is_target[static_cast<size_t>(object)] != 0;
    }
    // A transparent or mirror object that is not a photon target: its caustics come from
    // the ordinary (unaimed) photons.
    bool has_specular_non_target() const { return m_specular_non_target; }
    Aabb bounds() const { return m_bvh.bounds(); }

private:
    void find_touching_solids();
    void find_media();
    void find_lights_and_targets();

    Bvh m_bvh;
    std::vector<SphereEmitter> m_emitters;
    std::vector<LightPtr> m_lights;
    LightSampler m_light_sampler;
    PhotonTargets m_targets;
    std::vector<char> m_is_target;
    bool m_specular_non_target = false;
    // For each object, the transparent solids whose boxes touch its box: the only candidates
    // for a shared surface. Empty for nearly every object, so medium_beyond costs nothing.
    std::vector<std::vector<int>> m_touching;
    std::vector<int> m_medium_solids;
    // Per object, whether shadow rays pass it (a surfaceless boundary); empty when none does,
    // so occluded stays the BVH's plain any-hit test.
    std::vector<char> m_see_through;
};

}  // namespace lenslab
