#pragma once
// Tabulated CIE data, 5 nm apart (generated from colord-data at configure time).

namespace lenslab::cie {

inline constexpr double kStepNm = 5.0;
extern const double kCmfStartNm;
extern const double kX[], kY[], kZ[];  // CIE 1931 2-degree colour matching functions
extern const int kCmfCount;
extern const double kD65StartNm;
extern const double kD65[];  // CIE standard illuminant D65, relative spectral power (1 at 560 nm)
extern const int kD65Count;

}  // namespace lenslab::cie
