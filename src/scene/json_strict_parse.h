#pragma once
// JSON text parsed strictly, for scene files and everything read like them: a key given twice,
// nesting past a depth and values past a memory budget are refused with their place.

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

namespace lenslab {

// How deep arrays and objects may nest in a scene file, and how much memory its parsed values
// may take (an estimate counting each value, array, object and key as the library stores it).
// Far above any real scene; they keep a hostile or runaway file from exhausting the stack or
// the memory. docs/scene-format.md#limits gives the messages.
inline constexpr int kMaxJsonDepth = 512;
inline constexpr uint64_t kMaxJsonValueBytes = uint64_t{512} << 20;

// Parses JSON text, refusing what nlohmann would accept silently: a key given twice in one
// object (the first value would be lost). Throws SceneError with path `source` for syntax
// errors, numbers out of range, nesting deeper than kMaxJsonDepth and values over
// kMaxJsonValueBytes, and with the JSON path of a duplicated key. Time and memory are linear
// in the text's length.
// `max_value_bytes` is for tests.
nlohmann::json parse_json_strict(const std::string& text, const std::string& source,
                                 uint64_t max_value_bytes = kMaxJsonValueBytes);

}  // namespace lenslab
