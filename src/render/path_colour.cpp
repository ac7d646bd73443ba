#include "render/path_colour.h"

namespace lenslab {

Rgb PathColour::hero_colour(double value) const {
    // The hero wavelength carries the weight of all the sample's wavelengths: its value over
    // the density it was drawn with (uniform: what to_rgb of SampledSpectrum::hero_only gives),
    // or its share of a split.
    return xyz_sample_to_rgb(m_hero_xyz * (m_beta[band_of(m_hero_nm)] * value));
}

Rgb PathColour::of(const Spectrum& s) const {
    return m_dispersed ? hero_colour(s.eval(m_hero_nm)) : s.band_colour().through(m_beta);
}

Rgb PathColour::of(const LightSum& e) const {
    return m_dispersed ? hero_colour(e.m_hero) : e.m_bands.through(m_beta);
}

void LightSum::add(const Spectrum& s, double factor) {
    if (m_dispersed) {
        m_hero += s.eval(m_hero_nm) * factor;
    } else {
        m_bands += s.band_colour() * factor;
    }
}

void LightSum::add(const Spectrum& s, double factor, const BandWeights& bands) {
    if (m_dispersed) {
        m_hero += s.eval(m_hero_nm) * factor * bands[band_of(m_hero_nm)];
    } else {
        BandColour c = s.band_colour();
        for (int b = 0; b < 3; ++b) c.band[b] *= factor * bands[b];
        m_bands += c;
    }
}

void LightSum::add_illuminant(const Rgb& rgb) {
    if (rgb.is_black()) return;
    if (m_dispersed) {
        m_hero += illuminant_from_rgb(rgb, SampledWavelengths::single(m_hero_nm)).v[0];
    } else {
        m_bands += illuminant_band_colour(rgb);
    }
}

LightSum& LightSum::operator*=(double s) {
    m_bands *= s;
    m_hero *= s;
    return *this;
}

}  // namespace lenslab
