#pragma once
// An imported lens file's system data (Scene::bench) as the optical bench's defaults: what a
// request leaves open is measured as the lens design program that wrote the file would:
// at its wavelengths (its primary in the middle), its field angles, its entrance pupil or
// F-number, and on its image surface. Options the user gives always win.

#include <string>
#include <vector>

#include "analysis/report/analyze_request.h"
#include "scene/lens_bench.h"

namespace lenslab {

struct LensBenchDefaults {
    AnalyzeRequest request;  // with the file's values filled in
    // "wavelengths", "fields", "epd", "f_number", "stop", "ray_aiming", "image_distance"
    std::vector<std::string> taken;
    // What the file says that the bench does not take, and why ("fields: object heights
    // need --object-distance").
    std::vector<std::string> not_taken;
};

LensBenchDefaults with_lens_bench_defaults(const AnalyzeRequest& request, const LensBench& bench);

}  // namespace lenslab
