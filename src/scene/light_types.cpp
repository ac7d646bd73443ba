#include "scene/light_types.h"

namespace lenslab {

// Each kind's file defines its entry: light_json.cpp the classic four, and one file each for
// the area lights.
LightTypeEntry point_light_type();
LightTypeEntry beam_light_type();
LightTypeEntry laser_light_type();
LightTypeEntry spot_light_type();
LightTypeEntry rectangle_light_type();
LightTypeEntry disc_light_type();

const std::vector<LightTypeEntry>& light_types() {
    static const std::vector<LightTypeEntry> types{
        point_light_type(), beam_light_type(),      laser_light_type(),
        spot_light_type(),  rectangle_light_type(), disc_light_type(),
    };
    return types;
}

const LightTypeEntry* find_light_type(const std::string& name) {
    for (const LightTypeEntry& e : light_types()) {
        if (e.name == name) return &e;
    }
    return nullptr;
}

const std::vector<const ElementSpec*>& light_specs() {
    static const std::vector<const ElementSpec*> specs = [] {
        std::vector<const ElementSpec*> out;
        for (const LightTypeEntry& e : light_types()) out.push_back(&e.spec());
        return out;
    }();
    return specs;
}

const ElementSpec* find_light_spec(const std::string& type) {
    const LightTypeEntry* e = find_light_type(type);
    return e ? &e->spec() : nullptr;
}

}  // namespace lenslab
