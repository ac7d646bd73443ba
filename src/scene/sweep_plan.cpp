#include "scene/sweep_plan.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "scene/json_reader.h"

namespace lenslab {

namespace {

using nlohmann::json;

constexpr int kMaxSweepFrames = 100000;  // the five digits of the frame files

std::string quoted_set(const std::string& text) { return "--set '" + printable(text) + "'"; }

// The whole of `text` as a finite number, or nothing.
std::optional<double> sweep_number(const std::string& text) {
    if (text.empty()) return std::nullopt;
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(text.c_str(), &end);
    if (end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(v))
        return std::nullopt;
    return v;
}

std::vector<std::string> split_range(const std::string& range) {
    std::vector<std::string> parts;
    size_t start = 0;
    for (size_t colon; (colon = range.find(':', start)) != std::string::npos; start = colon + 1)
        parts.push_back(range.substr(start, colon - start));
    parts.push_back(range.substr(start));
    return parts;
}

std::string pointer_text(const json::json_pointer& pointer) { return pointer.to_string(); }

// Where `pointer` leaves `scene`: the deepest part that exists and what it holds.
std::string missing_target_reason(const json& scene, const json::json_pointer& pointer) {
    json::json_pointer found = pointer;
    while (!found.empty() && !scene.contains(found)) found = found.parent_pointer();
    std::string step = pointer.to_string().substr(found.to_string().size());
    const size_t next = step.find('/', 1);
    if (next != std::string::npos) step.resize(next);
    const std::string missing = found.to_string() + step;
    const json& there = scene.at(found);
    const std::string where = found.empty() ? "the scene" : found.to_string();
    if (there.is_array()) {
        return "the scene has nothing at " + missing + " (" + where + " holds " +
               std::to_string(there.size()) + " elements" +
               (there.empty() ? "" : ", 0 to " + std::to_string(there.size() - 1)) + ")";
    }
    if (there.is_object()) return "the scene has nothing at " + missing;
    return where + " is " + excerpt(there) + ", which holds nothing (so there is no " + missing +
           ")";
}

}  // namespace

SweepParameter parse_sweep_parameter(const std::string& text) {
    const std::string form =
        " (the form is POINTER=FROM:TO:COUNT, e.g. /objects/1/center/2=0:5:10)";
    const size_t equals = text.rfind('=');
    if (equals == std::string::npos) {
        throw SweepError(quoted_set(text) + ": no '=' between the pointer and the range" + form);
    }
    SweepParameter p;
    p.pointer = text.substr(0, equals);
    const std::string range = text.substr(equals + 1);
    if (p.pointer.empty() || p.pointer[0] != '/') {
        throw SweepError(quoted_set(text) + ": '" + printable(p.pointer) +
                         "' is not a JSON pointer into the scene (it starts with '/')" + form);
    }
    try {
        (void)json::json_pointer(p.pointer);
    } catch (const json::exception&) {
        throw SweepError(quoted_set(text) + ": '" + printable(p.pointer) +
                         "' is not a JSON pointer (a '~' is written ~0, a '/' in a key ~1)");
    }
    const std::vector<std::string> parts = split_range(range);
    if (parts.size() != 3) {
        throw SweepError(quoted_set(text) + ": the range '" + printable(range) +
                         "' is not FROM:TO:COUNT" + form);
    }
    const char* names[] = {"FROM", "TO"};
    double ends[2] = {0, 0};
    for (int i = 0; i < 2; ++i) {
        const auto v = sweep_number(parts[i]);
        if (!v) {
            throw SweepError(quoted_set(text) + ": " + names[i] + " '" + printable(parts[i]) +
                             "' is not a finite number");
        }
        ends[i] = *v;
    }
    p.from = ends[0];
    p.to = ends[1];
    const auto count = sweep_number(parts[2]);
    if (!count || *count != std::floor(*count) || *count < 1 || *count > kMaxSweepFrames) {
        throw SweepError(quoted_set(text) + ": COUNT '" + printable(parts[2]) +
                         "' is not a whole number from 1 to " + std::to_string(kMaxSweepFrames));
    }
    p.count = static_cast<int>(*count);
    return p;
}

double sweep_value(const SweepParameter& p, int frame) {
    if (frame <= 0 || p.count <= 1) return p.from;
    if (frame >= p.count - 1) return p.to;
    const double t = static_cast<double>(frame) / (p.count - 1);
    return p.from + (p.to - p.from) * t;
}

SweepPlan parse_sweep_plan(const std::vector<std::string>& sets) {
    if (sets.empty()) throw SweepError("--set: nothing to sweep (give POINTER=FROM:TO:COUNT)");
    SweepPlan plan;
    for (const std::string& text : sets) {
        plan.parameters.push_back(parse_sweep_parameter(text));
        const SweepParameter& p = plan.parameters.back();
        const SweepParameter& first = plan.parameters.front();
        if (p.count != first.count) {
            throw SweepError("--set: " + p.pointer + " has " + std::to_string(p.count) +
                             " frames but " + first.pointer + " has " +
                             std::to_string(first.count) +
                             " (the parameters change together, so their COUNTs must agree)");
        }
        for (size_t i = 0; i + 1 < plan.parameters.size(); ++i) {
            if (plan.parameters[i].pointer == p.pointer)
                throw SweepError("--set: " + p.pointer + " is swept twice");
        }
    }
    plan.count = plan.parameters.front().count;
    return plan;
}

void check_sweep_targets(const json& scene, const SweepPlan& plan) {
    for (const SweepParameter& p : plan.parameters) {
        const json::json_pointer pointer(p.pointer);
        if (!scene.contains(pointer)) {
            throw SweepError("--set " + pointer_text(pointer) + ": " +
                             missing_target_reason(scene, pointer));
        }
        const json& value = scene.at(pointer);
        if (!value.is_number()) {
            throw SweepError("--set " + pointer_text(pointer) + ": the scene has " +
                             excerpt(value) + " there, not a number");
        }
    }
}

json sweep_frame_json(json scene, const SweepPlan& plan, int frame) {
    for (const SweepParameter& p : plan.parameters) {
        json& target = scene.at(json::json_pointer(p.pointer));
        const double v = sweep_value(p, frame);
        // A whole number stays one where the file had one (a pixel count, a seed), so the
        // reader's whole-number checks see what a user would have typed.
        if (target.is_number_integer() && v == std::floor(v) && std::abs(v) < 9e15) {
            target = static_cast<int64_t>(v);
        } else {
            target = v;
        }
    }
    return scene;
}

std::vector<int> frames_for_rank(int count, int rank, int size) {
    if (count < 0 || size < 1 || rank < 0 || rank >= size) {
        throw std::invalid_argument("frames_for_rank: rank " + std::to_string(rank) + " of " +
                                    std::to_string(size) + ", " + std::to_string(count) +
                                    " frames");
    }
    std::vector<int> frames;
    for (int frame = rank; frame < count; frame += size) frames.push_back(frame);
    return frames;
}

std::string frame_stem(int frame) {
    char text[16];
    std::snprintf(text, sizeof text, "%05d", frame);
    return text;
}

}  // namespace lenslab
