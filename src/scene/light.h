#pragma once
// Light sources other than emitting objects. Powers are radiant fluxes in watts per RGB
// channel: the emitted power is color * power.

#include "math/vec3.h"
#include "optics/rgb.h"

namespace lenslab {

// Isotropic point source: radiant intensity I = color * power / (4 pi) in every direction.
struct PointLight {
    Vec3 position;
    Rgb color{1, 1, 1};
    double power = 0;
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
};

}  // namespace lenslab
