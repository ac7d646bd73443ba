#include "lensfile/zar_archive.h"

#include <cstdint>

#include "lensfile/lens_file_error.h"
#include "lensfile/lens_file_tokens.h"

namespace lenslab {

namespace {

// The two header layouts seen in the wild, by the version byte that starts an entry: where
// the packed size and the name are, from the entry's start, and where its bytes begin.
struct ZarLayout {
    size_t header, size_at, size_bytes, name_at;
    bool utf16_name;
};

constexpr ZarLayout kZarNewer{0x288, 0x10, 8, 0x30, true};   // version 0xEC..
constexpr ZarLayout kZarOlder{0x14C, 0x0C, 4, 0x20, false};  // version 0xEA..

uint64_t little_endian(const std::string& bytes, size_t at, size_t count) {
    uint64_t v = 0;
    for (size_t i = count; i-- > 0;) v = (v << 8) | static_cast<unsigned char>(bytes[at + i]);
    return v;
}

// A NUL-terminated name in the header (UTF-16 LE or 8-bit), as UTF-8 for ASCII names;
// other characters become '?' (names are only matched on their extension).
std::string zar_entry_name(const std::string& bytes, size_t at, size_t end, bool utf16) {
    std::string name;
    const size_t step = utf16 ? 2 : 1;
    for (size_t i = at; i + step <= end; i += step) {
        const unsigned code = utf16 ? static_cast<unsigned char>(bytes[i]) |
                                          static_cast<unsigned char>(bytes[i + 1]) << 8
                                    : static_cast<unsigned char>(bytes[i]);
        if (code == 0) break;
        name += code < 0x80 ? static_cast<char>(code) : '?';
    }
    return name;
}

// Lens files are kilobytes; a runaway code stream (a damaged or hostile archive: each code
// may define a word one longer than the last) stops here rather than filling the memory.
constexpr size_t kMaxUnpackedBytes = size_t(64) << 20;

bool ends_with_lzw(const std::string& name) {
    return name.size() > 4 && lens_file_upper(name.substr(name.size() - 4)) == ".LZW";
}

}  // namespace

std::string unpack_zar_lzw(const std::string& packed) {
    std::vector<std::string> words;
    words.reserve(4096);
    for (int c = 0; c < 256; ++c) words.emplace_back(1, static_cast<char>(c));
    const uint64_t bits = uint64_t(packed.size()) * 8;
    uint64_t at = 0;
    int width = 8;
    std::string previous, out;
    for (;;) {
        // The code width grows as soon as the dictionary fills the codes of this width.
        if (words.size() >= (size_t(1) << width)) ++width;
        if (at + uint64_t(width) > bits) break;  // the rest is padding
        size_t code = 0;
        for (int b = 0; b < width; ++b, ++at) {
            const auto byte = static_cast<unsigned char>(packed[at / 8]);
            code = (code << 1) | ((byte >> (7 - at % 8)) & 1u);
        }
        std::string word;
        if (code < words.size()) {
            word = words[code];
        } else if (code == words.size() && !previous.empty()) {
            word = previous + previous[0];  // the code being defined by this very step
        } else {
            throw LensFileError("", 0, "LZW code " + std::to_string(code) + " is not defined yet");
        }
        out += word;
        if (out.size() > kMaxUnpackedBytes)
            throw LensFileError("", 0, "unpacks to more than 64 MiB: no lens file is that long");
        if (!previous.empty()) words.push_back(previous + word[0]);
        previous = std::move(word);
    }
    return out;
}

std::vector<ZarEntry> read_zar_archive(const std::string& bytes, const std::string& file) {
    std::vector<ZarEntry> entries;
    size_t at = 0;
    while (at + 2 <= bytes.size()) {
        const auto version = static_cast<unsigned char>(bytes[at]);
        const ZarLayout* layout = version == 0xEC   ? &kZarNewer
                                  : version == 0xEA ? &kZarOlder
                                                    : nullptr;
        const std::string where =
            "entry " + std::to_string(entries.size() + 1) + " (byte " + std::to_string(at) + ")";
        if (!layout) {
            throw LensFileError(file, 0,
                                "not a Zemax archive, or one of an unknown version: " + where +
                                    " starts with byte " + std::to_string(version) +
                                    " (0xEA or 0xEC expected)");
        }
        if (at + layout->header > bytes.size())
            throw LensFileError(file, 0, where + ": the archive ends inside its header");
        const uint64_t size = little_endian(bytes, at + layout->size_at, layout->size_bytes);
        const std::string name =
            zar_entry_name(bytes, at + layout->name_at, at + layout->header, layout->utf16_name);
        const size_t start = at + layout->header;
        if (size > bytes.size() - start) {
            throw LensFileError(file, 0,
                                where + " ('" + name + "'): the archive ends before its " +
                                    std::to_string(size) + " bytes");
        }
        ZarEntry entry{name, bytes.substr(start, size)};
        if (ends_with_lzw(name)) {
            entry.name = name.substr(0, name.size() - 4);
            try {
                entry.data = unpack_zar_lzw(entry.data);
            } catch (const LensFileError& e) {
                throw LensFileError(file, 0, where + " ('" + name + "'): " + e.reason());
            }
        }
        entries.push_back(std::move(entry));
        at = start + size;
    }
    return entries;
}

}  // namespace lenslab
