#include "analysis/trace/ray_tree.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "scene/interaction.h"

namespace lenslab {

namespace {

RayTreeNode tree_node(const Vec3& from, const std::optional<Vec3>& to, int object, Event event,
                      const Vec3& direction, double weight) {
    RayTreeNode node;
    node.from = from;
    node.to = to;
    node.object = object;
    node.event = event;
    node.direction = direction;
    node.weight = weight;
    return node;
}

class TreeBuilder {
public:
    TreeBuilder(const Scene& scene, const RayTreeOptions& options, RayTree& tree)
        : m_scene(scene), m_options(options), m_tree(tree) {}

    // Follows the ray leaving `parent` and appends what happens at its next hit. `depth`
    // counts the specular bounces before this hit; as in the renderer, at most
    // `max_depth` of them are followed.
    void follow(RayTreeNode& parent, int depth) {
        const Vec3 origin = parent.to.value_or(parent.from);
        const Ray ray{origin, parent.direction};
        double w = parent.weight;
        Interaction it;
        std::vector<Vec3> curved;
        if (!next_interaction(m_scene, ray, m_options.wavelength_nm, it, &curved)) {
            parent.children.push_back(
                tree_node(origin, std::nullopt, -1, Event::Escape, ray.direction, w));
            m_tree.escaped += w;
            return;
        }
        // Light absorbed inside glass on the way here (Beer-Lambert) counts as absorbed.
        const double kept = segment_transmittance(it, ray.direction, m_options.wavelength_nm);
        m_tree.absorbed += w * (1.0 - kept);
        w *= kept;
        const Vec3& p = it.point();
        const int object = it.hit.object;
        const Scattering& s = it.scattering;
        const SurfaceIndices n = indices_at(it, m_options.wavelength_nm);
        // Each child of this hit records the surface it met there.
        const auto at_surface = [&](RayTreeNode& child) {
            child.path = curved;
            child.steps = it.grin_steps;
            child.normal = it.normal();
            child.n_inside = n.inside;
            child.n_outside = n.outside;
        };
        if (s.diffuse > 0.0) {
            parent.children.push_back(
                tree_node(origin, p, object, Event::Absorb, it.direction, w * s.diffuse));
            at_surface(parent.children.back());
            m_tree.absorbed += w * s.diffuse;
        }
        for (int i = 0; i < s.count; ++i) {
            const Branch& b = s.branches[i];
            const double bw = w * b.weight;
            if (bw < m_options.min_weight) {
                m_tree.truncated += bw;
                continue;
            }
            parent.children.push_back(tree_node(origin, p, object, b.event, b.direction, bw));
            RayTreeNode& child = parent.children.back();
            at_surface(child);
            if (depth >= m_options.max_depth) {
                child.truncated = true;
                m_tree.truncated += bw;
            } else {
                follow(child, depth + 1);
            }
        }
    }

private:
    const Scene& m_scene;
    const RayTreeOptions& m_options;
    RayTree& m_tree;
};

using Json = nlohmann::ordered_json;

Json vec_json(const Vec3& v) { return Json::array({v.x, v.y, v.z}); }

// `arriving`: the direction the light came along to this node's hit (its parent's).
Json node_json(const Scene& scene, const RayTreeNode& node, const Vec3* arriving) {
    Json j;
    j["from"] = vec_json(node.from);
    j["to"] = node.to ? vec_json(*node.to) : Json(nullptr);
    if (!node.path.empty()) {
        j["path"] = Json::array();
        for (const Vec3& q : node.path) j["path"].push_back(vec_json(q));
        j["steps"] = node.steps;
    }
    j["object"] = node.object >= 0 ? Json(scene.objects[node.object].name) : Json(nullptr);
    if (node.object >= 0) j["object_index"] = node.object;
    j["event"] = node.event ? event_name(*node.event) : "start";
    j["weight"] = node.weight;
    j["direction"] = vec_json(node.direction);
    if (arriving && node.to && node.object >= 0) {  // the surface met, as a lesson reads it
        j["normal"] = vec_json(node.normal);
        j["incidence_deg"] = angle_to_normal_deg(*arriving, node.normal);
        j["leaving_deg"] = angle_to_normal_deg(node.direction, node.normal);
        j["n_inside"] = node.n_inside;
        j["n_outside"] = node.n_outside;
    }
    if (node.truncated) j["truncated"] = true;
    j["children"] = Json::array();
    for (const RayTreeNode& c : node.children)
        j["children"].push_back(node_json(scene, c, &node.direction));
    return j;
}

}  // namespace

double angle_between_deg(const Vec3& a, const Vec3& b) {
    const double c = dot(normalize(a), normalize(b));
    return std::acos(std::clamp(c, -1.0, 1.0)) * 180 / std::numbers::pi;
}

double angle_to_normal_deg(const Vec3& d, const Vec3& normal) {
    return angle_between_deg(d, dot(d, normal) < 0 ? -normal : normal);
}

RayTree trace_ray_tree(const Scene& scene, const Ray& ray, const RayTreeOptions& options) {
    RayTree tree;
    tree.root.from = ray.origin;
    tree.root.to = ray.origin;
    tree.root.direction = normalize(ray.direction);
    tree.root.weight = 1.0;
    TreeBuilder(scene, options, tree).follow(tree.root, 0);
    return tree;
}

nlohmann::ordered_json to_json(const Scene& scene, const RayTree& tree) {
    Json j;
    j["tree"] = node_json(scene, tree.root, nullptr);
    j["summary"] = {
        {"escaped", tree.escaped}, {"absorbed", tree.absorbed}, {"truncated", tree.truncated}};
    return j;
}

}  // namespace lenslab
