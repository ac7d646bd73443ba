#pragma once
// The report's "graphic parameters" of a surface.
//
// | key          | meaning                                                    | default        |
// | color        | diffuse albedo (RGB, each in [0, 1])                       | [0.8,0.8,0.8]  |
// | transparency | fraction of light meeting the dielectric interface, kt     | 0              |
// | specular     | fraction reflected by a perfect mirror, ks                 | 0              |
// | ior          | absolute refractive index of the interior                  | 1.5            |
// | emission     | {color, intensity}: emitted radiance = color * intensity   | none           |
// The rest, 1 - transparency - specular, is diffuse (Lambertian) with albedo `color`.

#include <string>

#include "optics/rgb.h"

namespace lenslab {

struct Material {
    std::string name;
    Rgb color{0.8, 0.8, 0.8};
    double transparency = 0.0;
    double specular = 0.0;
    double ior = 1.5;
    Rgb emission_color{1.0, 1.0, 1.0};
    double emission_intensity = 0.0;  // radiance scale, W m^-2 sr^-1

    double diffuse_weight() const { return std::max(0.0, 1.0 - transparency - specular); }
    Rgb emitted_radiance() const { return emission_color * emission_intensity; }
    bool is_emitter() const {
        return emission_intensity > 0.0 && !emission_color.is_black();
    }
};

}  // namespace lenslab
