#include "optics/glass_catalogue_file.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "optics/dispersion_formula.h"

// Where the build and the installation put the catalogues (src/CMakeLists.txt).
#ifndef LENSLAB_GLASS_DATA_SOURCE
#define LENSLAB_GLASS_DATA_SOURCE ""
#endif
#ifndef LENSLAB_GLASS_DATA_INSTALL
#define LENSLAB_GLASS_DATA_INSTALL ""
#endif

namespace lenslab {

namespace {

using nlohmann::json;

// Names one entry of the file: "glasses[12] (N-BK7)".
struct CatalogueEntryPlace {
    std::string file;
    std::string entry;

    [[noreturn]] void fail(const std::string& key, const std::string& why) const {
        throw GlassDataError(file + ": " + entry + (key.empty() ? "" : "." + key) + ": " + why);
    }
};

double catalogue_number(const json& j, const char* key, const CatalogueEntryPlace& at) {
    if (!j.contains(key)) at.fail(key, "missing (required)");
    const json& v = j.at(key);
    if (!v.is_number() || !std::isfinite(v.get<double>())) at.fail(key, "must be a number");
    return v.get<double>();
}

std::vector<double> catalogue_numbers(const json& j, const char* key,
                                      const CatalogueEntryPlace& at) {
    if (!j.contains(key)) at.fail(key, "missing (required)");
    const json& v = j.at(key);
    if (!v.is_array()) at.fail(key, "must be an array of numbers");
    std::vector<double> out;
    for (const json& x : v) {
        if (!x.is_number()) at.fail(key, "must be an array of numbers");
        out.push_back(x.get<double>());
    }
    return out;
}

std::vector<std::pair<double, double>> catalogue_table(const json& j, const char* key,
                                                       const CatalogueEntryPlace& at) {
    const json& v = j.at(key);
    if (!v.is_array()) at.fail(key, "must be an array of [wavelength um, value] pairs");
    std::vector<std::pair<double, double>> out;
    for (const json& row : v) {
        if (!row.is_array() || row.size() != 2 || !row[0].is_number() || !row[1].is_number()) {
            at.fail(key, "row " + std::to_string(out.size() + 1) +
                             " must be a [wavelength um, value] pair of numbers");
        }
        out.emplace_back(row[0].get<double>(), row[1].get<double>());
    }
    return out;
}

std::string catalogue_string(const json& j, const char* key, const CatalogueEntryPlace& at) {
    if (!j.contains(key)) return {};
    if (!j.at(key).is_string()) at.fail(key, "must be a string");
    return j.at(key).get<std::string>();
}

IndexModelPtr catalogue_index_model(const json& g, const CatalogueEntryPlace& at) {
    if (!g.contains("formula")) at.fail("formula", "missing (required)");
    const json& f = g.at("formula");
    try {
        if (f == "tabulated") {
            if (!g.contains("n")) at.fail("n", "missing (a tabulated glass needs its n table)");
            return tabulated_index(catalogue_table(g, "n", at));
        }
        if (!f.is_number_integer()) at.fail("formula", "must be 1-9 or \"tabulated\"");
        const std::vector<double> range = catalogue_numbers(g, "range_um", at);
        if (range.size() != 2) at.fail("range_um", "must be [min, max] in um");
        return formula_index(f.get<int>(), catalogue_numbers(g, "coefficients", at), range[0],
                             range[1]);
    } catch (const DispersionDataError& e) {
        at.fail(f == "tabulated" ? "n" : "coefficients", e.what());
    }
}

Glass catalogue_glass(const json& g, const std::string& maker,
                      const std::vector<std::string>& references, const CatalogueEntryPlace& at) {
    Glass glass;
    glass.maker = maker;
    glass.name = catalogue_string(g, "name", at);
    if (glass.name.empty()) at.fail("name", "missing (required)");
    glass.model = catalogue_index_model(g, at);
    // Glasses the source gives without catalogue values carry NaN: nothing to check them by.
    const double none = std::numeric_limits<double>::quiet_NaN();
    const bool has_values = g.contains("n_d") || g.contains("V_d");
    glass.datasheet_n_d = has_values ? catalogue_number(g, "n_d", at) : none;
    glass.datasheet_v_d = has_values ? catalogue_number(g, "V_d", at) : none;
    if (g.contains("k")) glass.k_um = catalogue_table(g, "k", at);

    const std::string group = catalogue_string(g, "group", at);
    const std::string code = catalogue_string(g, "code", at);
    const std::string status = catalogue_string(g, "status", at);
    glass.description = maker + " " + (group.empty() ? "glass" : group + " glass");
    if (!code.empty()) glass.description += ", code " + code;
    if (!status.empty()) glass.description += ", " + status;
    std::string reference;
    if (g.contains("ref")) {
        const json& r = g.at("ref");
        if (!r.is_number_unsigned() || r.get<size_t>() >= references.size())
            at.fail("ref", "must index the file's references");
        reference = references[r.get<size_t>()];
    }
    glass.source = "refractiveindex.info (CC0)" + (reference.empty() ? "" : ": " + reference);
    return glass;
}

std::string upper_catalogue_name(std::string s) {
    for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

json parse_catalogue_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw GlassDataError(path + ": cannot open the glass catalogue");
    std::ostringstream buffer;
    buffer << in.rdbuf();
    const std::string text = buffer.str();
    try {
        return json::parse(text);
    } catch (const json::parse_error& e) {
        // nlohmann reports a byte offset; a maintainer opens the file at a line.
        const size_t upto = std::min<size_t>(e.byte, text.size());
        size_t line = 1, column = 1;
        for (size_t i = 0; i + 1 < upto; ++i) {
            if (text[i] == '\n') {
                ++line;
                column = 1;
            } else {
                ++column;
            }
        }
        throw GlassDataError(path + ":" + std::to_string(line) + ":" + std::to_string(column) +
                             ": not valid JSON");
    }
}

}  // namespace

std::vector<Glass> read_glass_catalogue(const std::string& path) {
    const json doc = parse_catalogue_text(path);
    const CatalogueEntryPlace top{path, "catalogue"};
    if (!doc.is_object()) throw GlassDataError(path + ": must be a JSON object");
    const std::string maker = catalogue_string(doc, "maker", top);
    if (maker.empty()) throw GlassDataError(path + ": maker: missing (required)");
    std::vector<std::string> references;
    if (doc.contains("references")) {
        for (const json& r : doc.at("references")) {
            if (!r.is_string()) throw GlassDataError(path + ": references: must be strings");
            references.push_back(r.get<std::string>());
        }
    }
    if (!doc.contains("glasses") || !doc.at("glasses").is_array())
        throw GlassDataError(path + ": glasses: missing (required, an array)");
    std::vector<Glass> glasses;
    std::map<std::string, size_t> first_entry;  // upper-cased name -> its index
    const json& list = doc.at("glasses");
    for (size_t i = 0; i < list.size(); ++i) {
        const json& g = list[i];
        std::string entry = "glasses[" + std::to_string(i) + "]";
        if (!g.is_object()) throw GlassDataError(path + ": " + entry + ": must be an object");
        if (g.contains("name") && g.at("name").is_string())
            entry += " (" + g.at("name").get<std::string>() + ")";
        glasses.push_back(catalogue_glass(g, maker, references, {path, entry}));
        // MAKER:NAME must name one glass; lookups ignore case, so the check does too.
        const std::string key = upper_catalogue_name(glasses.back().name);
        if (const auto [it, fresh] = first_entry.emplace(key, i); !fresh) {
            throw GlassDataError(path + ": " + entry + ".name: given twice in this catalogue " +
                                 "(also glasses[" + std::to_string(it->second) + "])");
        }
    }
    return glasses;
}

const std::vector<std::string>& glass_catalogue_files() {
    static const std::vector<std::string> files{"schott.json", "ohara.json",  "cdgm.json",
                                                "hoya.json",   "hikari.json", "sumita.json"};
    return files;
}

std::string glass_data_directory() {
    namespace fs = std::filesystem;
    const std::string probe = glass_catalogue_files().front();
    if (const char* env = std::getenv("LENSLAB_GLASS_DATA"); env && *env) {
        if (fs::exists(fs::path(env) / probe)) return env;
        throw GlassDataError(std::string("LENSLAB_GLASS_DATA=") + env + ": no " + probe +
                             " there (it must name the folder holding the glass catalogues)");
    }
    std::string looked;
    for (const char* dir : {LENSLAB_GLASS_DATA_SOURCE, LENSLAB_GLASS_DATA_INSTALL}) {
        if (!*dir) continue;
        if (fs::exists(fs::path(dir) / probe)) return dir;
        looked += (looked.empty() ? "" : ", ") + std::string(dir);
    }
    throw GlassDataError("the glass catalogues are not found (looked for " + probe + " in " +
                         (looked.empty() ? "no folder" : looked) +
                         "); set LENSLAB_GLASS_DATA to the folder that holds them");
}

}  // namespace lenslab
