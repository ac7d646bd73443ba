#include "analysis/diffraction/opd_fans.h"

#include <limits>
#include <optional>
#include <stdexcept>

#include "analysis/diffraction/field_wavefront.h"

namespace lenslab {

RayFans opd_fans(const OpticalSystem& system, const FirstOrder& first_order,
                 const RayFanOptions& options) {
    if (options.points < 2) throw std::invalid_argument("an OPD fan needs at least 2 points");
    constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
    RayFans out;
    out.image_z = options.image_z.value_or(system.last_vertex() + first_order.image_position);
    out.primary_nm = first_order.wavelength_nm;
    for (int k = 0; k < options.points; ++k)
        out.pupil.push_back(-1.0 + 2.0 * k / (options.points - 1));
    const std::vector<double> wavelengths = options.wavelengths.empty()
                                                ? std::vector<double>{first_order.wavelength_nm}
                                                : options.wavelengths;
    for (double field : options.fields) {
        FieldFans f;
        f.field = field;
        for (double nm : wavelengths) {
            RayFan fan;
            fan.wavelength_nm = nm;
            FieldWavefrontOptions o;
            o.field = field;
            o.wavelength_nm = nm;
            o.image_z = out.image_z;
            try {
                const FieldOpd opd(system, first_order, o);
                if (nm == first_order.wavelength_nm) f.reference = opd.reference();
                for (double p : out.pupil) {
                    fan.tangential.push_back(opd.opd_waves(0, p).value_or(kNone));
                    fan.sagittal.push_back(opd.opd_waves(p, 0).value_or(kNone));
                }
            } catch (const std::invalid_argument&) {  // no chief ray at this wavelength
                fan.tangential.assign(out.pupil.size(), kNone);
                fan.sagittal.assign(out.pupil.size(), kNone);
            }
            f.fans.push_back(std::move(fan));
        }
        out.fields.push_back(std::move(f));
    }
    return out;
}

}  // namespace lenslab
