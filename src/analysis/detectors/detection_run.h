#pragma once
// The work of `lenslab detect` without its files, shared by the command line and the Python
// module (lenslab.detect): the photon settings a scene's `render` block gives, the checks
// that there is something to measure, the measurement itself, and the summary both print.

#include <nlohmann/json.hpp>
#include <string>

#include "analysis/detectors/detector.h"
#include "render/render_control.h"
#include "scene/scene.h"

namespace lenslab {

// The detection settings of `scene`: photons, caustic_photons, aim_photons, seed and max_depth
// from its `render` block; `threads` worker threads (0: all cores).
DetectionSettings detection_settings(const Scene& scene, int threads);

// Throws Error "<name>: no detector in the scene (...)" or "<name>: no light to measure (...)"
// when `scene` (named `name`, its file) has nothing to measure.
void check_detectable(const Scene& scene, const std::string& name);

// check_detectable, then measure_detectors with `settings`; cancelled through `control`.
DetectionResult run_detection(const Scene& scene, const std::string& name,
                              const DetectionSettings& settings, RenderControl& control);

// The summary `lenslab detect --json` prints, without the files: {"scene", "photons_per_light",
// "photons_emitted", "photons_aimed", "seed", "seconds", "detectors": [detector_summary_json]}.
nlohmann::json detection_json(const std::string& name, const DetectionSettings& settings,
                              const DetectionResult& result);

}  // namespace lenslab
