#include "scene/medium_convention.h"

#include "optics/air_index.h"
#include "optics/glass_library.h"

namespace lenslab {

void apply_medium_convention(const SceneMediumConvention& convention,
                             std::vector<Material>& materials) {
    for (Material& m : materials) {
        if (m.glass.empty()) continue;
        // The reader stored a name lookups take back (MAKER:NAME for a maker's glass).
        const Glass* glass = lookup_glass(m.glass).glass;
        if (!glass) continue;
        if (const auto& k = glass_k_data(*glass); !k.empty()) {
            m.absorption = std::make_shared<Absorption>(k, convention.unit_mm);
        }
        if (convention.vacuum) m.index = relative_to_vacuum(m.index);
    }
}

}  // namespace lenslab
