#include <algorithm>
#include <chrono>

#include "cluster/byte_packing.h"
#include "render/integrator.h"

namespace lenslab {

bool ProgressiveIntegrator::render(const Scene& scene, const Camera&, Film& film,
                                   RenderControl& control) {
    const RenderSettings& r = scene.render;
    const auto start = std::chrono::steady_clock::now();
    auto elapsed = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    // passes == 0 means no pass limit (the scene reader then requires a time budget).
    while (r.passes == 0 || passes() < r.passes) {
        // A pass that has begun is finished; the budget is checked between passes, and the
        // first pass always runs. In a job of several ranks rank 0's clock decides for all,
        // so they run the same passes.
        bool out_of_time = r.time > 0 && passes() > 0 && elapsed() >= r.time;
        if (r.time > 0) broadcast_value(control.cluster(), out_of_time);
        if (out_of_time) break;
        if (!add_pass(control)) return false;
        double done = r.passes > 0 ? static_cast<double>(passes()) / r.passes : 0.0;
        if (r.time > 0) done = std::max(done, elapsed() / r.time);
        control.report(std::min(done, 1.0));
    }
    control.report(1.0);
    develop(film);
    return true;
}

}  // namespace lenslab
