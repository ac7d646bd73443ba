#pragma once
// A lens_group (or a prescription lens) written as a Zemax .zmx file in UTF-8, in mm, so a
// design made here opens in other lens design programs. Numbers are written with the fewest
// digits that read back to the same double, and a curvature is chosen so that 1/curvature
// reads back as the very radius: importing the file gives every number unchanged.

#include <nlohmann/json.hpp>
#include <string>

namespace lenslab {

// `object` is the lens_group (or `lens` in the prescription form) at JSON path `path`;
// `materials` the scene's materials (for elements naming one); `bench` the scene's bench
// block or null. Throws SceneError naming what cannot be written (a sag formula, an index
// model Zemax has no model glass for).
std::string zmx_from_lens_object(const nlohmann::json& object, const std::string& path,
                                 const nlohmann::json& materials, const nlohmann::json& bench);

// The shortest decimal text that reads back as `v` ("0.1", "1e-05", "62.8").
std::string shortest_number_text(double v);

}  // namespace lenslab
