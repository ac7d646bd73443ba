#pragma once
// The report's "graphic parameters" of a surface, with wavelength-dependent optics.
//
// | key          | meaning                                                    | default        |
// | color        | diffuse albedo (RGB, each in [0, 1])                       | [0.8,0.8,0.8]  |
// | transparency | fraction of light meeting the dielectric interface, kt     | 0              |
// | specular     | fraction reflected by a perfect mirror, ks                 | 0              |
// | ior / glass  | refractive index: a number, a model, or a catalogue glass  | 1.5            |
// | emission     | {color or spectrum, intensity}: emitted radiance           | none           |
// The rest, 1 - transparency - specular, is diffuse (Lambertian) with albedo `color`.

#include <string>

#include "optics/absorption.h"
#include "optics/glass.h"
#include "optics/grin_profile.h"
#include "optics/rgb.h"
#include "optics/spectrum.h"

namespace lenslab {

struct Material {
    std::string name;
    Rgb color{0.8, 0.8, 0.8};
    double transparency = 0.0;
    double specular = 0.0;
    IndexModelPtr index = constant_index(1.5);
    std::string glass;  // catalogue name when the index came from the catalogue
    // Beer-Lambert attenuation of light inside, when the glass has k data; null (and free)
    // otherwise. Set by the scene reader, which knows the scene's length unit.
    AbsorptionPtr absorption;
    // A gradient index inside the solid, or null. Its index replaces `index` everywhere inside;
    // `index` then only scales it with wavelength: n = profile x index(lambda) / index(d).
    std::shared_ptr<const GrinProfile> grin;
    Rgb emission_color{1.0, 1.0, 1.0};
    double emission_intensity = 0.0;  // radiance scale, W m^-2 sr^-1
    SpectrumPtr emission_spectrum;  // set when the emission gives a spectrum, else from the colour
    // The edge of a medium and nothing else (a shape with a `medium` and no `material`): no
    // surface, the index matched on both sides, so light passes straight through.
    bool surfaceless = false;

    // Spectra derived from the colours; `finish()` builds them after the fields are set.
    SpectrumPtr albedo;
    BandWeights albedo_bands{};  // albedo's value in each band (it is band-constant)
    SpectrumPtr emission;        // emitted radiance spectrum (intensity included)
    void finish();

    double diffuse_weight() const { return std::max(0.0, 1.0 - transparency - specular); }
    double ior(double nm) const { return index->n(nm); }
    // The GRIN profile's dispersion factor index(lambda) / index(d).
    double grin_scale(double nm) const { return index->n(nm) / index->n(kLineD); }
    bool is_emitter() const {
        return emission_intensity > 0.0 && emission && !emission_color.is_black();
    }
};

// `s` times a constant.
SpectrumPtr scaled_spectrum(SpectrumPtr s, double scale);

}  // namespace lenslab
