#pragma once
// Every integrator lenslab has, by name: what it is, whether it renders pass by pass, and
// how to make one. The render session, the interactive view, the command line and the
// editor choose integrators through it, never by testing names or casting.

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "render/integrator.h"
#include "render/integrator_names.h"
#include "scene/scene.h"

namespace lenslab {

struct IntegratorInfo {
    std::string_view name;         // as the scene file and --integrator spell it
    std::string_view description;  // one line, for help texts and tooltips
    // Renders pass by pass, each improving on the last (render.passes, render.time); the
    // others take render.spp samples per pixel.
    bool progressive = false;
    std::unique_ptr<Integrator> (*make)(const Scene& scene) = nullptr;
    // The integrator run pass by pass, for interactive views: itself when progressive, else
    // passes of one sample per pixel averaged (render/averaged_passes.h).
    std::unique_ptr<ProgressiveIntegrator> (*make_progressive)(const Scene& scene) = nullptr;
};

// All of them, in the order of kIntegratorNames (which they match; checked on first use).
const std::vector<IntegratorInfo>& integrator_registry();

// The one called `name`; throws std::invalid_argument("unknown integrator 'NAME'").
const IntegratorInfo& integrator_info(std::string_view name);

// The registry's names, in its order: tests iterate over them, so a new integrator is
// covered once registered.
std::vector<std::string> integrator_names();

// The integrator the scene's render block asks for.
// The scene's integrator; throws SceneError when it cannot render the scene (an atmosphere
// for any but the path integrator).
std::unique_ptr<Integrator> make_integrator(const Scene& scene);
std::unique_ptr<ProgressiveIntegrator> make_progressive_integrator(const Scene& scene);

}  // namespace lenslab
