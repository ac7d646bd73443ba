#pragma once
// A sequential prescription (lens_prescription.h) as a lenslab lens_group: each run of glass
// between two surfaces becomes an element, one glass directly after another a cemented pair,
// air spaces become gaps. Lengths are converted to millimetres. What a lens_group cannot hold
// (glass in object space, a glass running to the image, an aspheric r^2 term, a face too
// strongly curved for its semi-diameter) is refused with the line of the file that says it.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "lensfile/lens_prescription.h"

namespace lenslab {

struct ImportedLens {
    // {"name", "type": "lens_group", "diameter", "elements"}: a lens_group but its placement.
    nlohmann::ordered_json group;
    // The system data lenslab keeps beside the lens (docs/scene-format.md, "Lens files").
    nlohmann::ordered_json bench;
    std::vector<LensFileWarning> warnings;
    std::vector<int> element_lines;  // the line of each element's front surface
    // The name its lines are reported under (a .zar archive: "ARCHIVE.zar/LENS.zmx").
    std::string file;
};

// Throws LensFileError.
ImportedLens lens_group_from_prescription(const LensFilePrescription& p, const std::string& name);

}  // namespace lenslab
