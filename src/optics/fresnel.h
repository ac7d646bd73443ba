#pragma once
// Exact Fresnel reflectance of a smooth interface between two dielectrics, for unpolarised
// light (Hecht, Optics, 5th ed., section 4.6.2).

namespace lenslab {

struct FresnelTerms {
    double rs = 1;  // reflectance, s-polarisation (E perpendicular to the plane of incidence)
    double rp = 1;  // reflectance, p-polarisation (E in the plane of incidence)
    bool total_internal_reflection = false;

    double reflectance() const { return 0.5 * (rs + rp); }
    double transmittance() const { return 1.0 - reflectance(); }
};

// cos_incident: cosine of the angle between the incident ray and the normal, in [0, 1].
// eta_incident, eta_transmitted: refractive indices of the incident and far media.
FresnelTerms fresnel_dielectric(double cos_incident, double eta_incident, double eta_transmitted);

}  // namespace lenslab
