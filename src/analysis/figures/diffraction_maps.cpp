#include "analysis/figures/diffraction_maps.h"

#include <cmath>
#include <limits>

#include "analysis/figures/map_figure.h"
#include "analysis/figures/plot_panel.h"

namespace lenslab {

Image8 psf_map_image(const std::vector<FieldPsf>& psfs, ColourScale scale, const std::string& unit,
                     const std::string& field_unit) {
    MapFigure figure;
    figure.title = std::string("Polychromatic PSF") + (scale == ColourScale::Log ? " (log)" : "");
    // Each panel on its own peak, so an off-axis PSF far below the axis's still shows its shape;
    // the labels give the Strehl ratios.
    figure.unit = "of its peak";
    figure.scale = scale;
    figure.low = 0;
    figure.high = 1;
    for (const FieldPsf& f : psfs) {
        if (!f.error.empty()) continue;
        MapPanel panel;
        const Psf& p = f.psf;
        panel.width = panel.height = p.size;
        panel.values.resize(p.intensity.size());
        for (int i = 0; i < p.size; ++i)  // row 0 at the top: the largest y
            for (int j = 0; j < p.size; ++j)
                panel.values[static_cast<size_t>(i) * p.size + j] =
                    p.at(p.size - 1 - i, j) / p.strehl;
        panel.label = printf_text("%g ", f.field) + field_unit +
                      printf_text(": Strehl %.3f", p.strehl) +
                      printf_text(", %.3g ", p.size * p.spacing) + unit;
        figure.panels.push_back(std::move(panel));
    }
    figure.footer = {
        "each panel centred on the primary wavelength's chief ray, as wide as its label says; +y "
        "up",
        "each panel's intensity against its own peak; Strehl: that peak against the "
        "aberration-free polychromatic PSF's"};
    return map_figure_image(figure);
}

Image8 opd_map_image(const WavefrontFigures& figures, double wavelength_nm,
                     const std::string& field_unit) {
    MapFigure figure;
    figure.title = printf_text("OPD at %.2f nm", wavelength_nm);
    figure.unit = "waves";
    for (const WavefrontFigure& f : figures.figures) {
        if (!f.wavefront || f.wavelength_nm != wavelength_nm) continue;
        const PupilFunction& p = f.wavefront->pupil;
        const int first = p.size / 2 - p.samples / 2;
        MapPanel panel;
        panel.width = panel.height = p.samples;
        panel.values.assign(static_cast<size_t>(p.samples) * p.samples,
                            std::numeric_limits<double>::quiet_NaN());
        for (int i = 0; i < p.samples; ++i)
            for (int j = 0; j < p.samples; ++j) {
                const size_t cell = p.index(first + p.samples - 1 - i, first + j);
                if (p.amplitude[cell] > 0)
                    panel.values[static_cast<size_t>(i) * p.samples + j] = p.opd_waves[cell];
            }
        panel.label = printf_text("%g ", f.field) + field_unit +
                      printf_text(": RMS %.3f", f.wavefront->rms_waves) +
                      printf_text(" PV %.3f", f.wavefront->pv_waves);
        figure.panels.push_back(std::move(panel));
    }
    figure.footer = {
        "against the chief ray's reference sphere; pupil +x right, +y up (the system's axes)",
        "grey: no ray passed"};
    return map_figure_image(figure);
}

}  // namespace lenslab
