// `lenslab analyze SCENE`: the optical bench. Focal lengths, principal planes, spherical and
// chromatic aberration and spot sizes of the lenses on one axis, as a table or JSON, and a
// ray diagram as SVG.

#include <cstdio>
#include <iostream>
#include <memory>

#include "analysis/lens_report.h"
#include "analysis/ray_diagram.h"
#include "analysis/ray_diagram_svg.h"
#include "commands.h"
#include "scene/json_reader.h"
#include "scene/scene_json.h"
#include "util/atomic_file.h"

namespace lenslab::cli {

namespace {

struct AnalyzeArgs {
    std::string scene;
    double wavelength_nm = kLineD;
    bool json = false;
    std::string svg;
    double aperture = 0;  // beam diameter; 0: the usable aperture
    std::string lens;
    std::string unit;  // for the ray diagram's labels; empty: "units"
};

int usage_error(const std::string& message) {
    std::cerr << "lenslab: error: " << message << "\n";
    return 2;
}

// The object `name` names: its `name`, or its path "objects[i]".
std::optional<int> find_lens(const Scene& scene, const std::string& name, std::string& known) {
    for (int i = 0; i < static_cast<int>(scene.objects.size()); ++i) {
        const SceneObject& o = scene.objects[i];
        if (o.type != ObjectType::Lens) continue;
        // A lens group's elements answer to the group's name too.
        known +=
            (known.empty() ? "" : ", ") + o.name + (o.group.empty() ? "" : " [" + o.group + "]");
        if (o.name == name || o.group == name ||
            "objects[" + std::to_string(o.source) + "]" == name) {
            return i;
        }
    }
    return std::nullopt;
}

int run(const AnalyzeArgs& a) {
    if (!a.svg.empty()) check_output_file(a.svg);  // before the analysis
    const Scene scene = load_scene_file(a.scene, {.require_camera = false});
    std::optional<int> lens;
    if (!a.lens.empty()) {
        std::string known;
        lens = find_lens(scene, a.lens, known);
        if (!lens) {
            return usage_error("--lens: no lens named '" + a.lens + "' in " + a.scene +
                               (known.empty() ? " (it has no lens)" : " (lenses: " + known + ")"));
        }
    }
    try {
        const OpticalSystem system = build_optical_system(scene, lens);
        LensReportOptions options;
        options.wavelength_nm = a.wavelength_nm;
        if (a.aperture > 0) {
            check_wavelength(system, a.wavelength_nm, "--wavelength");
            const double usable = usable_aperture_radius(system, a.wavelength_nm);
            if (0.5 * a.aperture > usable * (1.0 + 1e-9)) {
                char usable_text[32];
                std::snprintf(usable_text, sizeof usable_text, "%.6g", 2.0 * usable);
                return usage_error("--aperture: a beam of diameter " + format_number(a.aperture) +
                                   " does not pass the lenses (the largest that does is " +
                                   usable_text + ")");
            }
            options.aperture_radius = 0.5 * a.aperture;
        }
        const LensReport report = analyze_lens_system(system, options);
        if (!a.svg.empty()) {
            RayDiagramOptions diagram;
            diagram.unit = a.unit;
            const std::string svg = ray_diagram_svg(make_ray_diagram(system, report, diagram));
            // Atomically: a failed write leaves no half file, and says why it failed.
            write_text_atomically(a.svg, svg);
        }
        if (a.json) {
            nlohmann::ordered_json j = report_json(system, report);
            j["scene"] = a.scene;
            if (!a.svg.empty()) j["svg"] = a.svg;
            std::cout << j.dump(2) << "\n";
        } else {
            std::cout << "lenslab analyze " << a.scene << ": " << report_table(system, report);
            if (!a.svg.empty()) std::cout << "\nray diagram written to " << a.svg << "\n";
        }
        return 0;
    } catch (const SceneError& e) {
        // The scene loaded but is not a lens system the bench can measure: name the file too.
        throw SceneError(a.scene + ": " + e.path(), e.reason());
    }
}

}  // namespace

Action add_analyze_command(CLI::App& app) {
    auto args = std::make_shared<AnalyzeArgs>();
    CLI::App* cmd = app.add_subcommand(
        "analyze",
        "Optical bench: focal lengths, aberrations and a ray diagram of the lenses on one axis");
    cmd->add_option("scene", args->scene, "Scene file (JSON); a camera is not needed")->required();
    cmd->add_option(
           "-w,--wavelength", args->wavelength_nm,
           "Wavelength in air in nm for the figures (default: the d line, 587.56 nm; in vacuum "
           "for a scene with \"ambient\": \"vacuum\")")
        ->check(CLI::PositiveNumber);
    cmd->add_flag("--json", args->json, "Print the figures as JSON");
    cmd->add_option("--svg", args->svg, "Write a ray diagram (SVG) to this file");
    cmd->add_option(
           "--aperture", args->aperture,
           "Diameter of the collimated beam, in the scene's unit (default: all the lens passes)")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--unit", args->unit,
                    "The scene's length unit, for the ray diagram's labels (e.g. mm); a scene "
                    "declares none, so they say \"units\" without it");
    cmd->add_option(
        "--lens", args->lens,
        "Measure this lens (name or objects[i]) and the lenses on its axis; others are ignored");
    return [args] { return run(*args); };
}

}  // namespace lenslab::cli
