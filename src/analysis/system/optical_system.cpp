#include "analysis/system/optical_system.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "geometry/lens/flat_surface.h"
#include "scene/scattering.h"
#include "util/scene_error.h"

namespace lenslab {

namespace {

// Six digits, as the builder's messages give numbers.
std::string stop_number(double v) {
    std::ostringstream s;
    s.precision(6);
    s << v;
    return s.str();
}

}  // namespace

double OpticalSystem::n_before(size_t i, double nm) const {
    const SystemSurface& s = surfaces[i];
    return s.travel * index_at(s.element_before, {0, 0, s.z}, nm);
}

double OpticalSystem::n_after(size_t i, double nm) const {
    const SystemSurface& s = surfaces[i];
    return s.travel_after() * index_at(s.element_after, {0, 0, s.z}, nm);
}

double OpticalSystem::index_at(int element, const Vec3& p, double nm) const {
    if (element < 0) return kOutsideIor;
    const SystemElement& e = elements[element];
    if (!e.grin) return e.index->n(nm);
    // As the renderer scales a profile: n(p, lambda) = n(p) n(lambda) / n_d (scene/material.h).
    const double scale = e.index->n(nm) / e.index->n(kLineD);
    return scale * e.grin->index(to_world(p) - e.grin_centre);
}

bool OpticalSystem::has_grin() const {
    return std::any_of(elements.begin(), elements.end(),
                       [](const SystemElement& e) { return e.grin != nullptr; });
}

bool OpticalSystem::folded() const {
    return std::any_of(surfaces.begin(), surfaces.end(),
                       [](const SystemSurface& s) { return s.mirror; });
}

bool OpticalSystem::coaxial() const {
    return std::none_of(surfaces.begin(), surfaces.end(),
                        [](const SystemSurface& s) { return s.pose.has_value(); });
}

double OpticalSystem::max_semi_diameter() const {
    double a = 0.0;
    for (const SystemElement& e : elements) a = std::max(a, e.semi_diameter);
    for (const SystemSurface& s : surfaces) {
        if (s.mirror) a = std::max(a, s.semi_diameter);
    }
    return a;
}

double OpticalSystem::scale() const {
    double low = 0.0, high = 0.0;
    for (const SystemSurface& s : surfaces) {
        low = std::min(low, s.z);
        high = std::max(high, s.z);
    }
    return std::max(high - low, 2.0 * max_semi_diameter());
}

std::optional<int> surface_at(const OpticalSystem& system, double z) {
    const double length = std::max(system.scale(), system.max_semi_diameter());
    for (size_t i = 0; i < system.surfaces.size(); ++i) {
        if (std::abs(system.surfaces[i].z - z) <= 1e-9 * length) return static_cast<int>(i);
    }
    return std::nullopt;
}

int insert_air_stop(OpticalSystem& system, double z, double semi_diameter) {
    for (const SystemElement& e : system.elements) {
        const double a = system.surfaces[e.first_surface].z;
        const double b = system.surfaces[e.last_surface].z;
        if (z > std::min(a, b) && z < std::max(a, b)) {
            throw SceneError(e.path, "the aperture stop at " + stop_number(z) +
                                         " from the first vertex lies inside this lens");
        }
    }
    // The first place along the light's way where it crosses the plane z in air: in front of
    // the first surface, or in a space between two or after the last (a folded system crosses
    // a plane more than once; the first crossing is taken).
    std::optional<size_t> index;
    if (z <= system.surfaces.front().z) index = 0;
    for (size_t k = 0; !index && k < system.surfaces.size(); ++k) {
        const SystemSurface& s = system.surfaces[k];
        const double travel = s.travel_after();
        const double next =
            k + 1 == system.surfaces.size() ? travel * INFINITY : system.surfaces[k + 1].z;
        if (s.element_after < 0 && (z - s.z) * travel >= 0 && (next - z) * travel > 0) {
            index = k + 1;
        }
    }
    if (!index) {
        throw SceneError("--stop", "the light never crosses the aperture stop's plane at " +
                                       stop_number(z) + " in air");
    }
    SystemSurface stop;
    stop.shape = std::make_shared<FlatSurface>();
    stop.z = z;
    stop.travel = *index == 0 ? 1.0 : system.surfaces[*index - 1].travel_after();
    stop.semi_diameter = semi_diameter;
    stop.span = intersect_span(*stop.shape, semi_diameter);
    stop.aim_span = intersect_span(*stop.shape, 2.0 * semi_diameter);
    stop.label = "stop";
    const int at = static_cast<int>(*index);
    system.surfaces.insert(system.surfaces.begin() + at, stop);
    for (SystemElement& e : system.elements) {
        if (e.first_surface >= at) ++e.first_surface;
        if (e.last_surface >= at) ++e.last_surface;
    }
    return at;
}

void check_wavelength(const OpticalSystem& system, double nm, const std::string& what) {
    for (const SystemElement& e : system.elements) {
        if (nm < e.index->min_nm || nm > e.index->max_nm) {
            throw SceneError(e.path + ".material",
                             what + " " + stop_number(nm) + " nm is outside the validity range " +
                                 stop_number(e.index->min_nm) + "-" + stop_number(e.index->max_nm) +
                                 " nm of " + e.glass);
        }
    }
}

}  // namespace lenslab
