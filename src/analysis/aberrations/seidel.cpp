#include "analysis/aberrations/seidel.h"

namespace lenslab {

SeidelSums& SeidelSums::operator+=(const SeidelSums& o) {
    spherical += o.spherical;
    coma += o.coma;
    astigmatism += o.astigmatism;
    petzval += o.petzval;
    distortion += o.distortion;
    axial_colour += o.axial_colour;
    lateral_colour += o.lateral_colour;
    return *this;
}

Seidel seidel_sums(const OpticalSystem& system, const FirstOrder& fo, double short_nm,
                   double long_nm) {
    Seidel result;
    result.short_nm = short_nm;
    result.long_nm = long_nm;
    const double h = fo.lagrange_invariant;
    for (size_t i = 0; i < system.surfaces.size(); ++i) {
        const SystemSurface& s = system.surfaces[i];
        const ParaxialRaySurface& m = fo.marginal.surfaces[i];
        const ParaxialRaySurface& p = fo.chief.surfaces[i];
        const double c = s.curvature;
        const double y = m.y, yb = p.y;
        const double a = m.n * (m.u + y * c);
        const double ab = p.n * (p.u + yb * c);
        const double d_u_n = m.u_after / m.n_after - m.u / m.n;
        const double d_inv_n = 1.0 / m.n_after - 1.0 / m.n;
        const double d_inv_n2 = 1.0 / (m.n_after * m.n_after) - 1.0 / (m.n * m.n);
        const double dn_after = system.n_after(i, short_nm) - system.n_after(i, long_nm);
        const double dn_before = system.n_before(i, short_nm) - system.n_before(i, long_nm);
        const double d_dn_n = dn_after / m.n_after - dn_before / m.n;

        SeidelSums t;
        t.spherical = -a * a * y * d_u_n;
        t.coma = -a * ab * y * d_u_n;
        t.astigmatism = -ab * ab * y * d_u_n;
        t.petzval = -h * h * c * d_inv_n;
        t.distortion = -ab * ab * ab * y * d_inv_n2 + ab * yb * c * (h + ab * y) * d_inv_n;
        t.axial_colour = a * y * d_dn_n;
        t.lateral_colour = ab * y * d_dn_n;

        // The fourth-order sag beyond the sphere's c^3 / 8 (any surface's, read through its
        // vertex Taylor series), written as products so a surface the marginal ray meets on
        // the axis needs no division by y.
        const double e = 8.0 * (s.a4 - c * c * c / 8.0) * (m.n_after - m.n);
        t.spherical += e * y * y * y * y;
        t.coma += e * y * y * y * yb;
        t.astigmatism += e * y * y * yb * yb;
        t.distortion += e * y * yb * yb * yb;
        result.surfaces.push_back(t);
        result.total += t;
    }
    const ParaxialRaySurface& last = fo.marginal.last();
    const double nu = last.n_after * last.u_after;
    const SeidelSums& s = result.total;
    SeidelTransverse& tr = result.transverse;
    tr.spherical = s.spherical / (2.0 * nu);
    tr.sagittal_coma = s.coma / (2.0 * nu);
    tr.tangential_coma = 3.0 * tr.sagittal_coma;
    tr.tangential_field = (3.0 * s.astigmatism + s.petzval) / (2.0 * nu);
    tr.sagittal_field = (s.astigmatism + s.petzval) / (2.0 * nu);
    tr.petzval = s.petzval / (2.0 * nu);
    tr.distortion = s.distortion / (2.0 * nu);
    tr.axial_colour = s.axial_colour / nu;
    tr.lateral_colour = s.lateral_colour / nu;
    tr.longitudinal_axial_colour = -s.axial_colour / (nu * last.u_after);
    return result;
}

}  // namespace lenslab
