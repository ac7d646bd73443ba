#pragma once
// Glass choice among a set (docs/optimizer.md): a discrete pass after the continuous
// optimisation. For each lens with a choice, in the design's order, each other glass of its
// set is put in, the design re-optimised briefly from there, and the glass kept when the
// merit ends lower than with the best so far.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace lenslab {

struct GlassChoice {
    int object = -1;  // the lens's index in the scene JSON's `objects`
    std::string lens;
    std::vector<std::string> glasses;
    std::string path;  // "glass_choices[0]"
};

// One glass tried, and the merit the brief re-optimisation reached with it (infinite where
// the design could not be evaluated with it).
struct GlassTrial {
    std::string lens, glass;
    double merit = 0;
    bool kept = false;
};

// The lens's glass as the scene JSON names it (its inline material's `glass`).
std::string lens_glass(const nlohmann::ordered_json& scene, int object);
void set_lens_glass(nlohmann::ordered_json& scene, int object, const std::string& glass);

// Reads `glass_choices[i]`: {"lens": NAME, "glasses": [NAME, ...]}; the lens's material must
// be written inline with a `glass` (so changing it changes no other lens), every glass must
// load and cover `wavelengths`. Throws SceneError naming the JSON path.
GlassChoice read_glass_choice(const nlohmann::json& spec, const std::string& path,
                              const nlohmann::ordered_json& scene, const std::string& base_dir,
                              const std::vector<double>& wavelengths);

}  // namespace lenslab
