#pragma once
// The wavefront of a real lens on its axis, from exact rays (real_ray.h): a collimated beam
// sampled on the pupil grid (pupil_function.h) across the entrance aperture, each ray's
// optical path measured from a plane wavefront in front of the system, through every medium
// (indices from OpticalSystem::n_before/n_after), to a reference sphere centred on the axis
// at the image point and crossing the axis at the exit-pupil position. The wavefront
// aberration is W = OPL(ray) − OPL(axial ray), in waves: negative at the rim for the
// undercorrected spherical aberration of a positive singlet referred to its paraxial focus
// (the opposite sign to Welford's W, which is positive when the wavefront leads the sphere).
//
// Rays that miss a surface or are totally reflected get amplitude 0 (vignetting). The grid
// is uniform over the entrance pupil; it is taken as uniform over the exit sphere, which
// holds for a system obeying the sine condition, and the image scale uses the paraxial
// F-number EFL/EPD (image space in air).

#include <optional>
#include <vector>

#include "analysis/diffraction/pupil_function.h"
#include "analysis/system/optical_system.h"
#include "math/vec3.h"

namespace lenslab {

struct RayPupilOptions {
    double wavelength_nm = 587.56;
    double aperture_radius = 0;  // entrance beam radius; 0: the usable aperture (aberrations.h)
    PupilSampling sampling;
    std::optional<double> pupil_z;    // where the reference sphere meets the axis; default: the
                                      // last vertex
    double nm_per_length_unit = 1e6;  // the system's length unit in nm (1e6: millimetres)
};

// The beam is traced once; its wavefront can then be referred to spheres centred anywhere
// on the axis (through focus) at the cost of one sphere intersection per ray.
class RayWavefront {
public:
    // Throws SceneError for an afocal system (paraxial.h), std::invalid_argument for bad
    // sampling or when no ray passes.
    RayWavefront(const OpticalSystem& system, const RayPupilOptions& options);

    double aperture_radius() const { return aperture_radius_; }
    double paraxial_focus_z() const { return paraxial_focus_z_; }
    double f_number() const { return f_number_; }
    double wavelength() const { return wavelength_; }  // in the system's length unit

    // The pupil function against the sphere centred at (0, 0, image_z).
    PupilFunction pupil(double image_z) const;
    // RMS wavefront (piston removed) against that sphere, in waves.
    double rms_waves(double image_z) const;
    // The image_z of least RMS wavefront (the best focus of the Maréchal criterion), found by
    // golden-section search over the span of the rays' axis crossings.
    double best_focus_z() const;

private:
    struct TracedRay {
        size_t cell;  // index into the pupil grid
        Vec3 point, direction;
        double path;  // optical path from the entrance plane to `point`
    };
    // OPL from the entrance plane to the sphere; nullopt when the ray misses it.
    std::optional<double> path_to_sphere(const TracedRay& ray, double image_z) const;
    std::vector<double> opd_samples(double image_z, std::vector<size_t>* cells) const;

    PupilSampling sampling_;
    double aperture_radius_ = 0, paraxial_focus_z_ = 0, f_number_ = 0, wavelength_ = 0;
    double pupil_z_ = 0, image_index_ = 1;
    double focus_span_ = 0;  // how far from the paraxial focus the rays cross the axis
    TracedRay axial_;
    std::vector<TracedRay> rays_;
};

}  // namespace lenslab
