#include "lensfile/seq_reader.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <optional>
#include <set>
#include <utility>

#include "lensfile/lens_file_glass.h"
#include "lensfile/lens_file_tokens.h"
#include "lensfile/seq_lines.h"
#include "lensfile/seq_radius_mode.h"
#include "util/format_number.h"

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

// CODE V's surface qualifiers: SO (the object), SI (the image), Sk (surface k).
bool seq_surface_qualifier(const std::string& word, size_t surfaces, size_t& index) {
    if (word == "SO") {
        index = 0;
        return true;
    }
    if (word == "SI") {
        index = surfaces - 1;
        return true;
    }
    if (word.size() < 2 || word[0] != 'S') return false;
    size_t k = 0;
    for (size_t i = 1; i < word.size(); ++i) {
        if (word[i] < '0' || word[i] > '9' || k > 100000) return false;
        k = 10 * k + static_cast<size_t>(word[i] - '0');
    }
    index = k;
    return true;
}

class SeqReader {
public:
    SeqReader(const std::vector<std::string>& lines, const std::string& file)
        : m_lines(lines), m_file(file) {
        m_lens.file = file;
        m_lens.format = "seq";
    }

    LensFilePrescription read() {
        for (const SeqLine& line : seq_logical_lines(m_lines)) {
            m_line = line.line;
            for (const std::string& command : seq_commands(line.text)) {
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
        take_edge_apertures();
        take_bends();
        settle_radius_mode();
        return std::move(m_lens);
    }

private:
    [[noreturn]] void refuse(const std::string& reason) const {
        throw LensFileError(m_file, m_line, reason);
    }
    void warn(const std::string& message) { m_lens.warnings.push_back({m_line, message}); }

    double number(size_t i, const std::string& what) const {
        if (i >= m_words.size()) refuse(m_words[0] + ": " + what + " missing");
        return lens_file_number(m_words[i], m_file, m_line, m_words[0] + " " + what);
    }

    // Distances of 1e10 and more stand for infinity (CODE V's own convention), as do INF and
    // INFINITY (written by other programs).
    double thickness(size_t i) const {
        const std::string word = i < m_words.size() ? lens_file_upper(m_words[i]) : "";
        if (word == "INF" || word == "INFINITY" || word == "+INF" || word == "+INFINITY") {
            return INFINITY;
        }
        const double t = number(i, "thickness");
        return std::abs(t) >= 1e10 ? INFINITY : t;
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
        if (upper == "REFL") {
            s.mirror = true;
            s.glass_line = m_line;
            return;
        }
        s.glass_line = m_line;
        s.model_nd = s.model_vd = 0.0;
        s.glass = upper == "AIR" ? "" : name;
        if (const auto colon = name.find(':'); colon != std::string::npos) {
            // n_d:V_d, as the open tools write a model glass (1.5168:64.17).
            char* end = nullptr;
            const double nd = std::strtod(name.c_str(), &end);
            const bool nd_ok = end == name.c_str() + colon;
            const double vd = std::strtod(name.c_str() + colon + 1, &end);
            if (nd_ok && *end == '\0' && nd >= 1.0 && nd < 3.0 && vd > 0.0) {
                s.glass.clear();
                s.model_nd = nd;
                s.model_vd = vd;
                warn("glass '" + name + "' read as a model glass of n_d " + format_number(nd) +
                     " and V_d " + format_number(vd));
                return;
            }
        }
        if (!lens_file_glass_code_like(name)) return;
        // A glass code: CODE V's model glass by n_d and V_d.
        const std::optional<LensFileGlassCode> code = lens_file_glass_code(name);
        if (!code) {
            refuse("glass '" + name +
                   "': a number, but not a glass code (NNNVVV as 517642: n_d 1.517, V_d 64.2; "
                   "or NNNNNN.VVVV as 517000.520000: n_d 1.517, V_d 52)");
        }
        s.glass.clear();
        s.model_nd = code->n_d;
        s.model_vd = code->V_d;
        warn("glass '" + name + "' read as a model glass of n_d " + format_number(code->n_d) +
             " and V_d " + format_number(code->V_d) + " (a CODE V glass code)" +
             (code->V_d > 0.0 ? "" : ", without dispersion"));
    }

    void add_surface() {
        LensFileSurface s;
        s.line = m_line;
        if (m_words.size() > 1) {
            // Before any RDM, a radius or a curvature: settled at the end (settle_radius_mode).
            if (!m_mode_given) m_unsure[m_lens.surfaces.size()] = number(1, "radius");
            set_radius(s, number(1, "radius"));
        }
        if (m_words.size() > 2) s.thickness = thickness(2);
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
            // RDM, RDM Y, RDM YES: radii; RDM N, RDM NO: curvatures.
            const std::string mode = m_words.size() > 1 ? lens_file_upper(m_words[1]) : "Y";
            if (mode != "Y" && mode != "YES" && mode != "N" && mode != "NO") {
                refuse("RDM '" + m_words[1] + "': Y (radii) or N (curvatures)");
            }
            m_curvature_mode = mode[0] == 'N';
            m_mode_given = true;
            return;
        }
        if (c == "RDY" || c == "CUY") {
            m_unsure.erase(m_lens.surfaces.size() - 1);
            const bool cm = m_curvature_mode;
            m_curvature_mode = c == "CUY";
            set_radius(surface(), number(1, c == "CUY" ? "curvature" : "radius"));
            m_curvature_mode = cm;
            return;
        }
        if (c == "THI") {
            surface().thickness = thickness(1);
            return;
        }
        if (c == "GLA") {
            if (m_words.size() < 2) refuse("GLA without a glass name");
            return set_glass(surface(), m_words[1]);
        }
        if (c == "REFL") {
            surface().mirror = true;
            return;
        }
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
        if (c == "CIR") return aperture();
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
        if (c == "ADE" || c == "BDE") {
            // A mirror's tilt, kept for BEN (a fold); settled in take_bends.
            (void)surface();  // refuses a tilt before the first surface
            const double v = number(1, "value");
            if (v != 0.0) m_tilts.insert({m_lens.surfaces.size() - 1, Tilt{c, v, m_line}});
            return;
        }
        if (c == "BEN") {
            (void)surface();
            m_bends.insert(m_lens.surfaces.size() - 1);
            return;
        }
        if (c == "XDE" || c == "YDE" || c == "ZDE" || c == "CDE") {
            if (number(1, "value") != 0.0) {
                refuse(c +
                       ": a decentre or tilt; a lens_group holds elements on one straight "
                       "axis and cannot represent it");
            }
            return;
        }
        if (c == "DEC" || c == "DAR" || c == "REV" || c == "RET") {
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

    // CIR [CLR | EDG | OBS | HOL] [Sk | SO | SI] [Zk] [L'label'] value: a clear aperture (the
    // semi-diameter), an edge aperture (where the lens is cut, drawn; the semi-diameter where
    // no clear aperture is given), a central obscuration (recorded), a hole (left out).
    void aperture() {
        surface();
        std::string kind = "CLR";
        size_t j = m_lens.surfaces.size() - 1;
        std::optional<double> value;
        for (size_t i = 1; i < m_words.size(); ++i) {
            const std::string w = lens_file_upper(m_words[i]);
            if (w == "CLR" || w == "EDG" || w == "OBS" || w == "HOL") {
                kind = w;
            } else if (seq_surface_qualifier(w, m_lens.surfaces.size(), j)) {
                if (j >= m_lens.surfaces.size()) refuse("CIR " + m_words[i] + ": no such surface");
            } else if (w.size() > 1 && w[0] == 'Z' &&
                       w.find_first_not_of("0123456789", 1) == std::string::npos) {
                if (w != "Z1") {
                    return warn("CIR " + m_words[i] +
                                ": an aperture of another zoom position than the first; left out");
                }
            } else if (w.size() > 1 && w[0] == 'L' && (w[1] == '\'' || w[1] == '"')) {
                // the aperture's label
            } else if (value) {
                refuse("CIR: '" + m_words[i] + "' after the semi-aperture");
            } else {
                value = number(i, "semi-aperture");
            }
        }
        if (!value) refuse("CIR: semi-aperture missing");
        LensFileSurface& s = m_lens.surfaces[j];
        const std::string where = " on surface " + std::to_string(j);
        if (kind == "CLR") {
            s.semi_diameter = *value;
        } else if (kind == "EDG") {
            m_edges[j] = {*value, m_line};
        } else if (kind == "OBS") {
            s.obscuration_semi_diameter = *value;
            warn("CIR OBS: a central obscuration of radius " + format_number(*value) + where +
                 "; on a mirror, its central hole; elsewhere recorded, but not yet used (no ray "
                 "is blocked by it)");
        } else {
            s.hole_semi_diameter = *value;
            warn("CIR HOL: a hole of radius " + format_number(*value) + where +
                 ": a mirror's central hole (left out on a surface that is not a mirror)");
        }
    }

    // A mirror tilted by ADE (about x) or BDE (about y) with BEN, the axis following the
    // reflection, is a fold: the mirror's tilt_x or tilt_y (CODE V's positive alpha turns y
    // towards z, so z towards -y, as lenslab's tilt_x). Any other tilt is refused at its line.
    void take_bends() {
        for (const auto& [j, tilt] : m_tilts) {
            LensFileSurface& s = m_lens.surfaces[j];
            if (!s.mirror || !m_bends.count(j)) {
                throw LensFileError(m_file, tilt.line,
                                    tilt.command +
                                        ": a tilt; a lens group holds elements on one axis, "
                                        "folded only by a tilted mirror with BEN");
            }
            (tilt.command == "ADE" ? s.tilt_x : s.tilt_y) = tilt.value;
            if (s.tilt_x != 0.0 && s.tilt_y != 0.0) {
                throw LensFileError(m_file, tilt.line,
                                    "ADE and BDE on one mirror: lenslab folds about one axis");
            }
        }
    }

    // Edge apertures stand in for the clear apertures the file does not give.
    void take_edge_apertures() {
        for (const auto& [j, edge] : m_edges) {
            LensFileSurface& s = m_lens.surfaces[j];
            if (s.semi_diameter != 0.0) continue;
            s.semi_diameter = edge.first;
            m_lens.warnings.push_back(
                {edge.second, "CIR EDG: surface " + std::to_string(j) +
                                  " has no clear aperture (CIR); its edge aperture " +
                                  format_number(edge.first) + " is taken as its semi-diameter"});
        }
    }

    // A file without RDM: its numbers after S are radii, as lenslab and most files written by
    // hand take them, unless they make sense only as curvatures (CODE V's RDM N).
    void settle_radius_mode() {
        if (m_unsure.empty()) return;
        const std::string as_radii = seq_implausible_radii(m_lens, m_unsure, false);
        if (as_radii.empty() || !seq_implausible_radii(m_lens, m_unsure, true).empty()) return;
        int line = 0;
        for (const auto& [j, v] : m_unsure) {
            m_lens.surfaces[j].radius = v == 0.0 ? 0.0 : 1.0 / v;
            if (!line && v != 0.0) line = m_lens.surfaces[j].line;
        }
        m_lens.warnings.push_back(
            {line,
             "no RDM: the numbers after S are read as curvatures, as after RDM N (as radii, " +
                 as_radii + "); write RDM N or RDM Y to say which"});
    }

    const std::vector<std::string>& m_lines;
    std::string m_file;
    LensFilePrescription m_lens;
    int m_line = 0;
    std::vector<std::string> m_words;
    bool m_curvature_mode = false;
    bool m_mode_given = false;          // an RDM was read
    std::map<size_t, double> m_unsure;  // surface: its number after S, before any RDM
    std::map<size_t, std::pair<double, int>> m_edges;  // surface: CIR EDG value, line
    struct Tilt {
        std::string command;  // ADE or BDE
        double value = 0;
        int line = 0;
    };
    std::multimap<size_t, Tilt> m_tilts;  // surface: its tilts
    std::set<size_t> m_bends;             // surfaces with BEN
    int m_primary = 1;
};

}  // namespace

LensFilePrescription read_seq(const std::vector<std::string>& lines, const std::string& file) {
    return SeqReader(lines, file).read();
}

}  // namespace lenslab
