#pragma once
// The scene's top-level choices that say how its materials' catalogue data is read:
// "ambient" (indices relative to air, as catalogues give them, or absolute) and
// "length_unit_mm" (how a catalogue's absorption per millimetre meets scene lengths).

#include <vector>

#include "scene/material.h"

namespace lenslab {

struct SceneMediumConvention {
    bool vacuum = false;   // "ambient": "vacuum": absolute indices at vacuum wavelengths
    double unit_mm = 1.0;  // one scene length unit in millimetres
};

// Applies the convention to the materials read from catalogue glasses (Material::glass set):
// their absorption from the glass's k data, and under vacuum their index made absolute.
// Materials given by `ior` are taken as written: relative to the ambient medium.
void apply_medium_convention(const SceneMediumConvention& convention,
                             std::vector<Material>& materials);

}  // namespace lenslab
