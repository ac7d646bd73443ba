#pragma once
// Reading a maker's glass catalogue from data/glass/<maker>.json, the project's own form of the
// refractiveindex.info database (tools/convert_glass_catalogues.py writes it).

#include <stdexcept>
#include <string>
#include <vector>

#include "optics/glass.h"

namespace lenslab {

// A catalogue file that is missing or malformed; the message names the file and the entry
// ("data/glass/schott.json: glasses[12] (N-BK7).coefficients: ...").
class GlassDataError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Every glass of one maker's file, in the file's order. Throws GlassDataError.
std::vector<Glass> read_glass_catalogue(const std::string& path);

// The folder holding the catalogue files: $LENSLAB_GLASS_DATA if set, else the source tree's
// data/glass, else the installed share/lenslab/glass. Throws GlassDataError if none has them.
std::string glass_data_directory();

// The makers' files in the order lookups and listings use, e.g. "schott.json".
const std::vector<std::string>& glass_catalogue_files();

}  // namespace lenslab
