#pragma once
// Radii or curvatures: CODE V reads the first number after S as a radius after RDM (RDM Y)
// and as a curvature after RDM N. Files written by CODE V say which; files written by hand
// often do not. Such a file's numbers are taken as radii, as lenslab and most hand-written
// files take them, unless they make sense only as curvatures.

#include <cstddef>
#include <map>
#include <string>

#include "lensfile/lens_prescription.h"

namespace lenslab {

// Why the numbers after S of the surfaces `unsure` (surface index: its number) cannot be radii
// (as_curvatures false) or curvatures (true) of `lens` (read as far as the rest goes): a face
// that cannot reach the semi-aperture the file requires (its CIR, and for a lens seen from
// infinity the entrance pupil's radius at the first curved surface and any flat ones before
// it), or every face more strongly curved than a hemisphere across the thinnest glass. Empty
// when they can.
std::string seq_implausible_radii(const LensFilePrescription& lens,
                                  const std::map<size_t, double>& unsure, bool as_curvatures);

}  // namespace lenslab
