#pragma once
// The objects photons are aimed at (Jensen 2001, section 5.1.2 "projection maps", with
// bounding cones in place of a map): the transparent and mirror objects that make caustics.
// From a point, each target's bounding sphere subtends a cone; photons drawn inside the
// union of the cones reach every target at the cost of the few that miss, instead of the
// small fraction of a light's whole emission that meets the glass.
//
// Unbiasedness: the union of the cones holds every direction whose first hit is a target.
// A photon traced from such a sample counts only if its first hit is a target, and a photon
// of the light's ordinary emission only if its first hit is not; each part of the light's
// emission is thus counted once, by the stream whose density it was divided by.

#include <vector>

#include "geometry/shape.h"

namespace lenslab {

class PhotonTargets {
public:
    PhotonTargets() = default;
    explicit PhotonTargets(std::vector<BoundingSphere> spheres) : m_spheres(std::move(spheres)) {}

    bool empty() const { return m_spheres.empty(); }
    const std::vector<BoundingSphere>& spheres() const { return m_spheres; }

    // A direction from `from` in the union of the cones the targets subtend, with its
    // density (per steradian) under the mixture that picks a cone in proportion to its
    // solid angle: pdf = (cones holding the direction) / (sum of the solid angles).
    // Returns false when that sum is at least `max_solid_angle` (aiming would not beat the
    // light's own sampling there); `dir` and `pdf` are then unset.
    bool sample_direction(const Vec3& from, double u0, double u1, double u2, double max_solid_angle,
                          Vec3& dir, double& pdf) const;

    // The same on a plane: a point of the plane through `origin` perpendicular to the unit
    // `normal`, inside the union of the discs the targets' spheres project to along it (the
    // points whose ray along `normal` can reach a target). The density is per unit area.
    // Returns false when the discs' total area is at least `max_area`; targets behind the
    // plane are skipped.
    bool sample_plane_point(const Vec3& origin, const Vec3& normal, double u0, double u1, double u2,
                            double max_area, Vec3& point, double& pdf) const;

    // The sum of the targets' solid angles seen from `from`, and of the areas of their discs
    // on the plane through `origin` perpendicular to `normal` (targets behind it skipped).
    double solid_angle(const Vec3& from) const;
    double plane_area(const Vec3& origin, const Vec3& normal) const;

private:
    std::vector<BoundingSphere> m_spheres;
};

}  // namespace lenslab
