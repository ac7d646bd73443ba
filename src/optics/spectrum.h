#pragma once
// Spectral light transport, never RGB (colour is an output, not a transport unit): radiometric
// quantities are sampled at four wavelengths per camera sample (hero-wavelength sampling, Wilkie et
// al. 2014, as pbrt-v4 does), spectra are functions of wavelength, and colour comes out through the
// CIE 1931 colour matching functions, XYZ and linear sRGB (IEC 61966-2-1).

#include <array>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "math/vec3.h"
#include "optics/rgb.h"

namespace lenslab {

// The visible range transported; the CIE 1931 tables span exactly this.
inline constexpr double kLambdaMinNm = 360.0;
inline constexpr double kLambdaMaxNm = 830.0;
inline constexpr int kWavelengthSamples = 4;

struct SampledWavelengths {
    std::array<double, kWavelengthSamples> nm{};

    // Hero wavelength uniform in the visible range, the others spread evenly after it
    // (wrapping around): stratified, each marginally uniform.
    static SampledWavelengths sample(double u);
    // All four at one wavelength (monochromatic tracing).
    static SampledWavelengths single(double nm);
    static constexpr double pdf() { return 1.0 / (kLambdaMaxNm - kLambdaMinNm); }
};

struct SampledSpectrum {
    std::array<double, kWavelengthSamples> v{};

    static SampledSpectrum constant(double c) { return {{c, c, c, c}}; }
    SampledSpectrum& operator+=(const SampledSpectrum& o) {
        for (int i = 0; i < kWavelengthSamples; ++i) v[i] += o.v[i];
        return *this;
    }
    SampledSpectrum& operator*=(const SampledSpectrum& o) {
        for (int i = 0; i < kWavelengthSamples; ++i) v[i] *= o.v[i];
        return *this;
    }
    SampledSpectrum& operator*=(double s) {
        for (double& x : v) x *= s;
        return *this;
    }
    bool is_black() const { return v[0] == 0 && v[1] == 0 && v[2] == 0 && v[3] == 0; }
    // After a dispersive refraction only the hero wavelength follows the refracted ray: it
    // carries all four samples' weight (pbrt-v4's TerminateSecondary).
    SampledSpectrum hero_only() const { return {{v[0] * kWavelengthSamples, 0.0, 0.0, 0.0}}; }
};

inline SampledSpectrum operator+(SampledSpectrum a, const SampledSpectrum& b) { return a += b; }
inline SampledSpectrum operator*(SampledSpectrum a, const SampledSpectrum& b) { return a *= b; }
inline SampledSpectrum operator*(SampledSpectrum a, double s) { return a *= s; }

// CIE 1931 colour matching functions at `nm` (linear interpolation of the 5 nm table).
Vec3 cie_xyz_bar(double nm);
// Integral of y-bar over the table, which normalises Y.
double cie_y_integral();
Rgb xyz_to_linear_srgb(const Vec3& xyz);

// Linear sRGB of a spectrum sampled at `w` (uniform pdf): the Monte Carlo estimate of
// (1 / int ybar) int S(l) cmf(l) dl, through XYZ.
Rgb to_rgb(const SampledSpectrum& s, const SampledWavelengths& w);
// Linear sRGB of a whole spectrum (summed over the 5 nm CIE grid).
Rgb spectrum_to_rgb(const class Spectrum& s);
// Its XYZ, unnormalised: the integrals of the spectrum times each colour matching function.
Vec3 spectrum_xyz(const class Spectrum& s);
// Linear sRGB of a single wavelength sample of value `value` drawn with density `pdf`.
Rgb sample_to_rgb(double value, double nm, double pdf);
// Linear sRGB of a wavelength sample given as the XYZ it adds, cie_xyz_bar(nm) * value / pdf
// or any weighting of it (render/dispersion_split.h).
Rgb xyz_sample_to_rgb(const Vec3& xyz);
// Radiant power of a spectrum over the visible range (W for a light's flux spectrum): the
// same integral spectrum_to_rgb takes, so one wavelength carrying it (sample_to_rgb with
// pdf 1) has, on average, the spectrum's colour.
double radiant_power(const class Spectrum& s);

// The three bands RGB colours become spectra over (see reflectance_from_rgb): 0 red
// (>= 585 nm), 1 green, 2 blue (< 490 nm).
int band_of(double nm);
// A value per band: a band-constant spectrum (an albedo), or a product of them.
using BandWeights = std::array<double, 3>;

// Linear sRGB of a spectrum cut into the three bands: spectrum_to_rgb's integral taken over
// each band alone, so the three sum to the spectrum's colour. A band-constant factor a (an
// albedo, a product of albedos) scales each band, so the colour of a S is exactly
// sum_b a_b band_b(S): no wavelength sampling, hence no colour noise.
struct BandColour {
    std::array<Rgb, 3> band{};

    Rgb total() const { return band[0] + band[1] + band[2]; }
    // The colour of `a` times this spectrum.
    Rgb through(const BandWeights& a) const {
        return band[0] * a[0] + band[1] * a[1] + band[2] * a[2];
    }
    BandColour& operator+=(const BandColour& o) {
        for (int b = 0; b < 3; ++b) band[b] += o.band[b];
        return *this;
    }
    BandColour& operator*=(double s) {
        for (Rgb& c : band) c *= s;
        return *this;
    }
};

inline BandColour operator*(BandColour c, double s) { return c *= s; }

// A spectral distribution: reflectances, illuminants, blackbodies, laser lines.
class Spectrum {
public:
    virtual ~Spectrum() = default;
    virtual double eval(double nm) const = 0;
    SampledSpectrum sample(const SampledWavelengths& w) const;
    // Draws a wavelength in the visible range with density proportional to a 1 nm
    // histogram of the spectrum (for photons), so a narrow laser line gets every photon;
    // returns the density (per nm).
    double sample_wavelength(double u, double& nm) const;
    // The spectrum's band colours, computed on first use.
    const BandColour& band_colour() const;

private:
    mutable std::once_flag m_cdf_once;
    mutable std::vector<double> m_cdf;  // built on first use
    mutable std::once_flag m_band_once;
    mutable BandColour m_band_colour;
};

using SpectrumPtr = std::shared_ptr<const Spectrum>;

// RGB colours as spectra. Both are piecewise constant over three bands (blue < 490 nm <=
// green < 585 nm <= red), with band weights solved so that the spectrum, lit by (or being)
// D65, renders back to the same linear sRGB colour: greys and white are exact, saturated
// colours are clamped to what three bands can make. A reflectance stays within [0, 1].
SpectrumPtr reflectance_from_rgb(const Rgb& rgb);
// The band weights of reflectance_from_rgb(rgb).
BandWeights reflectance_bands(const Rgb& rgb);
// The same for a quantity with no upper bound (an absorption or scattering coefficient):
// band weights that render back to `rgb`, each >= 0.
BandWeights coefficient_bands(const Rgb& rgb);
// An illuminant: D65 times the bands; renders to `rgb` (so [1, 1, 1] is D65 white, Y = 1).
SpectrumPtr illuminant_from_rgb(const Rgb& rgb);
SampledSpectrum illuminant_from_rgb(const Rgb& rgb, const SampledWavelengths& w);
// The band colours of illuminant_from_rgb(rgb), without building the spectrum (photon-map
// estimates are colours, turned into such illuminants at every pixel).
BandColour illuminant_band_colour(const Rgb& rgb);
// Light spectra are `power` times a shape whose integral over the visible range is that of
// D65 white (scaled to Y = 1); this converts such spectral power back to watts: the watts
// between lo_nm and hi_nm of spectral power `s` (radiant_power(s) / D65's, over the whole
// visible range).
double radiant_watts(const Spectrum& s, double lo_nm = kLambdaMinNm, double hi_nm = kLambdaMaxNm);

// Light spectra normalised to the radiant power of D65 white over the visible range, so a
// light's `power` means the same energy whatever its spectrum.
SpectrumPtr d65_spectrum();
// A blackbody's temperatures the scene accepts: from a candle's glow to a hot star's blue.
inline constexpr double kBlackbodyMinK = 500, kBlackbodyMaxK = 100000;
// Why `kelvin` is no blackbody temperature the scene accepts ("must be between 500 and
// 100000 K"), or nothing; every reader says it the same way.
std::optional<std::string> blackbody_problem(double kelvin);
// Why `nm` is no wavelength the renderer transports ("outside 360 to 830 nm, the range of the
// CIE tables"), or nothing.
std::optional<std::string> wavelength_problem(double nm);
SpectrumPtr blackbody_spectrum(double kelvin);
SpectrumPtr line_spectrum(double nm, double width_nm = 1.0);
SpectrumPtr illuminant_a_spectrum();
SpectrumPtr equal_energy_spectrum();

// The light spectra a scene may name (`"spectrum": "illuminant_a"`), in the order messages
// list them.
struct NamedSpectrum {
    std::string name, description;
    SpectrumPtr (*make)();
};
const std::vector<NamedSpectrum>& named_spectra();

}  // namespace lenslab
