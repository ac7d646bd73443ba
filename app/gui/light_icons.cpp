#include "light_icons.h"

#include <cmath>
#include <numbers>

#include "scene/light_spec.h"

namespace lenslab::gui {

namespace {

constexpr double kLightIconRadius = 7;   // the glyph's disc, pixels
constexpr double kLightIconReach = 12;   // how near a click must come
constexpr double kBeamArrowPixels = 40;  // a beam's arrow on screen

std::optional<Vec3> light_vector(const nlohmann::json& light, const char* key) {
    const auto it = light.find(key);
    if (it == light.end() || !it->is_array() || it->size() != 3) return std::nullopt;
    for (const auto& v : *it) {
        if (!v.is_number()) return std::nullopt;
    }
    return Vec3{(*it)[0].get<double>(), (*it)[1].get<double>(), (*it)[2].get<double>()};
}

// The light type's first required key of `kind` (where it is; which way it shines), or null:
// read from its declaration, so a new light type is drawn without an edit here.
const char* declared_key(const ElementSpec& spec, ParamKind kind) {
    for (const ParamSpec& p : spec.params) {
        if (p.kind == kind && p.required) return p.key.c_str();
    }
    return nullptr;
}

}  // namespace

std::vector<LightIcon> light_icons(const nlohmann::json& document, const ViewCamera& view) {
    std::vector<LightIcon> icons;
    const auto lights = document.find("lights");
    if (lights == document.end() || !lights->is_array()) return icons;
    for (size_t i = 0; i < lights->size(); ++i) {
        const nlohmann::json& light = (*lights)[i];
        const ElementSpec* spec = find_light_spec(light.value("type", ""));
        const char* where = spec ? declared_key(*spec, ParamKind::Point) : nullptr;
        if (!where) continue;
        const std::optional<Vec3> p = light_vector(light, where);
        if (!p) continue;
        const std::optional<QPointF> at = view.project(*p);
        if (!at) continue;
        LightIcon icon{int(i), *p, *at, std::nullopt};
        if (const char* towards = declared_key(*spec, ParamKind::Direction)) {
            if (const std::optional<Vec3> d = light_vector(light, towards)) {
                const double length = kBeamArrowPixels * view.units_per_pixel(*p);
                icon.beam_towards = view.project(*p + normalize(*d) * length);
            }
        }
        icons.push_back(icon);
    }
    return icons;
}

void paint_light_icon(QPainter& painter, const LightIcon& icon, bool selected) {
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing);
    const QColor glow = selected ? QColor(255, 160, 40) : QColor(255, 214, 64);
    painter.setPen(QPen(QColor(40, 30, 0), 1));
    if (icon.beam_towards) {
        painter.setPen(QPen(glow, 2));
        painter.drawLine(icon.at, *icon.beam_towards);
    }
    // A sun: a disc with eight short rays.
    painter.setPen(QPen(glow, 1.5));
    for (int k = 0; k < 8; ++k) {
        const double a = k * std::numbers::pi / 4;
        const QPointF u(std::cos(a), std::sin(a));
        painter.drawLine(icon.at + u * (kLightIconRadius + 2),
                         icon.at + u * (kLightIconRadius + 6));
    }
    painter.setPen(QPen(selected ? Qt::white : QColor(60, 45, 0), selected ? 2 : 1));
    painter.setBrush(glow);
    painter.drawEllipse(icon.at, kLightIconRadius, kLightIconRadius);
    painter.restore();
}

int light_icon_at(const std::vector<LightIcon>& icons, const QPointF& widget) {
    int best = -1;
    double nearest = kLightIconReach;
    for (const LightIcon& icon : icons) {
        const QPointF d = icon.at - widget;
        const double distance = std::hypot(d.x(), d.y());
        if (distance <= nearest) {
            nearest = distance;
            best = icon.index;
        }
    }
    return best;
}

}  // namespace lenslab::gui
