#pragma once
// Random scenes for property tests: spheres, lenses (report form, and prescriptions whose
// faces are spheres, conics, aspheres, flats or sag formulas), triangles, prisms and
// implicit solids, with random materials (diffuse, mirror, glass with a constant or a
// dispersive index, mixtures, emitters) and random lights of every kind and spectrum.
// Every scene goes through the scene reader, so it is one a user could have written.

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "scene/scene.h"

namespace lenslab::testing {

struct RandomSceneOptions {
    // Glass whose index depends on the wavelength (a catalogue glass, Cauchy, Abbe); without
    // it every photon keeps its light's whole spectrum.
    bool dispersive = true;
    int width = 12, height = 9, spp = 2;
    int64_t photons = 2000;
    int passes = 64;  // sppm
};

// The scene for `seed`, as JSON (for messages) and built. Objects the reader refuses (a lens
// whose random surfaces cross) are drawn again, so every seed gives a scene.
nlohmann::json random_scene_json(uint64_t seed, const RandomSceneOptions& options = {});
Scene random_scene(uint64_t seed, const RandomSceneOptions& options = {});

}  // namespace lenslab::testing
