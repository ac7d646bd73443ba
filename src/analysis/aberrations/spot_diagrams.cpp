#include "analysis/aberrations/spot_diagrams.h"

#include <cmath>

#include "analysis/system/field_beam.h"
#include "analysis/system/real_ray.h"

namespace lenslab {

int hexapolar_ray_count(int rings) { return 1 + 3 * rings * (rings + 1); }

double airy_radius_mm(double wavelength_nm, double f_number) {
    return 1.22 * wavelength_nm * 1e-6 * f_number;
}

SpotDiagrams spot_diagrams(const OpticalSystem& system, const FirstOrder& first_order,
                           const SpotOptions& options) {
    SpotDiagrams d;
    d.image_z = options.image_z.value_or(system.last_vertex() + first_order.image_position);
    d.rings = options.rings;
    d.rays_per_beam = hexapolar_ray_count(options.rings);
    d.primary_nm = first_order.wavelength_nm;
    d.working_f_number = first_order.working_f_number;
    d.wavelengths = options.wavelengths.empty() ? std::vector<double>{first_order.wavelength_nm}
                                                : options.wavelengths;
    d.weights =
        options.weights.empty() ? std::vector<double>(d.wavelengths.size(), 1.0) : options.weights;
    for (double field : options.fields) {
        FieldSpots f;
        f.field = field;
        f.airy_radius = airy_radius_mm(d.primary_nm, d.working_f_number);
        // Each wavelength's beam traced once, for its own spot and for the field's
        // polychromatic one.
        std::vector<FieldBeam> beams;
        for (double nm : d.wavelengths) {
            const FieldBeam& beam =
                beams.emplace_back(trace_field_beam(system, first_order, field, nm, d.rings));
            WavelengthSpot s;
            s.field = field;
            s.wavelength_nm = nm;
            s.spot = spot_at(beam.rays, d.image_z);
            if (beam.rays.empty()) s.spot.rms_radius = s.spot.geometric_radius = NAN;
            if (beam.chief) s.chief = at_plane(beam.chief->point, beam.chief->direction, d.image_z);
            s.rays = static_cast<int>(beam.rays.size()) + beam.lost;
            s.vignetted = beam.lost;
            s.airy_radius = airy_radius_mm(nm, d.working_f_number);
            f.spots.push_back(std::move(s));
        }
        f.polychromatic = polychromatic_spot(beams, d.weights, d.image_z);
        d.fields.push_back(std::move(f));
    }
    return d;
}

}  // namespace lenslab
