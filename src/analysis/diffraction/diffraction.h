#pragma once
// Scalar Fraunhofer diffraction of a sampled pupil (pupil_function.h): the point spread
// function by FFT, the Strehl ratio, the optical transfer function and its MTF cuts, and the
// encircled energy (Goodman, Introduction to Fourier Optics, 3rd ed., sections 4.2-4.4 and
// 6.3-6.4; Born & Wolf, Principles of Optics, 7th ed., sections 8.5 and 9.1).
//
// Conventions: the field at the reference sphere is A·exp(+i 2π W) with W the optical path
// of the ray minus that of the axial ray (pupil_from_rays.h), so a wavefront tilt
// W = t·x (x normalised) moves the PSF to image x = +2·t·λF: toward the side whose rays
// travel the longer path. Image coordinates are the system's (x, y), centred on the
// reference point (the reference sphere's centre).

#include <complex>
#include <vector>

#include "analysis/diffraction/pupil_function.h"

namespace lenslab {

// Intensity on a size × size grid in the image plane, centred on the reference point.
// Normalised so the aberration-free pupil of the same amplitude peaks at 1: the peak of an
// aberrated PSF is then its Strehl ratio.
struct Psf {
    int size = 0;
    double spacing = 0;             // image-space distance between samples (λ·F/padding)
    double cutoff = 0;              // the pupil's incoherent cutoff frequency 1/(λF)
    std::vector<double> intensity;  // row-major (row i: y, column j: x)
    double strehl = 0;              // the largest sample

    double at(int i, int j) const { return intensity[static_cast<size_t>(i) * size + j]; }
    // Image coordinate of column (or row) j: sample size/2 is the reference point.
    double coordinate(int j) const { return (j - size / 2) * spacing; }
};

// Throws std::invalid_argument when no light passes the pupil.
Psf compute_psf(const PupilFunction& pupil);

// Intensity at the reference point relative to the aberration-free pupil's peak,
// |Σ A·exp(i2πW)|² / (Σ A)²: the Strehl ratio when the PSF peaks at the reference point (on
// the axis, at best focus). Needs no FFT.
double strehl_at_reference(const PupilFunction& pupil);

// The optical transfer function, the Fourier transform of the PSF normalised to 1 at zero
// frequency, on a size × size grid of spatial frequencies centred on zero (index size/2).
struct OpticalTransfer {
    int size = 0;
    double spacing = 0;  // cycles per unit length between samples: cutoff / samples
    double cutoff = 0;   // 1/(λF)
    // Σ PSF samples / size²: turns sums over the OTF back into PSF values (radial_profile).
    double intensity_scale = 0;
    std::vector<std::complex<double>> values;

    const std::complex<double>& at(int i, int j) const {
        return values[static_cast<size_t>(i) * size + j];
    }
    // |OTF| at frequency (fx, fy), bilinearly interpolated; 0 beyond the grid.
    double modulation(double fx, double fy) const;
    // The OTF itself there, its complex values bilinearly interpolated; 0 beyond the grid.
    std::complex<double> value(double fx, double fy) const;
};

OpticalTransfer compute_otf(const Psf& psf);

// MTF cuts at the requested frequencies (cycles per unit length).
// Tangential: the frequency along y, the meridional direction (bars parallel to x);
// sagittal: along x. On the axis of a rotationally symmetric system the two agree.
struct MtfCurves {
    std::vector<double> frequencies;
    std::vector<double> tangential;
    std::vector<double> sagittal;
    std::vector<double> diffraction_limit;  // the aberration-free circular pupil
};

MtfCurves mtf_curves(const OpticalTransfer& otf, const std::vector<double>& frequencies);

// MTF of an aberration-free, uniformly filled circular pupil (Goodman, section 6.3.3):
// 2/π (φ - cos φ sin φ), φ = arccos(ν/ν_c), 0 at and beyond the cutoff ν_c = 1/(λF).
double diffraction_limited_mtf(double frequency, double cutoff);

// Fraction of the PSF's energy within each radius of the reference point. Computed from the
// OTF (Parseval): E(r) = ∫ OTF(ν) r J1(2π r ν)/ν d²ν, which is exact for the band-limited
// PSF instead of counting whole samples inside the circle.
std::vector<double> encircled_energy(const OpticalTransfer& otf, const std::vector<double>& radii);

// The PSF averaged around circles about the reference point, at any radius: the
// band-limited PSF's exact interpolation, Σ OTF(ν) J0(2π r ν) (the Hankel transform), in the
// PSF's units. For the Airy pattern it is [2 J1(v)/v]², v = π r/(λF).
std::vector<double> radial_profile(const OpticalTransfer& otf, const std::vector<double>& radii);

}  // namespace lenslab
