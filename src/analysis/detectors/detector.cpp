#include "analysis/detectors/detector.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <unordered_map>

#include "cluster/dealt_parts.h"
#include "optics/spectrum.h"
#include "render/photon_tracer.h"
#include "util/scene_error.h"

namespace lenslab {

namespace {

// Photons traced between two merges, and per parallel task.
constexpr int64_t kBatch = 1 << 16;
constexpr int64_t kChunk = 1024;

// Watts a light's whole spectrum carries per unit of photon scale: in total and per band.
struct SpectrumWatts {
    double total = 0;
    std::vector<double> band;
};

// One photon arriving on a detector's counted side.
struct Arrival {
    int detector;
    int cell;
    int band;  // the band of a single-wavelength photon; -1: the light's whole spectrum
    double u, v;
    double watts;
    double scale;  // whole-spectrum photons: the share of their light's spectrum
    int spectrum;  // whole-spectrum photons: index of the light's spectrum in scene.lights()
};

bool counts(DetectorSide side, const Vec3& direction, const Vec3& normal) {
    const double c = dot(direction, normal);
    switch (side) {
        case DetectorSide::Front:
            return c < 0;  // travelling against the normal: onto the front
        case DetectorSide::Back:
            return c > 0;
        case DetectorSide::Both:
            return true;
    }
    return false;
}

int band_of(const std::vector<double>& edges, double nm) {
    const auto it = std::upper_bound(edges.begin(), edges.end(), nm);
    if (it == edges.begin() || it == edges.end())
        return nm == edges.back() ? static_cast<int>(edges.size()) - 2 : -2;
    return static_cast<int>(it - edges.begin()) - 1;
}

void finish(DetectorMeasurement& m, double sum_u, double sum_v, double sum_r2) {
    const DetectorGrid& g = m.grid;
    const double full = g.cell_width() * g.cell_height();
    for (int c = 0; c < g.cell_count(); ++c) {
        if (g.cell_area(c) < 0.5 * full) continue;
        const double e = m.irradiance(c);
        if (m.peak_cell < 0 || e > m.peak_irradiance) {
            m.peak_irradiance = e;
            m.peak_cell = c;
        }
    }
    if (m.total_power > 0) {
        m.centroid_u = sum_u / m.total_power;
        m.centroid_v = sum_v / m.total_power;
        const double r2 =
            sum_r2 / m.total_power - m.centroid_u * m.centroid_u - m.centroid_v * m.centroid_v;
        m.rms_radius = std::sqrt(std::max(0.0, r2));
    }
    m.centroid = g.frame().at(m.centroid_u, m.centroid_v);
}

}  // namespace

double DetectorMeasurement::irradiance(int cell) const {
    const double a = grid.cell_area(cell);
    return a > 0 ? power[static_cast<size_t>(cell)] / a : 0.0;
}

double DetectorMeasurement::band_irradiance(int band, int cell) const {
    const double a = grid.cell_area(cell);
    return a > 0 ? band_power[static_cast<size_t>(band)][static_cast<size_t>(cell)] / a : 0.0;
}

std::vector<int> detector_objects(const Scene& scene) {
    std::vector<int> out;
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        if (scene.objects[i].detector) out.push_back(static_cast<int>(i));
    }
    return out;
}

DetectionResult measure_detectors(const Scene& scene, const DetectionSettings& settings,
                                  RenderControl& control) {
    const auto t0 = std::chrono::steady_clock::now();
    DetectionResult result;
    std::vector<int> detector_of(scene.objects.size(), -1);
    for (int o : detector_objects(scene)) {
        detector_of[static_cast<size_t>(o)] = static_cast<int>(result.detectors.size());
        DetectorMeasurement m;
        m.name = scene.objects[static_cast<size_t>(o)].name;
        m.object = o;
        m.settings = *scene.objects[static_cast<size_t>(o)].detector;
        m.grid = DetectorGrid::for_object(scene.objects[static_cast<size_t>(o)]);
        m.power.assign(static_cast<size_t>(m.grid.cell_count()), 0.0);
        m.band_power.assign(static_cast<size_t>(m.bands()), m.power);
        m.band_total.assign(static_cast<size_t>(m.bands()), 0.0);
        result.detectors.push_back(std::move(m));
    }
    if (result.detectors.empty()) return result;

    // Watts of every light's spectrum per detector's bands, looked up by the spectrum a
    // photon carries (whatever order the tracer numbers lights in).
    std::vector<const Spectrum*> spectra;
    for (const LightPtr& l : scene.lights()) spectra.push_back(&l->spectrum());
    // watts[detector][light]; spectrum_index: a light's spectrum to its index (as numbers, the
    // arrivals can go to another rank).
    std::unordered_map<const Spectrum*, int> spectrum_index;
    for (size_t l = 0; l < spectra.size(); ++l) spectrum_index[spectra[l]] = static_cast<int>(l);
    std::vector<std::vector<SpectrumWatts>> watts(result.detectors.size());
    for (size_t d = 0; d < result.detectors.size(); ++d) {
        const std::vector<double>& edges = result.detectors[d].settings.band_edges;
        for (const Spectrum* s : spectra) {
            SpectrumWatts w;
            w.total = radiant_watts(*s);
            for (size_t b = 0; b + 1 < edges.size(); ++b)
                w.band.push_back(radiant_watts(*s, edges[b], edges[b + 1]));
            watts[d].push_back(w);
        }
    }
    // In a job of several ranks each traces the chunks dealt to it and rank 0 sums all the
    // arrivals in photon order, as one process does: the same maps, byte for byte.
    Communicator& comm = control.cluster();

    PhotonTracingSettings tracing;
    tracing.photons_per_light = settings.photons_per_light;
    tracing.caustic_photons_per_light = settings.caustic_photons_per_light > 0
                                            ? settings.caustic_photons_per_light
                                            : settings.photons_per_light;
    tracing.aim = settings.aim;
    tracing.seed = settings.seed;
    tracing.max_depth = settings.max_depth;
    const PhotonPlan plan = photon_plan(scene, tracing);
    const int64_t total = plan.total();

    tbb::task_arena arena(settings.threads > 0 ? settings.threads : tbb::task_arena::automatic);
    std::vector<double> sum_u(result.detectors.size()), sum_v(sum_u.size()), sum_r2(sum_u.size());
    for (int64_t first = 0; first < total && !control.cancelled(); first += kBatch) {
        const int64_t last = std::min(total, first + kBatch);
        const int64_t chunks = (last - first + kChunk - 1) / kChunk;
        std::vector<std::vector<Arrival>> found(static_cast<size_t>(chunks));
        arena.execute([&] {
            tbb::parallel_for(
                tbb::blocked_range<int64_t>(0, chunks, 1),
                [&](const tbb::blocked_range<int64_t>& r) {
                    for (int64_t chunk = r.begin(); chunk != r.end(); ++chunk) {
                        if (!dealt_to(chunk, comm)) continue;
                        std::vector<Arrival>& out = found[static_cast<size_t>(chunk)];
                        const PhotonArrivalFn on_arrival = [&](const PhotonArrival& a) {
                            const int d =
                                detector_of[static_cast<size_t>(a.interaction->hit.object)];
                            if (d < 0) return;
                            const DetectorMeasurement& m = result.detectors[static_cast<size_t>(d)];
                            if (!counts(m.settings.side, a.direction, m.grid.frame().n)) return;
                            Arrival rec{};
                            rec.detector = d;
                            rec.u = m.grid.frame().u_of(a.interaction->point());
                            rec.v = m.grid.frame().v_of(a.interaction->point());
                            rec.cell = m.grid.cell_at(rec.u, rec.v);
                            const auto it = spectrum_index.find(a.spectrum);
                            if (it == spectrum_index.end())
                                throw std::logic_error("detector: a photon from an unknown light");
                            const SpectrumWatts& w =
                                watts[static_cast<size_t>(d)][static_cast<size_t>(it->second)];
                            if (a.lambda_nm > 0) {
                                // Dispersed: its whole share of the light's power, at one
                                // wavelength.
                                rec.band = band_of(m.settings.band_edges, a.lambda_nm);
                                rec.watts = a.scale * w.total;
                            } else {
                                rec.band = -1;
                                rec.spectrum = it->second;
                                rec.scale = a.scale;
                                rec.watts = a.scale * w.total;
                            }
                            out.push_back(rec);
                        };
                        const int64_t begin = first + (chunk * kChunk),
                                      end = std::min(last, begin + kChunk);
                        for (int64_t g = begin; g < end; ++g) {
                            trace_photon_path(scene, tracing, plan, g, on_arrival);
                        }
                    }
                });
        });
        gather_dealt_parts_to_root(comm, found);
        // Summed in photon order, so the result does not depend on the threads.
        for (const std::vector<Arrival>& chunk : found) {
            for (const Arrival& a : chunk) {
                DetectorMeasurement& m = result.detectors[static_cast<size_t>(a.detector)];
                const size_t c = static_cast<size_t>(a.cell);
                m.power[c] += a.watts;
                m.total_power += a.watts;
                ++m.arrivals;
                if (a.band >= 0) {
                    m.band_power[static_cast<size_t>(a.band)][c] += a.watts;
                    m.band_total[static_cast<size_t>(a.band)] += a.watts;
                } else if (a.band == -1) {
                    for (size_t b = 0; b < m.band_power.size(); ++b) {
                        const double w =
                            a.scale *
                            watts[static_cast<size_t>(a.detector)][static_cast<size_t>(a.spectrum)]
                                .band[b];
                        m.band_power[b][c] += w;
                        m.band_total[b] += w;
                    }
                }
                const size_t d = static_cast<size_t>(a.detector);
                sum_u[d] += a.watts * a.u;
                sum_v[d] += a.watts * a.v;
                sum_r2[d] += a.watts * (a.u * a.u + a.v * a.v);
            }
        }
        control.report(static_cast<double>(last) / static_cast<double>(total));
    }
    result.cancelled = control.cancelled();
    result.photons_emitted = total;
    result.photons_aimed = plan.aimed_total();
    for (size_t d = 0; d < result.detectors.size(); ++d)
        finish(result.detectors[d], sum_u[d], sum_v[d], sum_r2[d]);
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return result;
}

DetectionResult measure_detectors(const Scene& scene, const DetectionSettings& settings) {
    RenderControl control;
    return measure_detectors(scene, settings, control);
}

}  // namespace lenslab
