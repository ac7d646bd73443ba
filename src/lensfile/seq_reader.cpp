#include "lensfile/seq_reader.h"

#include <cmath>
#include <set>

#include "lensfile/lens_file_tokens.h"

namespace lenslab {

namespace {

// Commands that set up CODE V's session, weights, vignetting, solves and variables, not the
// lens: understood, and passed over.
const std::set<std::string>& seq_session_commands() {
    static const std::set<std::string> commands = {
        "LEN", "INI", "WTW", "WTF", "VUX", "VLX", "CCY", "THC", "GLC", "PIM", "GO",  "SPH",
        "CON", "ASP", "END", "DES", "DER", "PUX", "PUY", "PUI", "PCX", "PCY", "PCI", "SEL",
        "CCX", "CCK", "CCA", "CCB", "CCC", "CCD", "CCE", "CCF", "CCG", "TEL"};
    return commands;
}

// Lines split into commands at ';' (outside quotes), comments ('!' to the end) removed.
std::vector<std::string> seq_commands(const std::string& line) {
    std::vector<std::string> out(1);
    char quote = 0;
    for (const char c : line) {
        if (quote) {
            if (c == quote) quote = 0;
        } else if (c == '\'' || c == '"') {
            quote = c;
        } else if (c == '!') {
            break;
        } else if (c == ';') {
            out.emplace_back();
            continue;
        }
        out.back() += c;
    }
    return out;
}

class SeqReader {
public:
    SeqReader(const std::vector<std::string>& lines, const std::string& file)
        : m_lines(lines), m_file(file) {
        m_lens.file = file;
        m_lens.format = "seq";
    }

    LensFilePrescription read() {
        for (size_t i = 0; i < m_lines.size(); ++i) {
            m_line = static_cast<int>(i) + 1;
            for (const std::string& command : seq_commands(m_lines[i])) {
                m_words = lens_file_words(command);
                if (m_words.empty()) continue;
                m_words[0] = lens_file_upper(m_words[0]);
                this->command(m_words[0]);
            }
        }
        m_line = 0;
        if (m_lens.surfaces.empty()) refuse("no surface (SO, S, SI): not a CODE V sequence file");
        if (!m_lens.wavelengths_nm.empty() &&
            m_primary > static_cast<int>(m_lens.wavelengths_nm.size())) {
            refuse("REF names wavelength " + std::to_string(m_primary) + " of " +
                   std::to_string(m_lens.wavelengths_nm.size()));
        }
        m_lens.primary_wavelength = m_lens.wavelengths_nm.empty() ? 0 : m_primary - 1;
        return std::move(m_lens);
    }

private:
    [[noreturn]] void refuse(const std::string& reason) const {
        throw LensFileError(m_file, m_line, reason);
    }

    double number(size_t i, const std::string& what) const {
        if (i >= m_words.size()) refuse(m_words[0] + ": " + what + " missing");
        return lens_file_number(m_words[i], m_file, m_line, m_words[0] + " " + what);
    }

    LensFileSurface& surface() {
        if (m_lens.surfaces.empty()) refuse(m_words[0] + " before the first surface (SO or S)");
        return m_lens.surfaces.back();
    }

    std::vector<double> numbers(const std::string& what) const {
        std::vector<double> out;
        for (size_t i = 1; i < m_words.size(); ++i) out.push_back(number(i, what));
        return out;
    }

    void set_radius(LensFileSurface& s, double value) {
        if (m_curvature_mode) {
            s.radius = value == 0.0 ? 0.0 : 1.0 / value;
        } else {
            s.radius = value;  // CODE V writes a flat surface as radius 0
        }
        s.radius_line = m_line;
    }

    void set_glass(LensFileSurface& s, const std::string& name) {
        const std::string upper = lens_file_upper(name);
        if (upper == "REFL") refuse("a mirror (REFL): a lens_group holds refracting elements only");
        s.glass_line = m_line;
        s.glass = upper == "AIR" ? "" : name;
    }

    void add_surface() {
        LensFileSurface s;
        s.line = m_line;
        if (m_words.size() > 1) set_radius(s, number(1, "radius"));
        if (m_words.size() > 2) {
            const double t = number(2, "thickness");
            // Object distances of 1e10 and more stand for infinity (CODE V's own convention).
            s.thickness = std::abs(t) >= 1e10 ? INFINITY : t;
        }
        if (m_words.size() > 3) set_glass(s, m_words[3]);
        if (m_words.size() > 4) refuse(m_words[0] + ": more than radius, thickness and glass");
        m_lens.surfaces.push_back(s);
    }

    void aspheric(const std::string& c) {
        // A is the r^4 term, B r^6, ... G r^16 (even_terms[0] is the r^2 term).
        const int power_index = c[0] - 'A' + 1;
        LensFileSurface& s = surface();
        if (static_cast<int>(s.even_terms.size()) <= power_index) {
            s.even_terms.resize(power_index + 1, 0.0);
        }
        s.even_terms[power_index] = number(1, "coefficient");
    }

    void command(const std::string& c) {
        if (c == "SO" || c == "S" || c == "SI") {
            if (c == "SO" && !m_lens.surfaces.empty()) refuse("SO after the first surface");
            if (c != "SO" && m_lens.surfaces.empty()) {
                m_lens.surfaces.push_back({});  // an object at infinity when SO is left out
                m_lens.surfaces.back().thickness = INFINITY;
            }
            return add_surface();
        }
        if (c == "RDM") {
            m_curvature_mode = m_words.size() > 1 && lens_file_upper(m_words[1]) == "N";
            return;
        }
        if (c == "RDY" || c == "CUY") {
            const bool cm = m_curvature_mode;
            m_curvature_mode = c == "CUY";
            set_radius(surface(), number(1, c == "CUY" ? "curvature" : "radius"));
            m_curvature_mode = cm;
            return;
        }
        if (c == "THI") {
            surface().thickness = number(1, "thickness");
            return;
        }
        if (c == "GLA") {
            if (m_words.size() < 2) refuse("GLA without a glass name");
            return set_glass(surface(), m_words[1]);
        }
        if (c == "REFL") refuse("a mirror (REFL): a lens_group holds refracting elements only");
        if (c == "STO") {
            surface().stop = true;
            return;
        }
        if (c == "K") {
            surface().conic = number(1, "conic constant");
            return;
        }
        if (c.size() == 1 && c[0] >= 'A' && c[0] <= 'G') return aspheric(c);
        if (c == "H" || c == "J") {
            if (number(1, "coefficient") != 0.0) {
                refuse(c + ": aspheric terms beyond r^16 (G) cannot be represented");
            }
            return;
        }
        if (c == "CIR") {
            surface().semi_diameter = number(1, "semi-aperture");
            return;
        }
        if (c == "DIM") {
            const std::string u = m_words.size() > 1 ? lens_file_upper(m_words[1]) : "";
            if (u == "M")
                m_lens.unit_mm = 1.0;
            else if (u == "C")
                m_lens.unit_mm = 10.0;
            else if (u == "I")
                m_lens.unit_mm = 25.4;
            else
                refuse("DIM '" + u + "': CODE V's units are M (mm), C (cm) and I (inches)");
            return;
        }
        if (c == "WL") {
            m_lens.wavelengths_nm = numbers("wavelength (nm)");
            return;
        }
        if (c == "REF") {
            m_primary = static_cast<int>(number(1, "reference wavelength"));
            if (m_primary < 1) refuse("REF: the reference wavelength counts from 1");
            return;
        }
        if (c == "EPD" || c == "FNO" || c == "NA" || c == "NAO") {
            m_lens.aperture_type = c == "EPD"   ? "entrance_pupil_diameter"
                                   : c == "FNO" ? "f_number"
                                   : c == "NA"  ? "image_na"
                                                : "object_na";
            m_lens.aperture = number(1, "value");
            return;
        }
        if (c == "YAN" || c == "YOB" || c == "YIM") {
            m_lens.field_type = c == "YAN"   ? "angle"
                                : c == "YOB" ? "object_height"
                                             : "paraxial_image_height";
            m_lens.fields_y = numbers("field");
            return;
        }
        if (c == "VUY" || c == "VLY") {
            (c == "VUY" ? m_lens.vignetting_upper : m_lens.vignetting_lower) = numbers("factor");
            return;
        }
        if (c == "XAN" || c == "XOB" || c == "XIM") {
            m_lens.fields_x = numbers("field");
            return;
        }
        if (c == "TIT" || c == "TITLE") {
            if (m_words.size() > 1) m_lens.title = m_words[1];
            return;
        }
        if (c == "XDE" || c == "YDE" || c == "ZDE" || c == "ADE" || c == "BDE" || c == "CDE") {
            if (number(1, "value") != 0.0) {
                refuse(c +
                       ": a decentre or tilt; a lens_group holds elements on one straight "
                       "axis and cannot represent it");
            }
            return;
        }
        if (c == "DEC" || c == "DAR" || c == "BEN" || c == "REV" || c == "RET") {
            refuse(c +
                   ": a decentre or tilt; a lens_group holds elements on one straight axis "
                   "and cannot represent it");
        }
        if (c == "XYP" || c == "ZRN" || c == "SPS" || c == "TOR" || c == "DOE" || c == "HOE" ||
            c == "GRT" || c == "UDS" || c == "CYL") {
            refuse("surface type " + c +
                   " cannot be represented (lenslab reads spheres, conics and even aspheres)");
        }
        if (seq_session_commands().count(c)) return;
        m_lens.warnings.push_back({m_line, std::string("'").append(c).append(
                                               "' not understood; the command is left out")});
    }

    const std::vector<std::string>& m_lines;
    std::string m_file;
    LensFilePrescription m_lens;
    int m_line = 0;
    std::vector<std::string> m_words;
    bool m_curvature_mode = false;
    int m_primary = 1;
};

}  // namespace

LensFilePrescription read_seq(const std::vector<std::string>& lines, const std::string& file) {
    return SeqReader(lines, file).read();
}

}  // namespace lenslab
