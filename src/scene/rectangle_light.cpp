// The rectangular area light (`"type": "rectangle_light"`): its declaration, its reader and
// its sampling, in one file with the entry light_types.cpp lists (area_light_source.h says
// how it emits).

#include "math/constants.h"
#include "scene/area_light_source.h"
#include "scene/light_spec.h"
#include "scene/light_types.h"
#include "scene/planar_json.h"
#include "scene/spectral_json.h"

namespace lenslab {

namespace {

class RectangleLight final : public AreaLightSource {
public:
    RectangleLight(SpectrumPtr flux, const PlaneFrame& frame, double width, double height)
        : AreaLightSource(std::move(flux), frame, {0.5 * width, 0.5 * height}),
          m_width(width),
          m_height(height) {}

private:
    std::array<double, 2> sample_uv(double u1, double u2) const override {
        return {(u1 - 0.5) * m_width, (u2 - 0.5) * m_height};
    }

    double m_width, m_height;
};

ElementSpec declare_rectangle_light() {
    ElementSpec s{"rectangle light", "a rectangle light", {}, {}};
    s.params = {
        string_param("type", "rectangle_light").needed().describe("\"rectangle_light\""),
        point_param("center").describe("centre of the glowing rectangle").in_editor("Centre"),
        direction_param("normal").describe("the side it lights (its front)").in_editor("Normal"),
        // The rectangle object's own, read by the same read_plane_size and read_plane_up.
        rectangle_spec().param("size"),
        rectangle_spec().param("up"),
    };
    for (ParamSpec& p : light_emission_params(Rgb{1, 1, 1})) s.params.push_back(std::move(p));
    s.example = nlohmann::json::parse(
        R"json({"type": "rectangle_light", "center": [0, 2, 0], "normal": [0, -1, 0], "size": [1, 0.5], "power": 50})json");
    return s;
}

const ElementSpec& rectangle_light_spec() {
    static const ElementSpec spec = declare_rectangle_light();
    return spec;
}

void read_rectangle_light(SpecReader& r, SceneLights& lights) {
    const Vec3 centre = r.point("center");
    const Vec3 normal = r.unit_vector("normal");
    const std::array<double, 2> size = read_plane_size(r);
    const Vec3 up = read_plane_up(r, normal);
    Rgb colour{1, 1, 1};
    const SpectrumPtr flux = light_spectrum(r, colour, r.real("power"));
    lights.areas.push_back(std::make_shared<RectangleLight>(
        flux, PlaneFrame::from_normal_up(centre, normal, up), size[0], size[1]));
}

}  // namespace

LightTypeEntry rectangle_light_type() {
    return {"rectangle_light", &rectangle_light_spec, &read_rectangle_light};
}

}  // namespace lenslab
