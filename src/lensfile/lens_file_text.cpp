#include "lensfile/lens_file_text.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "lensfile/lens_file_error.h"

namespace lenslab {

namespace {

// Lens files are a few kilobytes; a limit keeps a device or a wrong file from filling memory.
constexpr std::uintmax_t kLensFileMaxBytes = 16u << 20;

std::string lens_text_hex_byte(unsigned char b) {
    char text[8];
    std::snprintf(text, sizeof text, "0x%02X", b);
    return text;
}

void lens_text_append_utf8(std::string& out, char32_t c) {
    if (c < 0x80) {
        out += static_cast<char>(c);
    } else if (c < 0x800) {
        out += static_cast<char>(0xC0 | (c >> 6));
        out += static_cast<char>(0x80 | (c & 0x3F));
    } else if (c < 0x10000) {
        out += static_cast<char>(0xE0 | (c >> 12));
        out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (c & 0x3F));
    } else {
        out += static_cast<char>(0xF0 | (c >> 18));
        out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (c & 0x3F));
    }
}

// Splits decoded text into lines; a NUL is no text (a binary file read as UTF-8).
std::vector<std::string> lens_text_split(const std::string& text, const std::string& file) {
    std::vector<std::string> lines(1);
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '\r' || c == '\n') {
            if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
            lines.emplace_back();
        } else if (c == '\0') {
            throw LensFileError(file, static_cast<int>(lines.size()),
                                "a NUL byte: this is not a text file (a binary file, or UTF-16 "
                                "text without its byte order mark)");
        } else {
            lines.back() += c;
        }
    }
    if (lines.back().empty()) lines.pop_back();
    return lines;
}

std::string lens_text_from_utf16(const std::string& bytes, size_t start, bool big_endian,
                                 const std::string& file) {
    if ((bytes.size() - start) % 2 != 0) {
        throw LensFileError(file, 0,
                            "UTF-16 text with an odd number of bytes: the file is cut short");
    }
    std::string out;
    int line = 1;
    const auto unit = [&](size_t i) -> char32_t {
        const auto a = static_cast<unsigned char>(bytes[i]);
        const auto b = static_cast<unsigned char>(bytes[i + 1]);
        return big_endian ? (a << 8 | b) : (b << 8 | a);
    };
    for (size_t i = start; i < bytes.size(); i += 2) {
        char32_t c = unit(i);
        if (c >= 0xD800 && c <= 0xDBFF) {
            const char32_t low = i + 3 < bytes.size() ? unit(i + 2) : 0;
            if (low < 0xDC00 || low > 0xDFFF) {
                throw LensFileError(file, line,
                                    "invalid UTF-16: a high surrogate not followed by a low one");
            }
            c = 0x10000 + ((c - 0xD800) << 10) + (low - 0xDC00);
            i += 2;
        } else if (c >= 0xDC00 && c <= 0xDFFF) {
            throw LensFileError(file, line, "invalid UTF-16: a low surrogate on its own");
        }
        if (c == '\n') ++line;
        lens_text_append_utf8(out, c);
    }
    return out;
}

// Whether the bytes can be ISO-8859-1 text: no control byte but tab, line and page breaks.
bool lens_text_latin1_like(const std::string& bytes) {
    for (const char ch : bytes) {
        const auto b = static_cast<unsigned char>(ch);
        if ((b < 0x20 && b != '\t' && b != '\n' && b != '\r' && b != '\f') || b == 0x7F)
            return false;
    }
    return true;
}

// Checks UTF-8 (RFC 3629: no overlong forms, no surrogates, nothing above U+10FFFF).
void lens_text_check_utf8(const std::string& text, size_t start, const std::string& file) {
    int line = 1;
    for (size_t i = start; i < text.size();) {
        const auto b = static_cast<unsigned char>(text[i]);
        if (b == '\n') ++line;
        if (b < 0x80) {
            ++i;
            continue;
        }
        int extra = 0;
        char32_t c = 0;
        if (b >= 0xC2 && b <= 0xDF) {
            extra = 1, c = b & 0x1F;
        } else if (b >= 0xE0 && b <= 0xEF) {
            extra = 2, c = b & 0x0F;
        } else if (b >= 0xF0 && b <= 0xF4) {
            extra = 3, c = b & 0x07;
        } else {
            throw LensFileError(file, line,
                                "not UTF-8 text: the byte " + lens_text_hex_byte(b) +
                                    " cannot start a character (a binary file, or another "
                                    "encoding)");
        }
        for (int k = 1; k <= extra; ++k) {
            const auto cont = i + k < text.size() ? static_cast<unsigned char>(text[i + k]) : 0u;
            if ((cont & 0xC0) != 0x80) {
                throw LensFileError(file, line,
                                    "not UTF-8 text: the character starting with byte " +
                                        lens_text_hex_byte(b) + " is cut short");
            }
            c = (c << 6) | (cont & 0x3F);
        }
        const char32_t smallest = extra == 1 ? 0x80 : extra == 2 ? 0x800 : 0x10000;
        if (c < smallest || c > 0x10FFFF || (c >= 0xD800 && c <= 0xDFFF)) {
            throw LensFileError(file, line, "not UTF-8 text: an invalid character encoding");
        }
        i += 1 + extra;
    }
}

}  // namespace

std::string read_lens_file_bytes(const std::string& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) {
        throw LensFileError(path, 0, "is a directory, not a lens file");
    }
    if (!std::filesystem::is_regular_file(path, ec)) {
        throw LensFileError(
            path, 0, std::filesystem::exists(path, ec) ? "is not a regular file" : "no such file");
    }
    const auto size = std::filesystem::file_size(path, ec);
    if (!ec && size > kLensFileMaxBytes) {
        throw LensFileError(path, 0,
                            "is " + std::to_string(size >> 20) +
                                " MiB; a lens file is a few kilobytes (at most 16 MiB read)");
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) throw LensFileError(path, 0, std::string("cannot open: ") + std::strerror(errno));
    std::ostringstream s;
    s << in.rdbuf();
    if (in.bad()) throw LensFileError(path, 0, "cannot read");
    return s.str();
}

std::vector<std::string> decode_lens_file_lines(const std::string& bytes, const std::string& file) {
    const auto at = [&](size_t i) {
        return i < bytes.size() ? static_cast<unsigned char>(bytes[i]) : 0x100u;
    };
    if (at(0) == 0xFF && at(1) == 0xFE) {
        return lens_text_split(lens_text_from_utf16(bytes, 2, false, file), file);
    }
    if (at(0) == 0xFE && at(1) == 0xFF) {
        return lens_text_split(lens_text_from_utf16(bytes, 2, true, file), file);
    }
    // UTF-16 without a byte order mark: ASCII text has a zero byte in every pair.
    if (bytes.size() >= 4 && at(0) != 0 && at(1) == 0 && at(2) != 0 && at(3) == 0) {
        return lens_text_split(lens_text_from_utf16(bytes, 0, false, file), file);
    }
    if (bytes.size() >= 4 && at(0) == 0 && at(1) != 0 && at(2) == 0 && at(3) != 0) {
        return lens_text_split(lens_text_from_utf16(bytes, 0, true, file), file);
    }
    const size_t start = at(0) == 0xEF && at(1) == 0xBB && at(2) == 0xBF ? 3 : 0;
    try {
        lens_text_check_utf8(bytes, start, file);
    } catch (const LensFileError&) {
        // Older files and some vendors' downloads are ISO-8859-1 (a title's "Ø" as 0xD8): text
        // with no control bytes is read so; anything else is no text.
        if (start != 0 || !lens_text_latin1_like(bytes)) throw;
        std::string out;
        for (const char c : bytes) lens_text_append_utf8(out, static_cast<unsigned char>(c));
        return lens_text_split(out, file);
    }
    return lens_text_split(bytes.substr(start), file);
}

}  // namespace lenslab
