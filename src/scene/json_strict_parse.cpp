#include "scene/json_strict_parse.h"

#include <string>

#include "util/scene_error.h"

namespace lenslab {

namespace {

using nlohmann::json;

// nlohmann's messages read "[json.exception.parse_error.101] parse error at line 3,
// column 5: ..."; keep the part after the tag.
std::string without_tag(const std::string& what) {
    const size_t tag_end = what.find("] ");
    return tag_end == std::string::npos ? what : what.substr(tag_end + 2);
}

// What each parsed value costs in memory, as nlohmann stores it (libstdc++, 64-bit, allocator
// rounding included): an array element is a 16-byte json in a vector that may have grown to
// twice its size; an array adds its vector, an object its map, a key its map node; strings
// longer than the small-string buffer add their characters.
constexpr uint64_t kArraySlotBytes = 32;
constexpr uint64_t kArrayBytes = 32;
constexpr uint64_t kObjectBytes = 64;
constexpr uint64_t kMemberBytes = 96;
constexpr uint64_t kStringBytes = 32;
uint64_t text_bytes(size_t length) { return length > 15 ? length + 17 : 0; }

// Builds the document the way nlohmann's own DOM parser does, with what that parser lacks:
// a key given twice is found by looking it up in the object being built (nlohmann's callback
// parser rescans the parent after every object, which made 10^6 objects take minutes), the
// nesting stops at kMaxJsonDepth, and the values' memory at kMaxJsonValueBytes. Returning
// false stops the parse; stop() says why.
class StrictBuilder {
public:
    enum class Stop { None, Syntax, Duplicate, TooDeep, TooLarge };

    StrictBuilder(json& root, uint64_t max_bytes) : m_root(root), m_max_bytes(max_bytes) {}

    bool null() { return add(json(nullptr), 0); }
    bool boolean(bool v) { return add(json(v), 0); }
    bool number_integer(json::number_integer_t v) { return add(json(v), 0); }
    bool number_unsigned(json::number_unsigned_t v) { return add(json(v), 0); }
    bool number_float(json::number_float_t v, const json::string_t& /*text*/) {
        return add(json(v), 0);
    }
    bool string(json::string_t& v) {
        const uint64_t cost = kStringBytes + text_bytes(v.size());
        return add(json(std::move(v)), cost);
    }
    bool binary(json::binary_t& /*v*/) { return false; }  // JSON text has none

    bool start_object(std::size_t /*size*/) { return open(json::object(), kObjectBytes); }
    bool start_array(std::size_t /*size*/) { return open(json::array(), kArrayBytes); }
    bool end_object() { return close(); }
    bool end_array() { return close(); }

    bool key(json::string_t& k) {
        Frame& top = m_frames.back();
        top.key = k;
        auto& members = top.value->get_ref<json::object_t&>();
        if (members.count(k)) {
            m_stop = Stop::Duplicate;
            return false;
        }
        if (!charge(kMemberBytes + text_bytes(k.size()))) return false;
        m_member = &members[std::move(k)];
        return true;
    }

    bool parse_error(std::size_t /*position*/, const std::string& /*last_token*/,
                     const nlohmann::detail::exception& e) {
        m_stop = Stop::Syntax;
        m_syntax = without_tag(e.what());
        return false;
    }

    Stop stop() const { return m_stop; }
    const std::string& syntax_error() const { return m_syntax; }
    uint64_t values() const { return m_values; }

    // Where the parser is: "objects[2].front".
    std::string path() const {
        std::string path;
        for (const Frame& f : m_frames) {
            if (f.value->is_array()) {
                path += "[" + std::to_string(f.value->size() - 1) + "]";
            } else {
                path += (path.empty() ? "" : ".") + f.key;
            }
        }
        return path;
    }

private:
    struct Frame {
        json* value;
        std::string key;  // an object's latest key
    };

    bool charge(uint64_t bytes) {
        m_bytes += bytes;
        if (m_bytes <= m_max_bytes) return true;
        m_stop = Stop::TooLarge;
        return false;
    }

    // Where the next value goes: the root, the end of the open array, or the member whose
    // key came last. Pointers on the stack stay valid: an array only grows while none of
    // its elements is open.
    json* place(uint64_t cost) {
        ++m_values;
        if (m_frames.empty()) return charge(cost) ? &m_root : nullptr;
        json& parent = *m_frames.back().value;
        if (!charge(cost + (parent.is_array() ? kArraySlotBytes : 0))) return nullptr;
        if (parent.is_array()) return &parent.get_ref<json::array_t&>().emplace_back();
        return m_member;
    }

    bool add(json&& value, uint64_t cost) {
        json* slot = place(cost);
        if (!slot) return false;
        *slot = std::move(value);
        return true;
    }

    bool open(json&& value, uint64_t cost) {
        if (m_frames.size() >= static_cast<size_t>(kMaxJsonDepth)) {
            m_stop = Stop::TooDeep;
            return false;
        }
        json* slot = place(cost);
        if (!slot) return false;
        *slot = std::move(value);
        m_frames.push_back({slot, {}});
        return true;
    }

    bool close() {
        m_frames.pop_back();
        return true;
    }

    json& m_root;
    uint64_t m_max_bytes;
    json* m_member = nullptr;
    std::vector<Frame> m_frames;
    Stop m_stop = Stop::None;
    std::string m_syntax;
    uint64_t m_bytes = 0;
    uint64_t m_values = 0;
};

// Where in `text` the arrays and objects first nest deeper than `limit`: "line 1, column
// 513 (byte 513)". Only called once the parser stopped there, so the text before is valid
// JSON and brackets inside strings are the only ones to skip.
std::string depth_position(const std::string& text, int limit) {
    int depth = 0;
    size_t line = 1, line_start = 0;
    bool in_string = false;
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (in_string) {
            if (c == '\\') {
                ++i;
            } else if (c == '"') {
                in_string = false;
            }
            continue;
        }
        if (c == '"') {
            in_string = true;
        } else if (c == '\n') {
            ++line;
            line_start = i + 1;
        } else if (c == '[' || c == '{') {
            if (++depth > limit) {
                return "line " + std::to_string(line) + ", column " +
                       std::to_string(i - line_start + 1) + " (byte " + std::to_string(i + 1) + ")";
            }
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return "the end";
}

}  // namespace

nlohmann::json parse_json_strict(const std::string& text, const std::string& source,
                                 uint64_t max_value_bytes) {
    json root;
    StrictBuilder builder(root, max_value_bytes);
    bool parsed = false;
    try {
        parsed = json::sax_parse(text, &builder, json::input_format_t::json, true);
    } catch (const json::exception& e) {
        throw SceneError(source, "invalid JSON: " + without_tag(e.what()));
    }
    if (parsed) return root;
    switch (builder.stop()) {
        case StrictBuilder::Stop::Duplicate:
            throw SceneError(builder.path(), "key given twice in the same object");
        case StrictBuilder::Stop::TooDeep:
            throw SceneError(source, "invalid JSON: arrays and objects nested more than " +
                                         std::to_string(kMaxJsonDepth) + " deep, at " +
                                         depth_position(text, kMaxJsonDepth));
        case StrictBuilder::Stop::TooLarge:
            throw SceneError(source, "too large: its values would take more than " +
                                         std::to_string(max_value_bytes >> 20) +
                                         " MiB of memory once read (stopped after " +
                                         std::to_string(builder.values()) + " values)");
        default:
            throw SceneError(source, "invalid JSON: " + builder.syntax_error());
    }
}

}  // namespace lenslab
