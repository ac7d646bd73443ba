#include "lensfile/lens_file_glass.h"

#include "lensfile/lens_file_tokens.h"
#include "optics/glass_library.h"

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

}  // namespace

std::string resolve_lens_file_glass(const std::string& name,
                                    const std::vector<std::string>& catalogues,
                                    const std::string& file, int line,
                                    std::vector<LensFileWarning>& warnings) {
    std::string glass = name;
    std::vector<std::string> makers;
    for (const std::string& c : catalogues) makers.push_back(lens_file_upper(c));
    // CODE V: NAME_MAKER.
    const size_t underscore = name.rfind('_');
    if (underscore != std::string::npos && underscore > 0) {
        const std::string maker = lens_file_upper(name.substr(underscore + 1));
        for (const std::string& m : glass_makers()) {
            if (m == maker) {
                glass = name.substr(0, underscore);
                makers.insert(makers.begin(), maker);
            }
        }
    }
    for (const std::string& m : makers) {
        if (const GlassLookup found = lookup_glass(m + ":" + glass); found.glass) {
            return lens_glass_scene_name(*found.glass);
        }
    }
    const GlassLookup found = lookup_glass(glass);
    if (found.glass) return lens_glass_scene_name(*found.glass);
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
    if (match) {
        warnings.push_back({line, "glass '" + name + "' read as " + glass_label(*match)});
        return lens_glass_scene_name(*match);
    }
    throw LensFileError(file, line, found.error);
}

}  // namespace lenslab
