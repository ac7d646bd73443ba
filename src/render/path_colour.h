#pragma once
// The colour of a camera sample without colour noise (issue 13).
//
// Until a path meets a dispersive refraction, nothing on it depends on the wavelength:
// specular weights are numbers, and every albedo is constant over the three bands RGB colours
// become (reflectance_from_rgb). The light it brings is then a sum of (number) x (product of
// band-constant albedos) x (a light's spectrum), whose colour is exact from the light's band
// colours (Spectrum::band_colour): the path carries the whole spectrum, and a white light on
// a grey floor is grey in every pixel. At a dispersive refraction only the camera sample's
// hero wavelength goes on, and the colour becomes that wavelength's Monte Carlo estimate;
// or, where the render splits paths at dispersive glass (render/dispersion_split.h), each of
// the split's wavelengths goes on in a copy of the path.

#include "optics/spectrum.h"
#include "render/dispersion_split.h"

namespace lenslab {

class LightSum;

// A camera path's throughput and what it still carries: the whole spectrum, or (dispersed)
// the hero wavelength alone. The throughput is a number times band-constant albedos, so
// three numbers, one per band, hold it exactly.
class PathColour {
public:
    // `split`: the wavelengths the path splits into at its first dispersive refraction, or
    // nullptr to follow the hero wavelength alone.
    explicit PathColour(const SampledWavelengths& w, const DispersionSplit* split = nullptr)
        : PathColour(w.nm[0], SampledWavelengths::pdf()) {
        m_split = split;
    }
    // A path that, once dispersed, follows `hero_nm` drawn with density `hero_pdf` (sppm's
    // pass wavelength).
    PathColour(double hero_nm, double hero_pdf)
        : m_hero_nm(hero_nm), m_hero_xyz(cie_xyz_bar(hero_nm) * (1.0 / hero_pdf)) {}

    double hero_nm() const { return m_hero_nm; }
    bool dispersed() const { return m_dispersed; }
    // A dispersive refraction: from here on only the hero wavelength follows the path (a
    // merged path stays whole).
    void disperse() { m_dispersed = !m_merged; }
    // The wavelengths to split into at a dispersive refraction, or nullptr (none given, or
    // already dispersed, or merged).
    const DispersionSplit* split() const { return m_dispersed || m_merged ? nullptr : m_split; }
    // The copy of this path that follows the split's wavelength number `k`.
    PathColour split_to(size_t k) const {
        const SplitWavelength& s = m_split->wavelengths()[k];
        PathColour c = *this;
        c.m_hero_nm = s.nm;
        c.m_hero_xyz = s.xyz_weight;
        c.m_dispersed = true;
        c.m_split_index = static_cast<int>(k);
        return c;
    }
    // The number of wavelengths a split copy's split has; 0 for a path that is none.
    size_t split_count() const { return m_split_index < 0 ? 0 : m_split->wavelengths().size(); }
    // Whether this split copy carries the split's merged branches: the middle wavelength.
    bool carries_merged() const {
        return m_split_index >= 0 && static_cast<size_t>(m_split_index) == middle_of(*m_split);
    }
    // The split's wavelengths joined again on this copy's path: the whole spectrum, as before
    // the split, and it stays whole through later dispersive glass. For branches too weak
    // for the split's dispersion to show (render.merge_weight): the light they bring keeps
    // its amount and its colour, only not its spread over the spectrum.
    PathColour merged() const {
        PathColour c = *this;
        c.m_dispersed = false;
        c.m_merged = true;
        c.m_split_index = -1;
        return c;
    }
    // A path too weak to split where it meets dispersive glass: the split's wavelengths
    // together from the start, as merged() joins them.
    PathColour merged_split() const { return split_to(middle_of(*m_split)).merged(); }

    PathColour& operator*=(double s) {
        for (double& b : m_beta) b *= s;
        return *this;
    }
    PathColour& operator*=(const BandWeights& albedo) {
        for (int b = 0; b < 3; ++b) m_beta[b] *= albedo[b];
        return *this;
    }

    // Linear sRGB that light of spectrum `s` (or a sum of such) met along the path brings
    // to the camera.
    Rgb of(const Spectrum& s) const;
    Rgb of(const LightSum& e) const;

private:
    // The wavelength whose path a merged split follows: the middle one.
    static size_t middle_of(const DispersionSplit& split) { return split.wavelengths().size() / 2; }
    // One wavelength's estimate of the colour, `value` being the light there.
    Rgb hero_colour(double value) const;

    double m_hero_nm;
    Vec3 m_hero_xyz;  // the XYZ a unit of light at the hero wavelength adds to the pixel
    const DispersionSplit* m_split = nullptr;
    bool m_dispersed = false;
    bool m_merged = false;
    int m_split_index = -1;  // which of its split's wavelengths a split copy follows
    BandWeights m_beta{1.0, 1.0, 1.0};
};

// Light arriving at a point (an irradiance, a radiance), a sum of weighted spectra, kept in
// the form the path that found it needs: band colours, or its value at the hero wavelength.
class LightSum {
public:
    explicit LightSum(const PathColour& path)
        : m_hero_nm(path.hero_nm()), m_dispersed(path.dispersed()) {}

    void add(const Spectrum& s, double factor);
    // The same, weighted in each band by `bands` (light attenuated by a coloured medium).
    void add(const Spectrum& s, double factor, const BandWeights& bands);
    // Adds illuminant_from_rgb(rgb): how photon-map estimates, which are colours, are lit.
    void add_illuminant(const Rgb& rgb);
    LightSum& operator*=(double s);

private:
    friend class PathColour;
    double m_hero_nm;
    bool m_dispersed;
    BandColour m_bands;  // when not dispersed
    double m_hero = 0;   // when dispersed
};

}  // namespace lenslab
