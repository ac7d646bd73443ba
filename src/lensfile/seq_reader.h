#pragma once
// CODE V sequence files (.seq), the commands textbook and patent prescriptions use: SO, S,
// SI (radius or, after RDM N, curvature; thickness; glass, or a glass code such as 517642 for
// a model glass), RDY, CUY, THI, GLA, STO, K and the aspheric terms A to G, CIR (the clear
// semi-aperture; CIR EDG the edge, taken where no clear one is given; CIR OBS a central
// obscuration, recorded), DIM, WL, REF, EPD, FNO, NA, NAO, and the fields YAN/XAN, YOB/XOB,
// YIM/XIM; a line ending in '&' goes on in the next. Without RDM the numbers after S are
// radii unless they make sense only as curvatures (seq_radius_mode.h). What cannot be
// represented (REFL mirrors, decentres and tilts, other surface types) is refused with its
// line; other commands are kept as warnings.

#include <string>
#include <vector>

#include "lensfile/lens_prescription.h"

namespace lenslab {

// Reads the decoded lines of the .seq file `file`; throws LensFileError.
LensFilePrescription read_seq(const std::vector<std::string>& lines, const std::string& file);

}  // namespace lenslab
