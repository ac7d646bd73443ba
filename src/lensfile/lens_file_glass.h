#pragma once
// A glass named in a lens file, found in lenslab's glass library. Zemax names a glass and
// lists the catalogues it comes from (GCAT); CODE V writes NAME_MAKER (N-BK7_SCHOTT, or
// NBK7_SCHOTT without the hyphen).

#include <string>
#include <vector>

#include "lensfile/lens_file_error.h"

namespace lenslab {

// The name a scene's material takes for the glass `name` ("SCHOTT:N-BK7", or a built-in
// glass's own name). `catalogues` are the makers the file names, tried first when several
// makers have the glass. A name found only without its hyphens adds a warning at `line`.
// Throws LensFileError at `line` for an unknown glass, with the closest names.
std::string resolve_lens_file_glass(const std::string& name,
                                    const std::vector<std::string>& catalogues,
                                    const std::string& file, int line,
                                    std::vector<LensFileWarning>& warnings);

}  // namespace lenslab
