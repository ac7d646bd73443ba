#include "scene/render_settings_spec.h"

#include "scene/limits.h"
#include "scene/render_settings.h"

namespace lenslab {

namespace {

ElementSpec declare_render_settings() {
    const RenderSettings d;  // the struct's initialisers are the defaults
    const std::string photon_map = "Photon map";
    const std::string sppm = "Progressive photon map (sppm, the view)";
    ElementSpec s{"render", "the render settings", {}, {}};
    s.params = {
        whole_param("width", d.width, 1, kMaxImageSide)
            .describe("Image width in pixels")
            .in_editor("Width")
            .on_command_line(),
        whole_param("height", d.height, 1, kMaxImageSide)
            .describe("Image height in pixels")
            .in_editor("Height")
            .on_command_line(),
        whole_param("spp", d.spp, 1, kMaxSpp)
            .describe("Camera samples per pixel")
            .in_editor("Samples per pixel")
            .on_command_line(),
        whole_param("max_depth", d.max_depth, 0, kMaxDepth)
            .describe("Longest chain of specular bounces followed")
            .in_editor("Max depth")
            .on_command_line(),
        whole_param("seed", int64_t(d.seed), 0, 2147483647)
            .describe("Random seed; the same seed gives the same image")
            .in_editor("Seed")
            .on_command_line(),
        colour_param("ambient", d.ambient)
            .describe("Ambient radiance lighting every diffuse surface")
            .in_editor("Ambient"),
        colour_param("background", d.background)
            .describe("Radiance of rays that leave the scene")
            .in_editor("Background"),
        whole_param("light_samples", d.light_samples, 1, 4096)
            .describe("Shadow rays per emitting sphere from every diffuse point shaded")
            .in_editor("Light samples"),
        fraction_param("min_weight", d.min_weight)
            .at_least(kMinBranchWeight)
            .because("each camera ray then spawns at most about a million rays")
            .describe("Specular branches carrying less than this share are not followed")
            .in_editor("Min branch weight", 6),
        number_param("grin_tolerance", d.grin_tolerance)
            .at_least(1e-12)
            .at_most(1e-3)
            .describe("Local error of a step through a gradient-index medium, relative to the "
                      "solid's size")
            .in_editor("GRIN tolerance", 12),
        choice_param("integrator", d.integrator, kIntegratorNames)
            .describe("Rendering algorithm: whitted, photon_map, sppm or path")
            .in_editor("Integrator")
            .on_command_line(),
        whole_param("dispersion_samples", d.dispersion_samples, 0, kMaxDispersionSamples)
            .meaning_auto("auto: 7 when a material disperses")
            .describe("whitted, photon_map: wavelengths a camera path splits into at dispersive "
                      "glass (0: auto)")
            .in_editor("Dispersion samples (0 = auto)")
            .on_command_line(),
        fraction_param("merge_weight", d.merge_weight)
            .describe("whitted, photon_map: the wavelengths of a split whose branch carries less "
                      "than this share of the camera sample follow one path together, carrying "
                      "the whole spectrum (0: never)")
            .in_editor("Merge weight", 6)
            .on_command_line(),
        whole_param("photons", d.photons, 1, kMaxPhotonsPerLight)
            .describe("photon_map: photons emitted per light")
            .in_editor("Photons per light")
            .under(photon_map)
            .on_command_line(),
        number_param("radius", d.radius)
            .at_least(0)
            .meaning_auto("auto: 0.5% of the scene's diagonal")
            .describe("photon_map: largest gather radius in scene units (0: auto)")
            .in_editor("Gather radius (0 = auto)", 5)
            .under(photon_map)
            .on_command_line(),
        choice_param("filter", choice_name(kPhotonFilterNames, d.filter), kPhotonFilterNames)
            .describe("photon_map: photon filter: cone, gaussian or box")
            .in_editor("Filter")
            .under(photon_map)
            .on_command_line(),
        number_param("filter_k", d.filter_k)
            .at_least(1)
            .because("the cone reaches zero at k r")
            .describe("photon_map: cone filter constant k")
            .in_editor("Filter constant k", 3)
            .under(photon_map)
            .on_command_line(),
        whole_param("max_photons_per_estimate", d.max_photons_per_estimate, 1, 1000000)
            .describe("photon_map: cap on the photons one radiance estimate gathers")
            .in_editor("Max photons per estimate")
            .under(photon_map)
            .on_command_line(),
        choice_param("direct", choice_name(kDirectLightNames, d.direct), kDirectLightNames)
            .describe("photon_map: direct light from shadow_rays or the photon_map")
            .in_editor("Direct light")
            .under(photon_map)
            .on_command_line(),
        whole_param("caustic_photons", d.caustic_photons, 0, kMaxPhotonsPerLight)
            .meaning_auto("auto")
            .describe("Photons aimed at the glass and mirrors, per light (sppm: per pass; 0: auto)")
            .in_editor("Caustic photons per light (0 = as many)")
            .under(photon_map)
            .on_command_line(),
        flag_param("aim_photons", d.aim_photons)
            .describe("Aim caustic photons at the glass and mirrors (off: emit all uniformly)")
            .in_editor("Aim photons at glass and mirrors")
            .under(photon_map)
            .on_command_line(),
        whole_param("pass_photons", d.pass_photons, 0, int64_t{1} << 30)
            .meaning_auto("auto")
            .describe("sppm: photons emitted per light in each pass (0: auto)")
            .in_editor("Photons per light per pass (0 = auto)")
            .under(sppm)
            .on_command_line(),
        whole_param("passes", d.passes, 0, 1 << 24)
            .describe("sppm: passes to run (0: no limit, needs a time budget)")
            .in_editor("Passes (lenslab render)")
            .under(sppm)
            .on_command_line(),
        number_param("time", d.time)
            .at_least(0)
            .in_unit("seconds")
            .because("0: no time limit")
            .describe("sppm: time budget in seconds (passes run until it is spent)")
            .in_editor("Time budget (s, 0 = none)", 1)
            .under(sppm)
            .on_command_line(),
        number_param("initial_radius", d.initial_radius)
            .above(0)
            .meaning_auto("auto")
            .describe("sppm: initial gather radius in scene units (default: auto)")
            .under(sppm)
            .on_command_line(),
        number_param("alpha", d.alpha)
            .above(0)
            .below(1)
            .describe("sppm: share of each pass's new photons kept as the radius shrinks")
            .in_editor("Alpha", 4)
            .under(sppm),
        whole_param("volume_neighbours", d.volume_neighbours, 0, 256)
            .describe("sppm in fog: 0, sharp volume photon discs; N, a sparse photon's disc "
                      "grows until about N neighbours share it (a smooth glow, slower)")
            .in_editor("Volume neighbours")
            .under(sppm)
            .on_command_line(),
        choice_param("tone_map", choice_name(kToneMapNames, d.tone_map), kToneMapNames)
            .describe("How light brighter than white is shown: clip, or log (highlights on a "
                      "log scale, their colour kept)")
            .in_editor("Tone map")
            .on_command_line(),
        number_param("highlight_stops", d.highlight_stops)
            .at_least(1)
            .at_most(24)
            .describe("tone_map log: stops above the knee (0.5) that reach the top")
            .in_editor("Highlight stops", 1)
            .on_command_line(),
    };
    return s;
}

}  // namespace

const ElementSpec& render_settings_spec() {
    static const ElementSpec spec = declare_render_settings();
    return spec;
}

}  // namespace lenslab
