#pragma once
// A homogeneous participating medium (fog, smoke, milky water): light is absorbed and
// scattered at rates given per unit length of the scene, in each of the three bands RGB
// colours become (spectrum.h), and scattered with a Henyey–Greenstein phase function
// (optics/phase_function.h). Travelling a distance d, light keeps exp(-sigma_t d) of its
// power, sigma_t = absorption + scattering (Beer–Lambert).
//
// With a `density` (scene/medium_density.h) the medium is heterogeneous: both coefficients
// are multiplied by f(x) at each point, and transmittance is exp(-sigma_t \int f) along the
// way; the tracers then use delta and ratio tracking (render/density_tracking.h) instead of
// the closed forms below, which hold for the homogeneous medium only.

#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>

#include "optics/spectrum.h"
#include "scene/medium_density.h"
#include "scene/param_spec.h"

namespace lenslab {

struct Medium {
    BandWeights absorption{0, 0, 0};  // sigma_a per scene unit, per band
    BandWeights scattering{0, 0, 0};  // sigma_s per scene unit, per band
    double g = 0;                     // Henyey–Greenstein mean cosine
    // f(x) multiplying both coefficients; none: the same everywhere (homogeneous).
    std::shared_ptr<const MediumDensity> density;

    bool is_heterogeneous() const { return density != nullptr; }

    BandWeights extinction() const {
        return {absorption[0] + scattering[0], absorption[1] + scattering[1],
                absorption[2] + scattering[2]};
    }
    // exp(-sigma_t d) in each band: a homogeneous medium's transmittance.
    BandWeights transmittance(double d) const;
    bool is_clear() const { return extinction() == BandWeights{0, 0, 0}; }
    // The same in every band: light of any colour keeps its colour through it.
    bool is_grey() const {
        return absorption[0] == absorption[1] && absorption[1] == absorption[2] &&
               scattering[0] == scattering[1] && scattering[1] == scattering[2];
    }
};

// The keys of a medium (a shape's `medium`, the scene's `atmosphere`).
const ElementSpec& medium_spec();

// Reads a medium object at JSON path `path`, filling `region` (a shape's bounding box, the
// scene's bounds for the atmosphere): a density's majorant is estimated, and checked, over
// it. Throws SceneError.
Medium read_medium(const nlohmann::json& j, const std::string& path, const Aabb& region);

// The scene's atmosphere from its `"atmosphere"` object, over `region`: none when it is
// clear (no light is lost in it, so the tracers need not look for media). Throws SceneError.
std::optional<Medium> read_atmosphere(const nlohmann::json& j, const Aabb& region);

// Whether an atmosphere object has a density, which needs the scene's bounds to be read.
bool atmosphere_needs_region(const nlohmann::json& j);

}  // namespace lenslab
