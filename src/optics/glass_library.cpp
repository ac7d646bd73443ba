#include "optics/glass_library.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <unordered_map>
#include <unordered_set>

#include "optics/glass_catalogue_file.h"
#include "optics/user_glass_catalogues.h"
#include "util/edit_distance.h"

namespace lenslab {

namespace {

std::string upper_glass_name(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::toupper(c); });
    return s;
}

std::vector<const Glass*> glasses_named(const std::string& wanted_upper,
                                        const std::string& maker_upper) {
    // The makers' glasses by upper-case name, in catalogue order: a scene names a glass per
    // lens, and the optimiser reads its scene again at every step (a scan of the 1,600
    // glasses was a tenth of an evaluation).
    static const auto by_name = [] {
        std::unordered_map<std::string, std::vector<const Glass*>> index;
        for (const Glass& g : maker_glasses()) index[upper_glass_name(g.name)].push_back(&g);
        return index;
    }();
    std::vector<const Glass*> found;
    const auto it = by_name.find(wanted_upper);
    if (it == by_name.end()) return found;
    for (const Glass* g : it->second) {
        if (maker_upper.empty() || upper_glass_name(g->maker) == maker_upper) found.push_back(g);
    }
    return found;
}

// The names nearest to an unknown one: all at the smallest distance, at most five, and only
// if that distance is a slip (a third of the name, at least 1 and at most 3 edits). A
// built-in glass that a maker also lists (N-BK7) is offered as the maker's.
std::string closest_glass_names(const std::string& wanted_upper) {
    std::vector<std::pair<size_t, std::string>> scored;
    std::unordered_set<std::string> maker_names;
    for (const Glass& g : maker_glasses()) {
        const std::string name = upper_glass_name(g.name);
        scored.emplace_back(edit_distance(wanted_upper, name), glass_label(g));
        maker_names.insert(name);
    }
    for (const Glass& g : glass_catalogue()) {
        const std::string name = upper_glass_name(g.name);
        if (!maker_names.count(name))
            scored.emplace_back(edit_distance(wanted_upper, name), glass_label(g));
    }
    std::stable_sort(scored.begin(), scored.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    const size_t limit = std::min<size_t>(3, std::max<size_t>(1, wanted_upper.size() / 3));
    std::string out;
    for (size_t i = 0; i < scored.size() && i < 5; ++i) {
        if (scored[i].first > limit || scored[i].first != scored.front().first) break;
        out += (out.empty() ? "" : ", ") + scored[i].second;
    }
    return out;
}

}  // namespace

const std::vector<Glass>& maker_glasses() {
    static const std::vector<Glass> glasses = [] {
        const std::filesystem::path dir = glass_data_directory();
        std::vector<Glass> all;
        for (const std::string& file : glass_catalogue_files()) {
            std::vector<Glass> one = read_glass_catalogue((dir / file).string());
            all.insert(all.end(), std::make_move_iterator(one.begin()),
                       std::make_move_iterator(one.end()));
        }
        return all;
    }();
    return glasses;
}

const std::vector<std::string>& glass_makers() {
    static const std::vector<std::string> makers = [] {
        std::vector<std::string> list;
        for (const Glass& g : maker_glasses()) {
            if (list.empty() || list.back() != g.maker) list.push_back(g.maker);
        }
        return list;
    }();
    return makers;
}

std::string glass_label(const Glass& g) {
    return g.maker.empty() ? g.name : g.name + " (" + g.maker + ")";
}

GlassLookup lookup_glass(const std::string& name) {
    // The built-in glasses by upper-case name, the first of a name kept.
    static const auto built_in = [] {
        std::unordered_map<std::string, const Glass*> index;
        for (const Glass& g : glass_catalogue()) index.emplace(upper_glass_name(g.name), &g);
        return index;
    }();
    const std::string wanted = upper_glass_name(name);
    if (const auto it = built_in.find(wanted); it != built_in.end()) return {it->second, {}};
    if (const Glass* user = find_user_glass(wanted)) return {user, {}};
    const size_t colon = wanted.find(':');
    if (colon != std::string::npos) {
        const std::string maker = wanted.substr(0, colon), glass = wanted.substr(colon + 1);
        const std::vector<std::string>& makers = glass_makers();
        if (std::find(makers.begin(), makers.end(), maker) == makers.end()) {
            std::string known;
            for (const std::string& m : makers) known += (known.empty() ? "" : ", ") + m;
            return {nullptr, "unknown glass maker '" + name.substr(0, colon) + "' in '" + name +
                                 "' (makers: " + known + ")"};
        }
        const std::vector<const Glass*> found = glasses_named(glass, maker);
        if (!found.empty()) return {found.front(), {}};
        const std::string near = closest_glass_names(glass);
        return {nullptr, "unknown glass '" + name + "'" +
                             (near.empty() ? "" : "; did you mean " + near + "?")};
    }
    const std::vector<const Glass*> found = glasses_named(wanted, "");
    if (found.size() == 1) return {found.front(), {}};
    if (found.size() > 1) {
        std::string choices;
        for (const Glass* g : found)
            choices += (choices.empty() ? "" : ", ") + g->maker + ":" + g->name;
        return {nullptr, "glass '" + name + "' is in several catalogues; name one of " + choices};
    }
    const std::string near = closest_glass_names(wanted);
    return {nullptr,
            "unknown glass '" + name + "'" +
                (near.empty() ? " (see `lenslab glass`)" : "; did you mean " + near + "?")};
}

const Glass* find_glass(const std::string& name) { return lookup_glass(name).glass; }

}  // namespace lenslab

namespace lenslab {

const std::vector<std::pair<double, double>>& glass_k_data(const Glass& g) {
    if (!g.k_um.empty() || !g.maker.empty() || g.source.rfind("SCHOTT", 0) != 0) return g.k_um;
    try {
        if (const Glass* twin = lookup_glass("SCHOTT:" + g.name).glass) return twin->k_um;
    } catch (const GlassDataError&) {
        // Without the catalogue files the built-in glass keeps its index and is clear.
    }
    return g.k_um;
}

}  // namespace lenslab
