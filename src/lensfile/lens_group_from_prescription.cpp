#include "lensfile/lens_group_from_prescription.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "lensfile/lens_file_glass.h"
#include "lensfile/prescription_surface.h"
#include "optics/glass.h"
#include "optics/glass_library.h"
#include "util/format_number.h"

namespace lenslab {

namespace {

using nlohmann::ordered_json;

bool prescription_has_glass(const LensFileSurface& s) {
    return !s.glass.empty() || s.model_nd > 0.0;
}

class GroupBuilder {
public:
    explicit GroupBuilder(const LensFilePrescription& p)
        : m_p(p), m_s(p.surfaces), m_mm(p.unit_mm) {}

    ImportedLens build(const std::string& name) {
        check_ends();
        take_folds();
        ImportedLens out;
        estimate_semi_diameters(out.warnings);
        ordered_json elements = ordered_json::array();
        double group_diameter = 0.0;
        // Axial positions (mm) of the surfaces from surface 1, for the stop's place.
        std::vector<double> z(m_s.size(), 0.0);
        for (size_t i = 2; i + 1 < m_s.size(); ++i) z[i] = z[i - 1] + m_s[i - 1].thickness * m_mm;
        const size_t image = m_s.size() - 1;
        size_t first = 0;
        double travel = 1.0;  // -1: behind an odd number of mirrors
        for (size_t i = 1; i < image; ++i) {
            if (m_s[i].mirror) {
                if (!first) first = i;
                elements.push_back(mirror_element(i, travel, group_diameter, out));
                travel = -travel;
                continue;
            }
            if (!prescription_has_glass(m_s[i])) continue;
            if (!first) first = i;
            const LensFileSurface& front = m_s[i];
            const LensFileSurface& back = m_s[i + 1];
            if (i + 1 == image) {
                refuse(front.glass_line ? front.glass_line : front.line,
                       "the glass after " + prescription_surface_label(i) +
                           " runs to the image surface: the file is cut short, or the lens has "
                           "no last surface");
            }
            if (back.mirror) {
                refuse(back.glass_line ? back.glass_line : back.line,
                       prescription_surface_label(i + 1) +
                           ": a mirror on a glass face (a Mangin mirror, light reflected inside "
                           "the glass) is not yet supported");
            }
            if (!(travel * front.thickness > 0.0)) {
                refuse(front.line,
                       prescription_surface_label(i) + ": a glass thickness of " +
                           format_number(front.thickness) +
                           (travel > 0 ? " (must be > 0)" : " (after a mirror, must be < 0)"));
            }
            const double sd = std::max(semi_diameter(i), semi_diameter(i + 1)) * m_mm;
            if (!(sd > 0.0)) {
                refuse(front.line, "the element from " + prescription_surface_label(i) + " to " +
                                       prescription_surface_label(i + 1) +
                                       " has no semi-diameter (Zemax DIAM, CODE V CIR)");
            }
            check_prescription_span(m_p, i, sd);
            check_prescription_span(m_p, i + 1, sd);
            ordered_json e;
            e["front"] = prescription_surface_json(m_p, i);
            e["thickness"] = travel * front.thickness * m_mm;
            static const char* const kMotionKeys[] = {"decenter_x", "decenter_y", "tilt_x",
                                                      "tilt_y", "tilt_z"};
            for (int k = 0; k < 5; ++k) {
                if (front.element_motion[k] != 0.0)
                    e[kMotionKeys[k]] = front.element_motion[k] * (k < 2 ? m_mm : 1.0);
            }
            e["diameter"] = 2.0 * sd;
            group_diameter = std::max(group_diameter, 2.0 * sd);
            e["material"] = material_json(front, out.warnings);
            if (!prescription_has_glass(back)) {
                e["back"] = prescription_surface_json(m_p, i + 1);
                air_after(i + 1, i + 1, travel, e, out);
            }
            elements.push_back(e);
            out.element_lines.push_back(front.line);
        }
        if (!first) {
            refuse(0, "no glass or mirror between the object and the image: no lens to import");
        }
        for (size_t j = 1; j < first; ++j) in_air(j, out.warnings);

        out.group["name"] = name;
        out.group["type"] = "lens_group";
        out.group["diameter"] = group_diameter;
        out.group["elements"] = elements;
        bench(out.bench, z, first);
        out.warnings.insert(out.warnings.begin(), m_p.warnings.begin(), m_p.warnings.end());
        std::stable_sort(
            out.warnings.begin(), out.warnings.end(),
            [](const LensFileWarning& a, const LensFileWarning& b) { return a.line < b.line; });
        return out;
    }

private:
    [[noreturn]] void refuse(int line, const std::string& reason) const {
        throw LensFileError(m_p.file, line, reason);
    }

    void check_ends() const {
        if (m_s.size() < 3) {
            refuse(0, "only " + std::to_string(m_s.size()) +
                          " surface(s): a lens file lists the object, the lens surfaces and the "
                          "image (the file is cut short?)");
        }
        if (prescription_has_glass(m_s[0])) {
            refuse(m_s[0].glass_line, "the object space is glass; a lens_group stands in air");
        }
        const LensFileSurface& image = m_s.back();
        if (prescription_has_glass(image)) {
            refuse(image.glass_line,
                   "the last surface has glass after it: the file is cut short (no image surface)");
        }
        for (size_t i = 1; i + 1 < m_s.size(); ++i) {
            if (!std::isfinite(m_s[i].thickness)) {
                refuse(m_s[i].line, prescription_surface_label(i) + ": an infinite thickness");
            }
        }
    }

    // The index after surface j at the primary wavelength (air: 1).
    double index_after(size_t j) const {
        const LensFileSurface& s = m_s[j];
        if (s.glass.empty()) return s.model_nd > 0.0 ? s.model_nd : 1.0;
        std::vector<LensFileWarning> ignored;
        const std::string name =
            resolve_lens_file_glass(s.glass, m_p.catalogues, m_p.file, s.glass_line, ignored);
        const double nm =
            m_p.wavelengths_nm.empty() ? kLineD : m_p.wavelengths_nm[m_p.primary_wavelength];
        return lookup_glass(name).glass->model->n(nm);
    }

    // CODE V files often give no semi-apertures (CODE V finds them from the pupil, the fields
    // and the vignetting factors). Where none is given and the entrance pupil is (as a
    // diameter, or as an F-number: EFL / N), each surface gets the largest height of the
    // paraxial rim rays of every field (chief ray plus or minus the marginal ray, cut by VUY
    // and VLY), the usual first estimate of a clear aperture.
    void estimate_semi_diameters(std::vector<LensFileWarning>& warnings) {
        const size_t image = m_s.size() - 1;
        bool missing = false;
        for (size_t j = 1; j < image; ++j) missing = missing || m_s[j].semi_diameter == 0.0;
        const bool epd = m_p.aperture_type == "entrance_pupil_diameter";
        if (!missing || !(epd || m_p.aperture_type == "f_number") || !(m_p.aperture > 0)) return;
        // Two rays from surface 1: A at unit height parallel to the axis (scaled to the
        // pupil's rim below), B through the vertex at unit slope; the chief ray is the mix of
        // them that crosses the stop's centre.
        std::vector<double> ya(m_s.size()), yb(m_s.size());
        double a_y = 1.0, a_u = 0.0, b_y = 0.0, b_u = 1.0, n = 1.0;
        size_t stop = 1;
        for (size_t j = 1; j < image; ++j) {
            if (m_s[j].stop) stop = j;
            ya[j] = a_y, yb[j] = b_y;
            const double c = m_s[j].radius == 0.0 ? 0.0 : 1.0 / m_s[j].radius;
            const double n2 = m_s[j].mirror ? -n : (n < 0 ? -1.0 : 1.0) * index_after(j);
            a_u = (n * a_u - a_y * c * (n2 - n)) / n2;
            b_u = (n * b_u - b_y * c * (n2 - n)) / n2;
            n = n2;
            a_y += a_u * m_s[j].thickness;
            b_y += b_u * m_s[j].thickness;
        }
        // The entrance pupil's radius: as given, or EFL / (2 N), EFL = -1 / u' of ray A.
        const double pupil_radius = epd ? 0.5 * m_p.aperture : -0.5 / (a_u * m_p.aperture);
        if (!std::isfinite(pupil_radius) || pupil_radius == 0.0) return;  // afocal
        for (double& y : ya) y *= std::abs(pupil_radius);
        // Each y field's beam: its chief ray, and its rim rays cut by the vignetting factors.
        std::vector<double> angles = {0.0};
        if (m_p.field_type == "angle") angles = m_p.fields_y.empty() ? angles : m_p.fields_y;
        double largest = 0.0;
        for (size_t j = 1; j < image; ++j) {
            if (m_s[j].semi_diameter != 0.0) continue;
            double sd = std::abs(ya[j]);
            for (size_t f = 0; f < angles.size(); ++f) {
                const double beta = std::tan(angles[f] * 3.14159265358979323846 / 180.0);
                const double alpha = ya[stop] != 0.0 ? -beta * yb[stop] / ya[stop] : 0.0;
                const double chief = alpha * ya[j] + beta * yb[j];
                const double up = f < m_p.vignetting_upper.size() ? m_p.vignetting_upper[f] : 0.0;
                const double low = f < m_p.vignetting_lower.size() ? m_p.vignetting_lower[f] : 0.0;
                sd = std::max({sd, std::abs(chief + (1.0 - up) * ya[j]),
                               std::abs(chief - (1.0 - low) * ya[j])});
                largest = std::max(largest, std::abs(angles[f]));
            }
            m_s_estimate[j] = sd;
        }
        warnings.push_back({0, std::string(m_s_estimate.size() + 1 == image
                                               ? "no semi-apertures given"
                                               : "some surfaces have no semi-aperture") +
                                   ": each surface without one gets the largest height of the "
                                   "paraxial rim rays (entrance pupil " +
                                   format_number(2.0 * std::abs(pupil_radius)) + ", fields up to " +
                                   format_number(largest) + " degrees, vignetting as given)"});
    }

    double semi_diameter(size_t j) const {
        const auto it = m_s_estimate.find(j);
        return it != m_s_estimate.end() ? it->second : m_s[j].semi_diameter;
    }

    // The air after surface `from` (whose thickness starts it) to the next glass or mirror,
    // through any surfaces in air between: the element's `gap`, counted the way light travels;
    // or, when the image comes first, the bench's image distance (signed along the axis).
    void air_after(size_t owner, size_t from, double travel, ordered_json& e,
                   ImportedLens& out) const {
        const size_t image = m_s.size() - 1;
        size_t next = from;
        double gap = 0.0;
        while (next < image &&
               (next == from || (!prescription_has_glass(m_s[next]) && !m_s[next].mirror))) {
            gap += travel * m_s[next].thickness * m_mm;
            if (next > owner) in_air(next, out.warnings);
            ++next;
        }
        if (next < image) {
            if (!(gap > 0.0)) {
                refuse(m_s[from].line,
                       "an air space of " + format_number(travel * gap) + " after " +
                           prescription_surface_label(from) +
                           (travel > 0 ? " (must be > 0)"
                                       : " (light travels back after a mirror: must be < 0)"));
            }
            e["gap"] = gap;
        } else {
            out.bench["image_distance"] = travel * gap;
        }
    }

    ordered_json mirror_element(size_t i, double travel, double& group_diameter,
                                ImportedLens& out) const {
        const LensFileSurface& s = m_s[i];
        if (prescription_has_glass(m_s[i - 1])) {
            refuse(s.glass_line ? s.glass_line : s.line,
                   prescription_surface_label(i) +
                       ": a mirror on a glass face (a Mangin mirror, light reflected inside the "
                       "glass) is not yet supported");
        }
        const double sd = semi_diameter(i) * m_mm;
        if (!(sd > 0.0)) {
            refuse(s.line, "the mirror " + prescription_surface_label(i) +
                               " has no semi-diameter (Zemax DIAM, CODE V CIR)");
        }
        check_prescription_span(m_p, i, sd);
        ordered_json e;
        e["mirror"] = prescription_surface_json(m_p, i);
        e["diameter"] = 2.0 * sd;
        // In a sequential trace a central obscuration on a mirror stops the same rays as a hole.
        const double hole = std::max(s.hole_semi_diameter, s.obscuration_semi_diameter);
        if (hole > 0.0) {
            if (!(hole * m_mm < sd)) {
                refuse(s.line, prescription_surface_label(i) + ": a central hole of radius " +
                                   format_number(hole) + " as large as the mirror");
            }
            e["hole_diameter"] = 2.0 * hole * m_mm;
        }
        if (s.tilt_x != 0.0 || s.tilt_y != 0.0) {
            if (s.tilt_x != 0.0) e["tilt_x"] = s.tilt_x;
            if (s.tilt_y != 0.0) e["tilt_y"] = s.tilt_y;
        }
        e["material"] = {{"color", 0}, {"specular", 1}};
        group_diameter = std::max(group_diameter, 2.0 * sd);
        air_after(i, i, -travel, e, out);
        out.element_lines.push_back(s.line);
        return e;
    }

    // Zemax writes a fold mirror as a coordinate break tilting the frame about x or y, the
    // mirror, and a coordinate break of the same tilt (the frame then turned by twice the
    // tilt; Zemax's fold mirror tool writes it so): the mirror's tilt_x or tilt_y, the space
    // after the second break the mirror's. Any other decentre or tilt is refused.
    void take_folds() {
        const size_t image = m_s.size() - 1;
        for (size_t i = 1; i < image; ++i) {
            const LensFileSurface& b = m_s[i];
            if (!b.coordinate_break || !turns(b)) continue;
            const double* t = b.break_parameters;
            const bool fold = i + 2 < image && m_s[i + 1].mirror && m_s[i + 2].coordinate_break &&
                              t[0] == 0 && t[1] == 0 && t[4] == 0 && (t[2] == 0) != (t[3] == 0) &&
                              b.thickness == 0 && m_s[i + 1].thickness == 0 &&
                              std::equal(t, t + 5, m_s[i + 2].break_parameters);
            if (!fold && take_element_motion(i)) continue;
            if (!fold) {
                static const char* const kWhat[] = {"a decentre in x", "a decentre in y",
                                                    "a tilt about x", "a tilt about y",
                                                    "a tilt about z"};
                const int k =
                    static_cast<int>(std::find_if(t, t + 5, [](double v) { return v != 0; }) - t);
                refuse(b.break_line ? b.break_line : b.line,
                       std::string("coordinate break with ") + kWhat[k] +
                           ": lenslab reads a fold (a mirror between two breaks of the same "
                           "tilt about x or y) and a moved element (a break of order 0, the "
                           "element, back to that plane, the inverse break of order 1)");
            }
            LensFileSurface& mirror = m_s[i + 1];
            mirror.tilt_x = t[2];
            mirror.tilt_y = t[3];
            mirror.thickness = m_s[i + 2].thickness;
            m_s[i + 2].thickness = 0.0;
            std::fill(m_s[i].break_parameters, m_s[i].break_parameters + 6, 0.0);
            std::fill(m_s[i + 2].break_parameters, m_s[i + 2].break_parameters + 6, 0.0);
            i += 2;
        }
    }

    // Zemax writes a decentred or tilted element as a coordinate break of order 0 before it and
    // its inverse after it (the same values negated, order 1), the thicknesses between
    // returning to the first break's plane (its tilt/decenter elements tool writes it so):
    // the element's decentre and tilts, the air after it counted as designed.
    bool take_element_motion(size_t i) {
        const size_t image = m_s.size() - 1;
        const double* t = m_s[i].break_parameters;
        if (t[5] != 0.0 || m_s[i].thickness != 0.0) return false;
        size_t j = i + 1;
        while (j < image && !m_s[j].coordinate_break) ++j;
        if (j >= image || j < i + 3) return false;  // a front and a back face at least
        const double* back = m_s[j].break_parameters;
        for (int k = 0; k < 5; ++k) {
            if (back[k] != -t[k]) return false;
        }
        if (back[5] == 0.0) return false;
        // One element (or cemented run): glass behind each face but the last.
        double inside = 0.0;
        for (size_t k = i + 1; k < j; ++k) {
            if (m_s[k].mirror || prescription_has_glass(m_s[k]) != (k + 1 < j)) return false;
            if (k + 1 < j) inside += m_s[k].thickness;
        }
        if (std::abs(inside + m_s[j - 1].thickness) > 1e-9 * std::max(1.0, std::abs(inside)))
            return false;
        std::copy(t, t + 5, m_s[i + 1].element_motion);
        m_s[j - 1].thickness = m_s[j].thickness - inside;
        m_s[j].thickness = 0.0;
        std::fill(m_s[i].break_parameters, m_s[i].break_parameters + 6, 0.0);
        std::fill(m_s[j].break_parameters, m_s[j].break_parameters + 6, 0.0);
        return true;
    }

    static bool turns(const LensFileSurface& s) {
        return std::any_of(s.break_parameters, s.break_parameters + 5,
                           [](double v) { return v != 0.0; });
    }

    // A surface with air on both sides bends no light: left out, said when it is not flat.
    void in_air(size_t j, std::vector<LensFileWarning>& warnings) const {
        const LensFileSurface& s = m_s[j];
        if (s.radius != 0.0 || !s.even_terms.empty()) {
            warnings.push_back({s.line, prescription_surface_label(j) +
                                            " has air on both sides and bends no light; left out"});
        }
    }

    ordered_json material_json(const LensFileSurface& s,
                               std::vector<LensFileWarning>& warnings) const {
        ordered_json m = {{"color", 1}, {"transparency", 1}};
        if (!s.glass.empty()) {
            m["glass"] =
                resolve_lens_file_glass(s.glass, m_p.catalogues, m_p.file, s.glass_line, warnings);
        } else if (s.model_vd > 0.0) {
            m["ior"] = {{"model", "abbe"}, {"n_d", s.model_nd}, {"V_d", s.model_vd}};
        } else {
            m["ior"] = s.model_nd;
        }
        return m;
    }

    void bench(ordered_json& b, const std::vector<double>& z, size_t first) const {
        ordered_json out;
        out["unit"] = "mm";
        if (!m_p.wavelengths_nm.empty()) {
            out["wavelengths"] = m_p.wavelengths_nm;
            out["primary_wavelength"] = m_p.wavelengths_nm[m_p.primary_wavelength];
        }
        const bool heights = m_p.field_type != "angle";
        const auto scaled = [&](std::vector<double> v) {
            if (heights) {
                for (double& x : v) x *= m_mm;
            }
            return v;
        };
        if (!m_p.fields_y.empty() || !m_p.fields_x.empty()) {
            out["field_type"] = m_p.field_type;
            out["fields_x"] = scaled(m_p.fields_x);
            out["fields_y"] = scaled(m_p.fields_y);
        }
        if (!m_p.aperture_type.empty()) {
            out["aperture_type"] = m_p.aperture_type;
            out["aperture"] =
                m_p.aperture_type == "entrance_pupil_diameter" ? m_p.aperture * m_mm : m_p.aperture;
        }
        if (!m_p.ray_aiming.empty()) out["ray_aiming"] = m_p.ray_aiming;
        for (size_t j = 1; j + 1 < m_s.size(); ++j) {
            if (!m_s[j].stop) continue;
            out["stop_position"] = z[j] - z[first];
            out["stop_semi_diameter"] = semi_diameter(j) * m_mm;
        }
        if (b.contains("image_distance")) out["image_distance"] = b["image_distance"];
        b = out;
    }

    const LensFilePrescription& m_p;
    std::vector<LensFileSurface> m_s;  // the file's, its folds taken into the mirrors
    double m_mm;
    std::map<size_t, double> m_s_estimate;  // estimated semi-diameters, in the file's unit
};

}  // namespace

ImportedLens lens_group_from_prescription(const LensFilePrescription& p, const std::string& name) {
    return GroupBuilder(p).build(name);
}

}  // namespace lenslab
