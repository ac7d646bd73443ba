#pragma once
// Light sources other than emitting objects. `power` is the radiant flux; the spectrum's
// shape comes from `color` (D65 white for [1, 1, 1]) or from a named spectrum (blackbody,
// D65, laser line), normalised to the radiant power of D65 white, so a spectrum changes the
// colour and not the energy.

#include <vector>

#include "math/vec3.h"
#include "optics/rgb.h"
#include "optics/spectrum.h"

namespace lenslab {

// Isotropic point source: radiant intensity I = color * power / (4 pi) in every direction.
struct PointLight {
    Vec3 position;
    Rgb color{1, 1, 1};
    double power = 0;
    SpectrumPtr spectrum;  // emitted power per nm, shape times power (scene reader sets it)
};

// Collimated beam: parallel rays along `direction` leaving a disc of `radius` centred on
// `origin` and perpendicular to the direction; irradiance across the beam is
// color * power / (pi radius^2).
struct BeamLight {
    Vec3 origin;
    Vec3 direction;  // unit
    double radius = 0;
    Rgb color{1, 1, 1};
    double power = 0;
    SpectrumPtr spectrum;  // as for PointLight
};

// Spot light: a point source whose intensity fills a cone of half-angle `cone_angle` around
// `direction`, full up to `cone_angle - falloff` and fading smoothly (smoothstep in the
// cosine, as pbrt-v4's spot light) to nothing at the cone's edge. `power` is the flux it
// sends into the cone, so a narrower cone is brighter, not dimmer.
struct SpotLight {
    Vec3 position;
    Vec3 direction;          // unit, the cone's axis
    double cone_angle = 30;  // degrees, (0, 90]
    double falloff = 0;      // degrees, [0, cone_angle]
    Rgb color{1, 1, 1};
    double power = 0;
    SpectrumPtr spectrum;  // as for PointLight
};

// The lights without geometry a scene holds (a laser is a beam with a line spectrum).
struct SceneLights {
    std::vector<PointLight> points;
    std::vector<BeamLight> beams;
    std::vector<SpotLight> spots;
};

}  // namespace lenslab
