#pragma once
// What every kind of light offers the tracers (pbrt-v4's Light interface, in lenslab's
// terms): its power, photons of its emission (all of it, or only the part aimed at the
// photon targets), and the light it sends to a point, for shadow rays. Photon tracing,
// progressive photon mapping, detectors and direct lighting see lights only through this.
//
// Spectra: `spectrum()` is the light's spectral flux for point lights and beams (W per nm)
// and its spectral radiance for emitting spheres; a photon carries `scale` times it, and a
// light sample's irradiance is `factor` times it.

#include <array>
#include <memory>
#include <vector>

#include "geometry/shape.h"
#include "math/aabb.h"
#include "math/ray.h"
#include "math/rng.h"
#include "optics/spectrum.h"
#include "scene/photon_targets.h"

namespace lenslab {

// The numbers an aimed photon is drawn from.
using AimSample = std::array<double, 5>;

struct PhotonStart {
    Ray ray;
    const Spectrum* spectrum = nullptr;  // the light's spectrum(), before `scale`
    // The share of it this photon carries when it is the only one sent (divide by the
    // number sent); 0 when the sample fell where the light does not emit (the photon still
    // counts as sent, so the estimate stays unbiased).
    double scale = 0;
};

struct LightSample {
    Vec3 wi;              // unit, from the lit point towards the light
    double distance = 0;  // to the light along wi: the shadow ray's length
    // Irradiance on a surface facing wi, per unit of spectrum(), divided by the sample's
    // probability: multiply by the cosine at the surface and the spectrum.
    double factor = 0;
};

class Light {
public:
    explicit Light(SpectrumPtr spectrum)
        : m_spectrum(std::move(spectrum)), m_spectrum_watts(radiant_watts(*m_spectrum)) {}
    virtual ~Light() = default;

    const Spectrum& spectrum() const { return *m_spectrum; }
    // Radiant flux over the visible range, W.
    virtual double power() const = 0;
    // A photon of the whole emission.
    virtual PhotonStart sample_le(Rng& rng) const = 0;
    // A photon of the part of the emission that can reach `targets` first (photon_targets.h);
    // the light's own sampling where aiming would not be denser. `u`: uniform numbers in
    // [0, 1) (a point of a stratified sequence: math/halton.h).
    virtual PhotonStart sample_le_towards(const PhotonTargets& targets,
                                          const AimSample& u) const = 0;
    // Whether aiming at `targets` is denser than the light's own sampling, so that an aimed
    // stream is worth sending (photon_emission.h); false when the targets fill its emission.
    virtual bool worth_aiming(const PhotonTargets& targets) const = 0;
    // Light reaching `p`, with no shadow ray traced; false when none can.
    virtual bool sample_li(const Vec3& p, Rng& rng, LightSample& out) const = 0;
    // One sample of sample_li is exact (a point or a beam), not an estimate.
    virtual bool is_delta() const = 0;
    // Where the light sits (a point light's point, a beam's origin, an area light's patch):
    // the box a scene's media and sppm's volume photons fill holds it.
    virtual Aabb bounds() const = 0;
    // Whether media gather this light's single scattering along whole ray segments
    // (sample_in_scattering) rather than at scattering points: every delta light, and
    // emitting spheres.
    virtual bool samples_in_scattering() const { return is_delta(); }
    // A distance along `ray` (unit direction), in [0, t_max), where light of this light
    // scattered by a medium into the ray is worth gathering, and its density per unit length
    // (`u` uniform in [0, 1)). False when none can be (the ray misses a beam). Points, spots
    // and emitting spheres: equiangular sampling towards the point or the sphere's centre
    // (Kulla and Fajardo 2012), density proportional to 1 / distance^2; beams: uniform along
    // the chord the ray cuts through the beam.
    virtual bool sample_in_scattering(const Ray& ray, double t_max, double u, double& t,
                                      double& pdf) const {
        (void)ray, (void)t_max, (void)u, (void)t, (void)pdf;
        return false;
    }

protected:
    // radiant_watts(spectrum()), integrated once: photon plans and the light sampler ask for
    // the power of every light each time they are built (each sppm pass).
    double spectrum_watts() const { return m_spectrum_watts; }

private:
    SpectrumPtr m_spectrum;
    double m_spectrum_watts;
};

// A light sending everything from one point (point and spot lights): its light falls off as
// 1 / r^2, photons are aimed from the point, and in a medium its in-scattering is sampled
// equiangularly. A kind gives its intensity, its own direction sampling and the solid angle
// it fills.
class PointSourceLight : public Light {
public:
    PointSourceLight(SpectrumPtr spectrum, const Vec3& position)
        : Light(std::move(spectrum)), m_position(position) {}

    double power() const override { return spectrum_watts(); }
    PhotonStart sample_le(Rng& rng) const override;
    PhotonStart sample_le_towards(const PhotonTargets& targets, const AimSample& u) const override;
    bool worth_aiming(const PhotonTargets& targets) const override;
    bool sample_li(const Vec3& p, Rng& rng, LightSample& out) const override;
    bool is_delta() const override { return true; }
    Aabb bounds() const override { return {m_position, m_position}; }
    bool sample_in_scattering(const Ray& ray, double t_max, double u, double& t,
                              double& pdf) const override;

protected:
    const Vec3& position() const { return m_position; }
    // Radiant intensity towards the unit `dir`, per unit of spectrum().
    virtual double intensity(const Vec3& dir) const = 0;
    // A direction of the light's own sampling from two uniform numbers, with its density.
    virtual Vec3 sample_direction(double u1, double u2, double& pdf) const = 0;
    // The solid angle its light fills: aiming pays where the targets subtend less.
    virtual double emission_solid_angle() const = 0;

private:
    PhotonStart photon_towards(const Vec3& dir, double pdf) const {
        return {{m_position, dir}, &spectrum(), intensity(dir) / pdf};
    }

    Vec3 m_position;
};

using LightPtr = std::shared_ptr<const Light>;

struct PointLight;
struct BeamLight;
struct SpotLight;
LightPtr make_point_light(const PointLight& l);
// A beam, with or without a slit (beam_light_source.cpp), or a line laser's fan.
LightPtr make_beam_light(const BeamLight& b);
LightPtr make_fan_light(const BeamLight& b);   // fan_light_source.cpp
LightPtr make_spot_light(const SpotLight& s);  // spot_light_source.cpp
// Equiangular sampling of a distance along `ray` within [0, t_max) towards the point `light`
// (Kulla and Fajardo 2012, "Importance sampling techniques for path tracing in participating
// media"): density D / ((theta_b - theta_a) (D^2 + (t - delta)^2)), D the ray's distance from
// the light and delta where it passes closest. False when the ray runs through the light.
bool sample_equiangular(const Ray& ray, double t_max, const Vec3& light, double u, double& t,
                        double& pdf);
// A Lambertian sphere of spectral radiance `radiance`: `shape`, which is the sphere `sphere`.
LightPtr make_sphere_light(std::shared_ptr<const Shape> shape, BoundingSphere sphere,
                           SpectrumPtr radiance);

}  // namespace lenslab
