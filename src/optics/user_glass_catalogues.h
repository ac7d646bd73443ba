#pragma once
// The users' own glass catalogues (AGF files named by a scene's "glass_catalogues" or the
// command line's --catalogue), which lookup_glass consults after the built-in materials and
// before the makers' catalogues. Process-wide: a file is read once and its glasses stay valid
// (lookups hand out pointers to them) until the program ends.

#include <string>
#include <vector>

#include "optics/glass.h"

namespace lenslab {

// Reads the AGF file at `path` (agf_catalogue.h) unless already loaded; later catalogues come
// after earlier ones. Throws GlassDataError ("my.agf:12: ...").
void load_user_glass_catalogue(const std::string& path);

// The glass NAME (the first loaded catalogue's that has it) or CATALOGUE:NAME, upper-cased;
// nullptr when no user catalogue has it.
const Glass* find_user_glass(const std::string& wanted_upper);

// Every glass of the catalogues loaded so far, in the order they were loaded (for searches,
// the glass map and the editor's picker).
std::vector<const Glass*> user_glasses();

}  // namespace lenslab
