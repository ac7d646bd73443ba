#include "lensfile/zmx_writer.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <vector>

#include "lensfile/lens_file_glass.h"
#include "util/scene_error.h"

namespace lenslab {

namespace {

using nlohmann::json;

// An x near `guess` whose image under `forward` is exactly `target`: division by a
// reciprocal or a unit factor need not give back the number divided, but a neighbour a few
// units in the last place away does whenever `target` came from such a division.
double zmx_exact_preimage(double target, double guess,
                          const std::function<double(double)>& forward) {
    double up = guess, down = guess;
    if (forward(guess) == target) return guess;
    for (int k = 0; k < 16; ++k) {
        up = std::nextafter(up, INFINITY);
        down = std::nextafter(down, -INFINITY);
        if (forward(up) == target) return up;
        if (forward(down) == target) return down;
    }
    return guess;
}

// One surface as written: its shape, the distance after it, the glass after it.
struct ZmxSurface {
    json shape;
    std::string path;
    double after = 0;
    std::string glass;
    double semi_diameter = 0;
    bool stop = false;
    double hole = 0;  // a mirror's central hole, written as a central obscuration
    // A coordinate break (a fold around a mirror, or a pair around a moved element): PARM 1-6,
    // decentre x and y, tilts about x, y and z, the order flag.
    bool coordinate_break = false;
    std::array<double, 6> parameters{};
};

struct ZmxElement {
    std::string path;
    json front, back;  // back null: cemented to the next
    json mirror;       // a mirror element's surface (front and back null)
    double thickness = 0, gap = 0, diameter = 0, hole_diameter = 0;
    double tilt_x = 0, tilt_y = 0;  // a fold mirror's
    // A lens element's decenter_x, decenter_y, tilt_x, tilt_y, tilt_z (with those cemented to
    // it).
    std::array<double, 5> motion{};
    json material;

    bool moved() const {
        return std::any_of(motion.begin(), motion.end(), [](double v) { return v != 0; });
    }
};

// A coordinate break that bends nothing: `after` to the next surface.
ZmxSurface coordinate_break(const std::string& path, const std::array<double, 6>& parameters,
                            double after) {
    ZmxSurface s;
    s.path = path;
    s.after = after;
    s.coordinate_break = true;
    s.parameters = parameters;
    return s;
}

class ZmxWriter {
public:
    ZmxWriter(const json& materials, const json& bench) : m_materials(materials), m_bench(bench) {}

    std::string write(const json& object, const std::string& path) {
        read_elements(object, path);
        std::string out;
        line(out, "MODE SEQ");
        line(out, "NAME " + object.value("name", std::string()));
        line(out, "UNIT MM X W X CM MR CPMM");
        system_data(out);
        line(out, "SURF 0");
        line(out, "  TYPE STANDARD");
        line(out, "  CURV 0");
        line(out, "  DISZ INFINITY");
        std::vector<ZmxSurface> surfaces;
        double travel = 1;               // thicknesses behind an odd number of mirrors are negative
        std::array<double, 6> moving{};  // the break before a moved run of cemented elements
        double moved_depth = 0;          // the run's thickness so far
        for (size_t i = 0; i < m_elements.size(); ++i) {
            const ZmxElement& e = m_elements[i];
            if (!e.mirror.is_null()) {
                travel = -travel;
                const double after = i + 1 < m_elements.size() ? travel * e.gap : image_distance();
                const bool tilted = e.tilt_x != 0 || e.tilt_y != 0;
                // A fold: coordinate break, mirror, coordinate break of the same tilt.
                ZmxSurface fold = coordinate_break(e.path, {0, 0, e.tilt_x, e.tilt_y, 0, 0}, 0);
                if (tilted) surfaces.push_back(fold);
                surfaces.push_back({e.mirror, e.path + ".mirror", tilted ? 0 : after, "MIRROR",
                                    0.5 * e.diameter, false, 0.5 * e.hole_diameter});
                if (tilted) {
                    fold.after = after;
                    surfaces.push_back(fold);
                }
                continue;
            }
            double sd = 0.5 * e.diameter;
            // A cemented face belongs to both elements: the smaller rim keeps each element's own.
            if (i > 0 && m_elements[i - 1].back.is_null()) {
                sd = 0.5 * std::min(e.diameter, m_elements[i - 1].diameter);
            }
            // A moved element (and those cemented to it): a coordinate break of order 0, the
            // faces, back to the break's plane, and the inverse break (order 1), as Zemax's
            // tilt/decenter elements tool writes it.
            if (e.moved()) {
                const auto& m = e.motion;
                moving = {m[0], m[1], m[2], m[3], m[4], 0};
                moved_depth = 0;
                surfaces.push_back(coordinate_break(e.path, moving, 0));
            }
            moved_depth += e.thickness;
            surfaces.push_back(
                {e.front, e.path + ".front", travel * e.thickness, glass(e), sd, false});
            if (!e.back.is_null()) {
                const double after = i + 1 < m_elements.size() ? travel * e.gap : image_distance();
                const bool returning = moving != std::array<double, 6>{};
                surfaces.push_back({e.back, e.path + ".back",
                                    returning ? -travel * moved_depth : after, "", 0.5 * e.diameter,
                                    false});
                if (returning) {
                    std::array<double, 6> back{};
                    for (int k = 0; k < 5; ++k) back[k] = -moving[k];
                    back[5] = 1;
                    surfaces.push_back(
                        coordinate_break(e.path, back, travel * moved_depth + after));
                    moving = {};
                }
            }
        }
        place_stop(surfaces);
        for (size_t i = 0; i < surfaces.size(); ++i)
            surface(out, static_cast<int>(i) + 1, surfaces[i]);
        line(out, "SURF " + std::to_string(surfaces.size() + 1));
        line(out, "  TYPE STANDARD");
        line(out, "  CURV 0");
        line(out, "  DISZ 0");
        if (!m_makers.empty()) {
            // GCAT belongs with the system data, before the surfaces.
            out.insert(out.find("SURF 0"), catalogue_line() + "\n");
        }
        return out;
    }

private:
    static void line(std::string& out, const std::string& text) { out += text + "\n"; }

    double image_distance() const {
        return m_bench.is_object() && m_bench.contains("image_distance") &&
                       m_bench["image_distance"].is_number()
                   ? m_bench["image_distance"].get<double>()
                   : 0.0;
    }

    void read_elements(const json& object, const std::string& path) {
        const std::string type = object.value("type", std::string());
        if (type == "lens") {
            if (!object.contains("front")) {
                throw SceneError(path,
                                 "a lens in the report form has no prescription to export; "
                                 "write it with front, back, thickness and diameter");
            }
            ZmxElement e;
            e.path = path;
            e.front = object.at("front");
            e.back = object.at("back");
            e.thickness = object.at("thickness").get<double>();
            e.diameter = object.at("diameter").get<double>();
            e.material = object.at("material");
            m_elements.push_back(e);
            return;
        }
        if (type != "lens_group") {
            throw SceneError(path,
                             "a " + type + " is not a lens; export takes a lens_group or a lens");
        }
        const double diameter = object.at("diameter").get<double>();
        const json& list = object.at("elements");
        for (size_t i = 0; i < list.size(); ++i) {
            const json& j = list[i];
            ZmxElement e;
            e.path = path + ".elements[" + std::to_string(i) + "]";
            e.gap = j.value("gap", 0.0);
            e.diameter = j.value("diameter", diameter);
            if (j.contains("mirror")) {
                e.mirror = j.at("mirror");
                e.hole_diameter = j.value("hole_diameter", 0.0);
                e.tilt_x = j.value("tilt_x", 0.0);
                e.tilt_y = j.value("tilt_y", 0.0);
                m_elements.push_back(e);
                continue;
            }
            e.front = j.at("front");
            e.back = j.contains("back") ? j.at("back") : json();
            e.thickness = j.at("thickness").get<double>();
            e.gap = j.value("gap", 0.0);
            e.diameter = j.value("diameter", diameter);
            e.material = j.at("material");
            static const char* const kMotionKeys[] = {"decenter_x", "decenter_y", "tilt_x",
                                                      "tilt_y", "tilt_z"};
            for (int k = 0; k < 5; ++k) e.motion[k] = j.value(kMotionKeys[k], 0.0);
            m_elements.push_back(e);
        }
    }

    std::string glass(const ZmxElement& e) {
        json m = e.material;
        const std::string path = e.path + ".material";
        if (m.is_string()) {
            const std::string name = m.get<std::string>();
            if (!m_materials.is_object() || !m_materials.contains(name)) {
                throw SceneError(path, "unknown material '" + name + "'");
            }
            m = m_materials[name];
        }
        if (m.contains("glass")) {
            std::string g = m["glass"].get<std::string>();
            const size_t colon = g.find(':');
            if (colon != std::string::npos) {
                const std::string maker = g.substr(0, colon);
                if (std::find(m_makers.begin(), m_makers.end(), maker) == m_makers.end()) {
                    m_makers.push_back(maker);
                }
                m_glasses.push_back({g.substr(colon + 1), g});
                g = g.substr(colon + 1);
            }
            return g;
        }
        if (m.contains("ior")) {
            const json& ior = m["ior"];
            if (ior.is_number()) {
                return "___BLANK 1 0 " + shortest_number_text(ior.get<double>()) + " 0 0 0 0 0 0 0";
            }
            if (ior.value("model", std::string()) == "abbe") {
                return "___BLANK 1 0 " + shortest_number_text(ior.at("n_d").get<double>()) + " " +
                       shortest_number_text(ior.at("V_d").get<double>()) + " 0 0 0 0 0 0";
            }
        }
        throw SceneError(path,
                         "no catalogue glass, constant index or n_d/V_d model: a .zmx "
                         "file has no glass for it");
    }

    void surface(std::string& out, int n, const ZmxSurface& z) {
        line(out, "SURF " + std::to_string(n));
        if (z.stop) line(out, "  STOP");
        if (z.coordinate_break) {
            line(out, "  TYPE COORDBRK");
            for (int k = 0; k < 6; ++k) {
                if (z.parameters[k] != 0)
                    line(out, "  PARM " + std::to_string(k + 1) + " " +
                                  shortest_number_text(z.parameters[k]));
            }
            line(out, "  DISZ " + shortest_number_text(z.after));
            return;
        }
        const json& s = z.shape;
        const std::string& path = z.path;
        const std::string shape = s.value("shape", std::string());
        static const std::map<std::string, std::string> kTypes = {
            {"flat", "STANDARD"},    {"sphere", "STANDARD"},       {"conic", "STANDARD"},
            {"asphere", "EVENASPH"}, {"biconic", "BICONICX"},      {"toroidal", "TOROIDAL"},
            {"zernike", "SZERNSAG"}, {"xy_polynomial", "XPOLYNOM"}};
        const auto type = kTypes.find(shape);
        if (type == kTypes.end()) {
            throw SceneError(path,
                             "a " + shape +
                                 " surface has no Zemax surface type lenslab writes "
                                 "(flat, sphere, conic, asphere, biconic, toroidal, zernike and "
                                 "xy_polynomial do)");
        }
        line(out, "  TYPE " + type->second);
        const auto curvature = [&](const char* key) {
            const double r = s.at(key).get<double>();
            if (r == 0) return std::string("0");
            return shortest_number_text(
                zmx_exact_preimage(r, 1.0 / r, [](double x) { return 1.0 / x; }));
        };
        const auto parameter = [&](int k, double v) {
            line(out, "  PARM " + std::to_string(k) + " " + shortest_number_text(v));
        };
        const char* conic = shape == "biconic" ? "k_y" : "k";
        line(out,
             "  CURV " + (shape == "flat" ? std::string("0")
                                          : curvature(shape == "biconic" ? "radius_y" : "radius")));
        if (s.contains(conic)) line(out, "  CONI " + shortest_number_text(s[conic].get<double>()));
        if (shape == "biconic") {
            parameter(1, s.at("radius_x").get<double>());
            parameter(2, s.value("k_x", 0.0));
        }
        if (shape == "toroidal") {
            parameter(1, s.at("radius_of_rotation").get<double>());
            parameter(2, 0);
        }
        if (shape == "xy_polynomial" && !s.value("coefficients", json::array()).empty()) {
            throw SceneError(path + ".coefficients",
                             "Zemax's extended polynomial (XPOLYNOM) has no aspheric terms: "
                             "a .zmx file cannot hold them");
        }
        if (shape == "asphere" || shape == "zernike") parameter(1, 0);
        if (shape == "asphere" || shape == "toroidal" || shape == "zernike") {
            const json a = s.value("coefficients", json::array());
            for (size_t i = 0; i < a.size(); ++i)
                parameter(int(i) + 2 + (shape == "toroidal"), a[i].get<double>());
        }
        if (shape == "zernike" || shape == "xy_polynomial") {
            const json& terms = s.at(shape == "zernike" ? "zernike" : "terms");
            const auto extra = [&](size_t k, double v) {
                line(out, "  XDAT " + std::to_string(k) + " " + shortest_number_text(v));
            };
            extra(1, double(terms.size()));
            extra(2, s.at("normalization_radius").get<double>());
            for (size_t i = 0; i < terms.size(); ++i) extra(i + 3, terms[i].get<double>());
        }
        line(out, "  DISZ " + shortest_number_text(z.after));
        if (!z.glass.empty()) line(out, "  GLAS " + z.glass);
        line(out, "  DIAM " + shortest_number_text(z.semi_diameter));
        if (z.hole > 0) line(out, "  OBSC 0 " + shortest_number_text(z.hole) + " 0");
    }

    void system_data(std::string& out) {
        if (!m_bench.is_object()) return;
        const std::string type = m_bench.value("aperture_type", std::string());
        if (m_bench.contains("aperture")) {
            const std::string value = shortest_number_text(m_bench["aperture"].get<double>());
            if (type == "entrance_pupil_diameter") line(out, "ENPD " + value);
            if (type == "f_number") line(out, "FNUM " + value);
            if (type == "object_na") line(out, "OBNA " + value);
        }
        if (type == "float_by_stop_size") line(out, "FLOA");
        if (m_bench.contains("ray_aiming")) {
            line(out, std::string("RAIM 0 ") + (m_bench["ray_aiming"] == "paraxial" ? "0" : "2"));
        }
        const json waves = m_bench.value("wavelengths", json::array());
        const json fx = m_bench.value("fields_x", json::array());
        const json fy = m_bench.value("fields_y", json::array());
        static const std::vector<std::string> kTypes = {
            "angle", "object_height", "paraxial_image_height", "real_image_height"};
        int field_type = 0;
        for (size_t i = 0; i < kTypes.size(); ++i) {
            if (m_bench.value("field_type", std::string("angle")) == kTypes[i])
                field_type = static_cast<int>(i);
        }
        const size_t fields = std::max(fx.size(), fy.size());
        line(out, "FTYP " + std::to_string(field_type) + " 0 " + std::to_string(fields) + " " +
                      std::to_string(waves.size()) + " 0 0 0");
        const auto list = [&](const char* key, const json& values) {
            if (values.empty()) return;
            std::string text = key;
            for (size_t i = 0; i < fields; ++i) {
                text.append(" ").append(
                    i < values.size() ? shortest_number_text(values[i].get<double>()) : "0");
            }
            line(out, text);
        };
        if (fields) {
            list("XFLN", fx.empty() ? json(std::vector<double>(fields, 0.0)) : fx);
            list("YFLN", fy.empty() ? json(std::vector<double>(fields, 0.0)) : fy);
        }
        int primary = 1;
        for (size_t i = 0; i < waves.size(); ++i) {
            const double nm = waves[i].get<double>();
            const double um =
                zmx_exact_preimage(nm, nm / 1000.0, [](double x) { return 1000.0 * x; });
            line(out, "WAVM " + std::to_string(i + 1) + " " + shortest_number_text(um) + " 1");
            if (m_bench.contains("primary_wavelength") &&
                m_bench["primary_wavelength"].get<double>() == nm) {
                primary = static_cast<int>(i) + 1;
            }
        }
        if (!waves.empty()) line(out, "PWAV " + std::to_string(primary));
    }

    // GCAT with the makers in an order under which every glass name reads back as the same
    // maker's glass (SF2 is a SCHOTT and a HIKARI glass): the reader tries them in order.
    std::string catalogue_line() {
        std::vector<std::string> order = m_makers;
        const auto reads_back = [&](const std::vector<std::string>& makers) {
            std::vector<LensFileWarning> ignored;
            for (const auto& [name, full] : m_glasses) {
                try {
                    if (resolve_lens_file_glass(name, makers, "", 0, ignored) != full) return false;
                } catch (const LensFileError&) {
                    return false;
                }
            }
            return true;
        };
        std::vector<std::string> sorted = order;
        std::sort(sorted.begin(), sorted.end());
        if (!reads_back(order)) {
            do {
                if (reads_back(sorted)) {
                    order = sorted;
                    break;
                }
            } while (std::next_permutation(sorted.begin(), sorted.end()));
        }
        std::string text = "GCAT";
        for (const std::string& m : order) text.append(" ").append(m);
        return text;
    }

    // The stop of the bench data, where the reader will find it again: on a surface at its
    // position, else a flat surface of its own before the lens or in an air space, the space
    // split so that both the stop's position and the space read back as the same numbers.
    void place_stop(std::vector<ZmxSurface>& surfaces) const {
        if (!m_bench.is_object() || !m_bench.contains("stop_position")) return;
        const double at = m_bench["stop_position"].get<double>();
        const double sd = m_bench.value("stop_semi_diameter", 0.0);
        ZmxSurface stop{json{{"shape", "flat"}}, "bench.stop_position", 0, "", sd, true};
        if (at < 0) {
            stop.after = -at;
            surfaces.insert(surfaces.begin(), stop);
            return;
        }
        double z = 0;  // as the reader sums the thicknesses
        for (size_t i = 0; i < surfaces.size(); ++i) {
            if (z == at && !surfaces[i].coordinate_break) {
                surfaces[i].stop = true;
                return;
            }
            const double next = z + surfaces[i].after;
            // Not inside a moved element's way back to its break.
            const bool forward = surfaces[i].after > 0 && !surfaces[i].coordinate_break;
            if (surfaces[i].glass.empty() && forward && at > z &&
                (at < next || i + 1 == surfaces.size())) {
                const double space = surfaces[i].after;
                const double a = zmx_exact_preimage(at, at - z, [z](double x) { return z + x; });
                stop.after = zmx_exact_preimage(space, space - a, [a](double x) { return a + x; });
                surfaces[i].after = a;
                surfaces.insert(surfaces.begin() + static_cast<long>(i) + 1, stop);
                return;
            }
            z = next;
        }
    }

    const json& m_materials;
    const json& m_bench;
    std::vector<ZmxElement> m_elements;
    std::vector<std::string> m_makers;  // in the order the glasses name them
    std::vector<std::pair<std::string, std::string>> m_glasses;  // GLAS name, MAKER:NAME
};

}  // namespace

std::string shortest_number_text(double v) {
    char text[64];
    const auto [end, ec] = std::to_chars(text, text + sizeof text, v);
    (void)ec;
    return std::string(text, end);
}

std::string zmx_from_lens_object(const nlohmann::json& object, const std::string& path,
                                 const nlohmann::json& materials, const nlohmann::json& bench) {
    try {
        return ZmxWriter(materials, bench).write(object, path);
    } catch (const json::exception& e) {
        throw SceneError(path, std::string("cannot be exported: ") + e.what());
    }
}

}  // namespace lenslab
