#pragma once
// The diffraction figures of a lens on its axis in one call, for `lenslab analyze --psf` and
// `--mtf`: the real-ray wavefront (pupil_from_rays.h) at the chosen focus, its PSF, Strehl
// ratio and MTF cuts beside the diffraction limit (diffraction.h).

#include <vector>

#include "analysis/diffraction/diffraction.h"
#include "analysis/diffraction/pupil_from_rays.h"

namespace lenslab {

enum class DiffractionFocus {
    Paraxial,  // the reference sphere centred at the paraxial focus
    Best,      // at the least-RMS wavefront focus (RayWavefront::best_focus_z)
};

struct DiffractionFigures {
    double wavelength_nm = 0;
    double f_number = 0;         // paraxial, EFL/EPD
    double aperture_radius = 0;  // the entrance beam's radius
    double image_z = 0;          // the reference sphere's centre, system z
    double wavefront_rms = 0;    // waves, piston removed
    double strehl = 0;           // the PSF's peak against the aberration-free one
    double airy_radius = 0;      // the first dark ring of the aberration-free pupil, 1.22 λN
    double encircled_energy_at_airy_radius = 0;  // 0.838 for a perfect lens
    Psf psf;
    MtfCurves mtf;  // tangential, sagittal and the diffraction limit at `frequencies`
};

// `frequencies` in cycles per unit length (cycles/mm for prescriptions); empty: the 10 of
// default_mtf_frequencies up to the cutoff. Throws what RayWavefront and compute_psf throw.
DiffractionFigures diffraction_figures(const OpticalSystem& system, const RayPupilOptions& options,
                                       const std::vector<double>& frequencies,
                                       DiffractionFocus focus = DiffractionFocus::Best);

// `count` frequencies evenly spaced up to the cutoff 1/(λN), the cutoff included (MTF 0):
// the default abscissae of an MTF table.
std::vector<double> default_mtf_frequencies(double cutoff, int count = 10);

}  // namespace lenslab
