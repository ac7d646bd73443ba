#pragma once
// The wavefront of a real system at any field point and wavelength: the optical path
// difference (OPD) over the exit pupil from exact rays, as lens-design programs report it.
//
// Rays from the field point are aimed (ray_aiming.h, with the first-order data's aiming)
// through a square grid of normalised stop coordinates (pupil_function.h's layout: sample
// (i, j) at (px, py) = (coordinate(j), coordinate(i)), py meridional). Each ray's optical path
// runs from the object's wavefront (the object point, or for an object at infinity the plane
// through the start of the beam square to the field direction) through every medium to the
// reference sphere. The sphere is centred on the chief ray's crossing of the image plane and
// passes through the chief ray's crossing of the paraxial exit pupil's plane (when the exit
// pupil lies at infinity, through the chief ray's last surface point). The OPD is
// W = OPL(ray) − OPL(chief ray) in waves: the sign of pupil_from_rays.h (negative at the rim
// for a positive singlet's undercorrected spherical aberration at the paraxial focus), so the
// PSF of the pupil (diffraction.h) is centred on the chief ray's image point.
//
// Rays that are vignetted or totally reflected get amplitude 0. The image scale of the PSF
// and MTF uses the paraxial working F-number; the grid is uniform in the stop, which the exit
// pupil follows for a system obeying the sine condition.

#include <optional>
#include <utility>
#include <vector>

#include "analysis/diffraction/pupil_function.h"
#include "analysis/system/first_order.h"
#include "analysis/system/optical_system.h"
#include "analysis/system/ray_aiming.h"
#include "analysis/system/real_ray.h"
#include "math/vec3.h"

namespace lenslab {

struct FieldWavefrontOptions {
    double field = 0;    // y: degrees for an object at infinity, else an object height
    double field_x = 0;  // the same in x
    double wavelength_nm = 587.56;
    PupilSampling sampling{64, 2};
    std::optional<double> image_z;    // the image plane; default: the paraxial image (first order)
    double nm_per_length_unit = 1e6;  // the system's length unit in nm (1e6: millimetres)
};

struct FieldWavefront {
    double field = 0, field_x = 0, wavelength_nm = 0;
    double image_z = 0;
    Vec3 reference;               // the reference sphere's centre (the chief ray's image point)
    double reference_radius = 0;  // the sphere's radius
    PupilFunction pupil;          // amplitude 1 where a ray passed, OPD in waves
    int passed = 0, lost = 0;     // rays inside the unit pupil that passed, and that did not
    double rms_waves = 0;  // RMS about the mean (piston removed), against the chief ray's sphere
    double pv_waves = 0;   // largest minus smallest OPD
    // Where each ray that passed meets the reference sphere, with its pupil grid cell: the
    // secondary sources of a Huygens PSF (huygens_psf.h).
    struct SpherePoint {
        size_t cell;
        Vec3 at;
    };
    std::vector<SpherePoint> sphere_points;
    double image_index = 1;  // the medium after the last surface
    // The largest OPD change between neighbouring samples (in x or y) that both passed: above
    // about half a wave the grid aliases the phase and its FFT figures are unreliable.
    double max_step_waves = 0;
};

// Refers the wavefront to the sphere centred on its PSF's centroid rather than the chief ray's
// image point, to first order: its tilt (remove_tilt) taken out and the reference moved by
// 2 t λN; the RMS, peak-to-valley and steps measured again (Zemax's "reference to centroid").
void refer_to_centroid(FieldWavefront& wavefront);

// The samples across the pupil that bring a wavefront's steps to `step` waves (scaling
// linearly from one measured at `wavefront`'s sampling), even, at least the current ones and
// at most `most`.
int samples_for_step(const FieldWavefront& wavefront, double step, int most);

// The FFT and matrix transforms need the pupil's phase to change by less than half a wave
// between samples: field_wavefront traced again, when its steps exceed kResolvedStepWaves,
// with proportionally more rays across (at most kMostResolvedSamples).
inline constexpr double kResolvedStepWaves = 0.25, kAliasingStepWaves = 0.5;
inline constexpr int kMostResolvedSamples = 512;
FieldWavefront resolved_field_wavefront(const OpticalSystem& system, const FirstOrder& first_order,
                                        FieldWavefrontOptions options);

// A ray as it leaves the last surface, with the optical path it has run so far.
struct PathRay {
    Vec3 point, direction;
    double path = 0;
};

// The OPD of any ray of one field and wavelength against the chief ray's reference sphere (as
// above): what the wavefront's grid and the OPD fans (opd_fans.h) sample. Keeps references
// to the system and first-order data, which must outlive it. Throws as field_wavefront.
class FieldOpd {
public:
    FieldOpd(const OpticalSystem& system, const FirstOrder& first_order,
             const FieldWavefrontOptions& options);

    // The OPD in waves of the ray through stop point (px, py), and where it meets the sphere;
    // none when it is vignetted, totally reflected or cannot be aimed.
    std::optional<double> opd_waves(double px, double py, Vec3* at_sphere = nullptr) const;

    double image_z() const { return image_z_; }
    const Vec3& reference() const { return reference_; }
    double reference_radius() const { return reference_radius_; }
    double image_index() const { return image_index_; }
    double wavelength() const { return wavelength_; }  // in the system's length unit

private:
    std::optional<PathRay> path_of(const RealRay& ray) const;
    std::optional<std::pair<double, Vec3>> path_to_sphere(const PathRay& ray) const;

    const OpticalSystem& system_;
    RayAimer aimer_;
    double nm_ = 0, wavelength_ = 0;
    bool collimated_ = true;
    double image_z_ = 0;
    Vec3 reference_, pupil_point_;
    double reference_radius_ = 0, image_index_ = 1, chief_path_ = 0;
};

// Throws SceneError through a gradient-index lens (its curved rays' optical path is not
// measured) and std::invalid_argument when the chief ray does not pass or misses the
// reference sphere, or the sampling is bad.
FieldWavefront field_wavefront(const OpticalSystem& system, const FirstOrder& first_order,
                               const FieldWavefrontOptions& options);

}  // namespace lenslab
