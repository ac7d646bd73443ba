#pragma once
// One surface of a sequential prescription as a lenslab lens surface (docs/scene-format.md,
// "Surfaces"), its lengths in millimetres: flat, sphere, conic, asphere (a flat base with
// terms: a sag formula in r), biconic or toroidal. Throws LensFileError, with the surface's
// line, for what a lens surface cannot hold.

#include <nlohmann/json.hpp>
#include <string>

#include "lensfile/lens_prescription.h"

namespace lenslab {

std::string prescription_surface_label(size_t i);

nlohmann::ordered_json prescription_surface_json(const LensFilePrescription& p, size_t i);

// A face must exist out to its element's semi-diameter (mm): |R| / sqrt(1 + k) for a conic.
void check_prescription_span(const LensFilePrescription& p, size_t i, double semi_diameter_mm);

}  // namespace lenslab
