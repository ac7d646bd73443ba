#include "analysis/detectors/detector_files.h"

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <sstream>

#include "analysis/detectors/detector_image.h"
#include "image/image_io.h"
#include "util/atomic_file.h"

namespace lenslab {

namespace {

// Shortest text that reads back as the same double.
std::string exact(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    for (int digits = 6; digits < 17; ++digits) {
        char shorter[32];
        std::snprintf(shorter, sizeof shorter, "%.*g", digits, v);
        if (std::strtod(shorter, nullptr) == v) return shorter;
    }
    return buf;
}

std::string nm(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

std::string band_label(const DetectorMeasurement& m, int b) {
    return nm(m.settings.band_edges[static_cast<size_t>(b)]) + "-" +
           nm(m.settings.band_edges[static_cast<size_t>(b) + 1]) + " nm";
}

std::string vec_text(const Vec3& v) {
    std::ostringstream s;  // (streamed: GCC 12 warns falsely, -Wrestrict, on "(" + string)
    s << "(" << exact(v.x) << ", " << exact(v.y) << ", " << exact(v.z) << ")";
    return s.str();
}

struct NamedDetector {
    std::string name;
    int object;
};

std::vector<std::string> stems_of(const std::vector<NamedDetector>& detectors) {
    std::vector<std::string> stems;
    std::set<std::string> used;
    for (const NamedDetector& m : detectors) {
        std::string s;
        for (char c : m.name)
            s += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_') ? c : '_';
        if (s.empty()) s = "detector";
        if (used.count(s)) {
            s += '_';
            s += std::to_string(m.object);
        }
        used.insert(s);
        stems.push_back(s);
    }
    return stems;
}

}  // namespace

std::vector<std::string> detector_file_stems(const DetectionResult& result) {
    std::vector<NamedDetector> detectors;
    for (const DetectorMeasurement& m : result.detectors) detectors.push_back({m.name, m.object});
    return stems_of(detectors);
}

std::vector<std::string> detector_file_stems(const Scene& scene) {
    std::vector<NamedDetector> detectors;
    for (const int o : detector_objects(scene))
        detectors.push_back({scene.objects[static_cast<size_t>(o)].name, o});
    return stems_of(detectors);
}

std::vector<std::string> detector_file_paths(const std::string& dir, const std::string& stem) {
    const std::string base = (std::filesystem::path(dir) / stem).string();
    return {base + ".csv", base + ".exr", base + ".png"};
}

std::string band_channel_name(const DetectorMeasurement& m, int band) {
    return "E_" + nm(m.settings.band_edges[static_cast<size_t>(band)]) + "_" +
           nm(m.settings.band_edges[static_cast<size_t>(band) + 1]) + "nm";
}

std::string detector_csv(const DetectorMeasurement& m, const DetectionSettings& settings) {
    const DetectorGrid& g = m.grid;
    const std::string unit = m.settings.unit;
    std::ostringstream csv;
    csv << "# lenslab detector '" << m.name << "' (objects[" << m.object << "])\n"
        << "# units: u, v in " << unit << " (the detector's own coordinates: origin "
        << vec_text(g.frame().origin) << ", u along " << vec_text(g.frame().u) << ", v along "
        << vec_text(g.frame().v) << " in scene coordinates); area in " << unit
        << "^2; irradiance E in " << irradiance_unit(m) << "; power in W\n"
        << "# light arriving on the "
        << (m.settings.side == DetectorSide::Front  ? "front"
            : m.settings.side == DetectorSide::Back ? "back"
                                                    : "front and back")
        << " face; E_total over all wavelengths, E_<a>_<b>nm over the band [a, b) nm\n"
        << "# photons per light " << settings.photons_per_light << ", seed " << settings.seed
        << ", " << m.arrivals << " arrivals counted\n"
        << "# total power " << exact(m.total_power) << " W";
    for (int b = 0; b < m.bands(); ++b)
        csv << "; " << band_label(m, b) << ": " << exact(m.band_total[static_cast<size_t>(b)])
            << " W";
    csv << "\n# peak irradiance " << exact(m.peak_irradiance) << " " << irradiance_unit(m)
        << "; centroid (u, v) = (" << exact(m.centroid_u) << ", " << exact(m.centroid_v) << ") "
        << unit << ", (x, y, z) = " << vec_text(m.centroid) << "; rms radius "
        << exact(m.rms_radius) << " " << unit << "\n";
    csv << "u,v,area,E_total";
    for (int b = 0; b < m.bands(); ++b) csv << "," << band_channel_name(m, b);
    csv << "\n";
    for (int c = 0; c < g.cell_count(); ++c) {
        csv << exact(g.cell_u(c)) << "," << exact(g.cell_v(c)) << "," << exact(g.cell_area(c))
            << "," << exact(m.irradiance(c));
        for (int b = 0; b < m.bands(); ++b) csv << "," << exact(m.band_irradiance(b, c));
        csv << "\n";
    }
    return csv.str();
}

void write_detector_files(const DetectorMeasurement& m, const DetectionSettings& settings,
                          const std::string& dir, const std::string& stem, ColourScale scale) {
    const std::vector<std::string> paths = detector_file_paths(dir, stem);
    write_text_atomically(paths[0], detector_csv(m, settings));
    // EXR rows run top to bottom: row 0 is the highest v, as in the picture.
    const DetectorGrid& g = m.grid;
    const int nu = g.cells_u(), nv = g.cells_v();
    std::vector<ExrChannel> channels(static_cast<size_t>(m.bands()) + 1);
    channels[0].name = "E_total";
    for (int b = 0; b < m.bands(); ++b)
        channels[static_cast<size_t>(b) + 1].name = band_channel_name(m, b);
    for (ExrChannel& ch : channels) ch.values.resize(static_cast<size_t>(g.cell_count()));
    for (int c = 0; c < g.cell_count(); ++c) {
        const size_t at = static_cast<size_t>((nv - 1 - c / nu) * nu + c % nu);
        channels[0].values[at] = static_cast<float>(m.irradiance(c));
        for (int b = 0; b < m.bands(); ++b)
            channels[static_cast<size_t>(b) + 1].values[at] =
                static_cast<float>(m.band_irradiance(b, c));
    }
    write_exr_channels(nu, nv, channels, paths[1]);
    write_png_image(detector_image(m, scale), paths[2]);
}

nlohmann::json detector_summary_json(const DetectorMeasurement& m) {
    using nlohmann::json;
    json bands = json::array();
    for (int b = 0; b < m.bands(); ++b) {
        bands.push_back({{"band_nm",
                          {m.settings.band_edges[static_cast<size_t>(b)],
                           m.settings.band_edges[static_cast<size_t>(b) + 1]}},
                         {"power", m.band_total[static_cast<size_t>(b)]}});
    }
    return {{"name", m.name},
            {"object", m.object},
            {"units",
             {{"length", m.settings.unit},
              {"power", "W"},
              {"irradiance", irradiance_unit(m)},
              {"wavelength", "nm"}}},
            {"total_power", m.total_power},
            {"band_powers", bands},
            {"peak_irradiance", m.peak_irradiance},
            {"centroid", {m.centroid.x, m.centroid.y, m.centroid.z}},
            {"centroid_uv", {m.centroid_u, m.centroid_v}},
            {"rms_radius", m.rms_radius},
            {"resolution", {m.grid.cells_u(), m.grid.cells_v()}},
            {"arrivals", m.arrivals}};
}

std::string detector_summary_text(const DetectorMeasurement& m) {
    char buf[512];
    const std::string unit = m.settings.unit;
    std::ostringstream out;
    out << m.name << " (" << m.grid.cells_u() << "x" << m.grid.cells_v() << " cells, " << m.arrivals
        << " photons):\n";
    std::snprintf(buf, sizeof buf, "  total power      %.6g W\n", m.total_power);
    out << buf;
    for (int b = 0; b < m.bands(); ++b) {
        std::snprintf(buf, sizeof buf, "    %-14s %.6g W\n", band_label(m, b).c_str(),
                      m.band_total[static_cast<size_t>(b)]);
        out << buf;
    }
    std::snprintf(buf, sizeof buf, "  peak irradiance  %.6g %s\n", m.peak_irradiance,
                  irradiance_unit(m).c_str());
    out << buf;
    std::snprintf(buf, sizeof buf,
                  "  centroid         (u, v) = (%.6g, %.6g) %s, (x, y, z) = (%.6g, %.6g, %.6g)\n",
                  m.centroid_u, m.centroid_v, unit.c_str(), m.centroid.x, m.centroid.y,
                  m.centroid.z);
    out << buf;
    std::snprintf(buf, sizeof buf, "  rms radius       %.6g %s\n", m.rms_radius, unit.c_str());
    out << buf;
    return out.str();
}

}  // namespace lenslab
