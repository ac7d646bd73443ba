#include "analysis/detectors/detection_run.h"

#include "analysis/detectors/detector_files.h"
#include "render/photon_emission.h"
#include "util/error.h"

namespace lenslab {

DetectionSettings detection_settings(const Scene& scene, int threads) {
    DetectionSettings settings;
    settings.photons_per_light = scene.render.photons;
    settings.caustic_photons_per_light = scene.render.caustic_photons;
    settings.aim = scene.render.aim_photons;
    settings.seed = scene.render.seed;
    settings.max_depth = scene.render.max_depth;
    settings.threads = threads;
    return settings;
}

void check_detectable(const Scene& scene, const std::string& name) {
    if (detector_objects(scene).empty()) {
        throw Error(name +
                    ": no detector in the scene (mark a triangle, disc or rectangle with "
                    "\"detector\": true)");
    }
    if (photon_light_count(scene) == 0) {
        throw Error(name +
                    ": no light to measure (add a point light, a beam or an emitting sphere)");
    }
}

DetectionResult run_detection(const Scene& scene, const std::string& name,
                              const DetectionSettings& settings, RenderControl& control) {
    check_detectable(scene, name);
    return measure_detectors(scene, settings, control);
}

nlohmann::json detection_json(const std::string& name, const DetectionSettings& settings,
                              const DetectionResult& result) {
    nlohmann::json doc{{"scene", name},
                       {"photons_per_light", settings.photons_per_light},
                       {"photons_emitted", result.photons_emitted},
                       {"photons_aimed", result.photons_aimed},
                       {"seed", settings.seed},
                       {"seconds", result.seconds},
                       {"detectors", nlohmann::json::array()}};
    for (const DetectorMeasurement& m : result.detectors)
        doc["detectors"].push_back(detector_summary_json(m));
    return doc;
}

}  // namespace lenslab
