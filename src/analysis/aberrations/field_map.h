#pragma once
// The RMS spot radius over a square grid of field points in x and y: where a system is sharp
// across its field (a rotationally symmetric one's map is round; a folded or tilted one's
// need not be). Each cell is the beam of that field point (field_beam.h, aimed through the
// hexapolar grid of the stop) at one wavelength, in one image plane, its RMS radius about
// its own centroid.

#include <vector>

#include "analysis/system/first_order.h"

namespace lenslab {

struct FieldMapOptions {
    int points = 5;          // field points along each side (odd puts one on the axis)
    double max_field = 0.0;  // the grid spans [-max_field, max_field] in x and in y
    double wavelength_nm = 0.0;
    double image_z = 0.0;  // the image plane (system z)
    int rings = 6;
};

struct FieldMap {
    std::vector<double> fields_x, fields_y;  // the grid's field values, increasing
    // rms[j][i]: at fields_x[i], fields_y[j]; NaN where no ray of the beam passed.
    std::vector<std::vector<double>> rms;
    FieldMapOptions options;
};

FieldMap field_map(const OpticalSystem& system, const FirstOrder& first_order,
                   const FieldMapOptions& options);

}  // namespace lenslab
