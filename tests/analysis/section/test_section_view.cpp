#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <numbers>
#include <utility>

#include "analysis/section/section_view.h"
#include "geometry/lens/lens_solid.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

int section_object_named(const Scene& scene, const std::string& name) {
    for (int i = 0; i < int(scene.objects.size()); ++i) {
        if (scene.objects[i].name == name) return i;
    }
    return -1;
}

const SectionObject* section_of(const SectionView& view, int object) {
    for (const SectionObject& o : view.objects) {
        if (o.object == object) return &o;
    }
    return nullptr;
}

TEST(SectionView, DefaultLensOutlineFollowsTheSagOfItsSpheres) {
    const Scene scene = default_scene();
    const int lens = section_object_named(scene, "glass lens");
    ASSERT_GE(lens, 0);
    const SectionPlane plane = default_section_plane(scene, lens);
    // The plane holds the lens's axis and the camera's up.
    const Vec3 axis = normalize(Vec3{0.2, 1, 0.45});
    EXPECT_NEAR(dot(plane.normal(), axis), 0, 1e-12);
    EXPECT_NEAR(dot(plane.normal(), scene.camera.up), 0, 1e-12);

    const std::vector<SectionCurve> curves = section_outline(*scene.objects[lens].shape, plane);
    ASSERT_EQ(curves.size(), 1u);
    ASSERT_TRUE(curves[0].closed);
    // The report's lens: two spheres of radius R = 0.9 meeting at aperture radius h = 0.5;
    // each face's sag from its vertex is R - sqrt(R^2 - r^2), the vertices t/2 from the centre.
    const double R = 0.9, h = 0.5;
    const double half_t = R - std::sqrt(R * R - h * h);
    const Vec3 centre{0.35, 0.9, 0.9};
    double widest = 0;
    for (const DiagramPoint& p : curves[0].points) {
        const Vec3 w = plane.at(p) - centre;
        const double z = dot(w, axis);
        const double r = length(w - axis * z);
        ASSERT_LE(r, h + 1e-12);
        const double sag = R - std::sqrt(R * R - r * r);
        const double front = -half_t + sag, back = half_t - sag;
        EXPECT_LT(std::min(std::abs(z - front), std::abs(z - back)), 1e-9) << "r = " << r;
        widest = std::max(widest, r);
    }
    EXPECT_NEAR(widest, h, 1e-12);
    EXPECT_GT(curves[0].points.size(), 100u);
}

TEST(SectionView, ChosenPlanesOfTheAxesThroughTheSelection) {
    const Scene scene = default_scene();
    const int lens = section_object_named(scene, "glass lens");
    const Vec3 centre{0.35, 0.9, 0.9};
    const std::pair<SectionPlaneChoice, Vec3> normals[] = {{SectionPlaneChoice::XY, {0, 0, 1}},
                                                           {SectionPlaneChoice::YZ, {1, 0, 0}},
                                                           {SectionPlaneChoice::ZX, {0, 1, 0}}};
    for (const auto& [choice, normal] : normals) {
        const SectionPlane plane = section_plane(scene, lens, choice);
        EXPECT_LT(length(plane.normal() - normal), 1e-15);
        EXPECT_LT(length(plane.origin - centre), 1e-15);
        // The lens is cut across its axis: contoured, and a beam along u instead.
        const std::vector<SectionCurve> curves = section_outline(*scene.objects[lens].shape, plane);
        ASSERT_EQ(curves.size(), 1u);
        EXPECT_TRUE(curves[0].closed);
        const std::optional<SectionBeam> beam = default_section_beam(scene, lens, plane);
        ASSERT_TRUE(beam);
        EXPECT_LT(length(beam->direction - plane.u), 1e-15);
    }
}

TEST(SectionView, ContoursOfASphereCutOffCentreLieOnIt) {
    const Scene scene = default_scene();
    const int sphere = section_object_named(scene, "glass sphere");
    const SectionPlane plane{{-1.0, 0.78, 0.5}, {1, 0, 0}, {0, 1, 0}};  // 0.3 from the centre
    const std::vector<SectionCurve> curves = section_outline(*scene.objects[sphere].shape, plane);
    ASSERT_EQ(curves.size(), 1u);
    EXPECT_TRUE(curves[0].closed);
    EXPECT_GT(curves[0].points.size(), 100u);
    const double circle = std::sqrt(0.55 * 0.55 - 0.3 * 0.3);
    for (const DiagramPoint& p : curves[0].points) EXPECT_NEAR(std::hypot(p.z, p.y), circle, 1e-9);
}

TEST(SectionView, ATorusCutThroughItsAxisGivesTwoLoops) {
    const Scene scene = parse_scene(R"({
      "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
      "materials": {"glass": {"transparency": 1, "ior": 1.5}},
      "objects": [{"type": "implicit", "center": [0, 0, 0],
                   "formula": "(sqrt(x^2 + z^2) - 0.45)^2 + y^2 - 0.2^2",
                   "bounds": [[-0.7, -0.21, -0.7], [0.7, 0.21, 0.7]], "material": "glass"}]
    })");
    // Not convex: the plane z = 0 cuts the ring in two discs of radius 0.2 at x = +-0.45.
    const SectionPlane side{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const std::vector<SectionCurve> discs = section_outline(*scene.objects[0].shape, side);
    ASSERT_EQ(discs.size(), 2u);
    for (const SectionCurve& c : discs) {
        EXPECT_TRUE(c.closed);
        const double x = c.points[0].z > 0 ? 0.45 : -0.45;
        for (const DiagramPoint& p : c.points) EXPECT_NEAR(std::hypot(p.z - x, p.y), 0.2, 1e-7);
    }
    // The plane y = 0 cuts an annulus: two circles, radii 0.25 and 0.65, one inside the other.
    const SectionPlane flat{{0, 0, 0}, {1, 0, 0}, {0, 0, -1}};
    const std::vector<SectionCurve> rings = section_outline(*scene.objects[0].shape, flat);
    ASSERT_EQ(rings.size(), 2u);
    for (const SectionCurve& c : rings) {
        const double r = std::hypot(c.points[0].z, c.points[0].y) < 0.45 ? 0.25 : 0.65;
        for (const DiagramPoint& p : c.points) EXPECT_NEAR(std::hypot(p.z, p.y), r, 1e-7);
    }
}

TEST(SectionView, FloorTrianglesCutAsSegments) {
    const Scene scene = default_scene();
    const SectionPlane plane{{0, 0, 0.1}, {1, 0, 0}, {0, 1, 0}};
    const SectionView view = make_section_view(scene, plane, {});
    int segments = 0;
    for (const SectionObject& o : view.objects) {
        if (scene.objects[o.object].type != ObjectType::Triangle) continue;
        for (const SectionCurve& c : o.curves) {
            ++segments;
            ASSERT_EQ(c.points.size(), 2u);
            EXPECT_FALSE(c.closed);
            for (const DiagramPoint& p : c.points) EXPECT_NEAR(p.y, 0, 1e-12);  // the floor
        }
    }
    EXPECT_GT(segments, 8);
}

// A mirror cut through its axis is its profile: scenes/paraboloid_mirror.json's paraboloid
// (vertex (-0.8, 0.2, 0), radius 2, k = -1, facing +y) is y = 0.2 + (x + 0.8)^2 / 4 across its
// diameter 1.2, to the chords of its grid.
TEST(SectionView, AMirrorCutThroughItsAxisIsItsProfile) {
    const Scene scene =
        load_scene_file(std::string(LENSLAB_SOURCE_DIR) + "/scenes/paraboloid_mirror.json");
    const SectionPlane plane{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const SectionView view = make_section_view(scene, plane, {});
    double lowest = INFINITY, highest = -INFINITY;
    int points = 0;
    for (const SectionObject& o : view.objects) {
        if (scene.objects[o.object].name != "paraboloid") continue;
        for (const SectionCurve& c : o.curves) {
            for (const DiagramPoint& p : c.points) {
                EXPECT_NEAR(p.y, 0.2 + (p.z + 0.8) * (p.z + 0.8) / 4.0, 1e-4);
                lowest = std::min(lowest, p.z);
                highest = std::max(highest, p.z);
                ++points;
            }
        }
    }
    EXPECT_GT(points, 90);
    EXPECT_NEAR(lowest, -1.4, 1e-6);
    EXPECT_NEAR(highest, -0.2, 1e-6);
}

// The view's rays are the trees `lenslab trace` prints, for the same start rays: each
// start ray's first polyline runs along its strongest branches, hit for hit.
TEST(SectionView, RaysAgreeWithTheRayTreeOfLenslabTrace) {
    const Scene scene = default_scene();
    const int lens = section_object_named(scene, "glass lens");
    const SectionPlane plane = default_section_plane(scene, lens);
    SectionViewOptions options;
    options.rays.beam = default_section_beam(scene, lens, plane, 15);
    options.rays.rays_per_light = 0;
    options.rays.wavelengths_nm = {kLineD};
    const SectionView view = make_section_view(scene, plane, options);
    const std::vector<Ray> starts = section_start_rays(scene, plane, options.rays);
    ASSERT_EQ(starts.size(), 15u);

    RayTreeOptions tree_options;
    tree_options.max_depth = options.rays.max_depth;
    tree_options.min_weight = options.rays.min_weight;
    int through_lens = 0;
    for (const Ray& start : starts) {
        // The beam lies in the plane.
        EXPECT_NEAR(plane.distance(start.origin), 0, 1e-12);
        EXPECT_NEAR(dot(start.direction, plane.normal()), 0, 1e-12);
        const RayTree tree = trace_ray_tree(scene, start, tree_options);
        const SectionRayPath* path = nullptr;
        for (const SectionRayPath& p : view.rays) {
            if (!path && length(p.points[0] - start.origin) < 1e-15) path = &p;
        }
        ASSERT_TRUE(path);
        const RayTreeNode* node = &tree.root;
        size_t k = 1;
        for (; !node->children.empty() && k < path->points.size(); ++k) {
            const RayTreeNode* next = nullptr;
            for (const RayTreeNode& c : node->children) {
                if (c.event == Event::Absorb || c.event == Event::Escape) continue;
                if (!next || c.weight > next->weight) next = &c;
            }
            const Vec3 hit = node->children[0].to.value_or(path->points[k]);
            EXPECT_LT(length(path->points[k] - hit), 1e-9);
            if (!next) {
                ++k;
                break;
            }
            through_lens += next->object == lens && next->event == Event::Refract;
            node = next;
        }
        EXPECT_EQ(k, path->points.size());
    }
    EXPECT_GE(through_lens, 2 * 15);  // every beam ray enters and leaves the lens
}

// What `lenslab trace` prints (its stdout) for a command line.
std::string section_trace_output(const std::string& command) {
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
    std::string out;
    char buffer[4096];
    while (pipe && fgets(buffer, sizeof buffer, pipe.get())) out += buffer;
    return out;
}

// The same, through the command itself: its JSON tree for three of the beam's rays
// (both edges and the middle), followed along the strongest branches.
TEST(SectionView, RaysAgreeWithLenslabTraceOutput) {
    const Scene scene = load_scene_file(LENSLAB_SOURCE_DIR "/scenes/default.json");
    const int lens = section_object_named(scene, "glass lens");
    const SectionPlane plane = default_section_plane(scene, lens);
    SectionViewOptions options;
    options.rays.beam = default_section_beam(scene, lens, plane, 15);
    options.rays.rays_per_light = 0;
    options.rays.wavelengths_nm = {kLineD};
    const SectionView view = make_section_view(scene, plane, options);
    const std::vector<Ray> starts = section_start_rays(scene, plane, options.rays);
    ASSERT_EQ(starts.size(), 15u);
    for (int k : {0, 7, 14}) {
        const Ray& start = starts[size_t(k)];
        char args[512];
        std::snprintf(args, sizeof args,
                      " trace %s/scenes/default.json --origin %.17g,%.17g,%.17g --direction "
                      "%.17g,%.17g,%.17g --max-depth %d --min-weight %.17g",
                      LENSLAB_SOURCE_DIR, start.origin.x, start.origin.y, start.origin.z,
                      start.direction.x, start.direction.y, start.direction.z,
                      options.rays.max_depth, options.rays.min_weight);
        const nlohmann::json out =
            nlohmann::json::parse(section_trace_output(std::string(LENSLAB_BINARY) + args));
        const SectionRayPath* path = nullptr;
        for (const SectionRayPath& p : view.rays) {
            if (!path && length(p.points[0] - start.origin) < 1e-15) path = &p;
        }
        ASSERT_TRUE(path);
        const nlohmann::json* node = &out.at("tree");
        size_t compared = 0;
        for (size_t i = 1; i < path->points.size() && !node->at("children").empty(); ++i) {
            const nlohmann::json& to = node->at("children")[0].at("to");
            if (!to.is_null()) {
                const Vec3 hit{to[0].get<double>(), to[1].get<double>(), to[2].get<double>()};
                EXPECT_LT(length(path->points[i] - hit), 1e-9) << "ray " << k << ", hit " << i;
                ++compared;
            }
            const nlohmann::json* next = nullptr;
            for (const nlohmann::json& c : node->at("children")) {
                const std::string event = c.at("event");
                if (event == "absorb" || event == "escape") continue;
                if (!next || c.at("weight").get<double>() > next->at("weight").get<double>())
                    next = &c;
            }
            if (!next) break;
            node = next;
        }
        EXPECT_GE(compared, 3u) << "ray " << k;  // into the lens, out of it, the floor
    }
}

// A long glass slab, rays from inside meeting its top face at 40 and 45 degrees: the
// critical angle for n = 1.5 is asin(1 / 1.5) = 41.81 degrees.
TEST(SectionView, BeyondTheCriticalAngleTheRayIsTotallyReflected) {
    const Scene scene = parse_scene(R"({
      "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
      "materials": {"glass": {"transparency": 1, "ior": 1.5}},
      "objects": [{"type": "box", "center": [0, 0, 0], "size": [20, 2, 2], "material": "glass"}]
    })");
    const SectionPlane plane{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const auto trace_at = [&](double incidence_deg) {
        const double a = incidence_deg * std::numbers::pi / 180;
        SectionViewOptions options;
        options.rays.beam = SectionBeam{{-0.9, 0, 0}, {std::sin(a), std::cos(a), 0}, 0, 1};
        options.rays.wavelengths_nm = {kLineD};
        options.rays.max_depth = 3;
        return make_section_view(scene, plane, options);
    };
    const SectionView below = trace_at(40);
    const SectionView beyond = trace_at(45);
    const auto any_tir = [](const SectionView& v) {
        bool tir = false;
        for (const SectionRayPath& p : v.rays) tir |= p.tir;
        return tir;
    };
    EXPECT_FALSE(any_tir(below));
    EXPECT_TRUE(any_tir(beyond));
    // At 45 degrees nothing leaves through the top face: one path, reflected down at y = 1.
    ASSERT_EQ(beyond.rays.size(), 1u);
    const std::vector<Vec3>& p = beyond.rays[0].points;
    ASSERT_GE(p.size(), 3u);
    EXPECT_NEAR(p[1].y, 1, 1e-9);
    EXPECT_LT(p[2].y, p[1].y);
    // At 40 degrees the refracted ray leaves at asin(1.5 sin 40) = 74.6 degrees.
    bool left = false;
    for (const SectionRayPath& r : below.rays) {
        if (r.points.size() < 2) continue;
        const Vec3 d = normalize(r.points.back() - r.points[r.points.size() - 2]);
        left |= r.points[r.points.size() - 2].y > 0.999 &&
                std::abs(std::asin(d.x) - std::asin(1.5 * std::sin(40 * std::numbers::pi / 180))) <
                    1e-9;
    }
    EXPECT_TRUE(left);
}

TEST(SectionView, TheDrawingHasTheOutlinesAndTheRays) {
    const Scene scene = default_scene();
    const int lens = section_object_named(scene, "glass lens");
    const SectionPlane plane = default_section_plane(scene, lens);
    SectionViewOptions options;
    options.rays.beam = default_section_beam(scene, lens, plane, 15);
    const SectionView view = make_section_view(scene, plane, options);
    ASSERT_TRUE(section_of(view, lens));
    const RayDiagram d = section_diagram(scene, view, lens);
    size_t closed = 0;
    for (const DiagramPath& p : d.paths) closed += p.closed;
    // The lens (filled, then outlined as selected), the lamp; the spheres off the plane not.
    EXPECT_GE(closed, 3u);
    EXPECT_GT(d.paths.size(), view.rays.size());
    // The default glass has one index (1.5): one path per ray, at the d line, tells it all,
    // drawn in the white light's own colour (a dark grey on the page).
    ASSERT_EQ(d.legend.size(), 1u);
    EXPECT_EQ(d.legend[0].text, "white light");
    for (const SectionRayPath& r : view.rays) EXPECT_EQ(r.wavelength_nm, kLineD);
    EXPECT_LT(d.z_min, d.z_max);
}

// Any other object gets a beam across it from the left: a glass ball focuses it.
TEST(SectionView, ABallSelectedGetsABeamAcrossIt) {
    const Scene scene = default_scene();
    const int ball = section_object_named(scene, "glass sphere");
    const SectionPlane plane = default_section_plane(scene, ball);
    EXPECT_NEAR(plane.distance({-1.0, 0.78, 0.2}), 0, 1e-12);  // through its centre
    const std::optional<SectionBeam> beam = default_section_beam(scene, ball, plane, 7);
    ASSERT_TRUE(beam);
    EXPECT_NEAR(dot(beam->direction, plane.u), 1, 1e-12);
    EXPECT_NEAR(beam->width, 0.8 * 1.1, 1e-3);  // 80% of the diameter
    SectionRayOptions options;
    options.beam = beam;
    options.rays_per_light = 0;
    const std::vector<Ray> starts = section_start_rays(scene, plane, options);
    ASSERT_EQ(starts.size(), 7u);
    // The middle ray runs through the centre, undeviated (normal incidence).
    const RayTree tree = trace_ray_tree(scene, starts[3], {});
    const RayTreeNode* inside = nullptr;
    for (const RayTreeNode& c : tree.root.children) {
        if (c.event == Event::Refract) inside = &c;
    }
    ASSERT_TRUE(inside);
    EXPECT_LT(length(cross(inside->direction, plane.u)), 1e-6);
    EXPECT_FALSE(default_section_beam(scene, -1, plane));
}

// A spot light in the plane sends its fan only inside its cone, symmetric about its axis.
TEST(SectionView, ASpotsFanStaysInItsCone) {
    const Scene scene = parse_scene(R"({
      "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
      "lights": [{"type": "spot", "position": [0, 2, 0], "direction": [0, -1, 0],
                  "cone_angle": 25, "power": 1}]
    })");
    const SectionPlane plane{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    SectionRayOptions options;
    options.rays_per_light = 8;
    const std::vector<Ray> starts = section_start_rays(scene, plane, options);
    ASSERT_EQ(starts.size(), 8u);
    double sum_x = 0;
    for (const Ray& r : starts) {
        EXPECT_LT(std::acos(-r.direction.y), 25 * std::numbers::pi / 180);
        EXPECT_NEAR(r.direction.z, 0, 1e-12);
        sum_x += r.direction.x;
    }
    EXPECT_NEAR(sum_x, 0, 1e-12);
}

// A line laser's fan lying in the plane sends its rays from the aperture within half its
// angle of the beam; a slit beam's rays span the slit's width where the plane cuts across
// the slit, and the whole disc where it runs along it.
TEST(SectionView, AFanAndASlitShowTheirShapes) {
    const Scene scene = parse_scene(R"({
      "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
      "lights": [{"type": "laser", "position": [0, 0, 0], "direction": [1, 0, 0], "radius": 0.01,
                  "power": 1, "fan_angle": 40, "fan_axis": [0, 1, 0]},
                 {"type": "beam", "origin": [0, 2, 0], "direction": [1, 0, 0], "radius": 0.5,
                  "power": 1, "slit_width": 0.2, "slit_axis": [0, 0, 1]},
                 {"type": "beam", "origin": [0, -2, 0], "direction": [1, 0, 0], "radius": 0.5,
                  "power": 1, "slit_width": 0.2}]
    })");
    const SectionPlane plane{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    SectionRayOptions options;
    options.rays_per_light = 5;
    const std::vector<Ray> starts = section_start_rays(scene, plane, options);
    ASSERT_EQ(starts.size(), 15u);
    for (int i = 0; i < 5; ++i) {
        const Ray& r = starts[size_t(i)];
        EXPECT_NEAR(length(r.origin), 0, 1e-12);
        EXPECT_LT(std::abs(std::atan2(r.direction.y, r.direction.x)), 20 * std::numbers::pi / 180);
    }
    EXPECT_NEAR(starts[5].origin.y, 2 - 0.1, 1e-12);  // across the slit: its 0.2
    EXPECT_NEAR(starts[9].origin.y, 2 + 0.1, 1e-12);
    EXPECT_NEAR(std::abs(starts[10].origin.y - starts[14].origin.y), 1, 1e-12);  // along it
}

TEST(SectionView, DispersingGlassSplitsTheBeamIntoItsColours) {
    const Scene scene = parse_scene(R"({
      "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
      "materials": {"flint": {"transparency": 1, "glass": "N-SF11"}},
      "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "flint"}]
    })");
    const SectionPlane plane{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    SectionViewOptions options;
    options.rays.beam = SectionBeam{{-2, 0.5, 0}, {1, 0, 0}, 0, 1};
    const SectionView view = make_section_view(scene, plane, options);
    // The refracted path of each line: blue bends more than red (n_F > n_C).
    std::map<double, double> exit_slope;
    for (const SectionRayPath& r : view.rays) {
        if (r.weight < 0.5) continue;  // the weak reflections
        const Vec3 d = r.points.back() - r.points[r.points.size() - 2];
        exit_slope[r.wavelength_nm] = d.y / d.x;
    }
    ASSERT_EQ(exit_slope.size(), 3u);
    EXPECT_LT(exit_slope[kLineF], exit_slope[kLineD]);
    EXPECT_LT(exit_slope[kLineD], exit_slope[kLineC]);
    EXPECT_LT(exit_slope[kLineC], 0);  // towards the axis
    EXPECT_EQ(section_diagram(scene, view).legend.size(), 3u);
}

}  // namespace
}  // namespace lenslab
