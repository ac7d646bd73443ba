#pragma once
// A homogeneous participating medium (fog, smoke, milky water): light is absorbed and
// scattered at rates given per unit length of the scene, in each of the three bands RGB
// colours become (spectrum.h), and scattered with a Henyey–Greenstein phase function
// (optics/phase_function.h). Travelling a distance d, light keeps exp(-sigma_t d) of its
// power, sigma_t = absorption + scattering (Beer–Lambert).

#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>

#include "optics/spectrum.h"
#include "scene/param_spec.h"

namespace lenslab {

struct Medium {
    BandWeights absorption{0, 0, 0};  // sigma_a per scene unit, per band
    BandWeights scattering{0, 0, 0};  // sigma_s per scene unit, per band
    double g = 0;                     // Henyey–Greenstein mean cosine

    BandWeights extinction() const {
        return {absorption[0] + scattering[0], absorption[1] + scattering[1],
                absorption[2] + scattering[2]};
    }
    // exp(-sigma_t d) in each band.
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

// Reads a medium object at JSON path `path`. Throws SceneError.
Medium read_medium(const nlohmann::json& j, const std::string& path);

// The scene's atmosphere from its `"atmosphere"` object: none when it is clear (no light is
// lost in it, so the tracers need not look for media). Throws SceneError.
std::optional<Medium> read_atmosphere(const nlohmann::json& j);

}  // namespace lenslab
