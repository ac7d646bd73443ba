#include "analysis/aberrations/aberrations.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>

#include "analysis/system/real_ray.h"
#include "optics/refraction.h"

namespace lenslab {

namespace {

bool passes(const OpticalSystem& system, double nm, double height, double z_start) {
    const RealRay r = trace_real_ray(system, {{0, height, z_start}, {0, 0, 1}}, nm);
    return r.fate == RayFate::Passed && r.direction.z * system.image_travel() > 0;
}

// The hexapolar grid of `rings`, worked out once for each ring count a process asks for: it
// depends on nothing else, and its sines and cosines were a tenth of a beam's cost.
const std::vector<PupilPoint>& shared_hexapolar_pupil(int rings) {
    static std::mutex lock;
    static std::map<int, std::vector<PupilPoint>> grids;  // its elements never move
    const std::lock_guard<std::mutex> held(lock);
    auto [grid, fresh] = grids.try_emplace(rings);
    if (fresh) grid->second = hexapolar_pupil(rings);
    return grid->second;
}

// A ray of a beam traced in step with others: where it is, where it goes, whether it is
// still on its way through the surfaces.
struct StepRay {
    Vec3 p, d;
    bool on = true;
};

// A few rays of a beam through a system without gradient index, surface by surface in step:
// each ray's arithmetic is trace_real_ray's, bit for bit, and the processor overlaps one
// ray's chain of square roots and divisions with the others'. A ray that misses a surface
// or is totally reflected there stops (on = false).
void trace_in_step(const OpticalSystem& system, const IndexRatios& ratios, StepRay* rays,
                   size_t count) {
    for (size_t i = 0; i < system.surfaces.size(); ++i) {
        const SystemSurface& s = system.surfaces[i];
        for (StepRay* r = rays; r != rays + count; ++r) {
            if (!r->on) continue;
            const Ray local = s.to_local(r->p, r->d);
            double t = 0;
            if (!s.shape->intersect(local, s.span, 0.0, INFINITY, t)) {
                r->on = false;
                continue;
            }
            r->p = r->p + r->d * t;
            if (s.in_hole(r->p)) {
                r->on = false;
                continue;
            }
            Vec3 n = s.to_system(s.shape->normal(local.at(t)));
            if (dot(n, r->d) > 0) n = -n;  // facing the arriving ray
            if (s.mirror) {
                r->d = reflect(r->d, n);
                continue;
            }
            const auto refracted = refract(r->d, n, ratios.ratios[i]);
            if (!refracted) {
                r->on = false;
                continue;
            }
            r->d = *refracted;
        }
    }
}

}  // namespace

double beam_start_z(const OpticalSystem& system) {
    double z = 0.0;
    for (const SystemSurface& s : system.surfaces) z = std::min(z, s.z_at(s.semi_diameter));
    return z - 0.05 * system.scale();
}

double usable_aperture_radius(const OpticalSystem& system, double nm) {
    const double z0 = beam_start_z(system);
    const double a = system.surfaces.front().semi_diameter;
    if (passes(system, nm, a, z0)) return a;
    // Vignetting by a later, smaller lens or total internal reflection sets in above some
    // height: bisect for it.
    double lo = 0.0, hi = a;
    for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        (passes(system, nm, mid, z0) ? lo : hi) = mid;
    }
    return lo;
}

std::vector<PupilPoint> hexapolar_pupil(int rings) {
    std::vector<PupilPoint> out{{0.0, 0.0}};
    for (int ring = 1; ring <= rings; ++ring) {
        const double rho = static_cast<double>(ring) / rings;
        const int count = 6 * ring;
        for (int k = 0; k < count; ++k) {
            const double phi = 2.0 * M_PI * (k + 0.5 * (ring % 2)) / count;
            out.push_back({rho * std::cos(phi), rho * std::sin(phi)});
        }
    }
    return out;
}

std::vector<ExitRay> trace_collimated_beam(const OpticalSystem& system, double nm, double aperture,
                                           int rings, int* lost) {
    const double z0 = beam_start_z(system);
    const IndexRatios ratios = index_ratios(system, nm);
    const std::vector<PupilPoint>& pupil = shared_hexapolar_pupil(rings);
    std::vector<ExitRay> out;
    out.reserve(pupil.size());
    int missing = 0;
    const auto keep = [&](const Vec3& point, const Vec3& direction, bool passed) {
        if (passed && direction.z * system.image_travel() > 0) {
            out.push_back({point, direction});
        } else {
            ++missing;
        }
    };
    if (system.has_grin()) {
        RealRay r;
        for (const PupilPoint& q : pupil) {
            trace_real_ray_into(r, system, {{aperture * q.x, aperture * q.y, z0}, {0, 0, 1}},
                                ratios);
            keep(r.exit_point(), r.direction, r.fate == RayFate::Passed);
        }
    } else {
        constexpr size_t kInStep = 4;
        for (size_t first = 0; first < pupil.size(); first += kInStep) {
            StepRay rays[kInStep];
            const size_t count = std::min(kInStep, pupil.size() - first);
            for (size_t k = 0; k < count; ++k) {
                const PupilPoint& q = pupil[first + k];
                rays[k] = {{aperture * q.x, aperture * q.y, z0}, {0, 0, 1}};
            }
            trace_in_step(system, ratios, rays, count);
            for (size_t k = 0; k < count; ++k) keep(rays[k].p, rays[k].d, rays[k].on);
        }
    }
    if (lost) *lost = missing;
    return out;
}

std::vector<LsaPoint> longitudinal_spherical_aberration(const OpticalSystem& system,
                                                        const ParaxialResult& paraxial,
                                                        double aperture, int samples) {
    const double z0 = beam_start_z(system);
    std::vector<LsaPoint> out;
    for (int i = 1; i <= samples; ++i) {
        const double h = aperture * i / samples;
        const RealRay r = trace_real_ray(system, {{0, h, z0}, {0, 0, 1}}, paraxial.wavelength_nm);
        if (r.fate != RayFate::Passed || !(r.direction.z * system.image_travel() > 0)) continue;
        const Vec3& p = r.exit_point();
        const Vec3& d = r.direction;
        if (!(std::abs(d.y) > 1e-15)) continue;  // leaves parallel: crosses at infinity
        const double z_cross = p.z - p.y * d.z / d.y;
        out.push_back(
            {h, z_cross - paraxial.z_rear_focus, at_plane(p, d, paraxial.z_rear_focus).y});
    }
    return out;
}

SpotDiagram spot_at(const std::vector<ExitRay>& rays, double z_plane) {
    SpotDiagram s;
    s.z = z_plane;
    if (rays.empty()) return s;
    s.points.reserve(rays.size());
    for (const ExitRay& r : rays) {
        const Vec3 q = at_plane(r.point, r.direction, z_plane);
        s.points.push_back(q);
        s.centroid_x += q.x;
        s.centroid_y += q.y;
    }
    s.centroid_x /= rays.size();
    s.centroid_y /= rays.size();
    double sum = 0.0;
    for (const Vec3& q : s.points) {
        const double r2 = (q.x - s.centroid_x) * (q.x - s.centroid_x) +
                          (q.y - s.centroid_y) * (q.y - s.centroid_y);
        sum += r2;
        s.geometric_radius = std::max(s.geometric_radius, std::sqrt(r2));
    }
    s.rms_radius = std::sqrt(sum / rays.size());
    return s;
}

double best_focus_z(const std::vector<ExitRay>& rays, double z_ref) {
    // Hit at z_ref + s: q_i + s m_i with slopes m_i = (dx, dy) / dz. Centroid-referred:
    // mean |Δq_i + s Δm_i|^2 is least at s = -Σ Δq·Δm / Σ |Δm|^2.
    if (rays.size() < 2) return z_ref;
    std::vector<Vec3> q, m;
    q.reserve(rays.size());
    m.reserve(rays.size());
    Vec3 q_mean, m_mean;
    for (const ExitRay& r : rays) {
        q.push_back(at_plane(r.point, r.direction, z_ref));
        m.push_back({r.direction.x / r.direction.z, r.direction.y / r.direction.z, 0});
        q_mean += q.back();
        m_mean += m.back();
    }
    q_mean = q_mean / rays.size();
    m_mean = m_mean / rays.size();
    double qm = 0.0, mm = 0.0;
    for (size_t i = 0; i < q.size(); ++i) {
        const Vec3 dq = q[i] - q_mean, dm = m[i] - m_mean;
        qm += dq.x * dm.x + dq.y * dm.y;
        mm += dm.x * dm.x + dm.y * dm.y;
    }
    if (!(mm > 0)) return z_ref;  // all rays parallel: every plane is as good
    return z_ref - qm / mm;
}

}  // namespace lenslab
