#include "scene/planar_json.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "geometry/disc.h"
#include "geometry/rectangle.h"
#include "geometry/triangle.h"
#include "optics/spectrum.h"

namespace lenslab {

namespace {

using nlohmann::json;

constexpr int kMaxBands = 16;

void read_resolution(const json& v, const std::string& path, DetectorSettings& d) {
    const ParamSpec& declared = detector_spec().param("resolution");
    const int low = static_cast<int>(declared.min->value);
    const int high = static_cast<int>(declared.max->value);
    auto cells = [&](const json& n, const std::string& at) {
        const double x = JsonObjectReader::as_number(n, at);
        if (x != std::floor(x) || x < low || x > high) {
            throw SceneError(at, "must be a whole number of cells from " + std::to_string(low) +
                                     " to " + std::to_string(high) + ", got " + format_number(x));
        }
        return static_cast<int>(x);
    };
    if (v.is_array()) {
        if (v.size() != 2)
            throw SceneError(path, "must be a number of cells or [cells along u, cells along v]");
        d.cells_u = cells(v[0], path + "[0]");
        d.cells_v = cells(v[1], path + "[1]");
    } else {
        d.resolution_long = cells(v, path);
    }
}

void read_bands(const json& v, const std::string& path, DetectorSettings& d) {
    d.band_edges.clear();
    if (v.is_array()) {
        if (v.size() < 2 || v.size() > kMaxBands + 1) {
            throw SceneError(path, "must be a number of bands or an array of 2 to " +
                                       std::to_string(kMaxBands + 1) +
                                       " band edges in nm, increasing");
        }
        for (size_t i = 0; i < v.size(); ++i) {
            const std::string at = path + "[" + std::to_string(i) + "]";
            const double nm = JsonObjectReader::as_number(v[i], at);
            if (const auto problem = wavelength_problem(nm))
                throw SceneError(at, format_number(nm) + " nm: " + *problem);
            if (i > 0 && !(nm > d.band_edges.back())) {
                throw SceneError(at, "band edges must increase, got " + format_number(nm) +
                                         " after " + format_number(d.band_edges.back()));
            }
            d.band_edges.push_back(nm);
        }
        return;
    }
    const double n = JsonObjectReader::as_number(v, path);
    if (n != std::floor(n) || n < 1 || n > kMaxBands) {
        throw SceneError(path, "must be a whole number of bands from 1 to " +
                                   std::to_string(kMaxBands) +
                                   " (or an array of band edges in nm), got " + format_number(n));
    }
    const int bands = static_cast<int>(n);
    for (int i = 0; i <= bands; ++i)
        d.band_edges.push_back(kLambdaMinNm + (kLambdaMaxNm - kLambdaMinNm) * i / bands);
}

}  // namespace

// The frame's `up`: given (and not parallel to the normal), or the default.
Vec3 read_plane_up(JsonObjectReader& r, const Vec3& normal) {
    if (!r.has("up")) return default_plane_up(normal);
    const Vec3 up = r.direction("up");
    if (length(cross(up, normal)) < 1e-9)
        throw SceneError(r.child_path("up"), "must not be parallel to normal");
    return up;
}

std::array<double, 2> read_plane_size(JsonObjectReader& r) {
    const json& size = r.require("size");
    const std::string path = r.child_path("size");
    if (!size.is_array() || size.size() != 2) throw SceneError(path, "must be [width, height]");
    std::array<double, 2> wh;
    for (size_t i = 0; i < 2; ++i) {
        const std::string at = path + "[" + std::to_string(i) + "]";
        wh[i] = JsonObjectReader::as_number(size[i], at);
        if (!(wh[i] > 0)) throw SceneError(at, "must be > 0, got " + format_number(wh[i]));
    }
    return wh;
}

std::shared_ptr<const Shape> read_disc(SpecReader& r) {
    const Vec3 centre = r.point("center");
    const Vec3 normal = r.unit_vector("normal");
    const double radius = r.real("radius");
    return std::make_shared<Disc>(centre, normal, radius, read_plane_up(r, normal));
}

std::shared_ptr<const Shape> read_rectangle(SpecReader& r) {
    const Vec3 centre = r.point("center");
    const Vec3 normal = r.unit_vector("normal");
    const std::array<double, 2> wh = read_plane_size(r);
    return std::make_shared<Rectangle>(centre, normal, wh[0], wh[1], read_plane_up(r, normal));
}

std::optional<DetectorSettings> read_detector(JsonObjectReader& r) {
    const json* v = r.find("detector");
    if (!v) return std::nullopt;
    if (v->is_boolean())
        return v->get<bool>() ? std::optional<DetectorSettings>(DetectorSettings{}) : std::nullopt;
    const std::string path = r.child_path("detector");
    if (!v->is_object())
        throw SceneError(path,
                         "must be true, false or an object {\"resolution\": ..., \"bands\": ...}");
    SpecReader dr(*v, path, detector_spec());
    DetectorSettings d;
    read_resolution(dr.has("resolution") ? dr.require("resolution")
                                         : detector_spec().param("resolution").fallback,
                    dr.child_path("resolution"), d);
    if (const json* bands = dr.find("bands")) {
        read_bands(*bands, dr.child_path("bands"), d);
    } else {
        d.band_edges = detector_spec().param("bands").fallback.get<std::vector<double>>();
    }
    const std::string side = dr.text("side");
    d.side = side == "front" ? DetectorSide::Front
                             : (side == "back" ? DetectorSide::Back : DetectorSide::Both);
    d.unit = dr.text("unit");
    const bool printable =
        !d.unit.empty() && d.unit.size() <= 16 &&
        d.unit.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ") ==
            std::string::npos;
    if (!printable) {
        throw SceneError(
            dr.child_path("unit"),
            "must be the name of a length unit in 1 to 16 letters (e.g. \"mm\"), got '" + d.unit +
                "'");
    }
    return d;
}

void check_detector_size(const Shape& shape, const DetectorSettings& d, const std::string& path,
                         const std::string& size_key) {
    // The extent along u and v, as the detector grid will see it.
    const std::optional<FlatPatch> patch = shape.flat_patch();
    if (!patch) return;  // not a detector shape: check_detector_allowed refuses it
    const double width = patch->u1 - patch->u0, height = patch->v1 - patch->v0;
    int nu = 1, nv = 1;
    detector_cells(d, width, height, nu, nv);
    const double cell = std::min(width / nu, height / nv);
    if (!(cell >= kMinDetectorCell)) {
        throw SceneError(path + "." + size_key,
                         "too small for a detector: its cells would be " + format_number(cell) +
                             " across, and each must be at least " +
                             format_number(kMinDetectorCell) +
                             " so that its area and irradiance are ordinary numbers (use a "
                             "smaller length unit, or fewer cells)");
    }
}

void check_detector_allowed(const json& object, const std::string& path, const std::string& type) {
    if (object.is_object() && object.contains("detector")) {
        throw SceneError(path + ".detector",
                         "only a triangle, disc or rectangle can be a detector (this is a" +
                             std::string(type == "implicit" ? "n " : " ") + type + ")");
    }
}

}  // namespace lenslab
