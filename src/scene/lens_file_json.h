#pragma once
// A lens file in a scene: {"type": "lens_file", "file": "AC254-100.zmx", "vertex": ...,
// "axis": ...}. The Zemax or CODE V file (relative to the scene's folder) is imported as a
// lens_group (src/lensfile) and placed like one (docs/scene-format.md, "Lens file").

#include <nlohmann/json.hpp>
#include <string>

#include "scene/param_spec.h"

namespace lenslab {

const ElementSpec& lens_file_spec();

// The lens_group the lens file object `j` at JSON path `path` stands for, with its placement;
// files are found relative to `base_dir`. Throws SceneError (the file's own problems as
// `path.file: FILE:LINE: reason`). `bench`, when given, receives the file's system data
// (wavelengths, fields, aperture: lensfile/lens_group_from_prescription.h).
nlohmann::json lens_group_from_lens_file(const nlohmann::json& j, const std::string& path,
                                         const std::string& base_dir,
                                         nlohmann::json* bench = nullptr);

}  // namespace lenslab
