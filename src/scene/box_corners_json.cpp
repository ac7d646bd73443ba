#include "scene/box_corners_json.h"

#include "scene/json_reader.h"

namespace lenslab {

Aabb read_box_corners(const nlohmann::json& b, const std::string& path) {
    if (!b.is_array() || b.size() != 2) {
        throw SceneError(path, "must be two corners [[xmin, ymin, zmin], [xmax, ymax, zmax]]");
    }
    Aabb box;
    box.lo = JsonObjectReader::as_vec3(b[0], path + "[0]");
    box.hi = JsonObjectReader::as_vec3(b[1], path + "[1]");
    for (int a = 0; a < 3; ++a) {
        if (!(box.hi[a] > box.lo[a])) {
            throw SceneError(path, std::string("the second corner must exceed the first in ") +
                                       "xyz"[a] + ", got " + format_number(box.lo[a]) + " and " +
                                       format_number(box.hi[a]));
        }
    }
    return box;
}

}  // namespace lenslab
