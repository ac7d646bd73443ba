#include "random_scene.h"

#include <random>
#include <vector>

#include "scene/json_reader.h"
#include "scene/scene_json.h"

namespace lenslab::testing {

namespace {

using nlohmann::json;

class Draw {
public:
    explicit Draw(uint64_t seed) : m_rng(seed) {}
    double uniform(double lo, double hi) {
        return std::uniform_real_distribution<double>(lo, hi)(m_rng);
    }
    int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(m_rng); }
    bool chance(double p) { return uniform(0, 1) < p; }
    json point(double lo, double hi) { return {uniform(lo, hi), uniform(lo, hi), uniform(lo, hi)}; }
    json direction() {
        for (;;) {
            const double x = uniform(-1, 1), y = uniform(-1, 1), z = uniform(-1, 1);
            if (x * x + y * y + z * z > 0.01) return {x, y, z};
        }
    }
    json colour() { return {uniform(0, 1), uniform(0, 1), uniform(0, 1)}; }

private:
    std::mt19937_64 m_rng;
};

json index_of_refraction(Draw& d, bool dispersive) {
    if (!dispersive || d.chance(0.4)) return d.uniform(1.05, 2.4);
    switch (d.integer(0, 2)) {
        case 0:
            return {{"model", "cauchy"},
                    {"A", d.uniform(1.3, 1.8)},
                    {"B", d.uniform(0.001, 0.02)},
                    {"C", 0}};
        case 1:
            return {{"model", "abbe"}, {"n_d", d.uniform(1.4, 1.9)}, {"V_d", d.uniform(20, 80)}};
        default:
            return nullptr;  // a catalogue glass, below
    }
}

json material(Draw& d, bool dispersive, bool may_emit) {
    json m = {{"color", d.colour()}};
    switch (d.integer(0, may_emit ? 5 : 4)) {
        case 0:
            break;  // diffuse
        case 1:
            m["specular"] = d.uniform(0.5, 1.0);
            m["color"] = d.uniform(0, 1);
            break;  // mirror
        case 2:
        case 3: {  // glass, clear or tinted, sometimes partly mirrored
            const double t = d.uniform(0.5, 1.0);
            m["transparency"] = t;
            if (d.chance(0.3)) m["specular"] = d.uniform(0, 1.0 - t);
            const json n = index_of_refraction(d, dispersive);
            if (n.is_null()) {
                static const char* kGlasses[] = {"N-BK7", "N-SF11", "N-FK51A", "water", "PMMA"};
                m["glass"] = kGlasses[d.integer(0, 4)];
            } else {
                m["ior"] = n;
            }
            break;
        }
        case 4: {  // any mixture
            const double t = d.uniform(0, 1), s = d.uniform(0, 1.0 - t);
            m["transparency"] = t;
            m["specular"] = s;
            m["ior"] = d.uniform(1.1, 2.0);
            break;
        }
        default:  // an emitter (spheres only)
            m["emission"] = {{"color", d.colour()}, {"intensity", d.uniform(0.5, 20)}};
    }
    return m;
}

json spectrum_or_colour(Draw& d, json light) {
    switch (d.integer(0, 4)) {
        case 0:
            light["color"] = d.colour();
            break;
        case 1:
            light["spectrum"] = "d65";
            break;
        case 2:
            light["spectrum"] = {{"blackbody", d.uniform(1500, 20000)}};
            break;
        case 3:
            light["spectrum"] = {{"line", d.uniform(400, 700)}, {"width", d.uniform(0.01, 5)}};
            break;
        default:
            break;  // white
    }
    return light;
}

json lens_surface(Draw& d, double semi_diameter, double sign) {
    const double radius = sign * d.uniform(1.3, 6.0) * semi_diameter;
    switch (d.integer(0, 4)) {
        case 0:
            return {{"shape", "flat"}};
        case 1:
            return {{"shape", "sphere"}, {"radius", radius}};
        case 2:
            return {{"shape", "conic"}, {"radius", radius}, {"k", d.uniform(-3, 0.5)}};
        case 3:
            return {{"shape", "asphere"},
                    {"radius", radius},
                    {"k", d.uniform(-1, 0)},
                    {"coefficients", {d.uniform(-1e-3, 1e-3), d.uniform(-1e-5, 1e-5)}}};
        default: {
            const double c = 1.0 / radius;
            return {{"shape", "sag"},
                    {"formula", std::to_string(0.5 * c) + " * r^2 + " +
                                    std::to_string(d.uniform(-0.01, 0.01)) + " * x^2 * y"}};
        }
    }
}

json object(Draw& d, bool dispersive) {
    const json centre = {d.uniform(-2, 2), d.uniform(0.2, 2), d.uniform(-2, 2)};
    switch (d.integer(0, 5)) {
        case 0:
            return {{"type", "sphere"},
                    {"center", centre},
                    {"radius", d.uniform(0.1, 0.8)},
                    {"material", material(d, dispersive, true)}};
        case 1: {
            const double r = d.uniform(0.5, 2);
            return {{"type", "lens"},
                    {"center", centre},
                    {"axis", d.direction()},
                    {"curvature_radius", r},
                    {"aperture_radius", d.uniform(0.1, r)},
                    {"material", material(d, dispersive, false)}};
        }
        case 2: {
            const double diameter = d.uniform(0.3, 2);
            return {{"type", "lens"},
                    {"center", centre},
                    {"axis", d.direction()},
                    {"thickness", d.uniform(0.05, 0.8)},
                    {"diameter", diameter},
                    {"front", lens_surface(d, diameter / 2, 1)},
                    {"back", lens_surface(d, diameter / 2, -1)},
                    {"material", material(d, dispersive, false)}};
        }
        case 3:
            return {{"type", "triangle"},
                    {"vertices", {d.point(-3, 3), d.point(-3, 3), d.point(-3, 3)}},
                    {"material", material(d, dispersive, false)}};
        case 4:
            return {{"type", "prism"},
                    {"center", centre},
                    {"apex_angle", d.uniform(10, 170)},
                    {"side", d.uniform(0.2, 1.5)},
                    {"height", d.uniform(0.2, 1.5)},
                    {"material", material(d, dispersive, false)}};
        default: {
            const double a = d.uniform(0.2, 0.8);
            return {{"type", "implicit"},
                    {"center", centre},
                    {"formula", "x^4 + y^4 + z^4 - " + std::to_string(a * a * a * a)},
                    {"bounds", {{-1, -1, -1}, {1, 1, 1}}},
                    {"material", material(d, dispersive, false)}};
        }
    }
}

json light(Draw& d) {
    if (d.chance(0.5)) {
        return spectrum_or_colour(
            d, {{"type", "point"},
                {"position", {d.uniform(-3, 3), d.uniform(2, 5), d.uniform(-3, 3)}},
                {"power", d.uniform(10, 500)}});
    }
    const json target = {d.uniform(-1, 1), d.uniform(0, 1), d.uniform(-1, 1)};
    const json origin = {d.uniform(-4, 4), d.uniform(1, 5), d.uniform(-4, 4)};
    json dir = {target[0].get<double>() - origin[0].get<double>(),
                target[1].get<double>() - origin[1].get<double>(),
                target[2].get<double>() - origin[2].get<double>()};
    return spectrum_or_colour(d, {{"type", "beam"},
                                  {"origin", origin},
                                  {"direction", dir},
                                  {"radius", d.uniform(0.05, 1)},
                                  {"power", d.uniform(1, 50)}});
}

bool readable(const json& scene) {
    try {
        (void)scene_from_json(scene);
        return true;
    } catch (const SceneError&) {
        return false;
    }
}

}  // namespace

json random_scene_json(uint64_t seed, const RandomSceneOptions& o) {
    Draw d(seed);
    static const char* kFilters[] = {"cone", "gaussian", "box"};
    json scene = {{"camera",
                   {{"position", {d.uniform(-1, 1), d.uniform(2, 4), d.uniform(6, 9)}},
                    {"look_at", {0, 0.7, 0}},
                    {"fov", d.uniform(30, 80)}}},
                  {"render",
                   {{"width", o.width},
                    {"height", o.height},
                    {"spp", o.spp},
                    {"seed", d.integer(0, 1000)},
                    {"max_depth", d.integer(0, 12)},
                    {"photons", o.photons},
                    {"passes", o.passes},
                    {"radius", d.uniform(0.05, 0.5)},
                    {"filter", kFilters[d.integer(0, 2)]},
                    {"light_samples", d.integer(1, 3)},
                    {"direct", d.chance(0.5) ? "shadow_rays" : "photon_map"},
                    {"ambient", d.chance(0.3) ? d.uniform(0, 0.1) : 0.0},
                    {"background", d.chance(0.3) ? d.uniform(0, 0.2) : 0.0}}},
                  {"objects", json::array()},
                  {"lights", json::array()}};
    // A floor, so light has somewhere to land.
    const json floor_material = {{"color", d.colour()}};
    scene["objects"].push_back({{"type", "triangle"},
                                {"vertices", {{-6, 0, -6}, {-6, 0, 6}, {6, 0, 6}}},
                                {"material", floor_material}});
    scene["objects"].push_back({{"type", "triangle"},
                                {"vertices", {{-6, 0, -6}, {6, 0, 6}, {6, 0, -6}}},
                                {"material", floor_material}});
    const int objects = d.integer(2, 7);
    for (int i = 0; i < objects; ++i) {
        for (int attempt = 0; attempt < 20; ++attempt) {
            json trial = scene;
            trial["objects"].push_back(object(d, o.dispersive));
            if (readable(trial)) {
                scene = std::move(trial);
                break;
            }
        }
    }
    const int lights = d.integer(1, 3);
    for (int i = 0; i < lights; ++i) scene["lights"].push_back(light(d));
    return scene;
}

Scene random_scene(uint64_t seed, const RandomSceneOptions& options) {
    return scene_from_json(random_scene_json(seed, options));
}

}  // namespace lenslab::testing
