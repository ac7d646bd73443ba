#pragma once
// What the area lights share (rectangle_light.cpp, disc_light.cpp): a flat patch of area A
// that lights the side its normal faces as a Lambertian emitter, radiance L = Phi / (pi A)
// from every point (so it sends its `power` Phi in all), as pbrt-v4's diffuse area light.
// Soft shadows come from shadow rays to points of the patch; photons leave from a point
// drawn uniformly on it, cosine-distributed (or aimed at the photon targets, like an emitting
// sphere's). The patch is not itself seen by the camera or in mirrors, as POV-Ray's
// area_light: like the other lights of `lights`, it is a light, not an object.

#include <array>

#include "geometry/plane_frame.h"
#include "scene/light_source.h"

namespace lenslab {

class AreaLightSource : public Light {
public:
    // `flux`: the spectral radiant flux (W per nm); `half_size`: the patch's half extents
    // along the frame's u and v (its box).
    // The patch's area cancels from every estimate (L = Phi / (pi A), a point drawn with
    // density 1 / A), so it is not kept.
    AreaLightSource(SpectrumPtr flux, const PlaneFrame& frame, std::array<double, 2> half_size)
        : Light(std::move(flux)), m_frame(frame), m_half_size(half_size) {}

    double power() const override { return spectrum_watts(); }
    PhotonStart sample_le(Rng& rng) const override;
    PhotonStart sample_le_towards(const PhotonTargets& targets, const AimSample& u) const override;
    bool worth_aiming(const PhotonTargets& targets) const override;
    // A point of the patch drawn uniformly by area: E = L cos cos' A / d^2 over the pdf.
    bool sample_li(const Vec3& p, Rng& rng, LightSample& out) const override;
    bool is_delta() const override { return false; }
    Aabb bounds() const override;
    // Equiangular towards the centre, as an emitting sphere's.
    bool samples_in_scattering() const override { return true; }
    bool sample_in_scattering(const Ray& ray, double t_max, double u, double& t,
                              double& pdf) const override;

protected:
    // A point of the patch, as (u, v) in the frame, uniform by area from two uniform numbers.
    virtual std::array<double, 2> sample_uv(double u1, double u2) const = 0;

private:
    Vec3 sample_point(double u1, double u2) const;

    PlaneFrame m_frame;
    std::array<double, 2> m_half_size;
};

}  // namespace lenslab
