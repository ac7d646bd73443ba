#pragma once
// Zemax OpticStudio sequential lens files (.zmx): surfaces of type STANDARD and EVENASPH,
// coordinate breaks without decentre or tilt, the stop, glasses by catalogue name, semi-
// diameters, units, wavelengths, fields and the aperture. A line that changes the lens but
// cannot be represented (a mirror, a tilt, another surface type) is refused with its line;
// display and tolerancing data are passed over; anything else is kept as a warning.

#include <string>
#include <vector>

#include "lensfile/lens_prescription.h"

namespace lenslab {

// Reads the decoded lines of the .zmx file `file`; throws LensFileError.
LensFilePrescription read_zmx(const std::vector<std::string>& lines, const std::string& file);

}  // namespace lenslab
