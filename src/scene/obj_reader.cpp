#include "scene/obj_reader.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string_view>
#include <system_error>

namespace lenslab {

namespace {

using namespace std::string_view_literals;

// Statements OBJ defines that lenslab has no use for: names, groups, smoothing, materials
// (the scene's material applies), lines, points and display attributes.
constexpr std::string_view kIgnored[] = {
    "o"sv,         "g"sv,      "s"sv,      "usemtl"sv,   "mtllib"sv,   "l"sv,   "p"sv,
    "vp"sv,        "mg"sv,     "bevel"sv,  "c_interp"sv, "d_interp"sv, "lod"sv, "shadow_obj"sv,
    "trace_obj"sv, "maplib"sv, "usemap"sv, "ctech"sv,    "stech"sv};

// Free-form curves and surfaces: geometry lenslab cannot build, so refused rather than lost.
constexpr std::string_view kFreeForm[] = {"cstype"sv, "deg"sv,  "bmat"sv, "step"sv, "curv"sv,
                                          "curv2"sv,  "surf"sv, "parm"sv, "trim"sv, "hole"sv,
                                          "scrv"sv,   "sp"sv,   "end"sv,  "con"sv};

template <size_t N>
bool is_one_of(std::string_view word, const std::string_view (&words)[N]) {
    for (std::string_view w : words) {
        if (w == word) return true;
    }
    return false;
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// A token as messages quote it: bounded, so a megabyte-long word makes a short message.
std::string quoted(std::string_view token) {
    constexpr size_t kLongest = 40;
    // Appended piece by piece: GCC 12 at -O3 warns (-Wrestrict) about "'" + std::string.
    std::string out;
    out.reserve(kLongest + 5);
    out += '\'';
    out.append(token.substr(0, kLongest));
    if (token.size() > kLongest) out += "...";
    out += '\'';
    return out;
}

std::string count_of(size_t n, std::string_view singular, std::string_view plural) {
    return std::to_string(n) + " " + std::string(n == 1 ? singular : plural);
}

// 1e15 as "1e15", 1000 as "1000".
std::string format_limit(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    std::string out = text;
    const size_t plus = out.find("e+");
    if (plus != std::string::npos) out.erase(plus + 1, 1);
    return out;
}

// What an index of a corner refers to, for messages.
struct IndexKind {
    std::string_view singular;
    std::string_view plural;
};
constexpr IndexKind kVertex{"vertex", "vertices"};
constexpr IndexKind kTexture{"texture coordinate", "texture coordinates"};
constexpr IndexKind kNormal{"normal", "normals"};

class ObjParser {
public:
    ObjParser(const std::string& name, const ObjLimits& limits) : m_name(name), m_limits(limits) {}

    // One statement (continuation lines joined), starting at `line`.
    void statement(std::string_view text, size_t line) {
        m_line = line;
        const size_t words = split(text);
        if (words == 0) return;
        const std::string_view keyword = m_words[0];
        const size_t args = words - 1;  // only the first few kept in m_words
        if (keyword == "v") {
            vertex(args);
        } else if (keyword == "vt") {
            numbers_only(args, 1, 3, "a texture coordinate is vt u [v [w]]", "texture coordinate");
            ++m_texture_count;
        } else if (keyword == "vn") {
            numbers_only(args, 3, 3, "a normal is vn x y z", "normal");
            ++m_normal_count;
        } else if (keyword == "f") {
            face(args);
        } else if (is_one_of(keyword, kFreeForm)) {
            fail("free-form geometry (" + quoted(keyword) +
                 ") is not supported: export the model as polygons (f lines)");
        } else if (!is_one_of(keyword, kIgnored)) {
            fail("unknown statement " + quoted(keyword) +
                 " (lenslab reads v, vt, vn and f, and ignores o, g, s, usemtl, mtllib, l and p)");
        }
    }

    ObjMesh take() { return std::move(m_mesh); }

private:
    [[noreturn]] void fail(const std::string& reason) const {
        throw ObjError(m_name, m_line, reason);
    }

    // Keeps at most the words a statement may have, and counts the rest: a face of a
    // hundred million corners on one line is refused without storing its words.
    size_t split(std::string_view text) {
        const size_t most_kept = std::max<size_t>(m_limits.max_face_corners, 6) + 1;
        m_words.clear();
        size_t count = 0;
        size_t i = 0;
        while (i < text.size()) {
            while (i < text.size() && is_space(text[i])) ++i;
            const size_t start = i;
            while (i < text.size() && !is_space(text[i])) ++i;
            if (i == start) break;
            if (count++ < most_kept) m_words.push_back(text.substr(start, i - start));
        }
        return count;
    }

    // The whole token as a finite number, in the C locale's notation whatever the locale.
    double number(std::string_view token, std::string_view what) const {
        std::string_view digits = token;
        // from_chars takes no '+'; allow one before a digit or a point, as C's strtod does.
        if (digits.size() > 1 && digits[0] == '+' && digits[1] != '-' && digits[1] != '+') {
            digits.remove_prefix(1);
        }
        double value = 0;
        const char* end = digits.data() + digits.size();
        const auto [stop, error] = std::from_chars(digits.data(), end, value);
        if (error == std::errc::result_out_of_range) {
            fail(std::string(what) + " " + quoted(token) + " is out of the range of a double");
        }
        if (error != std::errc() || stop != end) {
            fail(std::string(what) + " " + quoted(token) + " is not a number");
        }
        if (!std::isfinite(value)) {
            fail(std::string(what) + " " + quoted(token) + " is not a finite number");
        }
        return value;
    }

    void numbers_only(size_t args, size_t fewest, size_t most, std::string_view form,
                      std::string_view what) const {
        if (args < fewest || args > most) {
            fail(std::string(form) + ", got " + count_of(args, "number", "numbers"));
        }
        for (size_t k = 1; k <= args; ++k) (void)number(m_words[k], what);
    }

    void vertex(size_t args) {
        if (args != 3 && args != 4 && args != 6) {
            fail("a vertex is v x y z, v x y z w or v x y z r g b, got " +
                 count_of(args, "number", "numbers"));
        }
        if (m_mesh.vertices.size() >= m_limits.max_vertices) {
            fail("more than the " + std::to_string(m_limits.max_vertices) + " vertices allowed");
        }
        Vec3 p;
        for (int k = 0; k < 3; ++k) {
            const std::string_view token = m_words[1 + k];
            p[k] = number(token, "vertex coordinate");
            if (std::abs(p[k]) > m_limits.max_coordinate) {
                const std::string limit = format_limit(m_limits.max_coordinate);
                fail("vertex coordinate " + quoted(token) + " is not between -" + limit + " and " +
                     limit);
            }
        }
        for (size_t k = 4; k <= args; ++k) {
            (void)number(m_words[k], args == 4 ? "vertex weight" : "vertex colour");
        }
        m_mesh.vertices.push_back(p);
    }

    // An index as OBJ numbers them: from 1, or back from the last one defined so far (-1).
    int32_t index(std::string_view token, const IndexKind& kind, size_t defined) const {
        int64_t i = 0;
        const char* end = token.data() + token.size();
        const auto [stop, error] = std::from_chars(token.data(), end, i);
        const std::string what = std::string(kind.singular) + " index " + quoted(token);
        if (error == std::errc::result_out_of_range ||
            (error == std::errc() && stop == end &&
             (i > std::numeric_limits<int32_t>::max() ||
              i < -std::numeric_limits<int32_t>::max()))) {
            fail(what + " is beyond the integer range");
        }
        if (error != std::errc() || stop != end) fail(what + " is not a whole number");
        const std::string face = "face " + std::to_string(m_mesh.faces.size() + 1);
        if (i == 0) {
            fail(face + " refers to " + std::string(kind.singular) +
                 " 0, but OBJ numbers them from 1 (or back from the last with -1)");
        }
        const auto count = static_cast<int64_t>(defined);
        if (i > 0 && i <= count) return static_cast<int32_t>(i - 1);
        if (i < 0 && -i <= count) return static_cast<int32_t>(count + i);
        std::string reason =
            face + " refers to " + std::string(kind.singular) + " " + std::string(token) + ", but ";
        if (defined == 0) {
            reason += "no " + std::string(kind.plural) + " are defined before this line";
        } else {
            reason += "only " + count_of(defined, kind.singular, kind.plural) +
                      (defined == 1 ? " is" : " are") + " defined before this line";
            if (i < 0 && defined > 1) {
                reason += " (-1 is the last, -" + std::to_string(defined) + " the first)";
            }
        }
        fail(reason);
    }

    void corner(std::string_view token) {
        // v, v/vt, v//vn or v/vt/vn: the parts between the slashes.
        std::string_view parts[3];
        size_t count = 0;
        size_t start = 0;
        while (true) {
            const size_t slash = token.find('/', start);
            if (count == 3) fail("corner " + quoted(token) + " has more than two slashes");
            parts[count++] =
                token.substr(start, slash == std::string_view::npos ? slash : slash - start);
            if (slash == std::string_view::npos) break;
            start = slash + 1;
        }
        const bool well_formed =
            !parts[0].empty() &&
            (count == 1 || (count == 2 && !parts[1].empty()) || (count == 3 && !parts[2].empty()));
        if (!well_formed) {
            fail("corner " + quoted(token) + " is not v, v/vt, v//vn or v/vt/vn");
        }
        const int32_t v = index(parts[0], kVertex, m_mesh.vertices.size());
        if (count >= 2 && !parts[1].empty()) (void)index(parts[1], kTexture, m_texture_count);
        if (count == 3) (void)index(parts[2], kNormal, m_normal_count);
        const size_t first = m_face_first;
        for (size_t k = first; k < m_mesh.corners.size(); ++k) {
            if (m_mesh.corners[k] == v) {
                fail("face " + std::to_string(m_mesh.faces.size() + 1) + " uses vertex " +
                     std::to_string(v + 1) + " twice");
            }
        }
        m_mesh.corners.push_back(v);
    }

    void face(size_t args) {
        if (args < 3) fail("a face needs at least 3 corners, got " + std::to_string(args));
        if (args > m_limits.max_face_corners) {
            fail("face " + std::to_string(m_mesh.faces.size() + 1) + " has " +
                 std::to_string(args) + " corners, more than the " +
                 std::to_string(m_limits.max_face_corners) + " allowed");
        }
        m_triangles += args - 2;
        if (m_triangles > m_limits.max_triangles) {
            fail("more than the " + std::to_string(m_limits.max_triangles) +
                 " triangles allowed (faces fan-split)");
        }
        m_face_first = m_mesh.corners.size();
        for (size_t k = 1; k <= args; ++k) corner(m_words[k]);
        m_mesh.faces.push_back({m_face_first, args, m_line});
    }

    const std::string& m_name;
    const ObjLimits& m_limits;
    ObjMesh m_mesh;
    std::vector<std::string_view> m_words;  // of the statement being read
    size_t m_line = 0;
    size_t m_texture_count = 0;
    size_t m_normal_count = 0;
    size_t m_triangles = 0;
    size_t m_face_first = 0;  // the first corner of the face being read
};

// A line without its comment and the spaces before its end ('\r' of CRLF included).
std::string_view content_of(std::string_view line) {
    const size_t hash = line.find('#');
    if (hash != std::string_view::npos) line = line.substr(0, hash);
    while (!line.empty() && is_space(line.back())) line.remove_suffix(1);
    return line;
}

}  // namespace

ObjMesh read_obj(std::string_view text, const std::string& name, const ObjLimits& limits) {
    ObjParser parser(name, limits);
    constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";
    if (text.starts_with(kByteOrderMark)) text.remove_prefix(kByteOrderMark.size());
    std::string joined;      // a statement continued over lines ending in '\'
    size_t joined_line = 0;  // where it started; 0 while none is open
    size_t line_number = 0;
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        const std::string_view line = content_of(text.substr(start, end - start));
        start = end + 1;
        ++line_number;
        if (!line.empty() && line.back() == '\\') {
            if (joined_line == 0) joined_line = line_number;
            joined.append(line.substr(0, line.size() - 1));
            joined += ' ';
            continue;
        }
        if (joined_line != 0) {
            joined.append(line);
            parser.statement(joined, joined_line);
            joined.clear();
            joined_line = 0;
        } else {
            parser.statement(line, line_number);
        }
    }
    if (joined_line != 0) parser.statement(joined, joined_line);
    return parser.take();
}

}  // namespace lenslab
