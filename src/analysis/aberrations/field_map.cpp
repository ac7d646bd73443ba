#include "analysis/aberrations/field_map.h"

#include <cmath>

#include "analysis/system/field_beam.h"

namespace lenslab {

FieldMap field_map(const OpticalSystem& system, const FirstOrder& first_order,
                   const FieldMapOptions& options) {
    FieldMap map;
    map.options = options;
    const int n = options.points;
    for (int k = 0; k < n; ++k) {
        const double f = n == 1 ? 0.0 : options.max_field * (2.0 * k / (n - 1) - 1.0);
        map.fields_x.push_back(f);
        map.fields_y.push_back(f);
    }
    for (double fy : map.fields_y) {
        std::vector<double> row;
        for (double fx : map.fields_x) {
            const FieldBeam beam =
                trace_field_beam(system, first_order, fy, options.wavelength_nm, options.rings, fx);
            row.push_back(beam.rays.empty() ? NAN : spot_at(beam.rays, options.image_z).rms_radius);
        }
        map.rms.push_back(row);
    }
    return map;
}

}  // namespace lenslab
