#pragma once
// Detectors: flat objects marked `detector` in a scene measure the irradiance of the light
// arriving on them. Photons are shot from every light exactly as for the photon maps
// (render/photon_tracer.h) and each arrival on a detector is binned, whatever the
// surface's material; the material then decides what happens to the photon, so a
// transparent detector with ior 1 is a "virtual" sensor plane that light passes through.
//
// Units: lengths in the scene's unit (the detector's `unit` names it), powers in W (a
// light's `power`), irradiance in W per unit². Wavelength bands in nm.

#include <cstdint>
#include <string>
#include <vector>

#include "analysis/detectors/detector_grid.h"
#include "render/render_control.h"
#include "scene/scene.h"

namespace lenslab {

struct DetectionSettings {
    int64_t photons_per_light = 200000;  // emitted as the lights emit, per light on average
    // Aimed at the photon targets (the glass and mirrors), per light; 0: as many as
    // photons_per_light. A detector behind a lens then gets its light through the lens.
    int64_t caustic_photons_per_light = 0;
    bool aim = true;
    uint64_t seed = 1;
    int max_depth = 8;  // specular bounces followed (render.max_depth)
    int threads = 0;    // 0: all cores
};

struct DetectorMeasurement {
    std::string name;  // the object's name
    int object = -1;   // index in Scene::objects
    DetectorSettings settings;
    DetectorGrid grid;

    // Power (W) that arrived in each cell, in total and per band (band_power[b][cell]).
    std::vector<double> power;
    std::vector<std::vector<double>> band_power;
    double total_power = 0;          // W
    std::vector<double> band_total;  // W per band
    int64_t arrivals = 0;            // photons counted

    double peak_irradiance = 0;  // W/unit², the brightest cell at least half on the surface
    int peak_cell = -1;
    // Power-weighted mean arrival point, in (u, v) and in scene coordinates, and the RMS
    // distance of the arrivals from it (the spot's RMS radius).
    double centroid_u = 0, centroid_v = 0;
    Vec3 centroid;
    double rms_radius = 0;

    int bands() const { return static_cast<int>(settings.band_edges.size()) - 1; }
    // W/unit² of a cell (0 for a cell wholly off the surface).
    double irradiance(int cell) const;
    double band_irradiance(int band, int cell) const;
};

struct DetectionResult {
    std::vector<DetectorMeasurement> detectors;  // in the order of Scene::objects
    int64_t photons_emitted = 0;                 // both streams
    int64_t photons_aimed = 0;
    bool cancelled = false;
    double seconds = 0;
};

// Indices of the objects that are detectors.
std::vector<int> detector_objects(const Scene& scene);

// Shoots the photons of both streams (render/photon_emission.h) and measures every detector. The
// result is the same for a given seed whatever the thread count (one random stream per
// photon; arrivals are summed in photon order). Reports progress and stops early (with
// `cancelled` set) through `control`.
DetectionResult measure_detectors(const Scene& scene, const DetectionSettings& settings,
                                  RenderControl& control);
// The same, run to the end with no progress reported.
DetectionResult measure_detectors(const Scene& scene, const DetectionSettings& settings);

}  // namespace lenslab
