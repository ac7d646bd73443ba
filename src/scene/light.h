#pragma once
// Light sources other than emitting objects. `power` is the radiant flux; the spectrum's
// shape comes from `color` (D65 white for [1, 1, 1]) or from a named spectrum (blackbody,
// D65, laser line), normalised to the radiant power of D65 white, so a spectrum changes the
// colour and not the energy.

#include <vector>

#include "math/vec3.h"
#include "optics/rgb.h"
#include "optics/spectrum.h"
#include "scene/light_source.h"

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
// color * power / (pi radius^2). Two shapes teachers use (make_beam_light picks the source):
//   - a slit: the disc masked by a strip `slit_width` wide whose long side is `slit_axis`;
//     `power` is what leaves the slit, spread evenly over disc and strip
//     (area 2 [h sqrt(r^2 - h^2) + r^2 asin(h / r)], h = slit_width / 2);
//   - a line laser's fan: a sheet 2 radius thick spreading `fan_angle` (full, degrees)
//     along `fan_axis` from the aperture, uniformly in angle (fan_light_source.cpp).
struct BeamLight {
    Vec3 origin;
    Vec3 direction;  // unit
    double radius = 0;
    Rgb color{1, 1, 1};
    double power = 0;
    SpectrumPtr spectrum;   // as for PointLight
    double slit_width = 0;  // 0: no slit; at most 2 radius
    Vec3 slit_axis;         // unit, across the beam (the reader sets it)
    double fan_angle = 0;   // degrees, [0, 180); 0: a plain beam
    Vec3 fan_axis;          // unit, across the beam (the reader sets it)
};

// The automatic axes of a beam along the unit `direction`: a slit stands upright (world +y
// made square to the direction) and a fan spreads horizontally (square to the direction and
// to +y); for a vertical beam, where +y is the direction, -z stands in for +y (as a flat
// shape's default up does), so the slit runs along -z and the fan along x.
inline Vec3 beam_vertical(const Vec3& direction) {
    const Vec3 y{0, 1, 0};
    return length(cross(y, direction)) > 1e-6 ? y : Vec3{0, 0, -1};
}
inline Vec3 default_slit_axis(const Vec3& direction) {
    const Vec3 up = beam_vertical(direction);
    return normalize(up - direction * dot(up, direction));
}
inline Vec3 default_fan_axis(const Vec3& direction) {
    return normalize(cross(beam_vertical(direction), direction));
}

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
    // Lights with an area (rectangle_light.cpp, disc_light.cpp), built by their readers.
    std::vector<LightPtr> areas;
};

}  // namespace lenslab
