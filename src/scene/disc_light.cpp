// The disc area light (`"type": "disc_light"`): its declaration, its reader and its sampling,
// in one file with the entry light_types.cpp lists (area_light_source.h says how it emits).

#include "math/constants.h"
#include "math/sampling.h"
#include "scene/area_light_source.h"
#include "scene/light_spec.h"
#include "scene/light_types.h"
#include "scene/planar_json.h"
#include "scene/spectral_json.h"

namespace lenslab {

namespace {

class DiscLight final : public AreaLightSource {
public:
    DiscLight(SpectrumPtr flux, const PlaneFrame& frame, double radius)
        : AreaLightSource(std::move(flux), frame, {radius, radius}), m_radius(radius) {}

private:
    // Concentric: neighbouring strata stay neighbours on the disc.
    std::array<double, 2> sample_uv(double u1, double u2) const override {
        double x, y;
        sample_disc_concentric(u1, u2, x, y);
        return {x * m_radius, y * m_radius};
    }

    double m_radius;
};

ElementSpec declare_disc_light() {
    ElementSpec s{"disc light", "a disc light", {}, {}};
    s.params = {
        string_param("type", "disc_light").needed().describe("\"disc_light\""),
        point_param("center").describe("centre of the glowing disc").in_editor("Centre"),
        direction_param("normal").describe("the side it lights (its front)").in_editor("Normal"),
        number_param("radius", 0).above(0).needed().describe("radius").in_editor("Radius"),
    };
    for (ParamSpec& p : light_emission_params(Rgb{1, 1, 1})) s.params.push_back(std::move(p));
    s.example = nlohmann::json::parse(
        R"json({"type": "disc_light", "center": [0, 2, 0], "normal": [0, -1, 0], "radius": 0.3, "power": 50})json");
    return s;
}

const ElementSpec& disc_light_spec() {
    static const ElementSpec spec = declare_disc_light();
    return spec;
}

void read_disc_light(SpecReader& r, SceneLights& lights) {
    const Vec3 centre = r.point("center");
    const Vec3 normal = r.unit_vector("normal");
    const double radius = r.real("radius");
    Rgb colour{1, 1, 1};
    const SpectrumPtr flux = light_spectrum(r, colour, r.real("power"));
    lights.areas.push_back(std::make_shared<DiscLight>(
        flux, PlaneFrame::from_normal_up(centre, normal, default_plane_up(normal)), radius));
}

}  // namespace

LightTypeEntry disc_light_type() { return {"disc_light", &disc_light_spec, &read_disc_light}; }

}  // namespace lenslab
