#pragma once
// Problems found in a lens file (.zmx, .seq), named by file and line: a refusal (the file
// cannot be read, or holds a lens a lens_group cannot represent) is thrown; a line that is
// not understood but does not change the lens is kept as a warning and shown to the user.

#include <string>

#include "util/error.h"

namespace lenslab {

// what() is "FILE:LINE: reason" (no line when the problem is the whole file).
class LensFileError : public Error {
public:
    LensFileError(const std::string& file, int line, const std::string& reason)
        : Error(message(file, line, reason)), m_line(line), m_reason(reason) {}
    int line() const { return m_line; }
    const std::string& reason() const { return m_reason; }

private:
    static std::string message(const std::string& file, int line, const std::string& reason) {
        std::string text = file;
        if (line > 0) text.append(":").append(std::to_string(line));
        return text.append(": ").append(reason);
    }

    int m_line;
    std::string m_reason;
};

struct LensFileWarning {
    int line = 0;
    std::string message;
};

}  // namespace lenslab
