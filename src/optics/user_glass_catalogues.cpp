#include "optics/user_glass_catalogues.h"

#include <algorithm>
#include <cctype>
#include <deque>
#include <filesystem>
#include <mutex>

#include "optics/agf_catalogue.h"

namespace lenslab {

namespace {

struct UserCatalogue {
    std::string key;  // the file's canonical path
    std::vector<Glass> glasses;
};

// A deque: loading another catalogue never moves the glasses handed out before.
std::deque<UserCatalogue>& user_catalogues() {
    static std::deque<UserCatalogue> catalogues;
    return catalogues;
}

std::mutex& user_catalogue_mutex() {
    static std::mutex m;
    return m;
}

std::string upper_user_glass(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::toupper(c); });
    return s;
}

}  // namespace

void load_user_glass_catalogue(const std::string& path) {
    std::error_code ec;
    std::string key = std::filesystem::weakly_canonical(path, ec).string();
    if (ec) key = path;
    {
        std::lock_guard lock(user_catalogue_mutex());
        for (const UserCatalogue& c : user_catalogues())
            if (c.key == key) return;
    }
    std::vector<Glass> glasses = read_agf_catalogue(path);  // throws, outside the lock
    std::lock_guard lock(user_catalogue_mutex());
    for (const UserCatalogue& c : user_catalogues())
        if (c.key == key) return;  // another thread read it meanwhile
    user_catalogues().push_back({key, std::move(glasses)});
}

std::vector<const Glass*> user_glasses() {
    std::lock_guard lock(user_catalogue_mutex());
    std::vector<const Glass*> out;
    for (const UserCatalogue& c : user_catalogues()) {
        for (const Glass& g : c.glasses) out.push_back(&g);
    }
    return out;
}

const Glass* find_user_glass(const std::string& wanted_upper) {
    std::lock_guard lock(user_catalogue_mutex());
    const size_t colon = wanted_upper.find(':');
    const std::string maker = colon == std::string::npos ? "" : wanted_upper.substr(0, colon);
    const std::string name =
        colon == std::string::npos ? wanted_upper : wanted_upper.substr(colon + 1);
    for (const UserCatalogue& c : user_catalogues()) {
        for (const Glass& g : c.glasses) {
            if (upper_user_glass(g.name) == name &&
                (maker.empty() || upper_user_glass(g.maker) == maker))
                return &g;
        }
    }
    return nullptr;
}

}  // namespace lenslab
