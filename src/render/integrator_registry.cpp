#include "render/integrator_registry.h"

#include <stdexcept>
#include <string>

#include "render/averaged_passes.h"
#include "render/integrators/path.h"
#include "render/integrators/photon_map.h"
#include "render/integrators/sppm.h"
#include "render/integrators/whitted.h"
#include "scene/render_settings.h"
#include "util/scene_error.h"

namespace lenslab {

namespace {

template <class T>
std::unique_ptr<Integrator> make(const Scene& scene) {
    return std::make_unique<T>(scene);
}

template <class T>
std::unique_ptr<ProgressiveIntegrator> make_averaged(const Scene& scene) {
    return std::make_unique<AveragedPasses>(scene, std::make_unique<T>(scene));
}

template <class T>
std::unique_ptr<ProgressiveIntegrator> make_progressive(const Scene& scene) {
    return std::make_unique<T>(scene);
}

// An integrator that takes samples per pixel.
template <class T>
IntegratorInfo per_pixel(std::string_view name, std::string_view description) {
    return {name, description, false, make<T>, make_averaged<T>};
}

// An integrator that improves pass by pass.
template <class T>
IntegratorInfo pass_by_pass(std::string_view name, std::string_view description) {
    return {name, description, true, make<T>, make_progressive<T>};
}

// The scene reader accepts kIntegratorNames (declared in src/scene, which cannot see this
// registry): the two must name the same integrators in the same order.
std::vector<IntegratorInfo> checked(std::vector<IntegratorInfo> all) {
    bool same = all.size() == kIntegratorNames.size();
    for (size_t i = 0; same && i < all.size(); ++i) same = all[i].name == kIntegratorNames[i];
    if (!same) {
        throw std::logic_error("the integrator registry does not match kIntegratorNames");
    }
    return all;
}

}  // namespace

const std::vector<IntegratorInfo>& integrator_registry() {
    static const std::vector<IntegratorInfo> all = checked({
        per_pixel<WhittedIntegrator>(integrators::kWhitted,
                                     "Whitted ray tracing: direct light by shadow rays, mirrors "
                                     "and glass followed; no caustics"),
        per_pixel<PhotonMapIntegrator>(integrators::kPhotonMap,
                                       "Whitted ray tracing plus photon maps for caustics (the "
                                       "report's method)"),
        pass_by_pass<SppmIntegrator>(integrators::kSppm,
                                     "Stochastic progressive photon mapping: converges pass by "
                                     "pass to the full light transport"),
        per_pixel<PathIntegrator>(integrators::kPath,
                                  "Unbiased path tracing: the reference; caustics of point "
                                  "lights need photons"),
    });
    return all;
}

const IntegratorInfo& integrator_info(std::string_view name) {
    for (const IntegratorInfo& info : integrator_registry()) {
        if (info.name == name) return info;
    }
    throw std::invalid_argument("unknown integrator '" + std::string(name) + "'");
}

std::vector<std::string> integrator_names() {
    std::vector<std::string> names;
    for (const IntegratorInfo& info : integrator_registry()) names.emplace_back(info.name);
    return names;
}

namespace {

// The JSON path of a medium of `scene`: its atmosphere, else a shape's.
std::string medium_path(const Scene& scene) {
    if (scene.atmosphere) return "atmosphere";
    const SceneObject& o = scene.objects[static_cast<size_t>(scene.medium_solids().front())];
    return "objects[" + std::to_string(o.source) + "].medium";
}

// Media are traced by the path and sppm integrators: the others would render the scene as
// if the air were clear.
void check_integrator_renders(const Scene& scene) {
    const std::string& name = scene.render.integrator;
    if (!scene.has_media() || name == integrators::kPath || name == integrators::kSppm) return;
    throw SceneError(medium_path(scene),
                     "is rendered by the path and sppm integrators (use \"integrator\": "
                     "\"path\" or \"sppm\", or --integrator)");
}

}  // namespace

std::unique_ptr<Integrator> make_integrator(const Scene& scene) {
    check_integrator_renders(scene);
    return integrator_info(scene.render.integrator).make(scene);
}

std::unique_ptr<ProgressiveIntegrator> make_progressive_integrator(const Scene& scene) {
    check_integrator_renders(scene);
    return integrator_info(scene.render.integrator).make_progressive(scene);
}

}  // namespace lenslab
