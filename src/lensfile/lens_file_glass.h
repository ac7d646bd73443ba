#pragma once
// A glass named in a lens file, found in lenslab's glass library. Zemax names a glass and
// lists the catalogues it comes from (GCAT); CODE V writes NAME_MAKER (N-BK7_SCHOTT, or
// NBK7_SCHOTT without the hyphen), or a glass code (517642, 517000.520000) for a model glass.

#include <optional>
#include <string>
#include <vector>

#include "lensfile/lens_file_error.h"

namespace lenslab {

// The name a scene's material takes for the glass `name` ("SCHOTT:N-BK7", or a built-in
// glass's own name). `catalogues` are the makers the file names, tried first when several
// makers have the glass. A glass found under another name than the file's adds a warning at
// `line` saying what it was read as: the name without its hyphens (NBK7), a name lens files
// use for a glass lenslab knows by another (BK7: N-BK7, SCHOTT's successor to it; SILICA:
// fused-silica), a moulded glass (L-TIM28_MOLD, L-TIM28-MOLD) as the glass it is moulded from.
// Throws LensFileError at `line` for an unknown glass, with the closest names as users name
// glasses: the maker's one-letter prefix (N-, S-, H-, D-, ...) set aside when comparing, a
// name with the file's prefix, else SCHOTT's lead-free N- successor, first.
std::string resolve_lens_file_glass(const std::string& name,
                                    const std::vector<std::string>& catalogues,
                                    const std::string& file, int line,
                                    std::vector<LensFileWarning>& warnings);

// A model glass written as CODE V writes one in place of a glass name: the six-digit glass
// code NNNVVV (517642: n_d 1.517, V_d 64.2) or the fictitious glass NNNNNN.VVVV (517000.520000
// or 517000.5200: n_d 1.517000, V_d 52.00; the digits before the point are n_d - 1, those
// after it V_d / 100).
struct LensFileGlassCode {
    double n_d = 0.0, V_d = 0.0;
};

// True when `word` is digits with at most one decimal point: a glass code, or a mistaken one.
bool lens_file_glass_code_like(const std::string& word);

// The glass code `word`, or nothing when it is none of the two forms (3 to 6 digits before
// the point of a fictitious glass, at least one after it).
std::optional<LensFileGlassCode> lens_file_glass_code(const std::string& word);

}  // namespace lenslab
