#pragma once
// Reading a user's glass catalogue in Zemax's AGF form, the file glass makers publish:
//   NM name formula MIL-code n_d V_d ...   a glass, with its dispersion formula's number
//   CD c1 c2 ...                           the formula's coefficients
//   LD min_um max_um                       the range they are valid over
//   IT wavelength_um tau thickness_mm      internal transmittance (gives the glass's k)
// (CC, GC, ED, TD, OD, BD lines carry comments, thermal and other data lenslab does not use.)
// The file may be ASCII, UTF-8 or UTF-16 with a byte order mark.

#include <string>
#include <vector>

#include "optics/glass.h"

namespace lenslab {

// Every glass of the file, named as in it, with maker = the file's name without extension, in
// upper case ("my.agf": MY). Throws GlassDataError ("my.agf:12: ...") for a file that cannot
// be read or a line that does not parse.
std::vector<Glass> read_agf_catalogue(const std::string& path);

// The same from the file's text, `source` naming it in errors and as the glasses' maker.
std::vector<Glass> parse_agf_catalogue(const std::string& bytes, const std::string& source,
                                       const std::string& maker);

// The index model of AGF dispersion formula `formula` (1 Schott, 2 Sellmeier 1, 3 Herzberger,
// 4 Sellmeier 2, 5 Conrady, 6 Sellmeier 3, 7 Handbook of Optics 1, 8 Handbook of Optics 2,
// 9 Sellmeier 4, 10 Extended, 11 Sellmeier 5, 12 Extended 2, 13 Extended 3) with the CD
// line's coefficients. Throws GlassDataError for another number.
IndexModelPtr agf_formula_index(int formula, const std::vector<double>& cd, double min_um,
                                double max_um);

}  // namespace lenslab
