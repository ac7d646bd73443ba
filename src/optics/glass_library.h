#pragma once
// Every glass lenslab knows by name: the built-in materials (glass_catalogue()) and the
// makers' catalogues (SCHOTT, OHARA, CDGM, HOYA, HIKARI, SUMITA) read from data/glass.

#include <string>
#include <vector>

#include "optics/glass.h"

namespace lenslab {

// All the makers' glasses, maker by maker in glass_catalogue_files() order, read on first use.
// Throws GlassDataError (glass_catalogue_file.h) if the files are missing or malformed.
const std::vector<Glass>& maker_glasses();

// "SCHOTT", "OHARA", ...: the makers of maker_glasses(), in their order.
const std::vector<std::string>& glass_makers();

// What lookup_glass found: the glass, or why there is none (glass is then nullptr).
struct GlassLookup {
    const Glass* glass = nullptr;
    std::string error;  // "unknown glass 'NBK7'; did you mean N-BK7 (SCHOTT)?"
};

// Names are matched ignoring case: a built-in material first (its name is kept for scenes
// written before the catalogues), then a user catalogue's (user_glass_catalogues.h: NAME or
// CATALOGUE:NAME), then a maker's glass whose name is unique across makers,
// or "MAKER:NAME" for one maker's. An unknown name's error suggests the closest names; a name
// several makers use lists the MAKER:NAME forms to choose from.
GlassLookup lookup_glass(const std::string& name);

// The glass's extinction coefficient k against wavelength (um): its own, or for a built-in
// SCHOTT glass (N-BK7, N-SF11, ...) the SCHOTT catalogue's for the same name, so the short
// name absorbs as the catalogue says. Empty when no data is known (or the catalogue files
// cannot be read).
const std::vector<std::pair<double, double>>& glass_k_data(const Glass& g);

// "N-BK7 (SCHOTT)" for a maker's glass, the plain name for a built-in one.
std::string glass_label(const Glass& g);

}  // namespace lenslab
