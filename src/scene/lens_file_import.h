#pragma once
// A lens file imported as the scene reader will take it: read (lensfile/lens_file.h) and
// built as a scene would build it, so a lens the scene reader refuses (a surface crossing its
// neighbour) is refused here, at the line of the element concerned.

#include <string>

#include "lensfile/lens_file.h"

namespace lenslab {

// Its lengths are millimetres times `scale` (read_lens_file). Throws LensFileError.
ImportedLens import_lens_file(const std::string& path, const std::string& name, double scale = 1.0,
                              int configuration = 0);

}  // namespace lenslab
