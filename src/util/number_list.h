#pragma once
// A list of numbers as a person types it ("0, 5, 10"): the editor's field and wavelength
// boxes, `lenslab spectra --wavelengths`.

#include <string>
#include <vector>

namespace lenslab {

// The numbers of `text` split at `separator`, spaces around each ignored ("0, 5" is 0 and 5;
// a blank text is none). Throws std::invalid_argument naming the text and the part for a part
// that is empty ("1,,2", "0, 5,") or not one finite number.
std::vector<double> parse_number_list(const std::string& text, char separator = ',');

}  // namespace lenslab
