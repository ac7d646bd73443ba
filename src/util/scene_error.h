#pragma once
// An error in a scene or its JSON, named by its JSON path. Kept apart from the reader so
// that analysis and the apps can throw and catch it without the reader's machinery.

#include <string>

#include "util/error.h"

namespace lenslab {

// what() is "path: reason", both printable(): a key or a name from the file with a NUL, a
// newline or an escape sequence in it is shown escaped, on one line.
class SceneError : public Error {
public:
    SceneError(const std::string& path, const std::string& reason)
        : Error(path.empty() ? printable(reason) : printable(path) + ": " + printable(reason)),
          m_path(printable(path)),
          m_reason(printable(reason)) {}
    const std::string& path() const { return m_path; }
    const std::string& reason() const { return m_reason; }

private:
    std::string m_path;
    std::string m_reason;
};

}  // namespace lenslab
