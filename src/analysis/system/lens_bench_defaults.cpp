#include "analysis/system/lens_bench_defaults.h"

#include <algorithm>
#include <cmath>

namespace lenslab {

namespace {

// The wavelengths in ascending order but with the primary moved to the middle, where the
// bench looks for it (--wavelengths: "the primary is the middle one").
std::vector<double> primary_in_the_middle(std::vector<double> nm, double primary) {
    std::sort(nm.begin(), nm.end());
    const auto at = std::find(nm.begin(), nm.end(), primary);
    if (at == nm.end()) return nm;
    nm.erase(at);
    nm.insert(nm.begin() + static_cast<std::ptrdiff_t>(nm.size() / 2), primary);
    return nm;
}

// Field angles of a rotationally symmetric system: the distance of each (x, y) field from
// the axis, each once, in the file's order.
std::vector<double> field_angles(const LensBench& b) {
    std::vector<double> out;
    const size_t n = std::max(b.fields_x.size(), b.fields_y.size());
    for (size_t i = 0; i < n; ++i) {
        const double x = i < b.fields_x.size() ? b.fields_x[i] : 0.0;
        const double y = i < b.fields_y.size() ? b.fields_y[i] : 0.0;
        const double angle = std::hypot(x, y);
        if (std::find(out.begin(), out.end(), angle) == out.end()) out.push_back(angle);
    }
    return out;
}

}  // namespace

LensBenchDefaults with_lens_bench_defaults(const AnalyzeRequest& request, const LensBench& b) {
    LensBenchDefaults d{request, {}, {}};
    AnalyzeRequest& a = d.request;
    if (!b.wavelengths.empty() && !a.wavelength_given && a.wavelengths.empty()) {
        if (b.wavelengths.size() == 1) {
            a.wavelength_nm = b.wavelengths[0];
        } else {
            a.wavelengths = primary_in_the_middle(b.wavelengths,
                                                  b.primary_wavelength.value_or(b.wavelengths[0]));
        }
        d.taken.push_back("wavelengths");
    }
    const bool fields_open = a.fields.empty() && a.field_heights.empty() && a.object_distance == 0;
    const std::vector<double> angles = field_angles(b);
    if (fields_open && !angles.empty()) {
        if (b.field_type == "angle") {
            a.fields = angles;
            d.taken.push_back("fields");
        } else {
            d.not_taken.push_back("fields: " + b.field_type +
                                  "s (the bench takes field angles, or object heights with "
                                  "--object-distance)");
        }
    }
    if (a.aperture == 0 && a.epd == 0 && a.f_number == 0 && b.aperture > 0) {
        if (b.aperture_type == "entrance_pupil_diameter") {
            a.epd = b.aperture;
            d.taken.push_back("epd");
        } else if (b.aperture_type == "f_number") {
            a.f_number = b.aperture;
            d.taken.push_back("f_number");
        } else if (!b.aperture_type.empty()) {
            d.not_taken.push_back("aperture: " + b.aperture_type +
                                  " (the bench takes an entrance pupil diameter or an F-number)");
        }
    }
    if (b.stop_position) {
        if (a.stop == 0) {
            a.stop_position = b.stop_position;
            a.stop_semi_diameter = b.stop_semi_diameter.value_or(0.0);
            d.taken.push_back("stop");
        } else {
            d.not_taken.push_back("stop: --stop " + std::to_string(a.stop) + " given");
        }
    }
    if (!b.ray_aiming.empty() && !a.ray_aiming) {
        a.ray_aiming = ray_aiming_named(b.ray_aiming);
        d.taken.push_back("ray_aiming");
    }
    // The image surface, for the figures measured on it (elsewhere it means nothing).
    const AnalyzeRequest tables = with_implied_tables(a);
    const bool on_image_plane = tables.spots || tables.fans || tables.field_curves;
    if (b.image_distance && !a.image_distance && on_image_plane) {
        a.image_distance = b.image_distance;
        d.taken.push_back("image_distance");
    }
    return d;
}

}  // namespace lenslab
