#pragma once
// Lens files in, lens files out: a Zemax .zmx or CODE V .seq file read as a lens_group (by
// its extension); and a lens_group written back as a .zmx file.

#include <nlohmann/json.hpp>
#include <string>

#include "lensfile/lens_group_from_prescription.h"

namespace lenslab {

// Whether `path` names a lens file by its extension (.zmx, .zar, .seq, any case).
bool is_lens_file_path(const std::string& path);

// Reads the lens file at `path` (.zmx, .zar or .seq, any case) into a lens_group named
// `name`, not yet checked as the scene reader checks one (scene/lens_file_import.h does).
// Its lengths are in millimetres times `scale` (the editor's import into a scene of another
// unit; the messages of a file refused then count in those units too). `configuration` (from
// 1) picks one of a zoom's configurations (Zemax MNUM and THIC records); 0: the one the
// file's surfaces hold. Throws LensFileError.
ImportedLens read_lens_file(const std::string& path, const std::string& name, double scale = 1.0,
                            int configuration = 0);

// The scene fragment `lenslab import` writes: the lens_group at the origin along +z, and the
// file's system data under "bench".
nlohmann::ordered_json imported_scene_json(const ImportedLens& lens, const std::string& path);

// "FILE:LINE: warning: message" lines, one per warning.
std::string lens_file_warnings_text(const ImportedLens& lens, const std::string& path);

}  // namespace lenslab
