#include "scene/camera_spec.h"

#include "scene/camera_settings.h"

namespace lenslab {

namespace {

nlohmann::json array_of(const Vec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); }

ElementSpec declare_camera() {
    const CameraSettings d;
    ElementSpec s{"camera", "the camera", {}, {}};
    s.params = {
        point_param("position").describe("the eye").in_editor("Position"),
        vector_param(ParamKind::Point, "look_at", nullptr)
            .describe("a point the camera looks at; must differ from position")
            .in_editor("Look at"),
        vector_param(ParamKind::Direction, "direction", nullptr)
            .describe("the view direction (instead of look_at)")
            .in_editor("Direction"),
        vector_param(ParamKind::Direction, "up", array_of(d.up))
            .describe("which way is up in the picture; must not be parallel to the view")
            .in_editor("Up"),
        number_param("fov", d.fov_deg)
            .above(0)
            .below(180)
            .in_unit("degrees")
            .describe("vertical field of view")
            .in_editor("Field of view (deg)", 2),
    };
    return s;
}

}  // namespace

const ElementSpec& camera_spec() {
    static const ElementSpec spec = declare_camera();
    return spec;
}

}  // namespace lenslab
