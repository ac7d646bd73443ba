#include "optics/glass_search.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "optics/glass_library.h"
#include "optics/user_glass_catalogues.h"

namespace lenslab {

namespace {

bool parse_range_end(const std::string& text, double fallback, double& out) {
    if (text.empty()) {
        out = fallback;
        return true;
    }
    size_t used = 0;
    try {
        out = std::stod(text, &used);
    } catch (const std::exception&) {
        return false;
    }
    return used == text.size() && std::isfinite(out);
}

bool model_covers_the_lines(const Glass& g) {
    return g.model->min_nm <= kLineF && g.model->max_nm >= kLineC;
}

bool same_maker(const std::string& a, const std::string& b) {
    return a.size() == b.size() &&
           std::equal(a.begin(), a.end(), b.begin(), [](unsigned char x, unsigned char y) {
               return std::toupper(x) == std::toupper(y);
           });
}

}  // namespace

std::optional<ValueRange> parse_value_range(const std::string& text) {
    const size_t colon = text.find(':');
    if (colon == std::string::npos || text.find(':', colon + 1) != std::string::npos)
        return std::nullopt;
    ValueRange r;
    if (!parse_range_end(text.substr(0, colon), r.min, r.min) ||
        !parse_range_end(text.substr(colon + 1), r.max, r.max) || r.min > r.max)
        return std::nullopt;
    return r;
}

double glass_n_d(const Glass& g) {
    return model_covers_the_lines(g) ? g.model->n_d() : g.datasheet_n_d;
}

double glass_v_d(const Glass& g) {
    return model_covers_the_lines(g) ? g.model->abbe_number() : g.datasheet_v_d;
}

std::vector<const Glass*> search_glasses(const GlassQuery& query) {
    auto matches = [&](const Glass& g) {
        if (!query.maker.empty()) {
            const bool builtin_wanted = same_maker(query.maker, "builtin");
            if (builtin_wanted ? !g.maker.empty() : !same_maker(query.maker, g.maker)) return false;
        }
        // NaN is in no range, so a glass without n_d drops out of an n_d search.
        if (query.n_d && !query.n_d->contains(glass_n_d(g))) return false;
        if (query.v_d && !query.v_d->contains(glass_v_d(g))) return false;
        return true;
    };
    std::vector<const Glass*> found;
    for (const Glass& g : glass_catalogue()) {
        if (matches(g)) found.push_back(&g);
    }
    // The users' catalogues (--catalogue, a scene's "glass_catalogues"), as lookups take them.
    for (const Glass* g : user_glasses()) {
        if (matches(*g)) found.push_back(g);
    }
    // The built-in materials alone need no catalogue files (they may be missing).
    if (same_maker(query.maker, "builtin")) return found;
    for (const Glass& g : maker_glasses()) {
        if (matches(g)) found.push_back(&g);
    }
    return found;
}

}  // namespace lenslab
