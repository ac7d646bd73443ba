#include "lensfile/zmx_reader.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "lensfile/lens_file_tokens.h"

namespace lenslab {

namespace {

// Keywords that describe how Zemax draws, optimises, tolerances or labels a design, not the
// lens itself: understood, and passed over without a warning.
const std::set<std::string>& zmx_display_keywords() {
    static const std::set<std::string> keywords = {
        "VERS", "PFIL", "LANG", "ENVD", "GFAC", "PUSH", "SDMA", "OMMA", "ROPD", "PICB", "FWGN",
        "FWGT", "WWGT", "VDXN", "VDYN", "VCXN", "VCYN", "VANN", "POLS", "GLRS", "GSTD", "NSCD",
        "COFN", "HIDE", "SLAB", "POPS", "FIMP", "BLNK", "TOL",  "MOFF", "NOTE", "COMM", "COAT",
        "TOLE", "PZUP", "PPAR", "PSCA", "MAZH", "CONF", "TCMM", "DMFS", "SCOL", "SWID"};
    return keywords;
}

// Lengths of the four UNIT names Zemax writes, in millimetres.
bool zmx_unit_mm(const std::string& unit, double& mm) {
    if (unit == "MM")
        mm = 1.0;
    else if (unit == "CM")
        mm = 10.0;
    else if (unit == "IN")
        mm = 25.4;
    else if (unit == "METER" || unit == "M")
        mm = 1000.0;
    else
        return false;
    return true;
}

class ZmxReader {
public:
    ZmxReader(const std::vector<std::string>& lines, const std::string& file)
        : m_lines(lines), m_file(file) {
        m_lens.file = file;
        m_lens.format = "zmx";
    }

    LensFilePrescription read() {
        for (size_t i = 0; i < m_lines.size(); ++i) {
            m_line = static_cast<int>(i) + 1;
            m_words = lens_file_words(m_lines[i]);
            if (m_words.empty()) continue;
            keyword(lens_file_upper(m_words[0]));
        }
        finish();
        return std::move(m_lens);
    }

private:
    [[noreturn]] void refuse(const std::string& reason) const {
        throw LensFileError(m_file, m_line, reason);
    }
    void warn(const std::string& message) { m_lens.warnings.push_back({m_line, message}); }

    double number(size_t i, const std::string& what) const {
        if (i >= m_words.size())
            refuse(m_words[0] + ": " + what + " missing (the line is cut short)");
        return lens_file_number(m_words[i], m_file, m_line, m_words[0] + " " + what);
    }

    // Zemax wavelengths are in um; read as nm by moving the decimal point, exactly.
    double micrometres_as_nm(size_t i) const {
        (void)number(i, "wavelength (um)");
        return lens_file_number_shifted(m_words[i], 3, m_file, m_line,
                                        m_words[0] + " wavelength (um)");
    }

    LensFileSurface& surface() {
        if (m_lens.surfaces.empty()) refuse(m_words[0] + " before the first SURF");
        return m_lens.surfaces.back();
    }

    void keyword(const std::string& k) {
        if (k == "SURF") return begin_surface();
        if (k == "TYPE") return surface_type();
        if (k == "CURV") {
            const double c = number(1, "curvature");
            surface().radius = c == 0.0 ? 0.0 : 1.0 / c;
            surface().radius_line = m_line;
            return;
        }
        if (k == "DISZ") {
            const bool infinite = m_words.size() > 1 && lens_file_upper(m_words[1]) == "INFINITY";
            surface().thickness = infinite ? INFINITY : number(1, "thickness");
            return;
        }
        if (k == "CONI") {
            surface().conic = number(1, "conic constant");
            return;
        }
        if (k == "PARM") return parameter();
        if (k == "XDAT") return extra_data();
        if (k == "GLAS") return glass();
        if (k == "DIAM") {
            surface().semi_diameter = number(1, "semi-diameter");
            return;
        }
        if (k == "MEMA") {
            // The mechanical semi-diameter: the element's edge where no DIAM is given.
            if (surface().semi_diameter == 0.0)
                surface().semi_diameter = number(1, "semi-diameter");
            return;
        }
        if (k == "FLAP") {
            // A floating aperture: the semi-diameter Zemax keeps for the surface, written
            // beside its DIAM; taken where no DIAM is given.
            if (surface().semi_diameter == 0.0)
                surface().semi_diameter = number(2, "floating aperture");
            return;
        }
        if (k == "CLAP") {
            // A circular aperture: a hard stop for rays at that radius. The element's rim is
            // there when it is smaller than the surface's DIAM (finish()).
            const double r = number(2, "circular aperture");
            (void)surface();  // refuses a CLAP before the first SURF
            m_clear_apertures[m_lens.surfaces.size() - 1] = r;
            return;
        }
        if (k == "OBSC") return obscuration();
        if (k == "STOP") {
            surface().stop = true;
            return;
        }
        if (k == "MIRR") return;  // how a mirror's substrate is drawn
        if (k == "MODE") {
            if (m_words.size() > 1 && lens_file_upper(m_words[1]) != "SEQ") {
                refuse("MODE " + m_words[1] +
                       ": only sequential designs (MODE SEQ) can become a lens_group");
            }
            return;
        }
        if (k == "NAME") {
            const std::string& text = m_lines[m_line - 1];
            const size_t at = text.find("NAME");
            m_lens.title = at + 4 < text.size() ? text.substr(at + 5) : "";
            while (!m_lens.title.empty() && m_lens.title.back() == ' ') m_lens.title.pop_back();
            return;
        }
        if (k == "UNIT") {
            const std::string unit = m_words.size() > 1 ? lens_file_upper(m_words[1]) : "";
            if (!zmx_unit_mm(unit, m_lens.unit_mm)) {
                refuse("UNIT '" + unit + "': lenslab reads MM, CM, IN and METER");
            }
            return;
        }
        if (k == "GCAT") {
            m_lens.catalogues.assign(m_words.begin() + 1, m_words.end());
            return;
        }
        if (k == "ENPD" || k == "FNUM" || k == "OBNA") {
            m_lens.aperture_type = k == "ENPD"   ? "entrance_pupil_diameter"
                                   : k == "FNUM" ? "f_number"
                                                 : "object_na";
            m_lens.aperture = number(1, "value");
            return;
        }
        if (k == "RAIM") {
            // RAIM <?> <mode> ...: mode 0 is Zemax's ray aiming off, rays aimed at the paraxial
            // entrance pupil; 1 (paraxial) and 2 (real) aim them through the stop.
            if (m_words.size() > 2) {
                m_lens.ray_aiming = number(2, "ray aiming") == 0 ? "paraxial" : "real";
            }
            return;
        }
        if (k == "FLOA") {
            m_lens.aperture_type = "float_by_stop_size";
            m_lens.aperture = 0.0;
            return;
        }
        if (k == "MNUM") {
            m_lens.configurations = static_cast<int>(number(1, "number of configurations"));
            if (m_lens.configurations < 1)
                refuse("MNUM: " + std::to_string(m_lens.configurations) + " configurations");
            if (m_words.size() > 2)
                m_lens.active_configuration = static_cast<int>(number(2, "active configuration"));
            return;
        }
        if (k == "THIC") {
            // A multi-configuration thickness: THIC surface configuration value ...
            m_lens.configuration_thicknesses.push_back(
                {static_cast<int>(number(1, "surface")),
                 static_cast<int>(number(2, "configuration")), m_line, number(3, "thickness")});
            return;
        }
        if (k == "WAVM") return wavelength();
        if (k == "WAVL") {
            for (size_t i = 1; i < m_words.size(); ++i)
                m_lens.wavelengths_nm.push_back(micrometres_as_nm(i));
            return;
        }
        if (k == "PWAV") {
            m_primary = static_cast<int>(number(1, "primary wavelength"));
            return;
        }
        if (k == "FTYP") {
            const int type = static_cast<int>(number(1, "field type"));
            static const char* const kTypes[] = {"angle", "object_height", "paraxial_image_height",
                                                 "real_image_height"};
            if (type < 0 || type > 3) {
                refuse("FTYP: field type " + std::to_string(type) +
                       " (lenslab reads 0 angle, 1 object height, 2 and 3 image height)");
            }
            m_lens.field_type = kTypes[type];
            if (m_words.size() > 3) m_field_count = static_cast<int>(number(3, "number of fields"));
            if (m_words.size() > 4)
                m_wave_count = static_cast<int>(number(4, "number of wavelengths"));
            return;
        }
        if (k == "XFLN" || k == "YFLN") {
            std::vector<double>& out = k == "XFLN" ? m_lens.fields_x : m_lens.fields_y;
            out.clear();
            for (size_t i = 1; i < m_words.size(); ++i) out.push_back(number(i, "field"));
            return;
        }
        if (zmx_display_keywords().count(k)) return;
        warn(std::string("'").append(k).append("' not understood; the line is left out"));
    }

    void begin_surface() {
        const int n = static_cast<int>(number(1, "surface number"));
        if (n != static_cast<int>(m_lens.surfaces.size())) {
            refuse("SURF " + std::to_string(n) + " where surface " +
                   std::to_string(m_lens.surfaces.size()) + " was expected");
        }
        LensFileSurface s;
        s.line = m_line;
        m_lens.surfaces.push_back(s);
        m_type = "STANDARD";
    }

    void surface_type() {
        surface();
        const std::string t = m_words.size() > 1 ? lens_file_upper(m_words[1]) : "";
        static const std::map<std::string, std::string> kFreeforms = {
            {"BICONICX", "biconic"},
            {"TOROIDAL", "toroidal"},
            {"SZERNSAG", "zernike"},
            {"XPOLYNOM", "xy_polynomial"}};
        const auto freeform = kFreeforms.find(t);
        if (t != "STANDARD" && t != "EVENASPH" && t != "COORDBRK" && freeform == kFreeforms.end()) {
            refuse("surface type '" + t +
                   "' cannot be represented (lenslab reads STANDARD, EVENASPH, BICONICX, "
                   "TOROIDAL, SZERNSAG, XPOLYNOM and COORDBRK)");
        }
        m_type = t;
        surface().coordinate_break = t == "COORDBRK";
        if (freeform != kFreeforms.end()) surface().anamorphic = freeform->second;
    }

    void parameter() {
        LensFileSurface& s = surface();
        const int i = static_cast<int>(number(1, "parameter number"));
        const double v = number(2, "value");
        if ((m_type == "EVENASPH" || m_type == "SZERNSAG") && i >= 1 && i <= 8) {
            if (static_cast<int>(s.even_terms.size()) < i) s.even_terms.resize(i, 0.0);
            s.even_terms[i - 1] = v;
            return;
        }
        if (m_type == "BICONICX" && (i == 1 || i == 2)) {
            (i == 1 ? s.radius_x : s.conic_x) = v;
            return;
        }
        // TOROIDAL: the radius of rotation, then the y curve's y^2, y^4, ... y^16 terms.
        if (m_type == "TOROIDAL" && i >= 1 && i <= 9) {
            if (i == 1) {
                s.radius_of_rotation = v;
                return;
            }
            if (static_cast<int>(s.even_terms.size()) < i - 1) s.even_terms.resize(i - 1, 0.0);
            s.even_terms[i - 2] = v;
            return;
        }
        if (m_type == "COORDBRK" && i >= 1 && i <= 6) {
            // Kept for the lens group builder, which takes the fold around a mirror.
            s.break_parameters[i - 1] = v;
            if (v != 0.0 && !s.break_line) s.break_line = m_line;
            return;
        }
        if (v != 0.0 && !s.anamorphic.empty()) {
            refuse("PARM " + std::to_string(i) + " = " + m_words[2] + " of a " + m_type +
                   " surface cannot be represented");
        }
        if (v != 0.0) {
            warn("PARM " + std::to_string(i) + " = " + m_words[2] + " means nothing for a " +
                 m_type + " surface; left out");
        }
    }

    // XDAT n value ...: the extra data of SZERNSAG and XPOLYNOM surfaces (what follows the
    // value says how Zemax solves for it).
    void extra_data() {
        LensFileSurface& s = surface();
        const int i = static_cast<int>(number(1, "extra data number"));
        const double v = number(2, "value");
        if (i < 1 || i > 300) refuse("XDAT " + std::to_string(i) + ": no such extra data");
        if (s.anamorphic != "zernike" && s.anamorphic != "xy_polynomial") {
            if (v != 0.0)
                warn("XDAT " + std::to_string(i) + " means nothing for a " + m_type +
                     " surface; left out");
            return;
        }
        if (static_cast<int>(s.extra_data.size()) < i) s.extra_data.resize(i, 0.0);
        s.extra_data[i - 1] = v;
        if (!s.extra_data_line) s.extra_data_line = m_line;
    }

    // OBSC r R ...: a circular obscuration from radius r to R (Zemax's "circular obscuration"
    // aperture). A central one (r = 0) is recorded; R = 0 obscures nothing.
    void obscuration() {
        LensFileSurface& s = surface();
        const double inner = number(1, "minimum radius"), outer = number(2, "maximum radius");
        if (outer == 0.0) return;
        const std::string where = " on surface " + std::to_string(m_lens.surfaces.size() - 1);
        if (inner != 0.0) {
            return warn("OBSC: an annular obscuration (radius " + m_words[1] + " to " + m_words[2] +
                        ")" + where + "; left out");
        }
        s.obscuration_semi_diameter = outer;
        warn("OBSC: a central obscuration of radius " + m_words[2] + where +
             "; on a mirror, its central hole; elsewhere recorded, but not yet used (no ray "
             "is blocked by it)");
    }

    void glass() {
        LensFileSurface& s = surface();
        if (m_words.size() < 2) refuse("GLAS without a glass name");
        const std::string name = m_words[1];
        if (lens_file_upper(name) == "MIRROR") {
            s.mirror = true;
            s.glass_line = m_line;
            return;
        }
        s.glass_line = m_line;
        if (name == "___BLANK") {
            // A model glass: GLAS ___BLANK <solve> <?> n_d V_d ...
            s.model_nd = number(4, "model glass n_d");
            s.model_vd = m_words.size() > 5 ? number(5, "model glass V_d") : 0.0;
            return;
        }
        s.glass = name;
    }

    void wavelength() {
        const int i = static_cast<int>(number(1, "wavelength number"));
        const double nm = micrometres_as_nm(2);
        if (i < 1 || i > 48) refuse("WAVM: wavelength number " + std::to_string(i));
        auto& w = m_lens.wavelengths_nm;
        if (static_cast<int>(w.size()) < i) w.resize(i, 0.0);
        w[i - 1] = nm;
    }

    void finish() {
        m_line = 0;
        for (const auto& [i, r] : m_clear_apertures) {
            double& sd = m_lens.surfaces[i].semi_diameter;
            sd = sd > 0.0 ? std::min(sd, r) : r;
        }
        if (m_lens.surfaces.empty()) refuse("no surface (SURF): not a Zemax lens file");
        // Zemax writes all 24 wavelength slots; FTYP says how many are used.
        auto& w = m_lens.wavelengths_nm;
        if (m_wave_count > 0 && static_cast<int>(w.size()) > m_wave_count) w.resize(m_wave_count);
        const int primary = std::max(1, m_primary);
        if (primary > static_cast<int>(w.size()) && !w.empty()) {
            m_lens.warnings.push_back({0, "PWAV names wavelength " + std::to_string(primary) +
                                              " of " + std::to_string(w.size()) +
                                              "; the first is taken"});
        }
        m_lens.primary_wavelength = primary <= static_cast<int>(w.size()) ? primary - 1 : 0;
        if (m_field_count > 0) {
            const auto cut = [&](std::vector<double>& f) {
                if (static_cast<int>(f.size()) > m_field_count) f.resize(m_field_count);
            };
            cut(m_lens.fields_x);
            cut(m_lens.fields_y);
        }
    }

    const std::vector<std::string>& m_lines;
    std::string m_file;
    LensFilePrescription m_lens;
    int m_line = 0;
    std::vector<std::string> m_words;
    std::string m_type = "STANDARD";
    std::map<size_t, double> m_clear_apertures;  // CLAP radii by surface
    int m_primary = 1;
    int m_field_count = 0;
    int m_wave_count = 0;
};

}  // namespace

LensFilePrescription read_zmx(const std::vector<std::string>& lines, const std::string& file) {
    return ZmxReader(lines, file).read();
}

}  // namespace lenslab
