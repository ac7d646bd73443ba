// The design file's declarations (optimize/lens_design_spec.h) held to docs/optimizer.md:
// the top-level keys' table (keys, defaults, whole numbers' ranges) and the keys each type of
// variable and operand takes, so a key the reader takes and the docs do not (or the reverse)
// fails; and the reader's refusal of a key a type does not take.

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "optimize/lens_design.h"
#include "optimize/lens_design_spec.h"

namespace lenslab {
namespace {

using nlohmann::json;

// The rows of the table whose header line is `header` in docs/optimizer.md: the first cell's
// backticked word -> the row's other cells.
// `occurrence`: which table with that header (1: the first).
std::map<std::string, std::vector<std::string>> docs_table(const std::string& header,
                                                           int occurrence = 1) {
    std::ifstream in(std::string(LENSLAB_SOURCE_DIR) + "/docs/optimizer.md");
    std::map<std::string, std::vector<std::string>> rows;
    std::string line;
    bool inside = false;
    static const std::regex row(R"(^\| `([A-Za-z_]+)` \|(.*)\|$)");
    while (std::getline(in, line)) {
        if (line == header) {
            inside = --occurrence == 0;
            continue;
        }
        if (!inside) continue;
        if (line.rfind("| ---", 0) == 0) continue;
        std::smatch m;
        if (!std::regex_match(line, m, row)) break;
        std::vector<std::string> cells;
        std::stringstream rest(m[2].str());
        std::string cell;
        while (std::getline(rest, cell, '|')) cells.push_back(cell);
        rows[m[1]] = cells;
    }
    EXPECT_FALSE(rows.empty()) << "no table under " << header;
    return rows;
}

// The backticked key names of a cell, leaving out what parentheses say about them.
std::vector<std::string> keys_in(const std::string& cell) {
    std::string outside;
    int depth = 0;
    for (char c : cell) {
        depth += c == '(';
        if (depth == 0) outside += c;
        depth -= c == ')' && depth > 0;
    }
    std::vector<std::string> keys;
    static const std::regex key("`([a-z_]+)`");
    for (std::sregex_iterator it(outside.begin(), outside.end(), key), end; it != end; ++it)
        keys.push_back((*it)[1]);
    return keys;
}

TEST(LensDesignSpec, TheDocsTableListsEveryTopLevelKeyWithItsDefaultAndRange) {
    const auto rows = docs_table("| key | type | default | meaning |");
    std::set<std::string> declared;
    for (const ParamSpec& p : lens_design_spec().params) {
        declared.insert(p.key);
        ASSERT_TRUE(rows.contains(p.key)) << p.key << " is not in the table";
        const std::string& type = rows.at(p.key).at(0);
        const std::string& fallback = rows.at(p.key).at(1);
        if (p.required) {
            EXPECT_NE(fallback.find("**required**"), std::string::npos) << p.key;
        }
        if (p.kind == ParamKind::WholeNumber) {
            EXPECT_NE(fallback.find("`" + p.fallback.dump() + "`"), std::string::npos) << p.key;
            // The stop's range is the system's surfaces, checked against the system.
            const std::string range = std::to_string(int64_t(p.min->value)) + " – " +
                                      std::to_string(int64_t(p.max->value));
            if (p.key != "stop") {
                EXPECT_NE(type.find(range), std::string::npos) << p.key;
            }
        }
    }
    for (const auto& [key, row] : rows)
        EXPECT_TRUE(declared.contains(key)) << key << " is documented, not declared";
}

// A block's table (the `occurrence`-th "| key | type | default | meaning |" table): every
// key declared, with its default and its whole-number range.
void expect_block_documented(const ElementSpec& block, int occurrence) {
    const auto rows = docs_table("| key | type | default | meaning |", occurrence);
    ASSERT_EQ(rows.size(), block.params.size()) << block.name;
    for (const ParamSpec& p : block.params) {
        ASSERT_TRUE(rows.contains(p.key)) << p.key << " is not in the " << block.name << " table";
        EXPECT_EQ(rows.at(p.key).at(1), " " + default_text(p) + " ") << p.key;
        if (p.kind == ParamKind::WholeNumber) {
            const std::string range = std::to_string(int64_t(p.min->value)) + " – " +
                                      std::to_string(int64_t(p.max->value));
            EXPECT_NE(rows.at(p.key).at(0).find(range), std::string::npos) << p.key;
        }
    }
}

TEST(LensDesignSpec, TheTolerancesTableListsItsKeysWithTheirDefaultsAndRanges) {
    expect_block_documented(tolerances_spec(), 4);
}

TEST(LensDesignSpec, TheConfigurationTableListsItsKeysWithTheirDefaults) {
    expect_block_documented(configuration_spec(), 5);
}

TEST(LensDesignSpec, TheGlassSubstitutionTableListsItsKeysWithTheirDefaultsAndRanges) {
    expect_block_documented(glass_substitution_spec(), 3);
}

TEST(LensDesignSpec, TheGlobalSearchTableListsItsKeysWithTheirDefaultsAndRanges) {
    expect_block_documented(global_search_spec(), 2);
}

template <class Kind>
void expect_documented(const std::vector<DesignEntryType<Kind>>& types, const std::string& header) {
    const auto rows = docs_table(header);
    EXPECT_EQ(rows.size(), types.size()) << header;
    for (const DesignEntryType<Kind>& t : types) {
        ASSERT_TRUE(rows.contains(t.type)) << t.type << " is not in the table";
        EXPECT_EQ(keys_in(rows.at(t.type).at(0)), t.keys) << t.type;
    }
}

TEST(LensDesignSpec, TheDocsTablesListEachTypesKeys) {
    expect_documented(variable_types(), "| `type` | keys | the number | written back as |");
    expect_documented(operand_types(), "| `type` | keys | value | residual |");
}

TEST(LensDesignSpec, AKeyATypeDoesNotTakeIsRefusedWithWhatItTakes) {
    const auto refusal = [](const json& entry) {
        JsonObjectReader reader(entry, "variables[0]", entry_keys(variable_types()));
        try {
            read_entry_type(entry, reader, variable_types(), "variable");
        } catch (const SceneError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_EQ(refusal({{"type", "thickness"}, {"lens", "L1"}, {"surface", "front"}}),
              "variables[0].surface: a thickness variable takes no surface (it takes lens, min, "
              "max)");
    EXPECT_EQ(refusal({{"type", "image_distance"}, {"lens", "L1"}}),
              "variables[0].lens: an image_distance variable takes no lens (it takes min, max)");
    EXPECT_EQ(refusal({{"type", "aspheric"}, {"lens", "L1"}, {"surface", "front"}, {"order", 6}}),
              "");
    EXPECT_NE(refusal({{"lens", "L1"}}).find("type: missing (required)"), std::string::npos);
}

}  // namespace
}  // namespace lenslab
