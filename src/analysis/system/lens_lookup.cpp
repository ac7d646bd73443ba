#include "analysis/system/lens_lookup.h"

namespace lenslab {

LensLookup find_lens(const Scene& scene, const std::string& name) {
    LensLookup lookup;
    for (int i = 0; i < static_cast<int>(scene.objects.size()); ++i) {
        const SceneObject& o = scene.objects[i];
        if (o.type != ObjectType::Lens) continue;
        // A lens group's elements answer to the group's name too.
        lookup.known += (lookup.known.empty() ? "" : ", ") + o.name +
                        (o.group.empty() ? "" : " [" + o.group + "]");
        if (o.name == name || o.group == name ||
            "objects[" + std::to_string(o.source) + "]" == name) {
            lookup.index = i;
            return lookup;
        }
    }
    return lookup;
}

std::string no_lens_message(const std::string& name, const std::string& where,
                            const LensLookup& lookup) {
    return "no lens named '" + name + "' in " + where +
           (lookup.known.empty() ? " (it has no lens)" : " (lenses: " + lookup.known + ")");
}

}  // namespace lenslab
