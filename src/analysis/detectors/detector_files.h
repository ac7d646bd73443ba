#pragma once
// A detector's measurement as files: <stem>.csv (one row per cell, a header stating the
// units and bands), <stem>.exr (linear float channels: total and one per band, in
// W/unit²) and <stem>.png (the false-colour picture), each written atomically; and the
// summary every front end prints (text or JSON).

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "analysis/detectors/detector.h"
#include "analysis/detectors/detector_image.h"

namespace lenslab {

// File name stems for the detectors: their names made safe for a file system
// ("focal plane" -> "focal_plane"), made unique by the object index when two collide.
std::vector<std::string> detector_file_stems(const DetectionResult& result);
// The same stems from the scene, before anything is measured.
std::vector<std::string> detector_file_stems(const Scene& scene);
// The files write_detector_files writes for `stem` into `dir`.
std::vector<std::string> detector_file_paths(const std::string& dir, const std::string& stem);

std::string detector_csv(const DetectorMeasurement& m, const DetectionSettings& settings);
// Name of the EXR channel of band `band` ("E_360_490nm"); the total is "E_total".
std::string band_channel_name(const DetectorMeasurement& m, int band);

// Writes the three files of `m` into `dir` (which must exist) as <stem>.{csv,exr,png};
// `scale` is the PNG's colour scale.
void write_detector_files(const DetectorMeasurement& m, const DetectionSettings& settings,
                          const std::string& dir, const std::string& stem,
                          ColourScale scale = ColourScale::Linear);

// {"name", "object", "units": {...}, "total_power", "band_powers": [...], "peak_irradiance",
//  "centroid": [x, y, z], "centroid_uv": [u, v], "rms_radius", "resolution", "arrivals"}
nlohmann::json detector_summary_json(const DetectorMeasurement& m);
// A few lines for people: total, bands, peak, centroid, with units.
std::string detector_summary_text(const DetectorMeasurement& m);

}  // namespace lenslab
