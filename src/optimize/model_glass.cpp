#include "optimize/model_glass.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "optics/glass_library.h"

namespace lenslab {

bool is_model_glass(const nlohmann::ordered_json& lens) {
    const auto material = lens.find("material");
    if (material == lens.end() || !material->is_object() || material->contains("glass"))
        return false;
    const auto ior = material->find("ior");
    return ior != material->end() && ior->is_object() && ior->value("model", "") == "abbe" &&
           ior->contains("n_d") && (*ior)["n_d"].is_number() && ior->contains("V_d") &&
           (*ior)["V_d"].is_number();
}

const GlassMapRange& catalogue_glass_range() {
    static const GlassMapRange range = [] {
        constexpr double kInf = std::numeric_limits<double>::infinity();
        GlassMapRange r{kInf, -kInf, kInf, -kInf};
        for (const Glass& g : maker_glasses()) {
            if (!std::isfinite(g.datasheet_n_d) || !std::isfinite(g.datasheet_v_d)) continue;
            r.n_d_min = std::min(r.n_d_min, g.datasheet_n_d);
            r.n_d_max = std::max(r.n_d_max, g.datasheet_n_d);
            r.v_d_min = std::min(r.v_d_min, g.datasheet_v_d);
            r.v_d_max = std::max(r.v_d_max, g.datasheet_v_d);
        }
        return r;
    }();
    return range;
}

double glass_map_distance(double n_d, double v_d, const Glass& g) {
    return std::hypot(100.0 * (g.datasheet_n_d - n_d), g.datasheet_v_d - v_d);
}

std::vector<const Glass*> nearest_catalogue_glasses(double n_d, double v_d,
                                                    const std::vector<std::string>& makers,
                                                    size_t count) {
    std::vector<const Glass*> glasses;
    for (const Glass& g : maker_glasses()) {
        if (!std::isfinite(g.datasheet_n_d) || !std::isfinite(g.datasheet_v_d)) continue;
        if (!makers.empty() && std::find(makers.begin(), makers.end(), g.maker) == makers.end())
            continue;
        glasses.push_back(&g);
    }
    const size_t kept = std::min(count, glasses.size());
    std::partial_sort(glasses.begin(), glasses.begin() + static_cast<ptrdiff_t>(kept),
                      glasses.end(), [&](const Glass* a, const Glass* b) {
                          const double da = glass_map_distance(n_d, v_d, *a);
                          const double db = glass_map_distance(n_d, v_d, *b);
                          return da < db || (da == db && a < b);
                      });
    glasses.resize(kept);
    return glasses;
}

std::string catalogue_glass_name(const Glass& g) {
    return g.maker.empty() ? g.name : g.maker + ":" + g.name;
}

void set_lens_catalogue_glass(nlohmann::ordered_json& scene, int object, const Glass& glass) {
    nlohmann::ordered_json& material = scene["objects"][object]["material"];
    material.erase("ior");
    material["glass"] = catalogue_glass_name(glass);
}

}  // namespace lenslab
