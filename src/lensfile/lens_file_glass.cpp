#include "lensfile/lens_file_glass.h"

#include <algorithm>
#include <charconv>
#include <tuple>
#include <unordered_set>

#include "lensfile/lens_file_tokens.h"
#include "optics/glass_library.h"
#include "util/edit_distance.h"

namespace lenslab {

namespace {

std::string lens_glass_scene_name(const Glass& g) {
    return g.maker.empty() ? g.name : g.maker + ":" + g.name;
}

// Upper case without hyphens and blanks: CODE V writes N-BK7 as NBK7.
std::string lens_glass_squeezed(const std::string& name) {
    std::string out;
    for (const char c : lens_file_upper(name)) {
        if (c != '-' && c != ' ') out += c;
    }
    return out;
}

// Names lens files give glasses lenslab knows by another name (compared without hyphens and
// blanks). SCHOTT replaced BK7 by the lead- and arsenic-free N-BK7 of the same n_d 1.5168 and
// V_d 64.17, and BK7 is what designers still write for it; Zemax's SILICA and F_SILICA and
// CODE V's SILICA_SPECIAL are fused silica (n_d 1.4585, V_d 67.8), lenslab's fused-silica.
struct LensGlassAlias {
    const char* name;
    const char* glass;  // as lookup_glass takes it
    const char* note;   // what the warning adds
    bool schott_only;   // not when the file names another maker (BK7_HIKARI)
};

constexpr LensGlassAlias kLensGlassAliases[] = {
    {"BK7", "SCHOTT:N-BK7", ", SCHOTT's successor to BK7 (no longer made)", true},
    {"SILICA", "fused-silica", " (fused silica)", false},
    {"F_SILICA", "fused-silica", " (fused silica)", false},
    {"FUSEDSILICA", "fused-silica", " (fused silica)", false},
    {"FUSED_SILICA", "fused-silica", " (fused silica)", false},
    {"SILICA_SPECIAL", "fused-silica", " (fused silica)", false},
    {"SIO2", "fused-silica", " (fused silica)", false},
};

// A glass found for a name, and whether it was found under another name (then `note` is what
// the warning adds to "read as NAME (MAKER)").
struct LensGlassFound {
    const Glass* glass = nullptr;
    bool renamed = false;
    std::string note;
};

// `glass` in the makers' catalogues (`makers` first), without its hyphens, or by an alias.
// `maker_named` is the maker of a CODE V NAME_MAKER ("" for none).
LensGlassFound lens_glass_find(const std::string& glass, const std::vector<std::string>& makers,
                               const std::string& maker_named) {
    for (const std::string& m : makers) {
        if (const GlassLookup found = lookup_glass(m + ":" + glass); found.glass) {
            return {found.glass, false, ""};
        }
    }
    if (const GlassLookup found = lookup_glass(glass); found.glass) return {found.glass, false, ""};
    // The same name but for hyphens, preferring the makers the file names.
    const std::string squeezed = lens_glass_squeezed(glass);
    const Glass* match = nullptr;
    for (const Glass& g : maker_glasses()) {
        if (lens_glass_squeezed(g.name) != squeezed) continue;
        bool preferred = false;
        for (const std::string& m : makers) preferred = preferred || m == g.maker;
        if (!match || preferred) match = &g;
        if (preferred) break;
    }
    if (match) return {match, true, ""};
    for (const LensGlassAlias& a : kLensGlassAliases) {
        if (squeezed != a.name) continue;
        if (a.schott_only && !maker_named.empty() && maker_named != "SCHOTT") continue;
        if (const Glass* g = lookup_glass(a.glass).glass) return {g, true, a.note};
    }
    return {};
}

// "N-BK7" as users compare glass names: the maker's one-letter prefix (N: SCHOTT's lead-free
// glasses; S, L: OHARA; H, D: CDGM; J, E: HIKARI; K: SUMITA; M: HOYA's moulding glasses) set
// apart from the rest, which is compared without hyphens and blanks.
struct LensGlassNameParts {
    std::string prefix, core, squeezed;
};

LensGlassNameParts lens_glass_name_parts(const std::string& name) {
    const std::string upper = lens_file_upper(name);
    LensGlassNameParts p;
    p.squeezed = lens_glass_squeezed(upper);
    if (upper.size() > 2 && upper[1] == '-' && upper[0] >= 'A' && upper[0] <= 'Z') {
        p.prefix = upper.substr(0, 1);
        p.core = lens_glass_squeezed(upper.substr(2));
    } else {
        p.core = p.squeezed;
    }
    return p;
}

// 0: the prefix the wanted name has (for a name without one: N-, SCHOTT's lead-free successor
// of an old glass, BK7 -> N-BK7); 1: no prefix; 2: another maker's.
int lens_glass_prefix_rank(const std::string& wanted, const std::string& prefix) {
    if (prefix == (wanted.empty() ? std::string("N") : wanted)) return 0;
    return prefix.empty() ? 1 : 2;
}

// The names nearest to an unknown glass, as users name glasses: those at the smallest
// distance (of the names without prefixes, or of the whole names without hyphens; a slip of
// at most a third of the name, 1 to 3 edits), of the makers the file names if any, with the
// best prefix; at most five, the closest spelled first.
std::string lens_glass_suggestions(const std::string& glass,
                                   const std::vector<std::string>& makers) {
    const LensGlassNameParts want = lens_glass_name_parts(glass);
    const std::string upper = lens_file_upper(glass);
    using Rank = std::tuple<size_t, int, int, size_t, size_t>;  // distance, maker, prefix, ...
    std::vector<std::pair<Rank, std::string>> scored;
    const auto consider = [&](const Glass& g) {
        const LensGlassNameParts p = lens_glass_name_parts(g.name);
        const size_t distance =
            std::min(edit_distance(want.core, p.core), edit_distance(want.squeezed, p.squeezed));
        const bool preferred =
            !g.maker.empty() &&
            std::find(makers.begin(), makers.end(), lens_file_upper(g.maker)) != makers.end();
        scored.push_back(
            {{distance, preferred ? 0 : 1, lens_glass_prefix_rank(want.prefix, p.prefix),
              edit_distance(upper, lens_file_upper(g.name)), scored.size()},
             glass_label(g)});
    };
    std::unordered_set<std::string> maker_names;
    for (const Glass& g : maker_glasses()) {
        consider(g);
        maker_names.insert(lens_file_upper(g.name));
    }
    for (const Glass& g : glass_catalogue()) {
        if (!maker_names.count(lens_file_upper(g.name))) consider(g);
    }
    std::sort(scored.begin(), scored.end());
    const size_t limit = std::min<size_t>(3, std::max<size_t>(1, want.core.size() / 3));
    std::string out;
    if (scored.empty() || std::get<0>(scored.front().first) > limit) return out;
    const auto group = [](const Rank& r) {
        return std::make_tuple(std::get<0>(r), std::get<1>(r), std::get<2>(r));
    };
    for (size_t i = 0; i < scored.size() && i < 5; ++i) {
        if (group(scored[i].first) != group(scored.front().first)) break;
        out += (out.empty() ? "" : ", ") + scored[i].second;
    }
    return out;
}

std::string lens_glass_unknown(const std::string& glass, const std::string& compared,
                               const std::vector<std::string>& makers) {
    const std::string near = lens_glass_suggestions(compared, makers);
    return "unknown glass '" + glass + "'" +
           (near.empty() ? " (see `lenslab glass`)" : "; did you mean " + near + "?");
}

// "1.517" or "52.0" read as one decimal number.
double lens_glass_code_number(const std::string& text) {
    double value = 0.0;
    (void)std::from_chars(text.data(), text.data() + text.size(), value);
    return value;
}

}  // namespace

std::string resolve_lens_file_glass(const std::string& name,
                                    const std::vector<std::string>& catalogues,
                                    const std::string& file, int line,
                                    std::vector<LensFileWarning>& warnings) {
    std::string glass = name, maker_named;
    std::vector<std::string> makers;
    for (const std::string& c : catalogues) makers.push_back(lens_file_upper(c));
    // CODE V: NAME_MAKER.
    const size_t underscore = name.rfind('_');
    if (underscore != std::string::npos && underscore > 0) {
        const std::string maker = lens_file_upper(name.substr(underscore + 1));
        for (const std::string& m : glass_makers()) {
            if (m == maker) {
                glass = name.substr(0, underscore);
                maker_named = maker;
                makers.insert(makers.begin(), maker);
            }
        }
    }
    const auto taken = [&](const LensGlassFound& f, const std::string& note) {
        if (f.renamed || !note.empty()) {
            warnings.push_back(
                {line, "glass '" + name + "' read as " + glass_label(*f.glass) + note});
        }
        return lens_glass_scene_name(*f.glass);
    };
    if (const LensGlassFound f = lens_glass_find(glass, makers, maker_named); f.glass) {
        return taken(f, f.note);
    }
    // A moulded glass (OHARA's L-TIM28_MOLD): the glass it is moulded from.
    const std::string upper = lens_file_upper(glass);
    for (const std::string suffix : {"_MOLD", "-MOLD"}) {
        if (upper.size() <= suffix.size() || !upper.ends_with(suffix)) continue;
        const std::string base = glass.substr(0, glass.size() - suffix.size());
        if (const LensGlassFound f = lens_glass_find(base, makers, maker_named); f.glass) {
            return taken(f,
                         ", the glass it is moulded from (lenslab has no data for the moulded "
                         "state)");
        }
        throw LensFileError(file, line, lens_glass_unknown(glass, base, makers));
    }
    throw LensFileError(file, line, lens_glass_unknown(glass, glass, makers));
}

bool lens_file_glass_code_like(const std::string& word) {
    int points = 0;
    bool digits = false;
    for (const char c : word) {
        if (c == '.') {
            ++points;
        } else if (c >= '0' && c <= '9') {
            digits = true;
        } else {
            return false;
        }
    }
    return digits && points <= 1;
}

std::optional<LensFileGlassCode> lens_file_glass_code(const std::string& word) {
    if (!lens_file_glass_code_like(word)) return std::nullopt;
    const size_t point = word.find('.');
    std::string n_text, v_text;
    if (point == std::string::npos) {
        // NNNVVV: n_d = 1.NNN, V_d = VV.V.
        if (word.size() != 6) return std::nullopt;
        n_text = "1." + word.substr(0, 3);
        v_text = word.substr(3, 2) + "." + word.substr(5);
    } else {
        // NNNNNN.VVVVVV: n_d = 1.NNNNNN, V_d = VV.VVVV.
        const std::string whole = word.substr(0, point);
        std::string fraction = word.substr(point + 1);
        if (whole.size() < 3 || whole.size() > 6 || fraction.empty()) return std::nullopt;
        if (fraction.size() < 2) fraction += '0';
        n_text = "1." + whole;
        v_text = fraction.substr(0, 2) + "." + (fraction.size() > 2 ? fraction.substr(2) : "0");
    }
    const LensFileGlassCode code{lens_glass_code_number(n_text), lens_glass_code_number(v_text)};
    if (!(code.n_d > 1.0)) return std::nullopt;
    return code;
}

}  // namespace lenslab
