// `lenslab glass [NAME --wavelength NM [--json]]`: the glass catalogue and refractive indices.

#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "commands.h"
#include "optics/glass.h"

namespace lenslab::cli {

namespace {

struct GlassArgs {
    std::string name;
    double wavelength_nm = kLineD;
    bool json = false;
};

int list_catalogue() {
    std::printf("%-14s %9s %7s  %-15s %s\n", "name", "n_d", "V_d", "range (nm)", "description");
    for (const Glass& g : glass_catalogue()) {
        std::printf("%-14s %9.5f %7.2f  %6.0f - %-6.0f  %s\n", g.name.c_str(), g.model->n_d(),
                    g.model->abbe_number(), g.model->min_nm, g.model->max_nm,
                    g.description.c_str());
    }
    return 0;
}

int run(const GlassArgs& a) {
    if (a.name.empty()) return list_catalogue();
    const Glass* g = find_glass(a.name);
    if (!g) {
        std::cerr << "lenslab: error: unknown glass '" << a.name
                  << "' (run `lenslab glass` for the catalogue)\n";
        return 1;
    }
    const IndexModel& m = *g->model;
    if (a.wavelength_nm < m.min_nm || a.wavelength_nm > m.max_nm) {
        std::cerr << "lenslab: error: --wavelength " << a.wavelength_nm << " nm is outside "
                  << g->name << "'s validity range " << m.min_nm << "-" << m.max_nm << " nm ("
                  << g->source << ")\n";
        return 1;
    }
    if (a.json) {
        const nlohmann::ordered_json j{{"name", g->name},
                                       {"wavelength_nm", a.wavelength_nm},
                                       {"n", m.n(a.wavelength_nm)},
                                       {"n_d", m.n_d()},
                                       {"V_d", m.abbe_number()}};
        std::cout << j.dump(2) << "\n";
    } else {
        std::printf("%s at %g nm: n = %.6f\nn_d = %.5f, V_d = %.2f (%s; source: %s)\n",
                    g->name.c_str(), a.wavelength_nm, m.n(a.wavelength_nm), m.n_d(),
                    m.abbe_number(), m.describe().c_str(), g->source.c_str());
    }
    return 0;
}

}  // namespace

Action add_glass_command(CLI::App& app) {
    auto args = std::make_shared<GlassArgs>();
    CLI::App* cmd = app.add_subcommand(
        "glass", "List the glass catalogue, or print a glass's refractive index");
    cmd->add_option("name", args->name, "Catalogue glass (e.g. N-BK7); omit to list the catalogue");
    cmd->add_option("-w,--wavelength", args->wavelength_nm,
                    "Vacuum wavelength in nm (default: the d line, 587.56 nm)")
        ->check(CLI::PositiveNumber);
    cmd->add_flag("--json", args->json, "Print {name, wavelength_nm, n, n_d, V_d} as JSON");
    return [args] { return run(*args); };
}

}  // namespace lenslab::cli
