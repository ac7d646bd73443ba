#include "scene/light_json.h"

#include "scene/json_reader.h"
#include "scene/light_spec.h"
#include "scene/light_types.h"
#include "scene/limits.h"
#include "scene/spec_reader.h"
#include "scene/spectral_json.h"

namespace lenslab {

namespace {

using nlohmann::json;

// An axis across the beam: given (not parallel to the direction), or the automatic one;
// made square to the direction.
Vec3 read_beam_axis(SpecReader& r, const std::string& key, const Vec3& direction,
                    const Vec3& automatic) {
    if (!r.has(key)) return automatic;
    const Vec3 axis = r.unit_vector(key);
    if (length(cross(axis, direction)) < 1e-6)
        throw SceneError(r.child_path(key), "must not be parallel to direction");
    return normalize(axis - direction * dot(axis, direction));
}

// A beam's slit or a line laser's fan (light.h).
void read_beam_shape(SpecReader& r, BeamLight& b) {
    b.slit_width = r.real("slit_width");
    b.fan_angle = r.real("fan_angle");
    if (b.slit_width > 2.0 * b.radius) {
        throw SceneError(r.child_path("slit_width"), "must be at most 2 radius (" +
                                                         format_number(2.0 * b.radius) + "), got " +
                                                         format_number(b.slit_width));
    }
    if (b.slit_width > 0.0 && b.fan_angle > 0.0) {
        throw SceneError(r.child_path("slit_width"),
                         "a slit and a fan (fan_angle) do not go together: give one");
    }
    b.slit_axis = read_beam_axis(r, "slit_axis", b.direction, default_slit_axis(b.direction));
    b.fan_axis = read_beam_axis(r, "fan_axis", b.direction, default_fan_axis(b.direction));
}

void read_point(SpecReader& r, SceneLights& lights) {
    PointLight l;
    l.position = r.point("position");
    l.power = r.real("power");
    l.spectrum = light_spectrum(r, l.color, l.power);
    lights.points.push_back(l);
}

// A laser is a beam of one line, placed by its `position`.
void read_beam_or_laser(SpecReader& r, SceneLights& lights, bool laser) {
    BeamLight b;
    b.origin = r.point(laser ? "position" : "origin");
    b.direction = r.unit_vector("direction");
    b.radius = r.real("radius");
    b.power = r.real("power");
    b.spectrum = laser ? laser_spectrum(r, r.real("wavelength"), b.power)
                       : light_spectrum(r, b.color, b.power);
    read_beam_shape(r, b);
    lights.beams.push_back(b);
}

void read_spot(SpecReader& r, SceneLights& lights) {
    SpotLight l;
    l.position = r.point("position");
    l.direction = r.unit_vector("direction");
    l.cone_angle = r.real("cone_angle");
    l.falloff = r.real("falloff");
    if (l.falloff > l.cone_angle) {
        throw SceneError(r.child_path("falloff"), "must be at most cone_angle (" +
                                                      format_number(l.cone_angle) + "), got " +
                                                      format_number(l.falloff));
    }
    l.power = r.real("power");
    l.spectrum = light_spectrum(r, l.color, l.power);
    lights.spots.push_back(l);
}

void read_light(const json& j, const std::string& path, SceneLights& lights) {
    const std::string type = read_type_key(j, path);
    const LightTypeEntry* kind = find_light_type(type);
    if (!kind) {
        std::string known;
        for (const LightTypeEntry& e : light_types()) known += (known.empty() ? "" : ", ") + e.name;
        throw SceneError(path + ".type",
                         "unknown light type '" + type + "' (known: " + known + ")");
    }
    SpecReader r(j, path, kind->spec());
    kind->read(r, lights);
}

}  // namespace

SceneLights lights_from_json(const nlohmann::json& lights) {
    if (!lights.is_array()) throw SceneError("lights", "must be an array");
    check_count(lights.size(), kMaxLights, "lights", "lights");
    SceneLights out;
    for (size_t i = 0; i < lights.size(); ++i)
        read_light(lights[i], element_path("lights", i), out);
    return out;
}

// The classic kinds' entries in the table of light_types.cpp.
LightTypeEntry point_light_type() { return {"point", &point_light_spec, &read_point}; }
LightTypeEntry beam_light_type() {
    return {"beam", &beam_spec,
            [](SpecReader& r, SceneLights& l) { read_beam_or_laser(r, l, false); }};
}
LightTypeEntry laser_light_type() {
    return {"laser", &laser_spec,
            [](SpecReader& r, SceneLights& l) { read_beam_or_laser(r, l, true); }};
}
LightTypeEntry spot_light_type() { return {"spot", &spot_light_spec, &read_spot}; }

}  // namespace lenslab
