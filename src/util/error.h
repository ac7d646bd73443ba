#pragma once
// The one base of every failure a user can act on (a bad scene, a file that cannot be
// written, more photons than memory holds): its message is printed as it stands and the
// program exits 1. Anything else that escapes is a bug in lenslab.

#include <cstdio>
#include <stdexcept>
#include <string>
#include <string_view>

namespace lenslab {

// `text` with its control characters (NUL, ESC, DEL, ...) written as \xNN, so a message that
// quotes input can neither be cut short at a NUL nor send escape sequences to a terminal.
// Newlines are kept when `keep_newlines` (a message quoting a child process's output).
// Backslashes are left alone, so escaping twice changes nothing.
inline std::string printable(std::string_view text, bool keep_newlines = false) {
    std::string out;
    out.reserve(text.size());
    for (const char c : text) {
        const auto u = static_cast<unsigned char>(c);
        if ((u < 0x20 && !(keep_newlines && c == '\n')) || u == 0x7f) {
            char hex[5];
            std::snprintf(hex, sizeof hex, "\\x%02x", u);
            out += hex;
        } else {
            out += c;
        }
    }
    return out;
}

// `noun` with its indefinite article, for messages: "a sphere", "an asphere".
inline std::string with_article(const std::string& noun) {
    const bool vowel =
        !noun.empty() && std::string_view("aeiouAEIOU").find(noun[0]) != std::string_view::npos;
    return (vowel ? "an " : "a ") + noun;
}

class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message) : std::runtime_error(printable(message, true)) {}
    explicit Error(const char* message) : Error(std::string(message)) {}
};

}  // namespace lenslab
