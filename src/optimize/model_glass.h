#pragma once
// Model glasses in a design (docs/optimizer.md#model-glasses-and-substitution): a lens whose
// material is a point (n_d, V_d) of the glass map (`"ior": {"model": "abbe", ...}`), which
// the optimiser may move like a radius, and the catalogue glasses nearest to such a point,
// which glass substitution puts in its place.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "optics/glass.h"

namespace lenslab {

// Whether a scene JSON lens object's material is written inline as a model glass.
bool is_model_glass(const nlohmann::ordered_json& lens);

// The makers' catalogue glasses' extent on the glass map: where a model glass is kept unless
// its variable gives bounds of its own.
struct GlassMapRange {
    double n_d_min, n_d_max, v_d_min, v_d_max;
};
const GlassMapRange& catalogue_glass_range();

// Distance on the glass map, n_d weighted 100 times V_d: 0.01 of index counts as one unit of
// Abbe number, about what each changes a lens's power and colour by (the glass map's own
// aspect, in which catalogue glasses lie about as spread along both axes).
double glass_map_distance(double n_d, double v_d, const Glass& g);

// The `count` catalogue glasses of the `makers` (all makers when empty) nearest to
// (n_d, V_d), nearest first; ties keep the catalogues' order.
std::vector<const Glass*> nearest_catalogue_glasses(double n_d, double v_d,
                                                    const std::vector<std::string>& makers,
                                                    size_t count);

// "MAKER:NAME", as a scene names a maker's glass.
std::string catalogue_glass_name(const Glass& g);

// The lens `object` of a scene JSON made of `glass` instead of its model (its other material
// keys kept).
void set_lens_catalogue_glass(nlohmann::ordered_json& scene, int object, const Glass& glass);

}  // namespace lenslab
