// `lenslab glass [NAME --wavelength NM [--json]]`: a glass's refractive index;
// `lenslab glass [--maker M] [--nd MIN:MAX] [--vd MIN:MAX] [--all] [--json]`: the catalogues.

#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "commands.h"
#include "image/glass_map.h"
#include "image/image_io.h"
#include "optics/absorption.h"
#include "optics/glass.h"
#include "optics/glass_catalogue_file.h"
#include "optics/glass_library.h"
#include "optics/glass_search.h"
#include "optics/user_glass_catalogues.h"
#include "util/atomic_file.h"

namespace lenslab::cli {

namespace {

struct GlassArgs {
    std::string name;
    double wavelength_nm = kLineD;
    bool json = false;
    bool all = false;
    std::string maker, nd, vd;
    std::string map;  // --map FILE.svg or FILE.png
};

// "1.5:1.6" for --nd and --vd, refused at parse time with the option's name.
CLI::Validator value_range_check() {
    return CLI::Validator(
        [](std::string& text) -> std::string {
            if (parse_value_range(text)) return "";
            return "must be MIN:MAX (e.g. 1.5:1.6, either may be left out), got '" + text + "'";
        },
        "MIN:MAX");
}

// "1.51680", or "-" where a glass has no catalogue value (infrared glasses, tabulated ones).
std::string catalogue_value(double v, int decimals) {
    if (!std::isfinite(v)) return "-";
    char text[32];
    std::snprintf(text, sizeof text, "%.*f", decimals, v);
    return text;
}

void print_glass_table(const std::vector<const Glass*>& glasses) {
    std::printf("%-16s %-7s %9s %7s  %-15s %s\n", "name", "maker", "n_d", "V_d", "range (nm)",
                "description");
    for (const Glass* g : glasses) {
        std::printf("%-16s %-7s %9s %7s  %6.0f - %-6.0f  %s\n", g->name.c_str(),
                    g->maker.empty() ? "builtin" : g->maker.c_str(),
                    catalogue_value(glass_n_d(*g), 5).c_str(),
                    catalogue_value(glass_v_d(*g), 2).c_str(), g->model->min_nm, g->model->max_nm,
                    g->description.c_str());
    }
}

void print_glass_json(const std::vector<const Glass*>& glasses) {
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    auto number_or_null = [](double v) {
        return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json();
    };
    for (const Glass* g : glasses) {
        list.push_back({{"name", g->name},
                        {"maker", g->maker.empty() ? "builtin" : g->maker},
                        {"n_d", number_or_null(glass_n_d(*g))},
                        {"V_d", number_or_null(glass_v_d(*g))},
                        {"min_nm", g->model->min_nm},
                        {"max_nm", g->model->max_nm}});
    }
    const nlohmann::ordered_json out{{"count", glasses.size()}, {"glasses", list}};
    std::cout << out.dump(2) << "\n";
}

bool known_maker(const std::string& maker) {
    GlassQuery q;
    q.maker = maker;
    return !search_glasses(q).empty();
}

// The filtered glasses as the glass map, SVG or PNG by the file's extension.
int draw_map(const GlassArgs& a, const std::vector<const Glass*>& found) {
    const std::string ext = a.map.size() >= 4 ? a.map.substr(a.map.size() - 4) : std::string();
    const bool svg = ext == ".svg" || ext == ".SVG", png = ext == ".png" || ext == ".PNG";
    if (!svg && !png) {
        std::cerr << "lenslab: error: --map: '" << a.map
                  << "' must end in .svg or .png (the map's format)\n";
        return 1;
    }
    if (svg) {
        write_text_atomically(a.map, glass_map_svg(found));
    } else {
        write_png_image(glass_map_image(found), a.map);
    }
    std::printf("wrote %s: %zu glasses on the map (n_d against V_d)\n", a.map.c_str(),
                glasses_on_map(found).size());
    return 0;
}

int search_catalogues(const GlassArgs& a) {
    GlassQuery query;
    query.maker = a.maker;
    if (!a.nd.empty()) query.n_d = parse_value_range(a.nd);
    if (!a.vd.empty()) query.v_d = parse_value_range(a.vd);
    if (!a.maker.empty() && !known_maker(a.maker)) {
        std::string makers = "builtin";
        for (const Glass* g : user_glasses()) {  // --catalogue's files, by name
            if (makers.find(", " + g->maker) == std::string::npos) makers += ", " + g->maker;
        }
        for (const std::string& m : glass_makers()) makers += ", " + m;
        std::cerr << "lenslab: error: --maker: unknown maker '" << a.maker
                  << "' (makers: " << makers << ")\n";
        return 1;
    }
    const std::vector<const Glass*> found = search_glasses(query);
    if (found.empty()) {
        std::cerr << "lenslab: error: no glass matches the search\n";
        return 1;
    }
    if (!a.map.empty()) return draw_map(a, found);
    if (a.json) {
        print_glass_json(found);
    } else {
        print_glass_table(found);
    }
    return 0;
}

// Without arguments: the built-in materials, and how to reach the makers' catalogues.
int list_builtin(const GlassArgs& a) {
    GlassQuery builtin;
    builtin.maker = "builtin";
    const std::vector<const Glass*> found = search_glasses(builtin);
    if (a.json) {
        print_glass_json(found);
        return 0;
    }
    print_glass_table(found);
    std::fflush(stdout);  // the table stands even if the catalogues' files are missing
    std::string makers;
    for (const std::string& m : glass_makers()) makers += (makers.empty() ? "" : ", ") + m;
    std::printf(
        "\nand %zu glasses of %s: search with --maker, --nd MIN:MAX, --vd MIN:MAX, "
        "or list them all with --all\n",
        maker_glasses().size(), makers.c_str());
    return 0;
}

// Where `lenslab glass NAME` gives the internal transmittance through 10 mm, the thickness
// the makers' data sheets print it for.
constexpr double kTransmittanceWavelengthsNm[] = {400, 450, 500, 550, 600, 650, 700};
constexpr double kTransmittanceThicknessMm = 10;

nlohmann::ordered_json transmittance_json(const Glass& g) {
    const auto& k = glass_k_data(g);
    if (k.empty()) return nullptr;
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (double nm : kTransmittanceWavelengthsNm) {
        list.push_back({{"wavelength_nm", nm},
                        {"tau", internal_transmittance(k, nm, kTransmittanceThicknessMm)}});
    }
    return list;
}

void print_transmittance(const Glass& g) {
    const auto& k = glass_k_data(g);
    if (k.empty()) {
        std::printf("internal transmittance: no absorption data (the glass does not absorb)\n");
        return;
    }
    std::printf("internal transmittance through 10 mm:");
    for (double nm : kTransmittanceWavelengthsNm) {
        std::printf(" %g nm %.4f%s", nm, internal_transmittance(k, nm, kTransmittanceThicknessMm),
                    nm == kTransmittanceWavelengthsNm[6] ? "\n" : ",");
    }
}

int print_index(const GlassArgs& a) {
    const GlassLookup found = lookup_glass(a.name);
    if (!found.glass) {
        std::cerr << "lenslab: error: " << found.error << "\n";
        return 1;
    }
    const Glass* g = found.glass;
    const IndexModel& m = *g->model;
    if (a.wavelength_nm < m.min_nm || a.wavelength_nm > m.max_nm) {
        std::cerr << "lenslab: error: --wavelength " << a.wavelength_nm << " nm is outside "
                  << g->name << "'s validity range " << m.min_nm << "-" << m.max_nm << " nm ("
                  << g->source << ")\n";
        return 1;
    }
    if (a.json) {
        const nlohmann::ordered_json j{{"name", g->name},
                                       {"maker", g->maker.empty() ? "builtin" : g->maker},
                                       {"wavelength_nm", a.wavelength_nm},
                                       {"n", m.n(a.wavelength_nm)},
                                       {"n_d", m.n_d()},
                                       {"V_d", m.abbe_number()},
                                       {"transmittance_10mm", transmittance_json(*g)}};
        std::cout << j.dump(2) << "\n";
    } else {
        std::printf("%s at %g nm: n = %.6f\nn_d = %.5f, V_d = %.2f (%s; source: %s)\n",
                    glass_label(*g).c_str(), a.wavelength_nm, m.n(a.wavelength_nm), m.n_d(),
                    m.abbe_number(), m.describe().c_str(), g->source.c_str());
        print_transmittance(*g);
    }
    return 0;
}

int run(const GlassArgs& a) {
    try {
        if (!a.name.empty()) return print_index(a);
        if (a.all || !a.map.empty() || !a.maker.empty() || !a.nd.empty() || !a.vd.empty())
            return search_catalogues(a);
        return list_builtin(a);
    } catch (const GlassDataError& e) {
        std::cerr << "lenslab: error: " << e.what() << "\n";
        return 1;
    }
}

}  // namespace

Action add_glass_command(CLI::App& app) {
    auto args = std::make_shared<GlassArgs>();
    CLI::App* cmd = app.add_subcommand(
        "glass",
        "Print a glass's refractive index, or list and search the glass catalogues (the "
        "built-in materials and the SCHOTT, OHARA, CDGM, HOYA, HIKARI and SUMITA catalogues)");
    CLI::Option* name = cmd->add_option(
        "name", args->name,
        "Glass (e.g. N-BK7, or MAKER:NAME such as HIKARI:SF10); omit to list or search");
    cmd->add_option("-w,--wavelength", args->wavelength_nm,
                    "Wavelength in air in nm (default: the d line, 587.56 nm)")
        ->check(CLI::PositiveNumber);
    cmd->add_flag("--json", args->json,
                  "Print {name, maker, wavelength_nm, n, n_d, V_d, transmittance_10mm: "
                  "[{wavelength_nm, tau}] or null} as JSON (tau: internal transmittance through "
                  "10 mm, from the catalogue's k); with a list or "
                  "search, {count, glasses: [{name, maker, n_d, V_d, min_nm, max_nm}]}");
    CLI::Option* maker =
        cmd->add_option("--maker", args->maker,
                        "List one maker's glasses: SCHOTT, OHARA, CDGM, HOYA, HIKARI, "
                        "SUMITA, or builtin (any case)");
    CLI::Option* nd =
        cmd->add_option("--nd", args->nd, "Only glasses whose n_d is in MIN:MAX, e.g. 1.5:1.6")
            ->check(value_range_check());
    CLI::Option* vd =
        cmd->add_option("--vd", args->vd, "Only glasses whose V_d is in MIN:MAX, e.g. 50:70")
            ->check(value_range_check());
    CLI::Option* all = cmd->add_flag("--all", args->all, "List every glass of every catalogue");
    CLI::Option* map = cmd->add_option(
        "--map", args->map,
        "Draw the glass map (n_d against V_d, V_d decreasing to the right, one colour per "
        "maker) of the glasses --maker/--nd/--vd select (all without them) to FILE.svg or "
        "FILE.png");
    for (CLI::Option* search : {maker, nd, vd, all, map}) name->excludes(search);
    return [args] { return run(*args); };
}

}  // namespace lenslab::cli
