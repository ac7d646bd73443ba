// Beer-Lambert in the photon tracer: a beam through a thick slab of a dense flint reaches a
// detector behind it with the slab's closed-form transmittance, at two wavelengths where the
// glass absorbs differently.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "analysis/detectors/detector.h"
#include "analysis/trace/ray_tree.h"
#include "optics/absorption.h"
#include "optics/glass_library.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

// A 1 W line beam at normal incidence through a box of N-SF57, `thickness` scene units
// thick, onto a detector behind it; the scene unit is `unit_mm` millimetres.
double slab_detector_power(double nm, double thickness, double unit_mm) {
    std::ostringstream text;
    text << R"({"camera": {"position": [0, 0, -100], "look_at": [0, 0, 0]}, "length_unit_mm": )"
         << unit_mm << R"(,
        "objects": [{"type": "box", "center": [0, 0, 0], "size": [40, 40, )"
         << thickness << R"(], "material": {"transparency": 1, "glass": "SCHOTT:N-SF57"}},
                    {"type": "rectangle", "center": [0, 0, )"
         << thickness << R"(], "normal": [0, 0, -1], "size": [30, 30],
                     "material": {"color": 0}, "detector": {"resolution": 4}}],
        "lights": [{"type": "beam", "origin": [0, 0, )"
         << -thickness << R"(], "direction": [0, 0, 1], "radius": 1, "power": 1,
                    "spectrum": {"line": )"
         << nm << R"(, "width": 0.05}}]})";
    RenderControl control;
    DetectionSettings s;
    s.photons_per_light = 40000;
    const DetectionResult r = measure_detectors(parse_scene(text.str()), s, control);
    EXPECT_EQ(r.detectors.size(), 1u);
    return r.detectors.at(0).total_power;
}

// A slab's transmittance at normal incidence with internal transmittance tau and surface
// reflectance R = ((n - 1) / (n + 1))^2, the incoherent sum over reflections inside:
// T = (1 - R)^2 tau / (1 - R^2 tau^2) (SCHOTT TIE-35, "Transmittance of optical glass",
// eq. 1.3; Hecht, Optics, section 4.6.2 for R).
double slab_transmittance(double n, double tau) {
    const double r = (n - 1) * (n - 1) / ((n + 1) * (n + 1));
    return (1 - r) * (1 - r) * tau / (1 - r * r * tau * tau);
}

TEST(GlassAbsorption, SlabPassesTheBeerLambertShareOfABeam) {
    // 50 mm of N-SF57: tau about 0.60 at 430 nm and 0.82 at 480 nm (its k there). Photons
    // draw their wavelength from a 1 nm histogram of the line, so the wavelengths are where k
    // changes slowly: a 0.1 nm shift moves tau by 0.2% at most.
    const Glass& sf57 = *lookup_glass("SCHOTT:N-SF57").glass;
    for (double nm : {430.0, 480.0}) {
        SCOPED_TRACE(nm);
        const double tau = internal_transmittance(sf57.k_um, nm, 50.0);
        const double expected = slab_transmittance(sf57.model->n(nm), tau);
        const double measured = slab_detector_power(nm, 50.0, 1.0);
        std::printf("%g nm: tau_i(50 mm) = %.4f, slab T = %.4f, detector %.4f W (%+.2f%%)\n", nm,
                    tau, expected, measured, 100 * (measured / expected - 1));
        EXPECT_NEAR(measured, expected, 0.01 * expected);
        // The same slab in centimetres: 5 units of 10 mm.
        EXPECT_NEAR(slab_detector_power(nm, 5.0, 10.0), expected, 0.01 * expected);
    }
    EXPECT_LT(internal_transmittance(sf57.k_um, 430, 50), 0.65);  // the test means something
    EXPECT_GT(internal_transmittance(sf57.k_um, 480, 50), 0.78);
}

TEST(GlassAbsorption, TraceCountsWhatTheGlassAbsorbs) {
    // `lenslab trace`'s tree: the ray through both faces of 50 mm of N-SF57 at normal incidence
    // keeps (1 - R)^2 tau_i of its power, and the summary's absorbed share holds the rest.
    const Scene scene = parse_scene(R"({"camera": {"position": [0, 0, -100], "look_at": [0, 0, 0]},
        "objects": [{"type": "box", "center": [0, 0, 0], "size": [40, 40, 50],
                     "material": {"transparency": 1, "glass": "SCHOTT:N-SF57"}}]})");
    const Glass& sf57 = *lookup_glass("SCHOTT:N-SF57").glass;
    RayTreeOptions options;
    options.wavelength_nm = 430;
    const RayTree tree = trace_ray_tree(scene, {{0, 0, -60}, {0, 0, 1}}, options);
    const double n = sf57.model->n(430), r = (n - 1) * (n - 1) / ((n + 1) * (n + 1));
    const double tau = internal_transmittance(sf57.k_um, 430, 50);
    const RayTreeNode& in = tree.root.children.at(1);  // reflected first, then refracted
    ASSERT_EQ(in.event, Event::Refract);
    const RayTreeNode& out = in.children.at(1);
    ASSERT_EQ(out.event, Event::Refract);
    EXPECT_NEAR(out.weight, (1 - r) * (1 - r) * tau, 1e-12);
    EXPECT_NEAR(tree.escaped + tree.absorbed + tree.truncated, 1.0, 1e-12);
    EXPECT_GT(tree.absorbed, 0.9 * (1 - r) * (1 - tau));
}

}  // namespace
}  // namespace lenslab
