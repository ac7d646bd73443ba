#pragma once
// The one wavelength that every dispersed path of an sppm pass follows. A camera path and a
// photon that both went through dispersive glass can only meet if they carry the same
// wavelength, so each pass draws one (pbrt-v4's SPPM shares a wavelength sample per pass for
// the same reason). It is drawn from the lights' spectra (each normalised to unit power,
// mixed with a uniform share so background and ambient light are never missed), so a laser
// line gets its own wavelength, and it is stratified over the passes (van der Corput).

#include <cstdint>
#include <memory>
#include <vector>

#include "optics/spectrum.h"
#include "scene/scene.h"

namespace lenslab {

// Radical inverse of i in base 2 (van der Corput): 0, 1/2, 1/4, 3/4, 1/8, ...
double radical_inverse_base2(uint32_t i);

class PassWavelength {
public:
    explicit PassWavelength(const Scene& scene);
    // Pass `pass`'s wavelength (nm) and the density it was drawn with (per nm). `rotation`
    // in [0, 1) shifts the van der Corput sequence (Cranley-Patterson rotation).
    double sample(int pass, double rotation, double& pdf) const;
    // A wavelength from the same density for uniform `u` in [0, 1).
    double draw(double u, double& pdf) const;

private:
    std::shared_ptr<const Spectrum> m_mixture;
};

}  // namespace lenslab
